//! A resolved scene as CONTACT module-3 input (issue 15), so that a user with CONTACT can make
//! reference data for a scene of their own: one CONTACT case per history row, with the control
//! digits and case structure of `reference/contact/README.contact.md` ("How the time histories are
//! formed"): a steady sweep is one steady case (T = 3) per point; a transient history starts a
//! sequence (P = 2) with its steady start (T = 3, step 0) or its first step (T = 2), then one
//! transient case (P = 0, T = 2) per step; shifts (`[rolling] motion = "shift"`) are T = 1 cases,
//! and a shift start (`[init] kind = "shift"`) the first case as T = 1 before the rolling ones
//! (which read CHI, DQ, VELOC with C = 2). Exact theory, Coulomb friction FSTAT = FKIN = μ (read
//! again, L = 0, in a case whose μ changed), FN prescribed (N = 1) or the approach (N = 0, PEN), both bodies of the scene's
//! material (dissimilar bodies, `[material] g1_mpa` … `poisson2`: each its own POISS, GG, and
//! MAXOUT = `[contact_solver] max_outer`), rolling in CONTACT's +x (CHI = 0) with DQ = courant·dx (CONTACT solves a steady case
//! with DQ = DX and keeps it: after a steady start at another DQ the first transient case gives DQ
//! again).
//!
//! Geometry (first case): Hertz's ellipse as IPOTCN = −3 (AA, BB, SCALE) when the load is constant;
//! when the load changes within the history or the approach is prescribed, the ellipse's fixed curvatures h = A1 x² + B1 y² on the
//! fixed grid (IPOTCN = 1, IBASE = 1), as this project's solvers keep the geometry; a geometry given
//! per element as IPOTCN = 1 with its grid and IBASE = 9, h per element in CONTACT's order.
//! Signs: cx, cy, cs are CKSI, CETA, CPHI as they are (this project uses CONTACT's convention).
//!
//! An interface layer (`[material] layer_g_mpa`, `layer_thickness_mm`) is CONTACT's M = 4 in every
//! case, GG3, LAYTHK, TAU_C0 (the yield limit, 0 for none) and K_TAU (the rate it moves at) after the material's POISS, GG; in transient rolling
//! both programs take the layer's previous displacement at the element's own index.
//!
//! Surface temperatures (`[material] bulk1_c` … `density2_kg_per_mm3`) are CONTACT's H = 3 in the
//! first case, its BKTEMP, HEATCP, LAMBDA, DENS lines after the material, and H = 1 after.
//!
//! Viscoelastic bodies (`[material] visco_ratio`, `visco_time_s`) are CONTACT's M = 1 in every
//! case, FG 1 = FG 2 and TC 1 = TC 2 after the material's POISS, GG; refused rolling along −x or
//! with bilinear tractions ([`check`]).
//!
//! The influence functions of bilinear tractions (`[contact_solver] influence = "bilinear"`) are
//! CONTACT's C = 3 wherever C is given (C = 2 otherwise).
//!
//! An extra rigid slip per element (`[creepage] extra_slip`) is CONTACT's E = 9 in the first case
//! (EXRHS, pairs in CONTACT's element order after the geometry) and E = 1 (kept) afterwards.
//!
//! Friction per grid row (`[friction] mu_rows`) is CONTACT's V = 3: FSTAT = FKIN = μ_j of every
//! row after the first case's geometry, V = 3 with L = 1 after it, prescribed forces over FN.
//!
//! A falling friction law (`[friction]`) is given as CONTACT's L = 2, 3, 4 in the first case (FKIN,
//! F1, SABSH1, F2, SABSH2 and MEMDST, MEM_S0) and kept (L = 1) afterwards, with the slip-velocity
//! iteration's start (G = 4: INISLP, OMGSLP) and its progress printed (W = 2); a rolling speed that
//! changes from one row to the next is given in the row where it first applies (C = 2: CHI, DQ,
//! VELOC and the material again), as reference/contact_friction/README.contact_friction.md forms
//! its histories.
//!
//! The temperature law (`[friction] law = "temperature"`) is CONTACT's L = 6 in the first case
//! (FREF, TREF, DFHEAT, DTHEAT and MEMDST, MEM_S0) and kept (L = 1) afterwards, with its
//! iteration's start (G = 4: INISLP = 1 from s = 0, −1 from s = V: the memory's rate) and damping
//! (OMGSLP), its progress printed (W = 2).

use crate::error::InputError;
use crate::physics::halfspace::influence::Basis;
use crate::physics::{FrictionLaw, NormalPressure};
use crate::problem::{LoadingKind, Problem, Sample};
use crate::scene::{InitialSlip, Motion};
use std::fmt::Write;

/// Values per line of an element-wise undeformed distance.
const PER_LINE: usize = 6;
/// A relative change of μ below this between two cases is rounding, not a new friction.
const MU_CHANGE_REL: f64 = 1e-9;
/// SABSH2 written for a second term that is absent (F2 = 0): any positive value gives the same
/// law; CONTACT's own inputs use 1000 mm/s.
const SABSH2_UNUSED_MM_S: f64 = 1000.0;

/// CONTACT's range of FSTAT = FKIN with L = 0, V = 3 (`m_friclaw.f90` line 803, `fric_input`:
/// `check_range('FKIN', fkin, 1d-4, 1d10)`).
const FKIN_COULOMB: (f64, f64) = (1e-4, 1e10);
/// CONTACT's range of SABSH1, SABSH2 [mm/s] with L = 2, 3, 4 (`m_friclaw.f90` lines 853-854,
/// `fric_input`), checked after a term whose F is below [`F_ABSENT`] had its SABSH raised to at
/// least 1e-4 (lines 833-846).
const SABSH_RANGE: (f64, f64) = (1e-5, 1e20);
/// A falling term with F below this is absent to CONTACT (`m_friclaw.f90` lines 833-846).
const F_ABSENT: f64 = 1e-8;

/// The values the deck gives CONTACT within the ranges of CONTACT's own input check (`fric_input`,
/// `m_friclaw.f90` lines 798-855): Coulomb's μ (FSTAT = FKIN, of every case and grid row) and a
/// falling law's SABSH1, SABSH2 where their term is present. An error names the scene's key.
pub fn check(p: &Problem) -> Result<(), InputError> {
    check_visco(p)?;
    match &p.friction {
        FrictionLaw::Coulomb { .. } => check_coulomb(p),
        FrictionLaw::Linear(t) | FrictionLaw::Rational(t) | FrictionLaw::Exponential(t) => {
            check_sabsh("friction.sabsh1_mm_s", t.sabsh1_mm_s, ("friction.f1", t.f1))?;
            check_sabsh("friction.sabsh2_mm_s", t.sabsh2_mm_s, ("friction.f2", t.f2))
        }
        // FREF > 0, FREF + DFHEAT > 0 (the scene's reader): CONTACT's ranges (`fric_input`).
        FrictionLaw::Temperature(_) => Ok(()),
    }
}

/// Viscoelastic bodies (M = 1) rolling along +x with piecewise constant tractions: CONTACT sets
/// CHI = 0 with M = 1 (`m_sdis.f90`) and adds the memory of piecewise constant tractions to C = 3's
/// bilinear coefficients (`m_visc.f90`), so either would make the deck another problem.
fn check_visco(p: &Problem) -> Result<(), InputError> {
    if p.material.visco.is_none() {
        return Ok(());
    }
    if p.rolling.chi_deg != 0.0 {
        return Err(InputError::new(
            "rolling.chi_deg",
            format!("{} with viscoelastic bodies", p.rolling.chi_deg),
            "chi_deg = 0 with viscoelastic bodies (CONTACT's M = 1 rolls along +x whatever CHI: m_sdis.f90 sets CHI = 0)",
        ));
    }
    if p.contact_solver.influence == Basis::Bilinear {
        return Err(InputError::new(
            "contact_solver.influence",
            "\"bilinear\" with viscoelastic bodies",
            "\"constant\" with viscoelastic bodies (CONTACT's M = 1 adds the memory of piecewise constant tractions to C = 3's bilinear coefficients)",
        ));
    }
    Ok(())
}

/// Coulomb's μ written as FSTAT = FKIN: each grid row's (`mu_rows`, V = 3), else each case's
/// (`contact.mu`, or a table's column `mu`), in [`FKIN_COULOMB`].
fn check_coulomb(p: &Problem) -> Result<(), InputError> {
    let (lo, hi) = FKIN_COULOMB;
    let allowed =
        format!("a coefficient of friction in [{lo:e}, {hi:e}] (CONTACT's FSTAT = FKIN, m_friclaw.f90 fric_input)");
    if let Some(rows) = &p.friction_rows {
        return match rows.rows().iter().enumerate().find(|(_, mu)| !(lo..=hi).contains(*mu)) {
            Some((j, mu)) => Err(InputError::new(format!("friction.mu_rows[{j}]"), mu, allowed)),
            None => Ok(()),
        };
    }
    match p.loading.rows().find(|s| !(lo..=hi).contains(&s.mu)) {
        Some(s) if s.mu == p.nominal.mu => Err(InputError::new("contact.mu", s.mu, allowed)),
        Some(s) => Err(InputError::new(format!("creepage.file column mu (step {})", s.step), s.mu, allowed)),
        None => Ok(()),
    }
}

/// A falling term's SABSH `key` = `sabsh` in [`SABSH_RANGE`] where its F (`f_key` = `f`) is at least
/// [`F_ABSENT`] (an absent term's SABSH CONTACT raises itself).
fn check_sabsh(key: &str, sabsh: f64, (f_key, f): (&str, f64)) -> Result<(), InputError> {
    let (lo, hi) = SABSH_RANGE;
    if f < F_ABSENT || (lo..=hi).contains(&sabsh) {
        return Ok(());
    }
    Err(InputError::new(
        key,
        sabsh,
        format!(
            "a slip velocity in [{lo:e}, {hi:e}] mm/s where {f_key} >= {F_ABSENT:e} ({f_key} = {f}; CONTACT's SABSH, m_friclaw.f90 fric_input)"
        ),
    ))
}

/// The CONTACT input that computes the problem's history, one case per row.
pub fn module3_input(p: &Problem) -> String {
    let rows: Vec<&Sample> = p.loading.rows().collect();
    let history = History::of(p, &rows);
    let mut last = LastRead::of(p);
    let mut out = format!(
        "%\n% CONTACT input written by creepbench for scene \"{}\" ({} cases, one per history row).\n%\n",
        p.name,
        rows.len()
    );
    let mut points_written = false;
    for (n, s) in rows.iter().enumerate() {
        let case = Case::of(p, &history, &rows, n, &mut last);
        let stress = stress_digit(p, s, n + 1 == rows.len(), &mut points_written);
        write_case(p, &history, &case, s, stress, &mut out);
    }
    out.push_str("\n 0  MODULE\n");
    out
}

/// What holds for every case of the history: its kind of cases, whether the load changes and
/// whether the friction falls with the slip velocity.
struct History {
    /// A steady start (T = 3, step 0) before the transient cases.
    steady_start: bool,
    /// Shifts (T = 1) in every case (`[rolling] motion = "shift"`).
    shifts: bool,
    /// A shift start (`[init] kind = "shift"`): the first case a shift before the rolling ones.
    shift_start: bool,
    /// A steady sweep: one steady case (T = 3) per point.
    sweep: bool,
    /// FN changes within the history or the approach is prescribed.
    load_varies: bool,
    /// A friction law falling with the slip velocity (L = 2, 3, 4).
    falling: bool,
    /// A law with an outer iteration around the tangential solve: falling or of the temperature (L = 6).
    iterates: bool,
}

impl History {
    /// The history of `p`, whose cases are `rows`.
    fn of(p: &Problem, rows: &[&Sample]) -> History {
        History {
            steady_start: p.loading.steady_start().is_some(),
            shifts: p.rolling.motion == Motion::Shift,
            shift_start: p.loading.shift_start().is_some(),
            sweep: p.loading.kind == LoadingKind::Sweep,
            // With the approach prescribed CONTACT would derive the curvatures (IPOTCN = −3) or the
            // grid (−1) from PEN (`hzcalc3d`): the fixed grid and curvatures keep this project's.
            load_varies: rows.iter().any(|s| s.fn_n != rows[0].fn_n || s.pen_mm.is_some()),
            falling: p.friction.is_falling(),
            iterates: p.friction.is_falling() || p.friction.temperature().is_some(),
        }
    }
}

/// What CONTACT last read and keeps for the cases that follow: μ, rolling speed, step and direction.
struct LastRead {
    mu: f64,
    v_mm_s: f64,
    dq_mm: f64,
    chi_deg: f64,
}

impl LastRead {
    /// Before the first case: no μ, the scene's rolling.
    fn of(p: &Problem) -> LastRead {
        LastRead { mu: f64::NAN, v_mm_s: p.rolling.v_mm_s, dq_mm: p.rolling.dq_mm, chi_deg: p.rolling.chi_deg }
    }

    /// Whether a case reads its μ (the first, or one whose μ changed), which it then keeps. A table's μ
    /// interpolated at a row's printed time may differ from the row by rounding: read again only a μ
    /// that changed beyond that.
    fn reads_mu(&mut self, mu: f64, first: bool, falling: bool) -> bool {
        let read_mu = first || (!falling && (mu - self.mu).abs() > MU_CHANGE_REL * self.mu.abs());
        if read_mu {
            self.mu = mu;
        }
        read_mu
    }

    /// Whether a case after the first (not `first`) rolls at another speed, step (where `dq_counts`)
    /// or direction than the case before; its rolling `(v_mm_s, dq_mm, chi_deg)` is then kept.
    fn rolling_changed(&mut self, first: bool, (v_mm_s, dq_mm, chi_deg): (f64, f64, f64), dq_counts: bool) -> bool {
        let speed_changed = !first && (v_mm_s != self.v_mm_s || (dq_mm != self.dq_mm && dq_counts));
        self.v_mm_s = v_mm_s;
        self.dq_mm = dq_mm;
        // A row's own rolling direction (the table's chi_deg) is read again where it changes.
        let chi_changed = !first && chi_deg != self.chi_deg;
        self.chi_deg = chi_deg;
        speed_changed || chi_changed
    }
}

/// One case's control decisions and rolling.
struct Case {
    first: bool,
    /// A steady case (T = 3): a sweep's point or the steady start.
    steady: bool,
    /// A shift (T = 1).
    shift: bool,
    /// A case that starts a sequence (P = 2).
    new_sequence: bool,
    /// The case reads its friction (L ≠ 1).
    read_mu: bool,
    v_mm_s: f64,
    dq_mm: f64,
    chi_deg: f64,
    /// The case reads its kinematics and material again (C = 2 or 3 after the first case).
    dq_again: bool,
    /// The case reads its own undeformed distance again (Z = 2).
    new_h: bool,
}

impl Case {
    /// Case `n` of the history's `rows`, after the cases before it read `last`.
    fn of(p: &Problem, h: &History, rows: &[&Sample], n: usize, last: &mut LastRead) -> Case {
        let s = rows[n];
        let first = n == 0;
        let steady = h.sweep || (h.steady_start && first);
        let read_mu = last.reads_mu(s.mu, first, h.falling);
        let (v_mm_s, dq_mm, chi_deg) = rolling(p, s, steady && !h.sweep);
        let rolling_changed = last.rolling_changed(first, (v_mm_s, dq_mm, chi_deg), !(h.shift_start && n == 1));
        Case {
            first,
            steady,
            shift: h.shifts || (h.shift_start && first),
            new_sequence: h.sweep || first,
            read_mu,
            v_mm_s,
            dq_mm,
            chi_deg,
            // The first rolling case after a shift start reads its rolling step (a shift reads none).
            dq_again: (h.steady_start && n == 1 && p.rolling.dq_mm != p.grid.dx_mm)
                || (h.shift_start && n == 1)
                || rolling_changed,
            // A row's own undeformed distance (IBASE = 1) is read again where it changes (Z = 2).
            new_h: !first && s.h_coefficients.is_some() && s.h_coefficients != rows[n - 1].h_coefficients,
        }
    }

    /// CHI, DQ, VELOC of the case as `kinematics_and_material` takes them (speed, step, direction).
    fn rolling(&self) -> (f64, f64, f64) {
        (self.v_mm_s, self.dq_mm, self.chi_deg)
    }
}

/// A row's rolling speed [mm/s], step [mm] (CONTACT's DQ) and direction [deg]. CONTACT solves the
/// steady start with DQ = DX and keeps that DQ for the cases that follow (`m_sdis.f90`): where the
/// scene's DQ is another, the first transient case gives it again (C = 2: kinematics and material
/// read again, influence coefficients recomputed); the steady start (`steady_start`) rolls DX
/// whatever its row says, and the scene's DQ is written for it.
fn rolling(p: &Problem, s: &Sample, steady_start: bool) -> (f64, f64, f64) {
    let v_mm_s = s.v_mm_s.unwrap_or(p.rolling.v_mm_s);
    // A row's own rolling step (a table's courant: CONTACT's DQ per case).
    let dq_mm = if steady_start { p.rolling.dq_mm } else { s.courant.map_or(p.rolling.dq_mm, |c| c * p.grid.dx_mm) };
    (v_mm_s, dq_mm, s.chi_deg_or(p.rolling.chi_deg))
}

/// One case of the deck: its MODULE line, control digits, solver settings, loading and the inputs
/// it reads (again).
fn write_case(p: &Problem, h: &History, case: &Case, s: &Sample, stress: u8, out: &mut String) {
    let _ = writeln!(out, "\n 3  MODULE      % step {}, t={} s", s.step, s.t_s);
    pbtnfs(p, h, case, s, stress, out);
    ldcmze(p, case, out);
    solver_lines(p, h.iterates, case.first, out);
    loading_line(p, s, out);
    case_inputs(p, h, case, s, out);
    if let (3, Some(at)) = (stress, &p.stress) {
        subsurface_points(at, out);
    }
}

/// The S digit of a row: 3 (read the points, then compute) at the first row of `[stress] steps`
/// (or the last row without `steps`), 1 (compute at the points kept) at the later ones, else 0.
fn stress_digit(p: &Problem, s: &Sample, last_row: bool, points_written: &mut bool) -> u8 {
    let Some(at) = &p.stress else { return 0 };
    if !at.steps.as_ref().map_or(last_row, |steps| steps.contains(&s.step)) {
        return 0;
    }
    if std::mem::replace(points_written, true) {
        1
    } else {
        3
    }
}

/// S = 3's input (user guide, "Input for the subsurface stress calculation"): MATFIL = 2 (the
/// full tensor in `.subs`), OUTPUT = 1, then each block as ISUBS = 9 with its X, Y, Z, and ISUBS = 0.
fn subsurface_points(at: &crate::scene::stress::StressPoints, out: &mut String) {
    out.push_str("   2   1        MATFIL, OUTPUT (subsurface)\n");
    for b in &at.blocks {
        let _ =
            writeln!(out, "   9            ISUBS\n {} {} {}   NX, NY, NZ", b.x_mm.len(), b.y_mm.len(), b.z_mm.len());
        for axis in [&b.x_mm, &b.y_mm, &b.z_mm] {
            let values: Vec<String> = axis.iter().map(|v| format!("{v:?}")).collect();
            for line in values.chunks(8) {
                let _ = writeln!(out, "   {}", line.join("  "));
            }
        }
    }
    out.push_str("   0            ISUBS\n");
}

/// B: the row's pressure, solved (0; 1 with a compressible sheet) or Hertz's elliptical (2),
/// parabolic (3).
fn bound_digit(p: &Problem, h: &History, case: &Case) -> u8 {
    match p.normal.of_row(case.first && (h.steady_start || h.shift_start)) {
        NormalPressure::Solved if p.material.sheet_mm3_per_n > 0.0 => 1,
        NormalPressure::Solved => 0,
        NormalPressure::Elliptical => 2,
        NormalPressure::Parabolic => 3,
    }
}

/// The control digits P-B-T-N-F-S: a new sequence (P = 2) or its continuation (0), the row's
/// pressure B, the kind of case T, the normal problem N, the forces prescribed F and the
/// subsurface stresses S ([`stress_digit`]).
fn pbtnfs(p: &Problem, h: &History, case: &Case, s: &Sample, stress: u8, out: &mut String) {
    let t = match (case.steady, case.shift) {
        (true, _) => 3,
        (_, true) => 1,
        _ => 2,
    };
    let pv = if case.new_sequence { 2 } else { 0 };
    // F = 1: Fx prescribed with CETA given, F = 2: Fx and Fy (the scene refuses Fy alone).
    let f = usize::from(s.fx_target.is_some()) + usize::from(s.fy_target.is_some());
    // N = 0: the approach prescribed (PEN), N = 1: FN.
    let n_digit = u8::from(s.pen_mm.is_none());
    let b = bound_digit(p, h, case);
    let _ = writeln!(
        out,
        "  {pv}{b}{t}{n_digit}{f}{stress}      P-B-T-N-F-S   PVTIME, BOUND , TANG  , NORM  , FORCE , STRESS"
    );
}

/// The control digits L-D-C-M-Z-E: the friction law read (L) or kept (1), the influence functions
/// (C) where the kinematics are read, a new undeformed distance (Z = 2); V = 3 before them with
/// friction per grid row.
fn ldcmze(p: &Problem, case: &Case, out: &mut String) {
    let law = law_digit(&p.friction);
    // V = 3: friction per grid row, in every case (CONTACT refuses a V that changes under L = 1).
    let v = if p.friction_rows.is_some() { "3" } else { "" };
    // C = 2: uniform elements, C = 3: bilinear tractions (`[contact_solver] influence`).
    let c = if p.contact_solver.influence == Basis::Bilinear { 3 } else { 2 };
    // M = 4: the interface layer, in every case (CONTACT reads M in each; GG3.. with the material).
    // M = 1: viscoelastic bodies, in every case likewise (FG, TC with the material).
    let m = if p.material.layer.is_some() {
        4
    } else if p.material.visco.is_some() {
        1
    } else {
        0
    };
    // E: 9 gives the extra rigid slip with the first case, 1 keeps it.
    let e = match (&p.extra_slip, case.first) {
        (None, _) => 0,
        (Some(_), true) => 9,
        (Some(_), false) => 1,
    };
    let ldc = match (case.first, case.dq_again) {
        (true, _) => format!("{v}{law}2{c}{m}2{e}"),
        (false, again) => format!(
            "{v}{}0{}{m}{}{e}",
            if case.read_mu { law } else { 1 },
            if again { c } else { 0 },
            if case.new_h { 2 } else { 0 }
        ),
    };
    let _ = writeln!(out, "  {ldc}      L-D-C-M-Z-E   FRCLAW, DISCNS, INFLCF, MATER , RZNORM, EXRHS");
}

/// The control digits H-G-I-A-O-W-R and the solver's iteration limits, with a falling or the
/// temperature law (`iterates`) the outer iteration's start and damping (G = 4: INISLP, OMGSLP)
/// and its progress printed (W = 2).
fn solver_lines(p: &Problem, iterates: bool, first: bool, out: &mut String) {
    let (g, w) = if iterates { (4, 2) } else { (0, 1) };
    // H = 3: surface temperatures with the first case's data (after the material), then H = 1.
    let heat = match (p.material.heat.is_some(), first) {
        (false, _) => 0,
        (true, true) => 3,
        (true, false) => 1,
    };
    let _ = writeln!(
        out,
        " {heat}{g}{}22{w}1    H-G-I-A-O-W-R   HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN",
        if first { 0 } else { 1 }
    );
    // Dissimilar bodies: the outer iteration's MAXOUT (1 for K = 0: CONTACT sets it so anyway).
    let maxout = if p.material.coupled() { p.contact_solver.max_outer } else { 1 };
    let _ = writeln!(out, "   999   200    30     {maxout}   1e-08          MAXGS, MAXIN, MAXNR, MAXOUT, EPS");
    if iterates {
        let _ = writeln!(
            out,
            "   {}   {:?}                                INISLP, OMGSLP",
            match p.friction.temperature() {
                // L = 6 keeps its start as the memory's rate: s = 0 is INISLP = 1 (INISLP = 0
                // would start from the previous case's slip), s = V is -1.
                Some(_) if p.contact_solver.inislp == InitialSlip::Above => -1,
                Some(_) => 1,
                None => inislp(p.contact_solver.inislp),
            },
            p.contact_solver.omgslp
        );
    }
}

/// The loading line: FN or PEN, CKSI or FXREL, CETA or FYREL, CPHI. CONTACT's FXREL, FYREL are
/// the force over FSTAT·FN (over FN with V = 3, its muscal = 1), its sign flipped (fx = −FX/FN here).
fn loading_line(p: &Problem, s: &Sample, out: &mut String) {
    let muscal = if p.friction_rows.is_some() { 1.0 } else { s.mu };
    let (x, y) = (s.fx_target.map_or(s.cx, |f| -f / muscal), s.fy_target.map_or(s.cy, |f| -f / muscal));
    let names = [
        if s.pen_mm.is_some() { "PEN" } else { "FN" },
        if s.fx_target.is_some() { "FXREL" } else { "CKSI" },
        if s.fy_target.is_some() { "FYREL" } else { "CETA" },
    ];
    let normal = s.pen_mm.unwrap_or(s.fn_n);
    let _ = writeln!(out, "  {normal:?}   {x:?}   {y:?}   {:?}        {}, CPHI", s.cs, names.join(", "));
}

/// The input lines after the loading: the friction where the case reads it, the first case's
/// geometry (or the kinematics and material read again), a new undeformed distance (Z = 2).
fn case_inputs(p: &Problem, h: &History, case: &Case, s: &Sample, out: &mut String) {
    if case.read_mu && p.friction_rows.is_none() {
        friction_lines(p, s.mu, out);
    }
    if case.first {
        let sheet = bound_digit(p, h, case) == 1;
        geometry(p, (!case.shift).then_some(case.rolling()), (h.load_varies, sheet), s.h_coefficients, out);
        row_friction_lines(p, out);
        extra_slip_lines(p, out);
    } else if case.dq_again {
        kinematics_and_material(p, Some(case.rolling()), bound_digit(p, h, case) == 1, out);
    }
    if let (false, Some(b)) = (case.first, s.h_coefficients.filter(|_| case.new_h)) {
        quadratic(b, out);
    }
}

/// CONTACT's L of the law: 0 Coulomb, 2 linear, 3 rational, 4 exponential (`m_friclaw.f90`).
fn law_digit(law: &FrictionLaw) -> u8 {
    match law {
        FrictionLaw::Coulomb { .. } => 0,
        FrictionLaw::Linear(_) => 2,
        FrictionLaw::Rational(_) => 3,
        FrictionLaw::Exponential(_) => 4,
        FrictionLaw::Temperature(_) => 6,
    }
}

/// CONTACT's INISLP of the slip-velocity iteration's start (`m_stang.f90` lines 258-264).
fn inislp(start: InitialSlip) -> i8 {
    match start {
        // CONTACT has no extrapolated start: its INISLP 0 is the start this one speeds up.
        InitialSlip::Previous | InitialSlip::Extrapolated => 0,
        InitialSlip::Below => 1,
        InitialSlip::Above => -1,
    }
}

/// The friction lines of a case that reads its law: FSTAT, FKIN = μ (Coulomb), the falling
/// law's FKIN, F1, SABSH1, F2, SABSH2 and the memory MEMDST, MEM_S0, or the temperature law's
/// FREF, TREF, DFHEAT, DTHEAT and no memory (MEMDST = 0).
fn friction_lines(p: &Problem, mu: f64, out: &mut String) {
    let t = match &p.friction {
        FrictionLaw::Coulomb { .. } => {
            let _ = writeln!(out, "  {mu:?}   {mu:?}                            FSTAT, FKIN");
            return;
        }
        FrictionLaw::Temperature(t) => {
            let _ = writeln!(
                out,
                "  {:?}   {:?}   {:?}   {:?}        FREF, TREF, DFHEAT, DTHEAT",
                t.fref, t.tref_c, t.dfheat, t.dtheat_c
            );
            let m = &p.memory;
            let _ = writeln!(out, "  {:?}   {:?}                           MEMDST, MEM_S0", m.memory_mm, m.s0_mm_s);
            return;
        }
        FrictionLaw::Linear(t) | FrictionLaw::Rational(t) | FrictionLaw::Exponential(t) => t,
    };
    let sabsh2 = if t.f2 == 0.0 && t.sabsh2_mm_s == 0.0 { SABSH2_UNUSED_MM_S } else { t.sabsh2_mm_s };
    let _ = writeln!(
        out,
        "  {:?}   {:?}   {:?}   {:?}   {sabsh2:?}        FKIN, F1, SABSH1, F2, SABSH2",
        t.fkin, t.f1, t.sabsh1_mm_s, t.f2
    );
    let m = &p.memory;
    let _ = writeln!(out, "  {:?}   {:?}                           MEMDST, MEM_S0", m.memory_mm, m.s0_mm_s);
}

/// V = 3: FSTAT, FKIN = μ_j of every grid row IY (after the geometry, as CONTACT reads them).
fn row_friction_lines(p: &Problem, out: &mut String) {
    for mu in p.friction_rows.iter().flat_map(|r| r.rows()) {
        let _ = writeln!(out, "  {mu:?}   {mu:?}                            FSTAT, FKIN");
    }
}

/// The kinematics (CHI, DQ, VELOC at the row's direction, rolling step and speed; `None`: a
/// shift, which reads none) and material lines of a case with C = 2 (FLXZ where `sheet`: B = 1).
fn kinematics_and_material(p: &Problem, rolling: Option<(f64, f64, f64)>, sheet: bool, out: &mut String) {
    let m = &p.material;
    if let Some((v_mm_s, dq_mm, chi_deg)) = rolling {
        let chi = match chi_deg {
            0.0 => "0.0".to_string(),
            180.0 => "180d".to_string(),
            deg => format!("{deg:?}d"),
        };
        let _ = writeln!(out, "  {chi}   {dq_mm:?}   {v_mm_s:?}                 CHI, DQ, VELOC");
    }
    // Dissimilar bodies: each body's own constants; else both bodies of the combined material.
    let (poiss, gg) = match m.bodies {
        Some(b) => (b.poisson, b.g_mpa),
        None => ([m.poisson; 2], [m.g_mpa; 2]),
    };
    let _ = writeln!(out, "  {:?}   {:?}   {:?}   {:?}    POISS 1,2,  GG 1,2", poiss[0], poiss[1], gg[0], gg[1]);
    if sheet {
        let _ = writeln!(out, "  {:?}                             FLXZ", m.sheet_mm3_per_n);
    }
    // M = 4: the layer, elastic (TAU_C0 = 0) or elasto-plastic (its yield limit and K_TAU).
    if let Some(l) = m.layer {
        let tau_c0 = l.yield_mpa.unwrap_or(0.0);
        let k_tau = l.hardening_mpa_per_mm;
        let _ = writeln!(
            out,
            "  {:?}   {:?}   {tau_c0:?}   {k_tau:?}    GG3, LAYTHK, TAU_C0, K_TAU",
            l.g_mpa, l.thickness_mm
        );
    }
    // M = 1: both bodies the same standard linear solid.
    if let Some(v) = m.visco {
        let _ = writeln!(out, "  {:?}   {:?}   {:?}   {:?}    FG 1,2, TC 1,2", v.ratio, v.ratio, v.time_s, v.time_s);
    }
}

/// The first case's kinematics, material and geometry lines.
fn geometry(
    p: &Problem,
    rolling: Option<(f64, f64, f64)>,
    (load_varies, sheet): (bool, bool),
    b: Option<[f64; 6]>,
    out: &mut String,
) {
    let (m, g) = (&p.material, &p.grid);
    kinematics_and_material(p, rolling, sheet, out);
    // H = 3: both bodies' BKTEMP, HEATCP, LAMBDA, DENS after the material.
    for (a, t) in m.heat.iter().flatten().enumerate() {
        let (c, l, d) = (t.heat_capacity_j_per_kg_c, t.conductivity_w_per_mm_c, t.density_kg_per_mm3);
        let n = a + 1;
        let _ = writeln!(out, "  {:?}   {c:?}   {l:?}   {d:?}    BKTEMP{n}, HEATCP{n}, LAMBDA{n}, DENS{n}", t.bulk_c);
    }
    if p.geometry.elliptic() && !load_varies && p.grid_edges.is_none() {
        let e = p.hertz();
        let _ = writeln!(out, "  -3                                          IPOTCN");
        let _ = writeln!(
            out,
            "  {}   {}   {:?}   {:?}   {:?}       MX, MY, AA, BB, SCALE",
            g.mx, g.my, e.a_mm, e.b_mm, p.grid_scale
        );
        return;
    }
    // The grid's lower-left corner in CONTACT's coordinates (x_C = −x).
    let (xl, yl) = match p.grid_edges {
        Some(([x0, _], [y0, _])) => (x0, y0),
        None => (-(g.x_mm[g.mx - 1] + 0.5 * g.dx_mm), g.y_mm[0] - 0.5 * g.dy_mm),
    };
    let _ = writeln!(out, "  1                                           IPOTCN");
    let _ = writeln!(
        out,
        "  {}   {}   {:?}   {:?}   {:?}   {:?}       MX, MY, XL, YL, DX, DY",
        g.mx, g.my, xl, yl, g.dx_mm, g.dy_mm
    );
    if p.geometry.elliptic() {
        let (a1, b1) = p.hertz().undeformed_curvatures(m);
        let _ = writeln!(out, "  1    1                                      IBASE, IPLAN");
        let _ = writeln!(out, "  {a1:?}   0.0   {b1:?}   0.0   0.0   0.0     B1..B6");
        return;
    }
    if let Some(b) = b {
        quadratic(b, out);
        return;
    }
    let h = p.geometry.undeformed_distance_mm(g, p.hertz().fn_n, m);
    let _ = writeln!(out, "  9    1                                      IBASE, IPLAN");
    let contact_order: Vec<f64> = (0..g.len()).map(|k| h[g.index(g.mx - 1 - k % g.mx, k / g.mx)]).collect();
    for chunk in contact_order.chunks(PER_LINE) {
        let line: Vec<String> = chunk.iter().map(|v| format!("{v:?}")).collect();
        let _ = writeln!(out, "  {}", line.join("  "));
    }
}

/// E = 9: the extra rigid slip EXRHS, one pair (wx, wy) a line in CONTACT's element order
/// (x_C = −x: the grid's rows read from its last column).
fn extra_slip_lines(p: &Problem, out: &mut String) {
    let (Some((wx, wy)), g) = (&p.extra_slip, &p.grid) else { return };
    for e in 0..g.len() {
        let k = g.index(g.mx - 1 - e % g.mx, e / g.mx);
        let _ = writeln!(out, "  {:?}  {:?}", wx[k], wy[k]);
    }
}

/// CONTACT's IBASE = 1: `h = B1 x² + B2 xy + B3 y² + B4 x + B5 y + B6` in its coordinates.
fn quadratic(b: [f64; 6], out: &mut String) {
    let _ = writeln!(out, "  1    1                                      IBASE, IPLAN");
    let line: Vec<String> = b.iter().map(|v| format!("{v:?}")).collect();
    let _ = writeln!(out, "  {}     B1..B6", line.join("   "));
}
