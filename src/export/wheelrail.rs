//! A wheel–rail scene as CONTACT module-1 input (issue 44; CONTACT's user guide, "Specification of
//! the input file", module 1), one CONTACT case per row of its cases table, as
//! reference/contact_wheelrail/examples/mbench_a22_left.inp forms its cases: the first case gives
//! everything (C-P-B-T-N-F-S = C2BTN00 (B = 1 with `[material] sheet_flexibility_mm3_per_n`, its FLXZ after POISS, GG), T = 3, 0 when frictionless, 1 in a shift from rest (P = 2; in a sequence of shifts P = 0 after the first case, each case's S_WS the position its shifts reached), V-L-D-C-M-Z-E = V022033 (D = 5 with `contact_search = "grid"`; V the
//! friction's variation: 0, 1 across the rail, 2 along the track), H-G-I-A-O-W-R = 0000321: the
//! solver's limits, FSTAT = FKIN = mu or NVF control points, POISS and GG of both bodies the scene's, DX, DS with DQREL 1,
//! the scene's A_SEP, D_SEP, D_COMB, the track, the rail profile with its options (PRFOPT = 2) and
//! the rail's deviations, the wheelset's dimensions, the wheel profile, the position and velocities,
//! with E = 5 the wheel's deviations DXWHL … VPITCHW where the scene has any); each later case keeps all
//! but its position and velocities (V111002, 0100321). C is the side (0 left, 1 right; 4, 5 on a
//! roller rig, `[rail] roller_radius_mm`, with NOMRAD_R in CANT's place and VPITCH_ROL in VS's), N the
//! vertical problem (1: FZ prescribed, 0: the height Z_WS), F the longitudinal one (1: FX_WS in
//! place of VPITCH, `[cases] longitudinal = "force"`); S_WS is the case's own (the cases' column
//! `s_mm`), else the scene's track position (`[wheelrail] s_mm`: a shift's, where friction varies
//! along the track or on a rail slices file; else 0), PITCH the case's `pitch_rad` (0 without the
//! column); in a shift the velocity line
//! is the step's shifts (CONTACT reads the same line as SHFT_S … per step). Profile names are
//! written relative to the deck's folder, where CONTACT looks for them. With the surface
//! temperatures H = 3 and both bodies' BKTEMP, HEATCP, LAMBDA, DENS in the first case, H = 1 in
//! the later ones; with friction of the temperature L = 6 (FREF … DTHEAT, MEMDST = 0) and MAXIN
//! of its iterations.

use crate::error::InputError;
use crate::safety::relative::relative;
use crate::scene::wheelrail::{
    Approach, CaseRow, ContactSearch, LongitudinalSpec, MotionSpec, MuBy, PlacementSpec, ProfileSpec, SideSpec,
    VerticalSpec, WheelDeviationSpec, WheelRailScene,
};
use crate::scene::{ContactSolverOptions, MaterialSpec, VeldepSolves};
use crate::wheelrail::profile::options::SCALE_MIN;
use std::fmt::Write;
use std::path::Path;

/// CONTACT's smallest Coulomb coefficient (`m_friclaw.f90`, `fric_input`: FKIN in [1e-4, 1e10]).
const FKIN_MIN: f64 = 1e-4;
/// Longest profile name written: a line of CONTACT's input holds 256 characters
/// (`m_print_output.f90`, MAX_CHAR_INP), the name and its three values.
const NAME_MAX: usize = 200;

/// The scene's values CONTACT's input check would refuse or change (an error names the scene's key):
/// mu below CONTACT's FKIN range, a profile scale CONTACT replaces by 1.
pub fn check(s: &WheelRailScene) -> Result<(), InputError> {
    let allowed = format!(
        "a coefficient of friction of at least {FKIN_MIN:e} (CONTACT's FSTAT = FKIN, m_friclaw.f90 fric_input)"
    );
    match &s.mu_variation {
        Some(v) => {
            if let Some(mu) = v.values.iter().find(|&&mu| mu < FKIN_MIN) {
                return Err(InputError::new("wheelrail.mu_values", mu, allowed));
            }
        }
        None if s.mu < FKIN_MIN => return Err(InputError::new("wheelrail.mu", s.mu, allowed)),
        None => {}
    }
    check_tangential(s)?;
    for (key, p) in [("rail.scale", &s.rail), ("wheel.scale", &s.wheel)] {
        if p.scale <= SCALE_MIN {
            let allowed = format!("a scale above {SCALE_MIN} (CONTACT replaces a smaller SCALE by 1, m_profile.f90)");
            return Err(InputError::new(key, p.scale, allowed));
        }
    }
    Ok(())
}

/// CONTACT's fixed stop of its temperature iteration (L = 6, `m_stang.f90`): rms(T_k − T_(k−1))
/// ≤ 1e-4 rms(T_k), each tangential solve to its EPS.
const CONTACT_TEMPDEP_TOLERANCE: f64 = 1e-4;
/// MAXIN written without the temperature law.
const MAXIN: usize = 100;

/// `[contact_solver]` as module 1's input says it: with the temperature law CONTACT's own stop
/// (`tempdep_tolerance = 1e-4`, `veldep_solves = "tight"`, OMGSLP its default) and its iterations
/// max(1, MAXIN − 10) + 1 written as MAXIN; without it, none.
fn check_tangential(s: &WheelRailScene) -> Result<(), InputError> {
    let (o, d) = (s.tangential.contact_solver, ContactSolverOptions::default());
    let contact = ContactSolverOptions {
        tempdep_tolerance: CONTACT_TEMPDEP_TOLERANCE,
        tempdep_max_iterations: o.tempdep_max_iterations,
        veldep_solves: VeldepSolves::Tight,
        ..d
    };
    match temperature_law(s) {
        false if o != d => Err(InputError::new(
            "contact_solver",
            format!("{o:?}"),
            "left out: module 1's input carries the exact solver's options only for [friction] law = \"temperature\"",
        )),
        true if o != contact || o.tempdep_max_iterations < 2 => Err(InputError::new(
            "contact_solver",
            format!("{o:?}"),
            "CONTACT's own stop of the temperature iteration: tempdep_tolerance = 1e-4, veldep_solves = \"tight\", tempdep_max_iterations of at least 2 (MAXIN = it + 9), no other key",
        )),
        _ => Ok(()),
    }
}

/// The module-1 deck of the scene, to be written into the folder `deck_dir` (existing or not).
pub fn module1_input(s: &WheelRailScene, deck_dir: &Path) -> Result<String, InputError> {
    let rail = profile_name(&s.rail, "rail.profile", deck_dir)?;
    let wheel = profile_name(&s.wheel, "wheel.profile", deck_dir)?;
    let mut out = format!(
        "%\n% CONTACT module-1 input written by creepbench for the wheel-rail scene \"{}\" ({} cases, one per row\n% of its cases table).\n%\n",
        s.name,
        s.cases.len()
    );
    let shifts = s.shift_positions_mm();
    for (n, row) in s.cases.iter().enumerate() {
        let _ = writeln!(out, "\n  1 MODULE      % row {}, contact_case {}", n + 1, row.contact_case);
        control_words(s, n == 0, &mut out);
        if n == 0 {
            setup(s, (&rail, &wheel), &mut out);
        }
        let s_mm = shifts.as_ref().map_or_else(|| row.s_mm.unwrap_or_else(|| track_s_mm(s)), |p| p[n]);
        position_and_velocity(s, row, s_mm, &mut out);
        if n == 0 && flexible(s) {
            wheel_deviation(s, &mut out);
        }
    }
    out.push_str("\n 0 MODULE\n");
    Ok(out)
}

/// A profile's name as the deck gives it: its path from the deck's folder, which CONTACT can quote.
fn profile_name(p: &ProfileSpec, key: &str, deck_dir: &Path) -> Result<String, InputError> {
    let rel = relative(deck_dir, &p.path).map_err(|e| InputError::new(key, p.path.display(), e.to_string()))?;
    match rel.to_str() {
        Some(name) if !name.contains('\'') && name.len() <= NAME_MAX => Ok(name.to_string()),
        _ => Err(InputError::new(
            key,
            rel.display(),
            format!(
                "a UTF-8 path from the deck's folder without ' of at most {NAME_MAX} characters (CONTACT's input line)"
            ),
        )),
    }
}

/// The three control words: the first case reads everything, the later ones position and velocity.
fn control_words(s: &WheelRailScene, first: bool, out: &mut String) {
    // C = 0, 1 a wheel on a track, 4, 5 on a roller rig.
    let c = u8::from(s.side == SideSpec::Right) + if s.roller.is_some() { 4 } else { 0 };
    let n = u8::from(s.vertical == VerticalSpec::Force);
    // F = 1 FX_WS given, 3 a massless rail (read with the track by the first case, kept after it).
    let f = if s.massless_rail.is_some() { 3 } else { u8::from(s.longitudinal == LongitudinalSpec::Force) };
    let t = match (s.frictionless, s.motion) {
        (true, _) => 0,
        (false, MotionSpec::Shift { steady_start: true, .. }) if first => 3,
        (false, MotionSpec::Shift { .. }) => 1,
        (false, MotionSpec::RollingSequence { from_rest, .. }) if !first || from_rest => 2,
        (false, MotionSpec::Rolling | MotionSpec::RollingSequence { .. }) => 3,
    };
    // A sequence of shifts or of transient rolling steps continues from the case before (P = 0)
    // after its first case.
    let p = match s.motion {
        MotionSpec::Shift { sequence: true, .. } | MotionSpec::RollingSequence { .. } if !first => 0,
        _ => 2,
    };
    let v = match s.mu_variation.as_ref().map(|v| v.by) {
        None => 0,
        Some(MuBy::ContactAngle) => 1,
        Some(MuBy::TrackS { .. }) => 2,
    };
    // A transient rolling step takes the initial estimate (I = 1), as CONTACT's `t3_t2_force` does:
    // with I = 0 and FZ prescribed CONTACT's step departs from its own I = 1 result (measured:
    // `t3_t2_force_1` exported, case 2 NPOT 5031 against 3526, FX(TR) 2 % off; docs/wheelrail.md).
    let rolling_step = matches!(s.motion, MotionSpec::RollingSequence { .. }) && !first;
    let (ldcmze, hgiaowr) = match (first, rolling_step) {
        (true, _) if flexible(s) => ("022035", "0000321"),
        (true, _) => ("022033", "0000321"),
        (false, true) => ("111002", "0110321"),
        (false, false) => ("111002", "0100321"),
    };
    // Friction of the temperature (L = 6) read by the first case, kept after it (L = 1); the
    // surface temperatures read (H = 3) by the first case, computed again (H = 1) by the later ones.
    let law = if first && temperature_law(s) { "6" } else { &ldcmze[..1] };
    // The grid search (`contact_search = "grid"`) is D = 5 (`"grid_steep"` 6), the conformal
    // approach D = 4, read by the first case, kept after it.
    let d = match (first, s.search, s.approach) {
        (true, ContactSearch::Grid, _) => "5",
        (true, ContactSearch::GridSteep, _) => "6",
        (true, ContactSearch::Locus, Approach::Conformal) => "4",
        (true, ContactSearch::Locus, Approach::PlanarSurfaceSlip) => "3",
        _ => &ldcmze[1..2],
    };
    // Blanco's conformal correction: C3 = 4, read with the first case's material (IF_METH,
    // VARIANT before POISS), kept after it.
    let c3 = if first && s.material.blanco.is_some() { "4" } else { &ldcmze[2..3] };
    let ldcmze = format!("{law}{d}{c3}{}", &ldcmze[3..]);
    let heat = match (s.material.heat.is_some(), first) {
        (true, true) => "3",
        (true, false) => "1",
        (false, _) => &hgiaowr[..1],
    };
    let hgiaowr = format!("{heat}{}", &hgiaowr[1..]);
    // B = 1: a compressible sheet (FLXZ read with the first case's material, kept after it).
    let b = u8::from(s.material.sheet_mm3_per_n > 0.0);
    let _ =
        writeln!(out, " {c}{p}{b}{t}{n}{f}0    C-P-B-T-N-F-S   CONFIG, PVTIME, BOUND,  TANG,   NORM,   FORCE,  STRESS");
    let _ = writeln!(out, " {v}{ldcmze}    V-L-D-C-M-Z-E   VARFRC, FRCLAW, DISCNS, INFLCF, MATER,  ZTRACK, EWHEEL");
    let _ = writeln!(out, " {hgiaowr}    H-G-I-A-O-W-R     HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW,   RETURN");
}

/// Whether the wheel deviates from its design place or moves on the wheelset (E = 5 in the first
/// case; the later cases' E = 2 keeps the deviations).
fn flexible(s: &WheelRailScene) -> bool {
    s.wheel_deviation != WheelDeviationSpec::default()
}

/// `DXWHL … DPITCHW` and `VXWHL … VPITCHW` (E = 4, 5; wheelset coordinates, rad and rad/s).
fn wheel_deviation(s: &WheelRailScene, out: &mut String) {
    let d = s.wheel_deviation;
    for (values, names) in [
        (d.position, "DXWHL, DYWHL, DZWHL, DROLLW, DYAWW, DPITCHW"),
        (d.velocity, "VXWHL, VYWHL, VZWHL, VROLLW, VYAWW, VPITCHW"),
    ] {
        let line: Vec<String> = values.iter().map(|v| format!("{v:?}")).collect();
        let _ = writeln!(out, "  {}      {names}", line.join("   "));
    }
}

/// The first case's groups: solver, friction, material, discretisation, track, rail, wheelset.
fn setup(s: &WheelRailScene, (rail, wheel): (&str, &str), out: &mut String) {
    let (g, nu) = (shear_modulus(&s.material), s.material.poisson);
    let maxin = if temperature_law(s) { s.tangential.contact_solver.tempdep_max_iterations + 9 } else { MAXIN };
    // Blanco's correction couples the normal and tangential problems: CONTACT's Panagiotopoulos
    // process, at most MAXOUT outer iterations (the scene's `max_outer`).
    let maxout = if s.material.blanco.is_some() { s.tangential.contact_solver.max_outer } else { 1 };
    let _ = writeln!(out, "    999     {maxin}    30    {maxout}     1e-5         MAXGS , MAXIN , MAXNR , MAXOUT, EPS");
    friction(s, out);
    if let Some(b) = s.material.blanco {
        let _ = writeln!(
            out,
            "      {}       {}                                 IF_METH, VARIANT",
            b.inclination.if_meth(),
            b.variant
        );
    }
    let _ = writeln!(out, "  {nu:?}   {nu:?}   {g:?}   {g:?}                POISS 1,2,  GG 1,2");
    if s.material.sheet_mm3_per_n > 0.0 {
        let _ = writeln!(out, "  {:?}                                FLXZ", s.material.sheet_mm3_per_n);
    }
    for t in s.material.heat.iter().flatten() {
        let (t0, cp, lambda, rho) =
            (t.bulk_c, t.heat_capacity_j_per_kg_c, t.conductivity_w_per_mm_c, t.density_kg_per_mm3);
        let _ = writeln!(out, "  {t0:?}   {cp:?}   {lambda:?}   {rho:?}          BKTEMP, HEATCP, LAMBDA, DENS");
    }
    let _ = writeln!(
        out,
        "  {:?}   {:?}   {:?}   {:?}   {:?}   {:?}   {:?}       DX, DS, DQREL, A_SEP, D_SEP, D_COMB, D_TURN",
        s.dx_mm,
        s.ds_mm,
        match s.motion {
            MotionSpec::RollingSequence { dq_rel, .. } => dq_rel,
            _ => 1.0,
        },
        s.a_sep_rad,
        s.d_sep_mm,
        s.d_comb_mm,
        s.d_turn_mm
    );
    let _ = match s.placement {
        PlacementSpec::Gauge { height_mm, width_mm } => {
            writeln!(out, "  {height_mm:?}   0   {width_mm:?}   {:?}         GAUGHT, GAUGSQ, GAUGWD, CANT", s.cant_rad)
        }
        PlacementSpec::Absolute { y_mm, z_mm } => match s.roller {
            Some(r) => {
                let radius = r.radius_mm;
                writeln!(out, "  -1.0   {y_mm:?}   {z_mm:?}   {radius:?}         GAUGHT, RAILY0, RAILZ0, NOMRAD_R")
            }
            None => {
                writeln!(out, "  -1.0   {y_mm:?}   {z_mm:?}   {:?}         GAUGHT, RAILY0, RAILZ0, CANT", s.cant_rad)
            }
        },
    };
    profile_line(rail, &s.rail, "RFNAME", out);
    let ([dy, dz, droll], [vy, vz, vroll]) = (s.rail_deviation.position, s.rail_deviation.velocity);
    let _ =
        writeln!(out, "  {dy:?}   {dz:?}   {droll:?}   {vy:?}   {vz:?}   {vroll:?}     DY, DZ, ROLL, VY, VZ, VROLL");
    if let Some(m) = &s.massless_rail {
        let _ = writeln!(
            out,
            "  {:?}   {:?}   {:?}   {:?}   {:?}     KYRAIL, FYRAIL, KZRAIL, FZRAIL, DYSTEP0",
            m.ky_n_per_mm, m.fy_n, m.kz_n_per_mm, m.fz_n, m.dy_step_mm
        );
    }
    let _ = writeln!(
        out,
        "  {:?}   {:?}   {:?}                         FBDIST, FBPOS, NOMRAD",
        s.flange_back_distance_mm, s.flange_back_position_mm, s.nominal_radius_mm
    );
    profile_line(wheel, &s.wheel, "WFNAME", out);
}

/// Whether the scene's friction is the temperature law (L = 6): one law, or per control point.
fn temperature_law(s: &WheelRailScene) -> bool {
    s.tangential.temperature_law.is_some() || s.mu_variation.as_ref().is_some_and(|v| v.temperature.is_some())
}

/// Friction of the temperature (L = 6): `FREF TREF DFHEAT DTHEAT`, or with a variation (V = 1, 2)
/// `NVF` and per control point `ALPHA (or SVF) FREF TREF DFHEAT DTHEAT`, then `MEMDST MEM_S0`;
/// Coulomb's law (L = 0): `FSTAT FKIN` with one μ, or with a variation `NVF` and per control point
/// `ALPHA (or SVF) FSTAT FKIN` (user guide, module 1, "VARFRC").
fn friction(s: &WheelRailScene, out: &mut String) {
    const NO_MEMORY: &str = "  0.0   1.0                                 MEMDST, MEM_S0";
    if let Some(t) = s.tangential.temperature_law {
        let (fref, tref, dfheat, dtheat) = (t.fref, t.tref_c, t.dfheat, t.dtheat_c);
        let _ = writeln!(out, "  {fref:?}   {tref:?}   {dfheat:?}   {dtheat:?}          FREF, TREF, DFHEAT, DTHEAT");
        let _ = writeln!(out, "{NO_MEMORY}");
        return;
    }
    let Some(v) = &s.mu_variation else {
        let _ = writeln!(out, "  {:?}   {:?}                                 FSTAT, FKIN", s.mu, s.mu);
        return;
    };
    let at = if v.by == MuBy::ContactAngle { "ALPHA" } else { "SVF" };
    let _ = writeln!(out, "  {}                                            NVF", v.at.len());
    match &v.temperature {
        Some([tref, dfheat, dtheat]) => {
            for k in 0..v.at.len() {
                let (x, fref, t, df, dt) = (v.at[k], v.values[k], tref[k], dfheat[k], dtheat[k]);
                let _ =
                    writeln!(out, "  {x:?}   {fref:?}   {t:?}   {df:?}   {dt:?}     {at}, FREF, TREF, DFHEAT, DTHEAT");
            }
            let _ = writeln!(out, "{NO_MEMORY}");
        }
        None => {
            for (x, mu) in v.at.iter().zip(&v.values) {
                let _ = writeln!(out, "  {x:?}   {mu:?}   {mu:?}                        {at}, FSTAT, FKIN");
            }
        }
    }
}

/// The wheelset's track position S_WS [mm] of a case without its own (the cases' column `s_mm`):
/// a shift's (the grid's anchor), where friction varies along the track (V = 2) its position
/// there, else `[wheelrail] s_mm` (on a rail slices file where the wheelset stands; 0 if absent).
fn track_s_mm(s: &WheelRailScene) -> f64 {
    match (s.motion, s.mu_variation.as_ref().map(|v| v.by)) {
        (MotionSpec::Shift { s_ws_mm, .. }, _) => s_ws_mm,
        (_, Some(MuBy::TrackS { s_mm })) => s_mm,
        _ => s.s_ws_mm,
    }
}

/// G as the scene gives it, or from E and ν (the reader requires one of them).
fn shear_modulus(m: &MaterialSpec) -> f64 {
    match (m.g_mpa, m.e_mpa) {
        (Some(g), _) => g,
        (None, Some(e)) => crate::physics::Material::from_e(e, m.poisson).g_mpa,
        (None, None) => f64::NAN,
    }
}

/// `'NAME' MIRRORY SCALE SMOOTH MIRRORZ PRFOPT`, PRFOPT = 2 with its lines `ISMOOTH ZIGTHRS
/// KINKHIGH KINKLOW KINKWID` and `ERRHND MAXOMIT` (ERRHND 0, CONTACT's default: warn and go on).
fn profile_line(name: &str, p: &ProfileSpec, what: &str, out: &mut String) {
    let _ = writeln!(
        out,
        "  '{name}'   {}   {:?}   {:?}   {}   2       {what}, MIRRORY, SCALE, SMOOTH, MIRRORZ, PRFOPT",
        u8::from(p.mirror_y),
        p.scale,
        p.smooth,
        p.mirror_z
    );
    let _ = writeln!(
        out,
        "  {}   {:?}   {:?}   {:?}   {:?}       ISMOOTH, ZIGTHRS, KINKHIGH, KINKLOW, KINKWID",
        u8::from(p.smooth_weighted),
        p.zig_zag_rad,
        p.kink_high_rad,
        p.kink_low_rad,
        p.kink_width_mm
    );
    let _ = writeln!(out, "  0   {:?}       ERRHND, MAXOMIT", p.max_omit);
}

/// S_WS, Y_WS, FZ or Z_WS, ROLL, YAW, PITCH (the cases' `pitch_rad`, 0 without it); then VS, VY,
/// VZ, VROLL, VYAW, VPITCH (or FX_WS with F = 1).
fn position_and_velocity(s: &WheelRailScene, r: &CaseRow, s_mm: f64, out: &mut String) {
    let (vertical, longitudinal) = (s.vertical, s.longitudinal);
    let third = if vertical == VerticalSpec::Force { "FZ" } else { "Z" };
    let _ = writeln!(
        out,
        "  {s_mm:?}   {:?}   {:?}   {:?}   {:?}   {:?}      S, Y, {third}, ROLL, YAW, PITCH",
        r.y_mm, r.vertical, r.roll_rad, r.yaw_rad, r.pitch_rad
    );
    let [vs, vy, vz, vroll, vyaw, sixth] = r.velocity;
    let last = if longitudinal == LongitudinalSpec::Force { "FX_WS" } else { "VPITCH" };
    // On a roller rig the first value is the roller's VPITCH_ROL (CONTACT's VS is 0 there).
    let (first, name) = match s.roller {
        Some(roller) => (roller.vpitch_rad_s, "VPITCH_ROL"),
        None => (vs, "VS"),
    };
    let _ = writeln!(
        out,
        "  {first:?}   {vy:?}   {vz:?}   {vroll:?}   {vyaw:?}   {sixth:?}      {name}, VY, VZ, VROLL, VYAW, {last}"
    );
}
