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
    let pairs: [(&'static str, bool); 10] = [
        ("FN", load_varies || a.pen_or_fn == b.pen_or_fn),
        // Coulomb: FSTAT alone counts (CONTACT overwrites FKIN with it).
        (
            "FSTAT, FKIN",
            (load_varies && coulomb)
                || a.friction == b.friction
                || (coulomb && a.friction.first() == b.friction.first()),
        ),
        ("MEMDST, MEM_S0", a.memory == b.memory),
        // CHI may change within a transient history (the table's chi_deg, [`turn_refused`]).
        ("CHI, DQ", (load_varies || a.chi_rad == b.chi_rad) && a.dq_mm == b.dq_mm),
        ("POISS, GG", (a.poiss, a.gg_mpa) == (b.poiss, b.gg_mpa)),
        (
            "the potential contact (IPOTCN and its line)",
            a.potcon == b.potcon || (load_varies && quadratics(a, b) && window_shift(a, b).is_some()),
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
                        && (!falling(&c3.state) || slip_iteration(&first.state) == slip_iteration(&c3.state))
                        && statuses[h.cases[0]].supported() == statuses[k].supported()
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
            if prescribed(last) != prescribed(c3) {
                statuses[k].refused.push(format!(
                    "F = {} after F = {}: the prescribed forces change within a history (one table has either creepages or forces)",
                    d.f, last.digits.f
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
            } else if hertz && prev.pen_or_fn != c3.state.pen_or_fn {
                statuses[k].refused.push(format!(
                    "FN = {} after {}: a Hertzian geometry (IPOTCN < 0) under a load that changes within a transient history (supported: the geometry as a grid, IPOTCN > 0)",
                    c3.state.pen_or_fn, prev.pen_or_fn
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

/// Which of x, y the case prescribes as a force (F = 1: x; F = 2: x and y).
fn prescribed(c: &Case3) -> [bool; 2] {
    [c.digits.f >= 1, c.digits.f == 2]
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
    let mu = match (s.friction_law, s.friction.as_slice()) {
        // FSTAT = μ_s(0) = FKIN + F1 + F2 (`m_friclaw.f90` lines 303-305), as `FrictionLaw::mu_static`.
        (2..=4, [fkin, f1, _, f2, _]) => fkin + f1 + f2,
        // Coulomb (L = 0): FSTAT, CONTACT's one coefficient (`fric_update`: fkin := fstat).
        _ => s.friction.first().copied().unwrap_or(f64::NAN),
    };
    if c.digits.t == 0 {
        return [0.0, 0.0, 0.0, s.pen_or_fn, mu];
    }
    // FSTAT is μ: Coulomb's one coefficient, a falling law's μ at zero slip.
    let [fx, fy] = prescribed(c);
    let x = if fx { force_ratio(s.cksi_or_fx, mu) } else { s.cksi_or_fx };
    let y = if fy { force_ratio(s.ceta_or_fy, mu) } else { s.ceta_or_fy };
    [x, y, s.cphi_per_mm, s.pen_or_fn, mu]
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

/// The table rows of a history whose speed changes per case: t_k = t_(k-1) + DQ / VELOC_k (the
/// steady start at t = 0), each case's values held over a quarter of the steps either side of t_k
/// (from t = 0 for the first), so that the scene's step k, the fixed point of v = V(t_(k-1) + DQ/v)
/// (`problem::loading`), finds VELOC_k and t_k exactly.
fn speed_rows(csv: &mut String, rows: &[[f64; 5]], columns: &[usize], v: &[f64], dq_mm: f64, steady_start: bool) {
    let mut t = Vec::with_capacity(rows.len());
    let mut t_s = 0.0;
    for (n, speed) in v.iter().enumerate() {
        if !(steady_start && n == 0) {
            t_s += dq_mm / speed;
        }
        t.push(t_s);
    }
    for (n, r) in rows.iter().enumerate() {
        let mut values: Vec<String> = columns.iter().map(|&j| format!("{:?}", r[j])).collect();
        values.push(format!("{:?}", v[n]));
        let values = values.join(",");
        let gap_after = if n + 1 < t.len() { t[n + 1] - t[n] } else { t[n] - if n > 0 { t[n - 1] } else { 0.0 } };
        let lower = if n == 0 { 0.0 } else { t[n] - 0.25 * (t[n] - t[n - 1]) };
        let _ = writeln!(csv, "{lower:?},{values}");
        let _ = writeln!(csv, "{:?},{values}", t[n] + 0.25 * gap_after);
    }
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
    match friction_table(s) {
        Some(f) => {
            doc.insert("friction".into(), f);
        }
        None => contact.push(("mu", Value::Float(rows[0][4]))),
    }
    let potcon = union_grid(cases, h).or_else(|| s.potcon.clone());
    let (mx, my) = potcon.as_ref().map_or((0, 0), Potcon::mx_my);
    let mut grid = vec![("mx", Value::Integer(mx as i64)), ("my", Value::Integer(my as i64))];
    match &potcon {
        Some(Potcon::Hertz { ipotcn: -3, params, .. }) => {
            contact.extend([("a_mm", Value::Float(params[0])), ("b_mm", Value::Float(params[1]))]);
            grid.push(("scale", Value::Float(params[2])));
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
    doc.insert("contact".into(), table(contact));
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
            for (j, key) in ["cx", "cy", "cs"].iter().enumerate() {
                if rows[0][j].to_bits() != 0 {
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
            let axis = ["cx", "cy", "cs"];
            if direction.iter().filter(|&&d| d != 0.0).count() == 1 {
                cr.push(("over", Value::String(axis[k].into())));
            } else {
                cr.push(("direction", floats(&direction)));
            }
            for (j, key) in axis.iter().enumerate() {
                if constants[j].to_bits() != 0 {
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
            let forces = prescribed(first);
            // N = 0: PEN is the column pen_mm, always written (FN is the solver's); N = 0 and 1 in
            // one history: both columns, each row's other cell empty.
            let normal: Vec<bool> = h.cases.iter().map(|&k| case3(cases, k).digits.n == 0).collect();
            let (by_pen, by_fn) = (normal.iter().any(|&p| p), normal.iter().any(|&p| !p));
            let columns: Vec<usize> =
                (0..5).filter(|&j| j == 0 || (j == 1 && forces[1]) || (j == 3 && by_pen) || varies(j)).collect();
            let names = [
                if forces[0] { "fx_over_fn" } else { "cx" },
                if forces[1] { "fy_over_fn" } else { "cy" },
                "cs",
                match (by_pen, by_fn) {
                    (true, true) => "fn_n,pen_mm",
                    (true, false) => "pen_mm",
                    _ => "fn_n",
                },
                "mu",
            ];
            let speed_column = if speeds(cases, h).is_some() { ",v_mm_s" } else { "" };
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
            let quad_columns = match (quads.is_some(), turns) {
                (true, _) => ",b1_per_mm,b2_per_mm,b3_per_mm,b4,b5,b6_mm",
                (false, true) => ",chi_deg",
                (false, false) => "",
            };
            let mut csv = format!(
                "t_s,{}{speed_column}{quad_columns}\n",
                columns.iter().map(|&j| names[j]).collect::<Vec<_>>().join(",")
            );
            match speeds(cases, h) {
                Some(_) if quads.is_some() => {
                    return Err(InputError::new(
                        format!("{file}, cases {} to {}", numbers[0], numbers[1]),
                        "VELOC and B(1..6) changing in one history",
                        "one of the speed (VELOC) and the undeformed distance (IBASE = 1) changing per case",
                    ))
                }
                Some(_) if by_pen && by_fn => {
                    return Err(InputError::new(
                        format!("{file}, cases {} to {}", numbers[0], numbers[1]),
                        "VELOC changing with N = 0 and N = 1 in one history",
                        "one of the speed (VELOC) changing per case and N changing per case",
                    ))
                }
                Some(v) => speed_rows(&mut csv, &rows, &columns, &v, roll.dq_mm, steady_start),
                None => {
                    for (n, r) in rows.iter().enumerate() {
                        let step = if steady_start { n } else { n + 1 };
                        let cell = |j: usize| match (j, by_pen && by_fn, normal[n]) {
                            (3, true, true) => format!(",{:?}", r[3]),
                            (3, true, false) => format!("{:?},", r[3]),
                            _ => format!("{:?}", r[j]),
                        };
                        let mut values: Vec<String> = columns.iter().map(|&j| cell(j)).collect();
                        if let Some(q) = &quads {
                            values.extend(q[n].iter().map(|b| format!("{b:?}")));
                        } else if turns {
                            values.push(format!("{:?}", chis[n]));
                        }
                        let _ = writeln!(csv, "{:?},{}", step as f64 * dt_s, values.join(","));
                    }
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
        doc.insert("contact_solver".into(), table(cs));
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
