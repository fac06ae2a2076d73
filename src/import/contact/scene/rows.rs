//! A case's values as the scene's rows take them: creepages or prescribed forces, load, friction,
//! and the speed, step and rolling direction where they change within a history; a steady sweep
//! through the cases' creepages.

use super::super::deck::{Case, Case3, State};
use super::case3;
use super::history::{History, Run, Start};

/// Which of x, y the case prescribes as a force (F = 1: x; F = 2: x and y; frictionless
/// compression, T = 0, has no tangential problem and prescribes none).
pub(super) fn prescribed(c: &Case3) -> [bool; 2] {
    let tangential = c.digits.t != 0;
    [tangential && c.digits.f >= 1, tangential && c.digits.f == 2]
}

/// A steady sweep's keys for its point's (x, y, cs): the creepages, or the force ratios
/// prescribed in their place (F = 1, 2: `fx_over_fn`, `fy_over_fn`), and which are forces.
pub(super) fn sweep_axes(c: &Case3) -> ([&'static str; 3], [bool; 3]) {
    let [fx, fy] = prescribed(c);
    let axis = [if fx { "fx_over_fn" } else { "cx" }, if fy { "fy_over_fn" } else { "cy" }, "cs"];
    (axis, [fx, fy, false])
}

/// CONTACT's FX, FY under F = 1, 2 are FXREL, FYREL: the force on body 1 over FSTAT·FN (user
/// guide, "Tangential forces"); this project's Fx/FN is the force on body 2 over FN: −FXREL·FSTAT.
/// The one place the importer converts a prescribed force.
pub fn force_ratio(relative: f64, fstat: f64) -> f64 {
    -relative * fstat
}

/// A case's row: [cx or Fx/FN, cy or Fy/FN, cs, FN, μ] (T = 0: zero creepage; the forces where
/// [`prescribed`], converted by [`force_ratio`]).
pub(super) fn row(c: &Case3) -> [f64; 5] {
    let s = &c.state;
    let per_row = row_mu(s);
    let mu = match (s.friction_law, s.friction.as_slice(), &per_row) {
        // V = 3: the scene's nominal μ is the rows' largest ([friction] mu_rows).
        (_, _, Some(rows)) => rows.iter().copied().fold(0.0, f64::max),
        // FSTAT = μ_s(0) = FKIN + F1 + F2 (`m_friclaw.f90` lines 303-305), as `FrictionLaw::mu_static`.
        (2..=4, [fkin, f1, _, f2, _], None) => fkin + f1 + f2,
        // Coulomb (L = 0): FSTAT, CONTACT's one coefficient (`fric_update`: fkin := fstat).
        _ => s.friction.first().copied().unwrap_or(f64::NAN),
    };
    if c.digits.t == 0 {
        return [0.0, 0.0, 0.0, s.pen_or_fn, mu];
    }
    // FSTAT is μ: Coulomb's one coefficient, a falling law's μ at zero slip. With V = 3 CONTACT
    // scales the forces by 1, not FSTAT (`m_sinput.f90`: muscal = 1 unless V = 0, 2).
    let scale = if per_row.is_some() { 1.0 } else { mu };
    let [fx, fy] = prescribed(c);
    let x = if fx { force_ratio(s.cksi_or_fx, scale) } else { s.cksi_or_fx };
    let y = if fy { force_ratio(s.ceta_or_fy, scale) } else { s.ceta_or_fy };
    [x, y, s.cphi_per_mm, s.pen_or_fn, mu]
}

/// Coulomb's μ per grid row of a case with V = 3 (L = 0: FSTAT of each row IY, CONTACT's one
/// coefficient as with V = 0), the first at the lowest y; `None` for one friction (V = 0).
pub(super) fn row_mu(s: &State) -> Option<Vec<f64>> {
    (!s.friction_rows.is_empty() && s.friction_law == 0).then(|| s.friction_rows.chunks(2).map(|r| r[0]).collect())
}

/// The speeds (VELOC) of a history's cases where they change within it.
pub(super) fn speeds(cases: &[Case], h: &History) -> Option<Vec<f64>> {
    if h.run == Run::Shifts {
        return None;
    }
    // A shift that starts a rolling history has no speed of its own: its rolling's.
    let rolling = |n: usize| {
        h.cases[if h.run == (Run::Transient { start: Start::Shift }) && n == 0 {
            (n + 1).min(h.cases.len() - 1)
        } else {
            n
        }]
    };
    let v: Vec<f64> = (0..h.cases.len()).map(|n| case3(cases, rolling(n)).state.veloc_mm_s).collect();
    v.iter().any(|x| *x != v[0]).then_some(v)
}

/// The rolling steps (DQ) of a history's cases where they change within it (a shift start takes
/// its rolling's).
pub(super) fn step_lengths(cases: &[Case], h: &History) -> Option<Vec<f64>> {
    if !matches!(h.run, Run::Transient { .. }) {
        return None;
    }
    let rolling = |n: usize| h.cases[if h.run.has_start() && n == 0 { (n + 1).min(h.cases.len() - 1) } else { n }];
    let dq: Vec<f64> = (0..h.cases.len()).map(|n| case3(cases, rolling(n)).state.dq_mm).collect();
    // A steady start rolls DX whatever its DQ (CONTACT's steady rolling): its row takes its rolling's.
    dq.iter().any(|x| *x != dq[0]).then_some(dq)
}

/// `[rolling] chi_deg` of CONTACT's CHI [rad]: 0 or 180 within 0.01 rad (CONTACT's own test,
/// `m_sdis.f90`), other directions in degrees in [0, 360), rounded to 1e-9 degrees (a deck's
/// `30d` is read in radians: its 30 comes back exactly).
pub fn chi_deg(chi_rad: f64) -> f64 {
    if chi_rad.abs() < 0.01 {
        0.0
    } else if (chi_rad - std::f64::consts::PI).abs() < 0.01 {
        180.0
    } else {
        ((chi_rad.to_degrees() * 1e9).round() / 1e9).rem_euclid(360.0)
    }
}

/// Whether CHI [rad] rolls along +x or -x (CONTACT's test, within 0.01 rad).
pub fn along_x(chi_rad: f64) -> bool {
    matches!(chi_deg(chi_rad), 0.0 | 180.0)
}

/// The Courant number whose `courant · dx` is DQ exactly where one is within a few ulps.
pub(super) fn courant_for(dq_mm: f64, dx_mm: f64) -> f64 {
    let start = dq_mm / dx_mm;
    let (mut up, mut down) = (start, start);
    let mut candidates = vec![start];
    for _ in 0..8 {
        up = up.next_up();
        down = down.next_down();
        candidates.extend([up, down]);
    }
    candidates.into_iter().find(|&c| c * dx_mm == dq_mm).unwrap_or(start)
}

/// The upper edge `x0 + n d`, moved by a few ulps so that `(x1 − x0)/n` is `d` exactly (the
/// project's grid divides the extent).
pub(super) fn upper_edge(x0: f64, n: usize, d: f64) -> f64 {
    let start = x0 + n as f64 * d;
    let mut candidates = vec![start];
    let (mut up, mut down) = (start, start);
    for _ in 0..8 {
        up = up.next_up();
        down = down.next_down();
        candidates.extend([up, down]);
    }
    candidates.into_iter().find(|&x1| (x1 - x0) / n as f64 == d).unwrap_or(start)
}

/// `c + d t` as a sweep point is sampled (`Scene::sweep_point`).
fn sweep_add(c: f64, d: f64, t: f64) -> f64 {
    if d == 0.0 {
        c
    } else if c == 0.0 {
        d * t
    } else {
        c + d * t
    }
}

/// A sweep `[cx, cy, cs] = constants + t·direction` through given points.
pub(super) struct Sweep {
    /// The creepage whose values are the parameter t (its direction component is 1).
    pub(super) param: usize,
    pub(super) direction: [f64; 3],
    pub(super) constants: [f64; 3],
    /// t per point.
    pub(super) t: Vec<f64>,
}

/// A sweep through the points, if it reproduces every point exactly.
pub(super) fn sweep_of(points: &[[f64; 3]]) -> Option<Sweep> {
    let varies = |j: usize| points.iter().any(|p| p[j].to_bits() != points[0][j].to_bits());
    let k = (0..3).find(|&j| varies(j)).unwrap_or(0);
    let last = points[points.len() - 1];
    let mut direction = [0.0; 3];
    let mut constants = [0.0; 3];
    for j in 0..3 {
        if j == k {
            direction[j] = 1.0;
        } else if varies(j) {
            direction[j] = last[j] / last[k];
        } else {
            constants[j] = points[0][j];
        }
    }
    let t: Vec<f64> = points.iter().map(|p| p[k]).collect();
    let exact = points
        .iter()
        .zip(&t)
        .all(|(p, &t)| (0..3).all(|j| sweep_add(constants[j], direction[j], t).to_bits() == p[j].to_bits()));
    (exact && direction.iter().all(|d| d.is_finite())).then_some(Sweep { param: k, direction, constants, t })
}
