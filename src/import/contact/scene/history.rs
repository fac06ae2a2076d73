//! Cases → histories: a run of cases that carries its state (a transient case with P = 0
//! continues the case before it; P = 2 starts afresh; consecutive steady cases of one setup are
//! one sweep), and the refusals of a case that changes its history's setup.

use super::super::deck::{Case, Case3, CaseKind, Potcon, State};
use super::super::CaseStatus;
use super::case3;
use super::rows::{chi_deg, prescribed, row};
use super::window::{hertz_axes, quadratics, same_hertz_grid, window_shift, HERTZ_GRID_REL};

/// How a history runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Run {
    /// Steady cases of one setup.
    Sweep,
    /// Transient rolling cases (T = 2) from `start`.
    Transient { start: Start },
    /// Shifts (T = 1) from zero traction: `[rolling] motion = "shift"`.
    Shifts,
}

/// The state a transient rolling history starts from (its step 0, where it has one).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Start {
    /// Zero traction (P = 2): no step 0.
    Zero,
    /// The steady case before it (`[init] kind = "steady"`).
    Steady,
    /// The shift (T = 1) before it (`[init] kind = "shift"`).
    Shift,
}

impl Run {
    /// Whether the history's first case is its step 0 (an initial state, not a step).
    pub(super) fn has_start(self) -> bool {
        matches!(self, Run::Transient { start: Start::Steady | Start::Shift })
    }
}

#[derive(Debug, Clone)]
pub(super) struct History {
    pub(super) run: Run,
    /// Indices into the deck's cases.
    pub(super) cases: Vec<usize>,
}

/// `[contact_solver] inislp` and `omgslp` of a case's INISLP, OMGSLP (`m_stang.f90` lines
/// 258-264: 0 from the previous solution, > 0 from s = 0, < 0 from s = V).
pub(super) fn slip_iteration(s: &State) -> (&'static str, f64) {
    let (inislp, omgslp) = s.slip_start.unwrap_or((0, crate::scene::OMGSLP));
    let start = match inislp {
        0 => "previous",
        i if i > 0 => "below",
        _ => "above",
    };
    (start, omgslp)
}

/// Whether a case's friction falls with the slip velocity (L = 2, 3, 4 in force).
pub(super) fn falling(s: &State) -> bool {
    matches!(s.friction_law, 2..=4)
}

/// Whether a case's friction law iterates around the tangential solve, damped by OMGSLP: falling
/// with the slip velocity (L = 2, 3, 4) or of the surface temperature (L = 6, `m_stang.f90`).
pub(super) fn outer_iteration(s: &State) -> bool {
    falling(s) || s.friction_law == 6
}

/// What differs between two cases' setups (all but the creepages, VELOC and, where `load_varies`,
/// FN and a Coulomb friction), named. A falling law and its memory are one for the whole history.
fn setup_difference(a: &State, b: &State, load_varies: bool) -> Option<&'static str> {
    let coulomb = a.friction_law == 0 && b.friction_law == 0;
    let coupled = crate::physics::material::combine_bodies(a.poiss, a.gg_mpa).k != 0.0;
    let pairs: [(&'static str, bool); 17] = [
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
        ("the interface layer (M = 4: GG3, LAYTHK, TAU_C0, K_TAU)", a.layer_in_force() == b.layer_in_force()),
        // M = 1: the relaxation distance VELOC·TC is the kernel's, so VELOC counts too.
        (
            "the viscoelastic bodies (M = 1: FG, TC, VELOC)",
            a.visco_in_force() == b.visco_in_force() && (a.visco_in_force().is_none() || a.veloc_mm_s == b.veloc_mm_s),
        ),
        ("the surface temperatures (H: BKTEMP, HEATCP, LAMBDA, DENS)", a.heat_in_force() == b.heat_in_force()),
        ("MAXOUT of dissimilar bodies", !coupled || a.max_outer() == b.max_outer()),
        (
            "the potential contact (IPOTCN and its line)",
            a.potcon == b.potcon
                || (load_varies && quadratics(a, b) && window_shift(a, b).is_some())
                || (load_varies && same_hertz_grid(a, b)),
        ),
        ("the undeformed distance (IBASE)", a.undeformed == b.undeformed || (load_varies && quadratics(a, b))),
        ("the friction law", a.friction_law == b.friction_law),
        ("the extra rigid slip (E = 9: EXRHS)", a.exrhs == b.exrhs),
        ("SPINXO, SPINYO", a.spin_centre_mm == b.spin_centre_mm),
        ("the rolling step (CHI, DQ, VELOC read)", a.rolling_read == b.rolling_read),
    ];
    pairs.iter().find(|(_, same)| !same).map(|(name, _)| *name)
}

/// Group the module-3 cases into histories; a transient case that changes its history's setup is
/// refused here.
pub(super) fn group(cases: &[Case], statuses: &mut [CaseStatus]) -> Vec<History> {
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
        match d.t {
            // Frictionless compression: a history of its own (what follows starts from zero traction).
            0 => hs.push(History { run: Run::Sweep, cases: vec![k] }),
            3 => match hs.last_mut() {
                Some(h) if open && h.run == Run::Sweep && joins_sweep(cases, statuses, h, k) => h.cases.push(k),
                _ => hs.push(History { run: Run::Sweep, cases: vec![k] }),
            },
            _ if continues => continue_history(cases, statuses, &mut hs, k),
            1 => hs.push(History { run: Run::Shifts, cases: vec![k] }),
            _ => hs.push(History { run: Run::Transient { start: Start::Zero }, cases: vec![k] }),
        }
        open = d.t != 0;
    }
    hs
}

/// Whether steady case `k` joins sweep `h`: the same setup, N, B, M (and K0_MF, ALFAMF, BETAMF), slip-velocity iteration,
/// support and prescribed forces, at the sweep's speed or creepages ([`sweep_continues`]).
fn joins_sweep(cases: &[Case], statuses: &[CaseStatus], h: &History, k: usize) -> bool {
    let (first, c3) = (case3(cases, h.cases[0]), case3(cases, k));
    setup_difference(&first.state, &c3.state, false).is_none()
        && first.digits.n == c3.digits.n
        && (!outer_iteration(&c3.state) || slip_iteration(&first.state) == slip_iteration(&c3.state))
        && (c3.state.friction_law != 6 || first.state.temperature_iterations() == c3.state.temperature_iterations())
        && first.digits.b == c3.digits.b
        && first.digits.m == c3.digits.m
        && first.state.slope_mf == c3.state.slope_mf
        && statuses[h.cases[0]].supported() == statuses[k].supported()
        && prescribed(first) == prescribed(c3)
        && sweep_continues(cases, h, c3)
}

/// Transient case `k` (P = 0) continues the last history: a shift becomes the initial state of
/// rolling, a steady case the steady start; the case is refused where it changes the history's
/// setup ([`continuation_refusal`]) and starts a history of its own where it cannot continue.
fn continue_history(cases: &[Case], statuses: &mut [CaseStatus], hs: &mut Vec<History>, k: usize) {
    let c3 = case3(cases, k);
    let t = c3.digits.t;
    let h = hs.last_mut().expect("an open history");
    if let Some(why) = continuation_refused(h, t) {
        statuses[k].refused.push(why.into());
        let run = if t == 1 { Run::Shifts } else { Run::Transient { start: Start::Zero } };
        hs.push(History { run, cases: vec![k] });
        return;
    }
    let mut prev = case3(cases, h.cases[h.cases.len() - 1]).state.clone();
    if h.run == Run::Shifts && t == 2 && h.cases.len() == 1 {
        // The shift is this rolling history's initial state; the rolling step is read now.
        h.run = Run::Transient { start: Start::Shift };
        (prev.chi_rad, prev.dq_mm, prev.veloc_mm_s) = (c3.state.chi_rad, c3.state.dq_mm, c3.state.veloc_mm_s);
        prev.rolling_read = c3.state.rolling_read;
    }
    if h.run == Run::Sweep && t == 2 {
        // The last steady case is this transient history's steady start.
        let start = h.cases.pop().expect("a steady case");
        if h.cases.is_empty() {
            hs.pop();
        }
        hs.push(History { run: Run::Transient { start: Start::Steady }, cases: vec![start] });
    }
    let h = hs.last_mut().expect("a history");
    continuation_checks(cases, statuses, h, &prev, k);
    h.cases.push(k);
}

/// The notes and refusals of transient case `k` continuing history `h` after a case in state
/// `prev`: a steady start solved with the transient cases' slip-velocity iteration, a Hertzian
/// grid re-specified, and any change of the setup, direction, iteration, pressure or load that a
/// history cannot take.
fn continuation_checks(cases: &[Case], statuses: &mut [CaseStatus], h: &History, prev: &State, k: usize) {
    let c3 = case3(cases, k);
    let d = c3.digits;
    let last = case3(cases, h.cases[h.cases.len() - 1]);
    let hertz = matches!(prev.potcon, Some(Potcon::Hertz { .. }));
    let after_start = h.run == (Run::Transient { start: Start::Steady }) && h.cases.len() == 1;
    let other_iteration = falling(&c3.state) && slip_iteration(prev) != slip_iteration(&c3.state);
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
    if prev.potcon != c3.state.potcon && same_hertz_grid(prev, &c3.state) {
        let axes = |s: &State| hertz_axes(s).map(|(.., [a, b])| format!("a = {a}, b = {b} mm"));
        statuses[k].notes.push(format!(
            "IPOTCN = {} re-specifies the Hertzian grid ({}) as the case before it ({}): the same MX, MY, SCALE and semi-axes within {HERTZ_GRID_REL:e}; the history keeps its first case's",
            c3.state.potcon.as_ref().map_or(0, Potcon::ipotcn),
            axes(&c3.state).unwrap_or_default(),
            axes(prev).unwrap_or_default()
        ));
    }
    if let Some(what) = setup_difference(prev, &c3.state, true) {
        statuses[k].refused.push(format!("changes {what} within a transient history"));
    } else if let Some(why) = turn_refused(cases, h, prev, &c3.state) {
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
