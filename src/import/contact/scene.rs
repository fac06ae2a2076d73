//! Cases → scenes: one scene per history. A history is a run of cases that carries its state: a
//! transient case with P = 0 continues the case before it (a steady case before it is its steady
//! start, `[init] kind = "steady"`); a case with P = 2 starts afresh. Consecutive steady cases
//! (T = 3, or T = 0 at zero creepage) of one setup are one sweep (`at` the cases' creepages). A
//! transient history is a creepage table (`<name>_table.csv`) at the times `k DQ / VELOC`; a grid
//! geometry is h per element (`<name>_h.csv`). Each scene is written as a TOML table, read back
//! with the project's scene reader and resolved in a temporary folder, and must give every case's
//! creepages, load and friction bit for bit. A history whose cases move one grid by whole elements
//! (a moving window) is written on the union grid of its windows, checked exact per case.

use super::deck::{self, Case, Case3, CaseKind, Potcon, State};
use super::{features, CaseStatus};
use crate::error::InputError;
use crate::physics::material::combine_bodies;
use crate::problem::Problem;
use std::fmt::Write;
use std::path::Path;
use toml::{Table, Value};

/// One scene's files: (file name, contents), the scene file first.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneFiles {
    pub name: String,
    /// The deck's first and last case of the scene.
    pub cases: [usize; 2],
    pub files: Vec<(String, String)>,
}

/// The import of one deck: its supported scenes and every case's status.
#[derive(Debug, Clone, PartialEq)]
pub struct Imported {
    pub scenes: Vec<SceneFiles>,
    pub statuses: Vec<CaseStatus>,
}

/// How a history runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Run {
    /// Steady cases of one setup.
    Sweep,
    /// Transient rolling cases (T = 2) from `start`.
    Transient { start: Start },
    /// Shifts (T = 1) from zero traction: `[rolling] motion = "shift"`.
    Shifts,
}

/// The state a transient rolling history starts from (its step 0, where it has one).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Start {
    /// Zero traction (P = 2): no step 0.
    Zero,
    /// The steady case before it (`[init] kind = "steady"`).
    Steady,
    /// The shift (T = 1) before it (`[init] kind = "shift"`).
    Shift,
}

impl Run {
    /// Whether the history's first case is its step 0 (an initial state, not a step).
    fn has_start(self) -> bool {
        matches!(self, Run::Transient { start: Start::Steady | Start::Shift })
    }
}

#[derive(Debug, Clone)]
struct History {
    run: Run,
    /// Indices into the deck's cases.
    cases: Vec<usize>,
}

/// The scenes of a deck's text (`file`: its name for `[origin]` and messages; `stem`: the scene
/// names' prefix).
pub fn import_text(file: &str, stem: &str, text: &str) -> Result<Imported, InputError> {
    let cases = deck::parse(file, text)?;
    let mut statuses: Vec<CaseStatus> = cases.iter().map(status).collect();
    // Steady cases whose creepages no sweep reproduces exactly are scenes of one case each.
    let grouped = group(&cases, &mut statuses);
    for h in &grouped {
        check_union(&cases, h, &mut statuses);
    }
    let histories: Vec<History> = grouped
        .into_iter()
        .flat_map(|h| {
            let points: Vec<[f64; 3]> =
                h.cases.iter().map(|&k| row(case3(&cases, k))).map(|r| [r[0], r[1], r[2]]).collect();
            if h.run == Run::Sweep && speeds(&cases, &h).is_none() && sweep_of(&points).is_none() {
                h.cases.iter().map(|&k| History { run: Run::Sweep, cases: vec![k] }).collect()
            } else {
                vec![h]
            }
        })
        .collect();
    let mut scenes = Vec::new();
    for h in histories {
        let numbers: Vec<usize> = h.cases.iter().map(|&k| cases[k].number).collect();
        let span = format!("cases {} to {}", numbers[0], numbers[numbers.len() - 1]);
        // A history's state flows forward: the cases before its first refused one are a history.
        let cut = h.cases.iter().position(|&k| !statuses[k].supported()).unwrap_or(h.cases.len());
        for &k in &h.cases[cut..] {
            if statuses[k].supported() {
                let bad = cases[h.cases[cut]].number;
                statuses[k].refused.push(format!("its history ({span}) holds case {bad}, which is not supported"));
            }
        }
        let h = match (h.run, cut) {
            (_, 0) => continue,
            // A start alone: the steady case or the shift itself.
            (Run::Transient { start: Start::Steady }, 1) => History { run: Run::Sweep, cases: vec![h.cases[0]] },
            (Run::Transient { start: Start::Shift }, 1) => History { run: Run::Shifts, cases: vec![h.cases[0]] },
            (run, cut) => History { run, cases: h.cases[..cut].to_vec() },
        };
        let numbers: Vec<usize> = h.cases.iter().map(|&k| cases[k].number).collect();
        let span = format!("cases {} to {}", numbers[0], numbers[numbers.len() - 1]);
        match build(file, stem, &cases, &h) {
            Ok(s) => {
                for &k in &h.cases {
                    statuses[k].scene = Some(s.name.clone());
                }
                scenes.push(s);
            }
            Err(e) => {
                for &k in &h.cases {
                    statuses[k].refused.push(format!("the project refuses the scene of its history ({span}): {e}"));
                }
            }
        }
    }
    Ok(Imported { scenes, statuses })
}

fn status(c: &Case) -> CaseStatus {
    let base = CaseStatus { case: c.number, line: c.line, module: 3, scene: None, refused: vec![], notes: vec![] };
    match &c.kind {
        CaseKind::Module1 => CaseStatus {
            module: 1,
            refused: vec![
                "MODULE = 1: wheel-rail contact (module 1) is not supported; module 3 cases are imported".into()
            ],
            ..base
        },
        CaseKind::Module3(c3) => {
            let (refused, notes) = features::assess(c3);
            CaseStatus { refused, notes, ..base }
        }
    }
}

fn case3(cases: &[Case], k: usize) -> &Case3 {
    match &cases[k].kind {
        CaseKind::Module3(c) => c,
        CaseKind::Module1 => unreachable!("histories hold module-3 cases only"),
    }
}

/// CONTACT's fixed stop of the slip-velocity iteration: rms(S_k − S_(k−1)) ≤ 0.001·rms(S_k)
/// (`m_stang.f90` line 579), `[contact_solver] veldep_tolerance` of an imported falling law.
const CONTACT_VELDEP_TOLERANCE: f64 = 1e-3;

/// `[contact_solver] inislp` and `omgslp` of a case's INISLP, OMGSLP (`m_stang.f90` lines
/// 258-264: 0 from the previous solution, > 0 from s = 0, < 0 from s = V).
fn slip_iteration(s: &State) -> (&'static str, f64) {
    let (inislp, omgslp) = s.slip_start.unwrap_or((0, crate::scene::OMGSLP));
    let start = match inislp {
        0 => "previous",
        i if i > 0 => "below",
        _ => "above",
    };
    (start, omgslp)
}

/// Whether a case's friction falls with the slip velocity (L = 2, 3, 4 in force).
fn falling(s: &State) -> bool {
    matches!(s.friction_law, 2..=4)
}

/// What differs between two cases' setups (all but the creepages, VELOC and, where `load_varies`,
/// FN and a Coulomb friction), named. A falling law and its memory are one for the whole history.
fn setup_difference(a: &State, b: &State, load_varies: bool) -> Option<&'static str> {
    let coulomb = a.friction_law == 0 && b.friction_law == 0;
    let pairs: [(&'static str, bool); 12] = [
        ("FN", load_varies || a.pen_or_fn == b.pen_or_fn),
        // Coulomb: FSTAT alone counts (CONTACT overwrites FKIN with it).
        (
            "FSTAT, FKIN",
            (load_varies && coulomb)
                || a.friction == b.friction
                || (coulomb && a.friction.first() == b.friction.first()),
        ),
        ("MEMDST, MEM_S0", a.memory == b.memory),
        ("FSTAT, FKIN per grid row (V = 3)", a.friction_rows == b.friction_rows),
        ("the influence functions (C)", a.inflcf == b.inflcf),
        // CHI or DQ may change within a transient history (the table's chi_deg, [`turn_refused`],
        // or its courant column; not both in one history, `build`).
        ("CHI, DQ", load_varies || (a.chi_rad, a.dq_mm) == (b.chi_rad, b.dq_mm)),
        ("POISS, GG", (a.poiss, a.gg_mpa) == (b.poiss, b.gg_mpa)),
        (
            "the potential contact (IPOTCN and its line)",
            a.potcon == b.potcon
                || (load_varies && quadratics(a, b) && window_shift(a, b).is_some())
                || (load_varies && same_hertz_grid(a, b)),
        ),
        ("the undeformed distance (IBASE)", a.undeformed == b.undeformed || (load_varies && quadratics(a, b))),
        ("the friction law", a.friction_law == b.friction_law),
        ("SPINXO, SPINYO", a.spin_centre_mm == b.spin_centre_mm),
        ("the rolling step (CHI, DQ, VELOC read)", a.rolling_read == b.rolling_read),
    ];
    pairs.iter().find(|(_, same)| !same).map(|(name, _)| *name)
}

/// Group the module-3 cases into histories; a transient case that changes its history's setup is
/// refused here.
fn group(cases: &[Case], statuses: &mut [CaseStatus]) -> Vec<History> {
    let mut hs: Vec<History> = Vec::new();
    // Whether the last history may be continued by the next case.
    let mut open = false;
    for (k, c) in cases.iter().enumerate() {
        let CaseKind::Module3(c3) = &c.kind else {
            open = false;
            continue;
        };
        let d = c3.digits;
        let continues = matches!(d.t, 1 | 2) && d.p != 2 && open;
        if d.t == 0 {
            // Frictionless compression: a history of its own (what follows starts from zero traction).
            hs.push(History { run: Run::Sweep, cases: vec![k] });
            open = false;
            continue;
        }
        if d.t == 3 {
            let joins = match hs.last() {
                Some(h) if open && h.run == Run::Sweep => {
                    let first = case3(cases, h.cases[0]);
                    setup_difference(&first.state, &c3.state, false).is_none()
                        && first.digits.n == d.n
                        && (!falling(&c3.state) || slip_iteration(&first.state) == slip_iteration(&c3.state))
                        && first.digits.b == c3.digits.b
                        && statuses[h.cases[0]].supported() == statuses[k].supported()
                        && prescribed(first) == prescribed(c3)
                        && sweep_continues(cases, h, c3)
                }
                _ => false,
            };
            match hs.last_mut() {
                Some(h) if joins => h.cases.push(k),
                _ => hs.push(History { run: Run::Sweep, cases: vec![k] }),
            }
            open = true;
            continue;
        }
        if continues {
            let h = hs.last_mut().expect("an open history");
            if let Some(why) = continuation_refused(h, d.t) {
                statuses[k].refused.push(why.into());
                let run = if d.t == 1 { Run::Shifts } else { Run::Transient { start: Start::Zero } };
                hs.push(History { run, cases: vec![k] });
                open = true;
                continue;
            }
            let mut prev = case3(cases, h.cases[h.cases.len() - 1]).state.clone();
            if h.run == Run::Shifts && d.t == 2 && h.cases.len() == 1 {
                // The shift is this rolling history's initial state; the rolling step is read now.
                h.run = Run::Transient { start: Start::Shift };
                (prev.chi_rad, prev.dq_mm, prev.veloc_mm_s) = (c3.state.chi_rad, c3.state.dq_mm, c3.state.veloc_mm_s);
                prev.rolling_read = c3.state.rolling_read;
            }
            if h.run == Run::Sweep && d.t == 2 {
                // The last steady case is this transient history's steady start.
                let start = h.cases.pop().expect("a steady case");
                if h.cases.is_empty() {
                    hs.pop();
                }
                hs.push(History { run: Run::Transient { start: Start::Steady }, cases: vec![start] });
            }
            let h = hs.last_mut().expect("a history");
            let last = case3(cases, h.cases[h.cases.len() - 1]);
            let hertz = matches!(prev.potcon, Some(Potcon::Hertz { .. }));
            let after_start = h.run == (Run::Transient { start: Start::Steady }) && h.cases.len() == 1;
            let other_iteration = falling(&c3.state) && slip_iteration(&prev) != slip_iteration(&c3.state);
            if after_start && other_iteration {
                let (start, omgslp) = slip_iteration(&c3.state);
                statuses[h.cases[0]].notes.push(format!(
                    "INISLP, OMGSLP = {:?}: the steady start is solved with its transient cases' inislp = {start:?}, omgslp = {omgslp} (one per scene, [contact_solver])",
                    prev.slip_start.unwrap_or((0, crate::scene::OMGSLP))
                ));
            }
            // B: one pressure for the history's steps, its start's may differ ([normal] start_pressure).
            let only_start = h.run.has_start() && h.cases.len() == 1;
            if !only_start && last.digits.b != d.b {
                statuses[k].refused.push(format!(
                    "B = {} after B = {}: the normal problem changes within a history (supported: one B for the steps of a history, [normal] pressure, and another for the shift or steady case that starts it, [normal] start_pressure)",
                    d.b, last.digits.b
                ));
            }
            if prev.potcon != c3.state.potcon && same_hertz_grid(&prev, &c3.state) {
                let axes = |s: &State| hertz_axes(s).map(|(.., [a, b])| format!("a = {a}, b = {b} mm"));
                statuses[k].notes.push(format!(
                    "IPOTCN = {} re-specifies the Hertzian grid ({}) as the case before it ({}): the same MX, MY, SCALE and semi-axes within {HERTZ_GRID_REL:e}; the history keeps its first case's",
                    c3.state.potcon.as_ref().map_or(0, Potcon::ipotcn),
                    axes(&c3.state).unwrap_or_default(),
                    axes(&prev).unwrap_or_default()
                ));
            }
            if let Some(what) = setup_difference(&prev, &c3.state, true) {
                statuses[k].refused.push(format!("changes {what} within a transient history"));
            } else if let Some(why) = turn_refused(cases, h, &prev, &c3.state) {
                statuses[k].refused.push(why);
            } else if other_iteration && !after_start {
                statuses[k].refused.push(
                    "changes INISLP, OMGSLP within a transient history (supported: one start and damping of the slip-velocity iteration per history, [contact_solver] inislp, omgslp)".into(),
                );
            } else if hertz && (prev.pen_or_fn != c3.state.pen_or_fn || last.digits.n != d.n) {
                let name = |n: u8| if n == 0 { "PEN" } else { "FN" };
                statuses[k].refused.push(format!(
                    "{} = {} after {} = {}: a Hertzian geometry (IPOTCN < 0) under a load or approach that changes within a transient history (CONTACT derives the curvatures or the grid from it anew; supported: one FN or one PEN per Hertzian history, or the geometry as a grid, IPOTCN > 0)",
                    name(d.n), c3.state.pen_or_fn, name(last.digits.n), prev.pen_or_fn
                ));
            }
            h.cases.push(k);
        } else if d.t == 1 {
            hs.push(History { run: Run::Shifts, cases: vec![k] });
        } else {
            hs.push(History { run: Run::Transient { start: Start::Zero }, cases: vec![k] });
        }
        open = true;
    }
    hs
}

/// Why a transient case (`t`: its T) cannot continue history `h` (P = 0), if it cannot: a shift
/// continues shifts only; rolling continues rolling, a steady case or one shift.
fn continuation_refused(h: &History, t: u8) -> Option<&'static str> {
    match (h.run, t) {
        (Run::Shifts, 1) | (Run::Transient { .. }, 2) | (Run::Sweep, 2) => None,
        (Run::Shifts, _) if h.cases.len() == 1 => None,
        (Run::Shifts, _) => Some("T = 2 after several shifts (T = 1) with P = 0: supported: one shift, the initial state of the rolling (`[init] kind = \"shift\"`)"),
        (_, _) => Some("T = 1 with P = 0 after a rolling case: supported: shifts from rest (P = 2) or after shifts"),
    }
}

/// Why a transient case may not roll along another CHI than the history so far, if it may not
/// (the table's chi_deg: the steady start at 0, no VELOC or B(1..6) changing with it, no -x).
fn turn_refused(cases: &[Case], h: &History, prev: &State, next: &State) -> Option<String> {
    let directions = |s: &State| chi_deg(s.chi_rad);
    let turns = h.cases.iter().map(|&k| directions(&case3(cases, k).state)).any(|d| d != directions(next))
        || directions(prev) != directions(next);
    if !turns {
        return None;
    }
    let start_turned =
        h.run == (Run::Transient { start: Start::Steady }) && directions(&case3(cases, h.cases[0]).state) != 0.0;
    let along_minus_x =
        std::iter::once(next).chain(h.cases.iter().map(|&k| &case3(cases, k).state)).any(|s| directions(s) == 180.0);
    let speeds = h.cases.iter().any(|&k| case3(cases, k).state.veloc_mm_s != next.veloc_mm_s);
    let quads = h.cases.iter().any(|&k| case3(cases, k).state.undeformed != next.undeformed);
    let why = if start_turned {
        "a steady start at CHI other than 0"
    } else if along_minus_x {
        "CHI = 180 degrees in it (rolling along -x is imported for a whole history only)"
    } else if speeds || quads {
        "VELOC or the undeformed distance (IBASE) changing in it too"
    } else {
        return None;
    };
    Some(format!(
        "CHI = {} rad: the rolling direction changes within a transient history with {why} (supported: CHI changing per case in transient rolling, the table's column chi_deg)",
        next.chi_rad
    ))
}

/// Whether a steady case continues a sweep: at the sweep's speed (VELOC) where its creepages
/// vary, or at its creepages where the speed varies (a speed sweep, `over = "v_mm_s"`).
fn sweep_continues(cases: &[Case], h: &History, c: &Case3) -> bool {
    let first = case3(cases, h.cases[0]);
    let speeds_vary = h.cases.iter().any(|&k| case3(cases, k).state.veloc_mm_s != first.state.veloc_mm_s);
    let same_speed = c.state.veloc_mm_s == first.state.veloc_mm_s;
    let same_creepage = row(c)[..3].iter().zip(&row(first)[..3]).all(|(a, b)| a.to_bits() == b.to_bits());
    (same_speed && !speeds_vary) || (same_creepage && (speeds_vary || h.cases.len() == 1))
}

/// Largest relative difference of the semi-axes of two Hertzian potential contacts taken as one
/// grid: CONTACT's printed curvature A1 = 0.2963e-2 of `testbank.inp` case 16 gives a = 4.09992
/// mm where case 13's AA = 4.1 (2e-5).
const HERTZ_GRID_REL: f64 = 1e-4;

/// The semi-axes [mm] of a case's Hertzian potential contact (IPOTCN = -3: AA, BB; -1: Hertz's of
/// A1, B1 at its FN; -2: of A1 and AOB), with MX, MY and SCALE; `None`: not Hertzian or N = 0.
fn hertz_axes(s: &State) -> Option<(usize, usize, f64, [f64; 2])> {
    let Some(Potcon::Hertz { ipotcn, mx, my, params }) = &s.potcon else {
        return None;
    };
    let axes = match ipotcn {
        -3 => [params[0], params[1]],
        -1 | -2 => {
            let b1 = if *ipotcn == -2 { params[0] * curvature_ratio(params[1], s) } else { params[1] };
            let radii = crate::physics::Radii { r_wx_mm: 0.5 / params[0], r_wy_mm: 1.0 / b1, r_ry_mm: 1.0 / b1 };
            let m = combine_bodies(s.poiss, s.gg_mpa);
            let material = crate::physics::Material::from_g(m.g_mpa, m.poisson);
            let e = crate::physics::HertzContact::from_radii(&radii, s.pen_or_fn, &material).ok()?;
            [e.a_mm, e.b_mm]
        }
        _ => return None,
    };
    Some((*mx, *my, params[2], axes))
}

/// Whether a case re-specifies its history's Hertzian grid as the same grid: MX, MY and SCALE
/// equal, the semi-axes within [`HERTZ_GRID_REL`] (the history keeps the first case's).
fn same_hertz_grid(a: &State, b: &State) -> bool {
    match (hertz_axes(a), hertz_axes(b)) {
        (Some((mx, my, scale, [aa, ab])), Some((nx, ny, sc, [ba, bb]))) => {
            (mx, my, scale) == (nx, ny, sc)
                && ((aa - ba) / aa).abs() <= HERTZ_GRID_REL
                && ((ab - bb) / ab).abs() <= HERTZ_GRID_REL
        }
        _ => false,
    }
}

/// Whether both cases give a quadratic undeformed distance (IBASE = 1, IPLAN alike) on one grid:
/// new B(1..6) per case are the table's columns `b1_per_mm` … `b6_mm`.
fn quadratics(a: &State, b: &State) -> bool {
    let q = |s: &State| s.undeformed.as_ref().filter(|u| u.ibase == 1).map(|u| u.iplan);
    matches!(a.potcon, Some(Potcon::Grid { .. })) && q(a).is_some() && q(a) == q(b)
}

/// The whole elements (x, y) by which `b`'s grid is `a`'s moved (same IPOTCN, MX, MY, DX, DY;
/// XL, YL shifted by integer multiples of DX, DY), if it is.
fn window_shift(a: &State, b: &State) -> Option<(i64, i64)> {
    let (
        Some(Potcon::Grid { ipotcn: ia, mx: ma, my: na, xl_mm: xa, yl_mm: ya, dx_mm: dxa, dy_mm: dya }),
        Some(Potcon::Grid { ipotcn: ib, mx: mb, my: nb, xl_mm: xb, yl_mm: yb, dx_mm: dxb, dy_mm: dyb }),
    ) = (&a.potcon, &b.potcon)
    else {
        return None;
    };
    let whole = |from: f64, to: f64, d: f64| {
        let k = ((to - from) / d).round();
        ((from + k * d - to).abs() <= 1e-9 * d).then_some(k as i64)
    };
    let same = (ia, ma, na, dxa, dya) == (ib, mb, nb, dxb, dyb);
    same.then_some(())?;
    Some((whole(*xa, *xb, *dxa)?, whole(*ya, *yb, *dya)?))
}

/// The quadratic undeformed distance B(1..6) at (x, y) (IBASE = 1).
fn quadratic(b: &[f64], (x, y): (f64, f64)) -> f64 {
    b[0] * x * x + b[1] * x * y + b[2] * y * y + b[3] * x + b[4] * y + b[5]
}

/// The union grid of a history whose cases move one grid by whole elements (`None` where the grid
/// does not move): the lowest XL, YL and the extent of every window.
fn union_grid(cases: &[Case], h: &History) -> Option<Potcon> {
    let first = &case3(cases, h.cases[0]).state;
    let shifts: Vec<(i64, i64)> =
        h.cases.iter().map(|&k| window_shift(first, &case3(cases, k).state)).collect::<Option<_>>()?;
    if shifts.iter().all(|&s| s == (0, 0)) {
        return None;
    }
    let Some(Potcon::Grid { ipotcn, mx, my, xl_mm, yl_mm, dx_mm, dy_mm }) = first.potcon.clone() else {
        return None;
    };
    let lo = |f: fn(&(i64, i64)) -> i64| shifts.iter().map(f).min().unwrap_or(0);
    let hi = |f: fn(&(i64, i64)) -> i64| shifts.iter().map(f).max().unwrap_or(0);
    let (x0, y0) = (lo(|s| s.0), lo(|s| s.1));
    Some(Potcon::Grid {
        ipotcn,
        mx: mx + (hi(|s| s.0) - x0) as usize,
        my: my + (hi(|s| s.1) - y0) as usize,
        xl_mm: xl_mm + x0 as f64 * dx_mm,
        yl_mm: yl_mm + y0 as f64 * dy_mm,
        dx_mm,
        dy_mm,
    })
}

/// A moving window (its grid moved by whole elements per case) is written on the union grid of
/// its history, exact where no element outside a case's window can touch: with the approach
/// prescribed (N = 0), the undeformed distance exceeds PEN at every such element, so its gap stays
/// open and its traction zero, as CONTACT's, which has no element there. Each case is refused
/// where this fails, or noted where it holds.
fn check_union(cases: &[Case], h: &History, statuses: &mut [CaseStatus]) {
    let Some(Potcon::Grid { mx, my, xl_mm, yl_mm, dx_mm, dy_mm, .. }) = union_grid(cases, h) else {
        return;
    };
    for &k in &h.cases {
        let c = case3(cases, k);
        let Some(Potcon::Grid { mx: wx, my: wy, xl_mm: xl, yl_mm: yl, .. }) = &c.state.potcon else { continue };
        let (ox, oy) = (((xl - xl_mm) / dx_mm).round() as usize, ((yl - yl_mm) / dy_mm).round() as usize);
        let b = c.state.undeformed.as_ref().map(|u| u.values.clone()).unwrap_or_default();
        let pen = c.state.pen_or_fn;
        let h_mm: Vec<f64> = (0..mx * my)
            .map(|e| quadratic(&b, (xl_mm + ((e % mx) as f64 + 0.5) * dx_mm, yl_mm + ((e / mx) as f64 + 0.5) * dy_mm)))
            .collect();
        let m = combine_bodies(c.state.poiss, c.state.gg_mpa);
        let by_pen = c.digits.n == 0;
        let pn = pressure_on(&h_mm, (mx, my, dx_mm, dy_mm), (m.g_mpa, m.poisson), pen, by_pen).unwrap_or_default();
        let touching = (0..mx * my).map(|e| (e % mx, e / mx)).find(|&(ix, iy)| {
            let inside = (ox..ox + wx).contains(&ix) && (oy..oy + wy).contains(&iy);
            !inside && pn.get(iy * mx + ix).is_none_or(|p| *p != 0.0)
        });
        match touching {
            Some((ix, iy)) => statuses[k].refused.push(format!(
                "XL = {xl}: the grid moves by whole elements, but at PEN or FN = {pen} element ({}, {}) of the union grid ({mx} x {my} from XL = {xl_mm}), outside case {}'s window, carries pressure {:?} MPa: it touches where CONTACT has no element (supported: a moving window outside which the union grid's normal solution is zero)",
                ix + 1,
                iy + 1,
                cases[k].number,
                pn.get(iy * mx + ix)
            )),
            None => statuses[k].notes.push(format!(
                "XL = {xl}: the moving window ({wx} x {wy}) is mapped to the union grid ({mx} x {my} from XL = {xl_mm}, YL = {yl_mm}) of its history; exact: at {} = {pen} the union grid's normal solution is zero outside the window, so it is the window's (the normal problem's solution is unique; no normal-tangential coupling) and the tangential traction, bounded by mu times it, is zero there too, as where CONTACT has no element",
                if by_pen { "PEN" } else { "FN" }
            )),
        }
    }
}

/// The B(1..6) of each case where they change within the history (IBASE = 1), else `None`.
fn quadratic_rows(cases: &[Case], h: &History) -> Option<Vec<[f64; 6]>> {
    let b = |k: usize| {
        let u = case3(cases, k).state.undeformed.as_ref()?;
        <[f64; 6]>::try_from(u.values.as_slice()).ok().filter(|_| u.ibase == 1)
    };
    let rows: Vec<[f64; 6]> = h.cases.iter().map(|&k| b(k)).collect::<Option<_>>()?;
    rows.iter().any(|r| r != &rows[0]).then_some(rows)
}

/// The load of approach `pen_mm` on undeformed distance `h_mm` (CONTACT's element order) of a
/// `mx × my` grid of `dx × dy` elements: the nominal `contact.fn_n` of a case with N = 0.
fn load_of_approach(
    h_mm: &[f64],
    (mx, my, dx, dy): (usize, usize, f64, f64),
    (g, nu): (f64, f64),
    pen_mm: f64,
) -> Option<f64> {
    use crate::physics::halfspace::{influence::Kernel, normal};
    let kernel = Kernel::new(mx, my, dx, dy, g, nu, 0.0).ok()?;
    let s = normal::NormalSolver::new(&kernel).ok()?.solve_approach(h_mm, pen_mm, &Default::default()).ok()?;
    Some(s.pn_mpa.iter().sum::<f64>() * dx * dy).filter(|f| f.is_finite() && *f > 0.0)
}

/// The pressure on undeformed distance `h_mm` (CONTACT's element order) of a `mx × my` grid of
/// `dx × dy` elements at approach `pen_or_fn` (`by_pen`, N = 0) or load (N = 1), or `None` where
/// the normal solver fails.
fn pressure_on(
    h_mm: &[f64],
    (mx, my, dx, dy): (usize, usize, f64, f64),
    (g, nu): (f64, f64),
    pen_or_fn: f64,
    by_pen: bool,
) -> Option<Vec<f64>> {
    use crate::physics::halfspace::{influence::Kernel, normal};
    let kernel = Kernel::new(mx, my, dx, dy, g, nu, 0.0).ok()?;
    let mut solver = normal::NormalSolver::new(&kernel).ok()?;
    let s = if by_pen {
        solver.solve_approach(h_mm, pen_or_fn, &Default::default()).ok()?
    } else {
        solver.solve(h_mm, pen_or_fn, &Default::default()).ok()?
    };
    s.converged.then_some(s.pn_mpa)
}

/// Which of x, y the case prescribes as a force (F = 1: x; F = 2: x and y; frictionless
/// compression, T = 0, has no tangential problem and prescribes none).
fn prescribed(c: &Case3) -> [bool; 2] {
    let tangential = c.digits.t != 0;
    [tangential && c.digits.f >= 1, tangential && c.digits.f == 2]
}

/// A steady sweep's keys for its point's (x, y, cs): the creepages, or the force ratios
/// prescribed in their place (F = 1, 2: `fx_over_fn`, `fy_over_fn`), and which are forces.
fn sweep_axes(c: &Case3) -> ([&'static str; 3], [bool; 3]) {
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
fn row(c: &Case3) -> [f64; 5] {
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
fn row_mu(s: &State) -> Option<Vec<f64>> {
    (!s.friction_rows.is_empty() && s.friction_law == 0).then(|| s.friction_rows.chunks(2).map(|r| r[0]).collect())
}

/// The speeds (VELOC) of a history's cases where they change within it.
fn speeds(cases: &[Case], h: &History) -> Option<Vec<f64>> {
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

/// The rows of a history whose speed or step changes per case, at t_k = t_(k-1) + DQ_k / VELOC_k
/// (`t_s`; the steady or shift start at t = 0): each case's values held over a quarter of the
/// steps either side of t_k (from t = 0 for the first), so that the scene's step k, the fixed
/// point of (v, dq) = (V, DQ)(t_(k-1) + dq/v) (`problem::loading`), finds VELOC_k, DQ_k and t_k.
/// Where DQ changes (`own`: each case's DQ_k / VELOC_k) the hold after t_k is also shorter than a
/// quarter of case k's own step: a step k + 1 four times as long as step k would otherwise find
/// the false fixed point t_k + DQ_k / VELOC_k inside it.
fn speed_rows(csv: &mut String, values: &[Vec<String>], t: &[f64], own: Option<&[f64]>) {
    for (n, cells) in values.iter().enumerate() {
        let cells = cells.join(",");
        let gap_after = if n + 1 < t.len() { t[n + 1] - t[n] } else { t[n] - if n > 0 { t[n - 1] } else { 0.0 } };
        let gap_after = own.map_or(gap_after, |d| gap_after.min(d[n]));
        let lower = if n == 0 { 0.0 } else { t[n] - 0.25 * (t[n] - t[n - 1]) };
        let _ = writeln!(csv, "{lower:?},{cells}");
        let _ = writeln!(csv, "{:?},{cells}", t[n] + 0.25 * gap_after);
    }
}

/// The rolling steps (DQ) of a history's cases where they change within it (a shift start takes
/// its rolling's).
fn step_lengths(cases: &[Case], h: &History) -> Option<Vec<f64>> {
    if !matches!(h.run, Run::Transient { .. }) {
        return None;
    }
    let rolling = |n: usize| h.cases[if h.run.has_start() && n == 0 { (n + 1).min(h.cases.len() - 1) } else { n }];
    let dq: Vec<f64> = (0..h.cases.len()).map(|n| case3(cases, rolling(n)).state.dq_mm).collect();
    // A steady start rolls DX whatever its DQ (CONTACT's steady rolling): its row takes its rolling's.
    dq.iter().any(|x| *x != dq[0]).then_some(dq)
}

/// A temporary folder to read a scene back in.
fn tempdir_for(place: &str) -> Result<tempfile::TempDir, InputError> {
    tempfile::tempdir()
        .map_err(|e| InputError::new(place, "a temporary folder", format!("a writable temporary folder: {e}")))
}

/// A scene name from the deck's stem: lower case, `[a-z0-9_]`.
fn scene_name(stem: &str, case: usize) -> String {
    let clean: String = stem
        .chars()
        .map(|c| c.to_ascii_lowercase())
        .map(|c| if c.is_ascii_lowercase() || c.is_ascii_digit() { c } else { '_' })
        .take(80)
        .collect();
    format!("{clean}_{case}")
}

/// The upper edge `x0 + n d`, moved by a few ulps so that `(x1 − x0)/n` is `d` exactly (the
/// project's grid divides the extent).
fn upper_edge(x0: f64, n: usize, d: f64) -> f64 {
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
fn courant_for(dq_mm: f64, dx_mm: f64) -> f64 {
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

/// Hertz's curvature ratio B/A of an ellipse with semi-axis ratio `a_over_b` (it depends on the
/// ratio alone: any load and material give it).
fn curvature_ratio(a_over_b: f64, s: &State) -> f64 {
    let m = combine_bodies(s.poiss, s.gg_mpa);
    let material = crate::physics::Material::from_g(m.g_mpa, m.poisson);
    let e = crate::physics::HertzContact { a_mm: a_over_b, b_mm: 1.0, fn_n: 1.0 };
    let (a, b) = e.undeformed_curvatures(&material);
    b / a
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
struct Sweep {
    /// The creepage whose values are the parameter t (its direction component is 1).
    param: usize,
    direction: [f64; 3],
    constants: [f64; 3],
    /// t per point.
    t: Vec<f64>,
}

/// A sweep through the points, if it reproduces every point exactly.
fn sweep_of(points: &[[f64; 3]]) -> Option<Sweep> {
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

/// `[friction]` of a falling law (L = 2, 3, 4) with its memory; `None`: Coulomb (`contact.mu`).
/// An absent second term (F2 = 0) and an absent memory (MEMDST = 0) are left out: they change no μ.
fn friction_table(s: &State) -> Option<Value> {
    let law = match s.friction_law {
        2 => "linear",
        3 => "rational",
        4 => "exponential",
        _ => return None,
    };
    let f = &s.friction;
    let mut pairs = vec![
        ("law", Value::String(law.into())),
        ("fkin", Value::Float(f[0])),
        ("f1", Value::Float(f[1])),
        ("sabsh1_mm_s", Value::Float(f[2])),
    ];
    if f[3] != 0.0 {
        pairs.extend([("f2", Value::Float(f[3])), ("sabsh2_mm_s", Value::Float(f[4]))]);
    }
    if s.memory[0] != 0.0 {
        pairs.extend([("memory_mm", Value::Float(s.memory[0])), ("memory_s0_mm_s", Value::Float(s.memory[1]))]);
    }
    Some(table(pairs))
}

fn table(pairs: Vec<(&str, Value)>) -> Value {
    Value::Table(pairs.into_iter().map(|(k, v)| (k.to_string(), v)).collect())
}

fn floats(v: &[f64]) -> Value {
    Value::Array(v.iter().map(|&x| Value::Float(x)).collect())
}

/// `[normal]` of a history whose B is 2 or 3 (Hertz's elliptical or parabolic pressure) in some
/// case: `pressure` its steps' B, `start_pressure` its start's where it differs; `None`: B = 0.
fn normal_table(cases: &[Case], h: &History) -> Option<Value> {
    let name = |b: u8| match b {
        2 => "elliptical",
        3 => "parabolic",
        _ => "solved",
    };
    let b_of = |n: usize| case3(cases, h.cases[n]).digits.b;
    let (start, steps) = if h.run.has_start() { (b_of(0), b_of(1)) } else { (b_of(0), b_of(0)) };
    let mut pairs = Vec::new();
    if steps != 0 {
        pairs.push(("pressure", Value::String(name(steps).into())));
    }
    if start != steps {
        pairs.push(("start_pressure", Value::String(name(start).into())));
    }
    (!pairs.is_empty()).then(|| table(pairs))
}

/// The scene of one history.
fn build(file: &str, stem: &str, cases: &[Case], h: &History) -> Result<SceneFiles, InputError> {
    let numbers = [cases[h.cases[0]].number, cases[h.cases[h.cases.len() - 1]].number];
    let name = scene_name(stem, numbers[0]);
    let first = case3(cases, h.cases[0]);
    let last = case3(cases, h.cases[h.cases.len() - 1]);
    let s = &first.state;
    // The rolling step of the history (after a shift start, its first rolling case's).
    let roll_case = case3(cases, h.cases[usize::from(h.run == (Run::Transient { start: Start::Shift }))]);
    let (roll, roll_t) = (&roll_case.state, roll_case.digits.t);
    let rows: Vec<[f64; 5]> = h.cases.iter().map(|&k| row(case3(cases, k))).collect();
    let quads = quadratic_rows(cases, h);
    let mut doc = Table::new();
    let mut files: Vec<(String, String)> = Vec::new();
    doc.insert("name".into(), Value::String(name.clone()));
    doc.insert("solvers".into(), Value::Array(vec![Value::String("contact".into())]));
    // The contact, its geometry and grid.
    let mut contact = vec![("fn_n", Value::Float(rows[0][3]))];
    match (friction_table(s), row_mu(s)) {
        (Some(f), _) => {
            doc.insert("friction".into(), f);
        }
        (None, Some(per_row)) => {
            let f = table(vec![("law", Value::String("coulomb".into())), ("mu_rows", floats(&per_row))]);
            doc.insert("friction".into(), f);
        }
        (None, None) => contact.push(("mu", Value::Float(rows[0][4]))),
    }
    let potcon = union_grid(cases, h).or_else(|| s.potcon.clone());
    let (mx, my) = potcon.as_ref().map_or((0, 0), Potcon::mx_my);
    let mut grid = vec![("mx", Value::Integer(mx as i64)), ("my", Value::Integer(my as i64))];
    // N = 0 on a Hertzian contact: the nominal load is Hertz's at the first case's PEN.
    let hertz_pen = (first.digits.n == 0).then_some(rows[0][3]);
    let hertz_material = || {
        let m = combine_bodies(s.poiss, s.gg_mpa);
        crate::physics::Material::from_g(m.g_mpa, m.poisson)
    };
    match &potcon {
        Some(Potcon::Hertz { ipotcn: -3, params, .. }) => {
            contact.extend([("a_mm", Value::Float(params[0])), ("b_mm", Value::Float(params[1]))]);
            grid.push(("scale", Value::Float(params[2])));
            if let Some(pen) = hertz_pen {
                // CONTACT (`hzcalc3d`, IPOTCN = −3, N = 0): AA, BB kept, the curvatures follow from
                // PEN, so FN is Hertz's of that ellipse at that approach.
                let e = crate::physics::HertzContact::with_approach(params[0], params[1], pen, &hertz_material());
                contact[0] = ("fn_n", Value::Float(e.fn_n));
            }
        }
        Some(Potcon::Hertz { ipotcn, params, .. }) => {
            // IPOTCN = −1: h = A1 x² + B1 y², as the radii R_wx = 1/(2 A1), R_wy = R_ry = 1/B1;
            // −2: A1 and a/b, B1 = A1 · (B/A of Hertz's ellipse of that a/b).
            let b1 = if *ipotcn == -2 { params[0] * curvature_ratio(params[1], s) } else { params[1] };
            let (rx, ry) = (0.5 / params[0], 1.0 / b1);
            contact.extend([
                ("r_wx_mm", Value::Float(rx)),
                ("r_wy_mm", Value::Float(ry)),
                ("r_ry_mm", Value::Float(ry)),
            ]);
            grid.push(("scale", Value::Float(params[2])));
            if let Some(pen) = hertz_pen {
                // CONTACT (`hzcalc3d`, N = 0): the curvatures kept, AA, BB (so the grid) follow from
                // PEN: the nominal load is Hertz's at that approach.
                let radii = crate::physics::Radii { r_wx_mm: rx, r_wy_mm: ry, r_ry_mm: ry };
                let e = crate::physics::HertzContact::from_radii_and_approach(&radii, pen, &hertz_material()).map_err(
                    |e| InputError::new(format!("{file}, case {}", numbers[0]), format!("PEN = {pen}"), e.to_string()),
                )?;
                contact[0] = ("fn_n", Value::Float(e.fn_n));
            }
        }
        Some(Potcon::Grid { xl_mm, yl_mm, dx_mm, dy_mm, .. }) => {
            let x1 = upper_edge(*xl_mm, mx, *dx_mm);
            let y1 = upper_edge(*yl_mm, my, *dy_mm);
            grid.extend([("x_mm", floats(&[*xl_mm, x1])), ("y_mm", floats(&[*yl_mm, y1]))]);
            let u = s.undeformed.as_ref().expect("a grid's undeformed distance (checked by the feature table)");
            let b = &u.values;
            let centre =
                |e: usize| (xl_mm + (((e % mx) as f64) + 0.5) * dx_mm, yl_mm + (((e / mx) as f64) + 0.5) * dy_mm);
            let h_mm: Vec<f64> = match u.ibase {
                9 => b.clone(),
                2 => (0..mx * my).map(|e| circular_in_x(b, centre(e))).collect(),
                _ => (0..mx * my).map(|e| quadratic(b, centre(e))).collect(),
            };
            if first.digits.n == 0 {
                // N = 0: the nominal load (it forms the nominal contact) of the first case's PEN.
                let m = combine_bodies(s.poiss, s.gg_mpa);
                let fn_n = load_of_approach(&h_mm, (mx, my, *dx_mm, *dy_mm), (m.g_mpa, m.poisson), rows[0][3])
                    .ok_or_else(|| {
                        InputError::new(
                            format!("{file}, case {}", numbers[0]),
                            format!("PEN = {}", rows[0][3]),
                            "an approach at which the undeformed distance makes contact on the grid",
                        )
                    })?;
                contact[0] = ("fn_n", Value::Float(fn_n));
            }
            let mut csv = String::from("ix,iy,h_mm\n");
            for (e, v) in h_mm.iter().enumerate() {
                let _ = writeln!(csv, "{},{},{v:?}", e % mx + 1, e / mx + 1);
            }
            let field = format!("{name}_h.csv");
            doc.insert(
                "geometry".into(),
                table(vec![("kind", Value::String("field".into())), ("field", Value::String(field.clone()))]),
            );
            files.push((field, csv));
        }
        None => {
            return Err(InputError::new(
                format!("{file}, case {}", numbers[0]),
                "no IPOTCN",
                "a potential contact (D = 2 in a case before)",
            ))
        }
    }
    if h.run == Run::Sweep && first.digits.n == 0 {
        // Steady cases (T = 0, 3) with N = 0: one PEN for the sweep (a setup of its own).
        contact.push(("pen_mm", Value::Float(rows[0][3])));
    }
    doc.insert("contact".into(), table(contact));
    if let Some(normal) = normal_table(cases, h) {
        doc.insert("normal".into(), normal);
    }
    let m = combine_bodies(s.poiss, s.gg_mpa);
    doc.insert("material".into(), table(vec![("g_mpa", Value::Float(m.g_mpa)), ("poisson", Value::Float(m.poisson))]));
    doc.insert("grid".into(), table(grid));
    // The loading.
    match h.run {
        Run::Sweep if speeds(cases, h).is_some() => {
            let at = speeds(cases, h).unwrap_or_default();
            let mut cr = vec![
                ("kind", Value::String("sweep".into())),
                ("over", Value::String("v_mm_s".into())),
                ("at", floats(&at)),
            ];
            let (axis, forced) = sweep_axes(first);
            for (j, key) in axis.iter().enumerate() {
                if rows[0][j].to_bits() != 0 || forced[j] {
                    cr.push((key, Value::Float(rows[0][j])));
                }
            }
            doc.insert("creepage".into(), table(cr));
        }
        Run::Sweep => {
            let points: Vec<[f64; 3]> = rows.iter().map(|r| [r[0], r[1], r[2]]).collect();
            let Sweep { param: k, direction, constants, t } =
                sweep_of(&points).expect("histories are split where no sweep fits");
            let mut cr = vec![("kind", Value::String("sweep".into())), ("at", floats(&t))];
            let (axis, forced) = sweep_axes(first);
            let over = direction.iter().filter(|&&d| d != 0.0).count() == 1;
            if over {
                cr.push(("over", Value::String(axis[k].into())));
            } else {
                cr.push(("direction", floats(&direction)));
            }
            // A prescribed force's constant is written even where 0 (the key prescribes it),
            // unless `over` names it.
            for (j, key) in axis.iter().enumerate() {
                if constants[j].to_bits() != 0 || (forced[j] && !(over && j == k)) {
                    cr.push((key, Value::Float(constants[j])));
                }
            }
            doc.insert("creepage".into(), table(cr));
        }
        Run::Transient { .. } | Run::Shifts => {
            let steady_start = h.run.has_start();
            // Shifts: CONTACT's time step is a dummy 1 s (user guide, "Tangential quantities in
            // case of a shift"); here too, with [rolling] v_mm_s = dx and courant 1.
            let dt_s = if h.run == Run::Shifts { 1.0 } else { roll.dq_mm / roll.veloc_mm_s };
            let varies = |j: usize| rows.iter().any(|r| r[j].to_bits() != rows[0][j].to_bits());
            // F per case: the force's column where a case prescribes it; creepages and forces in
            // one history (F changing): both columns, each row's other cell empty.
            let forces: Vec<[bool; 2]> = h.cases.iter().map(|&k| prescribed(case3(cases, k))).collect();
            let any = |i: usize| forces.iter().any(|f| f[i]);
            let mixed = |i: usize| any(i) && !forces.iter().all(|f| f[i]);
            // N = 0: PEN is the column pen_mm, always written (FN is the solver's); N = 0 and 1 in
            // one history: both columns, each row's other cell empty.
            let normal: Vec<bool> = h.cases.iter().map(|&k| case3(cases, k).digits.n == 0).collect();
            let (by_pen, by_fn) = (normal.iter().any(|&p| p), normal.iter().any(|&p| !p));
            let columns: Vec<usize> =
                (0..5).filter(|&j| j == 0 || (j == 1 && any(1)) || (j == 3 && by_pen) || varies(j)).collect();
            let pair = |i: usize, given: &str, force: &str| match (any(i), mixed(i)) {
                (false, _) => given.to_string(),
                (true, false) => force.to_string(),
                (true, true) => format!("{given},{force}"),
            };
            let names = [
                pair(0, "cx", "fx_over_fn"),
                pair(1, "cy", "fy_over_fn"),
                "cs".to_string(),
                match (by_pen, by_fn) {
                    (true, true) => "fn_n,pen_mm",
                    (true, false) => "pen_mm",
                    _ => "fn_n",
                }
                .to_string(),
                "mu".to_string(),
            ];
            // Row n's cell of column j: a pair's two cells (the given one first), one left empty.
            let cell = |j: usize, n: usize| {
                let (both, second) = match j {
                    0 => (mixed(0), forces[n][0]),
                    1 => (mixed(1), forces[n][1]),
                    3 => (by_pen && by_fn, normal[n]),
                    _ => (false, false),
                };
                match (both, second) {
                    (true, true) => format!(",{:?}", rows[n][j]),
                    (true, false) => format!("{:?},", rows[n][j]),
                    _ => format!("{:?}", rows[n][j]),
                }
            };
            let speed = speeds(cases, h);
            // DQ changing within the history: a courant column, courant·dx = DQ exactly (dx the
            // project's grid, read back from a probe of the scene).
            let courant = match step_lengths(cases, h) {
                Some(dq) => {
                    let dir = tempdir_for(&format!("{file}, cases {} to {}", numbers[0], numbers[1]))?;
                    let dx_mm = read_back(dir.path(), &format!("{name}.toml"), &probe(&doc), &files)?.grid.dx_mm;
                    Some((dq.iter().map(|&q| courant_for(q, dx_mm)).collect::<Vec<f64>>(), dx_mm))
                }
                None => None,
            };
            // CHI changing per case (a shift start takes its rolling cases' direction).
            let chis: Vec<f64> = h
                .cases
                .iter()
                .enumerate()
                .map(|(n, &k)| match (n, h.run) {
                    (0, Run::Transient { start: Start::Shift }) => chi_deg(roll.chi_rad),
                    _ => chi_deg(case3(cases, k).state.chi_rad),
                })
                .collect();
            let turns = h.run != Run::Shifts && chis.iter().any(|&c| c != chis[0]);
            if turns && courant.is_some() {
                return Err(InputError::new(
                    format!("{file}, cases {} to {}", numbers[0], numbers[1]),
                    "CHI and DQ changing in one history",
                    "one of the rolling direction (CHI) and the rolling step (DQ) changing per case",
                ));
            }
            let speed_column = if speed.is_some() { ",v_mm_s" } else { "" };
            let courant_column = if courant.is_some() { ",courant" } else { "" };
            let quad_columns = match (quads.is_some(), turns) {
                (true, _) => ",b1_per_mm,b2_per_mm,b3_per_mm,b4,b5,b6_mm",
                (false, true) => ",chi_deg",
                (false, false) => "",
            };
            let mut csv = format!(
                "t_s,{}{speed_column}{courant_column}{quad_columns}\n",
                columns.iter().map(|&j| names[j].as_str()).collect::<Vec<_>>().join(",")
            );
            let row_cells = |n: usize| columns.iter().map(|&j| cell(j, n)).collect::<Vec<String>>();
            match (&speed, &courant) {
                (None, None) => {
                    for n in 0..rows.len() {
                        let step = if steady_start { n } else { n + 1 };
                        let mut values = row_cells(n);
                        if let Some(q) = &quads {
                            values.extend(q[n].iter().map(|b| format!("{b:?}")));
                        } else if turns {
                            values.push(format!("{:?}", chis[n]));
                        }
                        let _ = writeln!(csv, "{:?},{}", step as f64 * dt_s, values.join(","));
                    }
                }
                _ if quads.is_some() => return Err(InputError::new(
                    format!("{file}, cases {} to {}", numbers[0], numbers[1]),
                    "VELOC or DQ and B(1..6) changing in one history",
                    "one of the speed (VELOC) or step (DQ) and the undeformed distance (IBASE = 1) changing per case",
                )),
                _ if by_pen && by_fn => {
                    return Err(InputError::new(
                        format!("{file}, cases {} to {}", numbers[0], numbers[1]),
                        "VELOC or DQ changing with N = 0 and N = 1 in one history",
                        "one of the speed (VELOC) or step (DQ) changing per case and N changing per case",
                    ))
                }
                (speed, courant) => {
                    let mut values: Vec<Vec<String>> = (0..rows.len()).map(row_cells).collect();
                    let (mut t_s, mut own) = (Vec::with_capacity(rows.len()), Vec::with_capacity(rows.len()));
                    let mut t = 0.0;
                    for (n, row) in values.iter_mut().enumerate() {
                        let v = speed.as_ref().map_or(roll.veloc_mm_s, |v| v[n]);
                        let dq = courant.as_ref().map_or(roll.dq_mm, |(c, dx)| c[n] * dx);
                        if !(steady_start && n == 0) {
                            t += dq / v;
                        }
                        t_s.push(t);
                        own.push(dq / v);
                        if let Some(v) = speed {
                            row.push(format!("{:?}", v[n]));
                        }
                        if let Some((c, _)) = courant {
                            row.push(format!("{:?}", c[n]));
                        }
                    }
                    speed_rows(&mut csv, &values, &t_s, courant.is_some().then_some(own.as_slice()));
                }
            }
            let file_name = format!("{name}_table.csv");
            let mut cr = vec![("kind", Value::String("table".into())), ("file", Value::String(file_name.clone()))];
            for (j, key) in [(1, "cy"), (2, "cs")] {
                if !columns.contains(&j) && rows[0][j].to_bits() != 0 {
                    cr.push((key, Value::Float(rows[0][j])));
                }
            }
            doc.insert("creepage".into(), table(cr));
            let init = match h.run {
                Run::Transient { start: Start::Steady } => Some("steady"),
                Run::Transient { start: Start::Shift } => Some("shift"),
                _ => None,
            };
            if let Some(kind) = init {
                doc.insert("init".into(), table(vec![("kind", Value::String(kind.into()))]));
            }
            files.push((file_name, csv));
        }
    }
    let mut contact_solver = Vec::new();
    if falling(&last.state) {
        // CONTACT's slip-velocity iteration as the deck sets it (the last case's: a steady start
        // is solved with its transient cases'), stopped where CONTACT stops it.
        let (start, omgslp) = slip_iteration(&last.state);
        // Every iterate solved tightly, as CONTACT does: its loose stop then falls on the same iterate.
        let mut cs = vec![
            ("veldep_tolerance", Value::Float(CONTACT_VELDEP_TOLERANCE)),
            ("veldep_solves", Value::String("tight".into())),
        ];
        if start != "previous" {
            cs.push(("inislp", Value::String(start.into())));
        }
        if omgslp != crate::scene::OMGSLP {
            cs.push(("omgslp", Value::Float(omgslp)));
        }
        contact_solver.extend(cs);
    }
    if last.state.inflcf == 3 {
        contact_solver.push(("influence", Value::String("bilinear".into())));
    }
    if !contact_solver.is_empty() {
        doc.insert("contact_solver".into(), table(contact_solver));
    }
    if h.run == Run::Shifts {
        doc.insert("rolling".into(), table(vec![("motion", Value::String("shift".into()))]));
    } else if roll.rolling_read {
        let mut rolling = vec![("v_mm_s", Value::Float(roll.veloc_mm_s)), ("courant", Value::Float(1.0))];
        // CONTACT rolls along CHI for T = 2, 3 only (shifts take CHI = 0, `m_sdis.f90`).
        if roll_t >= 2 && chi_deg(roll.chi_rad) != 0.0 {
            rolling.push(("chi_deg", Value::Float(chi_deg(roll.chi_rad))));
        }
        doc.insert("rolling".into(), table(rolling));
    }
    doc.insert(
        "origin".into(),
        table(vec![
            ("file", Value::String(file.into())),
            ("cases", Value::Array(numbers.iter().map(|&n| Value::Integer(n as i64)).collect())),
        ]),
    );
    // Read back in a temporary folder: the Courant number from the project's own grid, then the
    // final scene, which must reproduce every case.
    let place = format!("{file}, cases {} to {}", numbers[0], numbers[1]);
    let dir = tempfile::tempdir()
        .map_err(|e| InputError::new(&place, "a temporary folder", format!("a writable temporary folder: {e}")))?;
    let scene_file = format!("{name}.toml");
    if h.run == Run::Shifts {
        // dt = courant·dx/v = 1 s exactly with v = dx, courant = 1 (dx from the project's grid).
        let dx_mm = read_back(dir.path(), &scene_file, &probe(&doc), &files)?.grid.dx_mm;
        if let Some(Value::Table(r)) = doc.get_mut("rolling") {
            r.insert("v_mm_s".into(), Value::Float(dx_mm));
            r.insert("courant".into(), Value::Float(1.0));
        }
    } else if roll.rolling_read {
        let problem = read_back(dir.path(), &scene_file, &doc, &files)?;
        let courant = courant_for(roll.dq_mm, problem.grid.dx_mm);
        if let Some(Value::Table(r)) = doc.get_mut("rolling") {
            r.insert("courant".into(), Value::Float(courant));
        }
    }
    let problem = read_back(dir.path(), &scene_file, &doc, &files)?;
    check_rows(&problem, &rows, quads.as_deref(), &h.cases.iter().map(|&k| cases[k].number).collect::<Vec<_>>())?;
    let text = format!(
        "# Imported by `creepbench import contact` from {file}, cases {} to {}.\n{}",
        numbers[0],
        numbers[1],
        toml::to_string(&doc).map_err(|e| InputError::new(&place, "a scene", format!("a scene TOML can hold: {e}")))?
    );
    files.insert(0, (scene_file, text));
    Ok(SceneFiles { name, cases: numbers, files })
}

/// IBASE = 2 at an element centre (x, y): the NN heights linear in y between Y1 + (k−1) DY1
/// (extrapolated beyond), plus the circle in x as CONTACT evaluates it, its parabola
/// (x − XM)²/(2 RX1) (`m_sdis.f90` lines 358-405); `b` = NN, XM, RX1, Y1, DY1, heights.
fn circular_in_x(b: &[f64], (x, y): (f64, f64)) -> f64 {
    let (nn, xm, rx, y1, dy1) = (b[0] as usize, b[1], b[2], b[3], b[4]);
    let yn = y1 + (nn - 1) as f64 * dy1;
    let (left, y_left) = if y < y1 {
        (0, y1)
    } else if y >= yn {
        (nn - 2, yn - dy1)
    } else {
        let k = ((y - y1) / dy1) as usize;
        (k, y1 + k as f64 * dy1)
    };
    let heights = &b[5..];
    let slope = (heights[left + 1] - heights[left]) / dy1;
    heights[left] + slope * (y - y_left) + (x - xm) * (x - xm) / (2.0 * rx)
}

/// The scene with a one-step loading at zero creepage in place of its own (no `[init]`): read
/// back only for its grid.
fn probe(doc: &Table) -> Table {
    let mut probe = doc.clone();
    probe.remove("init");
    probe.remove("normal");
    let step = vec![("kind", Value::String("step".into())), ("c", Value::Float(0.0)), ("steps", Value::Integer(1))];
    probe.insert("creepage".into(), table(step));
    probe
}

/// Write the scene and its files into `dir`, read the scene back with the project's reader and
/// resolve it.
fn read_back(dir: &Path, scene_file: &str, doc: &Table, files: &[(String, String)]) -> Result<Problem, InputError> {
    let io =
        |e: std::io::Error| InputError::new(dir.display().to_string(), "a temporary folder", format!("writable: {e}"));
    let text = toml::to_string(doc)
        .map_err(|e| InputError::new(scene_file, "a scene", format!("a scene TOML can hold: {e}")))?;
    std::fs::write(dir.join(scene_file), text).map_err(io)?;
    for (name, contents) in files {
        std::fs::write(dir.join(name), contents).map_err(io)?;
    }
    let scene = crate::scene::Scene::from_file(&dir.join(scene_file))?;
    crate::pipeline::resolve(&scene)
}

/// Every row of the resolved scene equals its case: cx, cy, cs, FN (or PEN) and μ bit for bit,
/// and B(1..6) where they change per case.
fn check_rows(
    problem: &Problem,
    rows: &[[f64; 5]],
    quads: Option<&[[f64; 6]]>,
    numbers: &[usize],
) -> Result<(), InputError> {
    let got: Vec<[f64; 5]> = problem
        .loading
        .rows()
        .map(|s| [s.fx_target.unwrap_or(s.cx), s.fy_target.unwrap_or(s.cy), s.cs, s.pen_mm.unwrap_or(s.fn_n), s.mu])
        .collect();
    let got_quads: Vec<Option<[f64; 6]>> = problem.loading.rows().map(|s| s.h_coefficients).collect();
    for (n, (g, q)) in
        got_quads.iter().zip(quads.map(|q| q.iter().map(Some).collect::<Vec<_>>()).unwrap_or_default()).enumerate()
    {
        if g.map(|g| g.map(f64::to_bits)) != q.map(|q| q.map(f64::to_bits)) {
            return Err(InputError::new(
                format!("scene {}, case {}", problem.name, numbers[n]),
                format!("{g:?}"),
                format!("the case's B(1..6) = {q:?} exactly"),
            ));
        }
    }
    if got.len() != rows.len() {
        return Err(InputError::new(
            format!("scene {}", problem.name),
            format!("{} rows", got.len()),
            format!("one row per case ({} cases)", rows.len()),
        ));
    }
    for ((g, r), n) in got.iter().zip(rows).zip(numbers) {
        if g.iter().zip(r).any(|(a, b)| a.to_bits() != b.to_bits()) {
            return Err(InputError::new(
                format!("scene {}, case {n}", problem.name),
                format!("{g:?}"),
                format!("the case's [cx, cy, cs, FN, mu] = {r:?} exactly"),
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two steady cases: the second has no MODULE line before it (R = 0 in the first) and keeps
    /// the friction (L = 1), the material and rolling step (C = 0) and the grid (D = 0, Z = 0).
    const DECK: &str = "\
 3  MODULE
  203100      P-B-T-N-F-S
  022020      L-D-C-M-Z-E
 0000340      H-G-I-A-O-W-R   (R = 0: stay in module 3)
   80  200  5  1  1e-6
 82000.  0.001  0.0  0.0      FN, CKSI, CETA, CPHI
 0.3  0.3                     FSTAT, FKIN
 0.0  0.4  30000.             CHI, DQ, VELOC
 0.28 0.28 82000. 82000.      POISS, GG
 -3
 44  44  8.0  4.0  1.1
  3100        P-B-T-N-F-S  (leading zeros left out: P = 0, B = 0)
  100000      L-D-C-M-Z-E
  100341      H-G-I-A-O-W-R
 82000.  0.002  0.0  0.0
 0  MODULE
";

    #[test]
    fn a_case_keeps_what_it_does_not_read_and_steady_cases_form_one_sweep() {
        let cases = deck::parse("t.inp", DECK).unwrap();
        assert_eq!(cases.len(), 2);
        let CaseKind::Module3(c2) = &cases[1].kind else { panic!("module 3") };
        assert_eq!((c2.digits.p, c2.digits.t, c2.digits.l, c2.digits.d), (0, 3, 1, 0));
        assert_eq!((cases[1].line, c2.state.cksi_or_fx), (12, 0.002));
        assert_eq!((c2.state.friction.clone(), c2.state.dq_mm, c2.state.gg_mpa), (vec![0.3, 0.3], 0.4, [82000.0; 2]));
        assert_eq!(c2.state.potcon, Some(Potcon::Hertz { ipotcn: -3, mx: 44, my: 44, params: vec![8.0, 4.0, 1.1] }));
        let imported = import_text("t.inp", "t", DECK).unwrap();
        assert!(imported.statuses.iter().all(CaseStatus::supported), "{:?}", imported.statuses);
        assert_eq!(imported.scenes.len(), 1);
        let s = &imported.scenes[0];
        assert_eq!((s.name.as_str(), s.cases), ("t_1", [1, 2]));
        assert!(s.files[0].1.contains("at = [0.001, 0.002]"), "{}", s.files[0].1);
    }

    #[test]
    fn ibase_2_is_linear_in_y_through_its_heights_and_a_parabola_in_x() {
        // NN = 3 heights 1, 3, 2 at y = -1, 1, 3; circle of radius 5 around XM = 2.
        let b = [3.0, 2.0, 5.0, -1.0, 2.0, 1.0, 3.0, 2.0];
        let at = |x: f64, y: f64| circular_in_x(&b, (x, y));
        assert_eq!(at(2.0, -1.0), 1.0);
        assert_eq!(at(2.0, 0.0), 2.0);
        assert_eq!(at(2.0, 2.0), 2.5);
        // Beyond the points: the first and last segments extended (CONTACT extrapolates).
        assert_eq!(at(2.0, -3.0), -1.0);
        assert_eq!(at(2.0, 5.0), 1.0);
        // (x - XM)²/(2 RX1): the parabola CONTACT uses, not the circle.
        assert_eq!(at(4.0, 1.0), 3.0 + 0.4);
    }

    #[test]
    fn coulomb_friction_is_fstat_whatever_fkin_says() {
        // CONTACT's L = 0 overwrites FKIN with FSTAT (`fric_update`, m_friclaw.f90).
        let deck =
            DECK.replace(" 0.3  0.3                     FSTAT, FKIN", " 0.3  0.25                    FSTAT, FKIN");
        let imported = import_text("t.inp", "t", &deck).unwrap();
        assert!(imported.statuses.iter().all(CaseStatus::supported), "{:?}", imported.statuses);
        assert!(imported.statuses[0].notes.iter().any(|n| n.starts_with("FSTAT = 0.3, FKIN = 0.25")));
        assert!(imported.scenes[0].files[0].1.contains("mu = 0.3\n"), "{}", imported.scenes[0].files[0].1);
    }

    #[test]
    fn a_transient_case_after_a_steady_one_is_its_steady_start() {
        let deck = DECK.replace("  3100        P-B-T-N-F-S", "  2100        P-B-T-N-F-S");
        let imported = import_text("t.inp", "t", &deck).unwrap();
        assert_eq!(imported.scenes.len(), 1, "{:?}", imported.statuses);
        let files = &imported.scenes[0].files;
        assert!(files[0].1.contains("[init]\nkind = \"steady\""), "{}", files[0].1);
        // t = k DQ/VELOC from the steady start at t = 0.
        assert_eq!(files[1], ("t_1_table.csv".to_string(), format!("t_s,cx\n0.0,0.001\n{:?},0.002\n", 0.4 / 30000.0)));
    }
}
