//! What a wheel–rail scene cannot say (docs/scene-format.md, "A wheel–rail scene"), beyond the
//! unsupported rows of [`features::WHEELRAIL_FEATURES`]: a case using a refused row is not
//! imported, named with the row's value and reason; an accepted row is a note (read, not carried,
//! changes no result of the scene). The verdict of a case is [`assess`]: the feature table's
//! unsupported rows and this table's refused ones, the rest notes.

use super::super::super::features::{self, WheelRailFeature};
use super::super::super::wheelrail_deck::{
    Along, FrictionValues, ProfileCuration, ProfileFormat, ProfileSpec, RailPlacement, TrackFourth, WheelRailCase,
};
use std::f64::consts::PI;

/// One thing the scene cannot carry (a row of [`SCENE_LIMITS`]).
pub struct SceneLimit {
    pub name: &'static str,
    pub control: &'static str,
    /// Whether a case using it is imported (its value then not carried: a note).
    pub accepted: bool,
    pub reason: &'static str,
    pub used: fn(&WheelRailCase) -> Option<String>,
}

/// Rows of [`features::WHEELRAIL_FEATURES`] whose verdict [`SCENE_LIMITS`] gives instead: what the
/// project's physics carries (or is to carry) but the scene does not say.
const REPLACED: [WheelRailFeature; 5] = [
    WheelRailFeature::TransientContact,
    WheelRailFeature::FrictionLaw,
    WheelRailFeature::ConformalInfluence,
    WheelRailFeature::BilinearInfluence,
    WheelRailFeature::PatchCombination,
];

/// CONTACT's defaults of the profile curation (`m_profile.f90`, `profile_init`): ISMOOTH 0,
/// ZIGTHRS 150°, KINKHIGH 30°, KINKLOW KINKHIGH/5, KINKWID 2 mm, MAXOMIT 0.5 — the project's
/// profile stage's (`wheelrail::profile::options`).
const CURATION_DEFAULT: (i64, [f64; 4], f64) = (0, [150.0 * PI / 180.0, 30.0 * PI / 180.0, 6.0 * PI / 180.0, 2.0], 0.5);

/// Every limit of the scene, in the order of the input.
pub const SCENE_LIMITS: &[SceneLimit] = &[
    SceneLimit {
        name: "transient rolling",
        control: "T",
        accepted: false,
        reason: "supported: T = 2 from rest (P = 2) or continuing the case before (P = 0) in a sequence started by a steady case (T = 3) or from rest; after another run (P = 1, 3) it would need the state of a run before, not carried",
        used: |c| (c.digits.t == 2 && matches!(c.digits.p, 1 | 3)).then(|| format!("T = 2, P = {}", c.digits.p)),
    },
    SceneLimit {
        name: "transient rolling continuing a sequence",
        control: "T, P",
        accepted: true,
        reason: "carried as [wheelrail] motion = \"rolling_sequence\", dq_rel = DQREL (with start = \"rest\" from a step from zero tractions, P = 2) in the scene of the steady case (T = 3) or step from rest before it (the case must follow it, changing only the wheelset's position and velocity): the previous tractions on CONTACT's super-grid (fixed laterally in the rail's material, moving with the wheelset along the track; a steady case's grid snapped to it, `shift_grid_super`), rolled by DQ",
        used: |c| (c.digits.t == 2 && matches!(c.digits.p, 0 | 2)).then(|| format!("T = 2, P = {}", c.digits.p)),
    },
    SceneLimit {
        name: "a longitudinal force in transient rolling",
        control: "F",
        accepted: false,
        reason: "supported: F = 0 in transient rolling (T = 2): the pitch velocity given",
        used: |c| (c.digits.t == 2 && c.digits.f != 0).then(|| format!("T = 2, F = {}", c.digits.f)),
    },
    SceneLimit {
        name: "shifts from rest",
        control: "T",
        accepted: true,
        reason: "carried as [wheelrail] motion = \"shift\" with s_mm = S_WS: one shift step from zero tractions on CONTACT's material-fixed grid, the velocities the step's shifts",
        used: |c| (c.digits.t == 1 && c.digits.p == 2).then(|| "T = 1, P = 2".to_string()),
    },
    SceneLimit {
        name: "shifts continuing a sequence",
        control: "P",
        accepted: true,
        reason: "carried as [wheelrail] motion = \"shift_sequence\" in the scene of the shift before it (the case must follow it, its S_WS the one before plus the shift SHFT_S) or of the steady case (T = 3) before it (start = \"steady\": its S_WS the steady case's plus its own SHFT_S; the steady grid snapped to the super-grid, `shift_grid_super`): the previous case's tractions on CONTACT's material-fixed grid, its patches connected by overlap, split, merged or kept while out of contact (`wr_connect_cps`, `wr_update_allcps`), its grid widened to the contact of the time before (`merge_prev_potcon`)",
        used: |c| (c.digits.t == 1 && c.digits.p == 0).then(|| "T = 1, P = 0".to_string()),
    },
    SceneLimit {
        name: "shifts after another run",
        control: "P",
        accepted: false,
        reason: "supported: T = 1 from rest (P = 2) or continuing the case before (P = 0); P = 1 (a new sequence keeping the state) and P = 3 (the steady state as the previous one) are not carried",
        used: |c| (c.digits.t == 1 && matches!(c.digits.p, 1 | 3)).then(|| format!("T = 1, P = {}", c.digits.p)),
    },
    SceneLimit {
        name: "a longitudinal force in a shift",
        control: "F",
        accepted: false,
        reason: "supported: F = 0 in shifts (T = 1): the wheelset's shifts given; FX_WS or MY_WS prescribed is solved for steady rolling only",
        used: |c| (c.digits.t == 1 && c.digits.f != 0).then(|| format!("T = 1, F = {}", c.digits.f)),
    },
    SceneLimit {
        name: "frictionless compression",
        control: "T",
        accepted: true,
        reason: "carried as [wheelrail] frictionless = true: the normal problem only, no tangential forces",
        used: |c| (c.digits.t == 0).then(|| "T = 0".to_string()),
    },
    SceneLimit {
        name: "friction of the surface temperature",
        control: "L, V, FREF, TREF, DFHEAT, DTHEAT",
        accepted: true,
        reason: "carried as [friction] law = \"temperature\", fref, tref_c, dfheat, dtheat_c (V = 0), or per control point as [wheelrail] mu_by, mu_at, mu_values (FREF), tref_c_values, dfheat_values, dtheat_c_values (V = 1, 2: each patch's parameters interpolated at its contact angle or S_WS, CONTACT's fric_interp_arr) with [contact_solver] tempdep_tolerance (CONTACT's fixed 1e-4), tempdep_max_iterations (max(1, MAXIN - 10) + 1) and omgslp: each patch's exact solve iterates tractions and surface temperatures as module 3's (docs/models.md, \"Temperature-dependent friction\")",
        used: |c| features::wr_temperature_law_carried(c).then(|| "L (in force) = 6".to_string()),
    },
    SceneLimit {
        name: "friction laws other than Coulomb's",
        control: "L, V, MEMDST, H",
        accepted: false,
        reason: "supported: L = 0 (Coulomb) or L = 1 keeping it, and L = 6 (one set, V = 0, or sets across the rail or along the track, V = 1, 2), no memory (MEMDST = 0) and the surface temperatures (H = 1, 3 in steady rolling); not the falling laws (2, 3, 4)",
        used: |c| {
            let f = c.state.friction.as_ref().filter(|f| f.law != 0 && !features::wr_temperature_law_carried(c))?;
            Some(format!("L (in force) = {}, V = {}", f.law, c.digits.v))
        },
    },
    SceneLimit {
        name: "influence functions other than the half-space's with piecewise constant tractions",
        control: "C3",
        accepted: false,
        reason: "supported: C3 = 2 (piecewise constant) or 0, 1 keeping it, and C3 = 4 (Blanco-Lorenzo's conformal correction, imported as [material] blanco_variant = VARIANT, blanco_inclination = \"interpolated\" or \"linear\") with VARIANT 1 to 4 and IF_METH 0 or 1 on the conformal approach (D = 4); not the bilinear functions (3), nor C3 = 4 on a planar patch (its rows have no inclinations)",
        used: |c| {
            let m = c.state.material.as_ref()?;
            let conformal = c.state.discretisation.as_ref().is_some_and(|d| d.method == 4);
            let blanco = m.influence == 4 && conformal && m.if_correction.is_some_and(|[meth, var]| (0..=1).contains(&meth) && (1..=4).contains(&var));
            let [meth, var] = m.if_correction.unwrap_or([-1, -1]);
            match m.influence {
                2 => None,
                4 if blanco => None,
                4 => Some(format!("C3 (in force) = 4 with IF_METH = {meth}, VARIANT = {var}, D = {}", c.state.discretisation.as_ref().map_or(0, |d| d.method))),
                other => Some(format!("C3 (in force) = {other}")),
            }
        },
    },
    SceneLimit {
        name: "the contact reference weighted linearly by the gap",
        control: "M2 (tens digit)",
        accepted: false,
        reason: "supported: gap weighting 0 or 2 (CONTACT's default: the squared gap, as the project's patch search)",
        used: |c| (c.digits.gap_weighting == 1).then(|| "gap weighting = 1".to_string()),
    },
    SceneLimit {
        name: "a canted rail placed absolutely",
        control: "GAUGHT, CANT",
        accepted: false,
        reason: "supported: CANT = 0 with absolute placement (GAUGHT <= 0), any CANT with the gauge point (GAUGHT > 0); the project's rotation of a rail placed by RAILY0, RAILZ0 is not checked against CONTACT",
        used: |c| {
            let t = c.state.track?;
            let cant = match t.fourth {
                TrackFourth::CantRad(r) => r,
                TrackFourth::RollerRadiusMm(_) => 0.0,
            };
            (matches!(t.placement, RailPlacement::Absolute { .. }) && cant != 0.0)
                .then(|| format!("GAUGHT = {}, CANT = {cant}", gaught(&t.placement)))
        },
    },
    SceneLimit {
        name: "a SIMPACK profile's own mirroring undone",
        control: "MIRRORY",
        accepted: false,
        reason: "supported: MIRRORY = 0 or 1 on a SIMPACK file (-1 cancels the file's mirror.y, which the scene's mirror_y cannot say); -1 on other files is 0",
        used: |c| each_profile(c, |p| p.format() == ProfileFormat::Simpack && p.mirror_y == -1, |p| format!("MIRRORY = {}", p.mirror_y)),
    },
    SceneLimit {
        name: "MIRRORY = -1 on a profile that is not a SIMPACK file",
        control: "MIRRORY",
        accepted: true,
        reason: "taken as 0 (as is), as CONTACT takes it: mirror_y = false",
        used: |c| each_profile(c, |p| p.format() != ProfileFormat::Simpack && p.mirror_y == -1, |p| format!("MIRRORY = {}", p.mirror_y)),
    },
    SceneLimit {
        name: "mirroring of a profile's z given",
        control: "MIRRORZ",
        accepted: true,
        reason: "carried as [rail] and [wheel] mirror_z = \"keep\" (-1) or \"mirror\" (1)",
        used: |c| each_profile(c, |p| p.mirror_z != 0, |p| format!("MIRRORZ = {}", p.mirror_z)),
    },
    SceneLimit {
        name: "the weighted smoothing B-spline",
        control: "ISMOOTH",
        accepted: false,
        reason: "supported: ISMOOTH = 0 (the smoothing spline, lambda = SMOOTH) and 1 (weighted by the points' spacing, SMOOTH its filter length); not CONTACT's B-spline with a third-order penalty (2)",
        used: |c| each_profile(c, |p| p.curation.is_some_and(|k| !matches!(k.ismooth, 0 | 1)), curation_value),
    },
    SceneLimit {
        name: "profile curation other than CONTACT's defaults",
        control: "PRFOPT, ISMOOTH, ZIGTHRS, KINKHIGH, KINKLOW, KINKWID, MAXOMIT",
        accepted: true,
        reason: "carried as [rail] and [wheel] smooth_weighted (ISMOOTH = 1), zig_zag_rad, kink_high_rad, kink_low_rad, kink_width_mm, max_omit; ERRHND (messages only) is not carried",
        used: |c| {
            each_profile(c, |p| p.curation.is_some_and(|k| matches!(k.ismooth, 0 | 1) && !default_curation(&k)), curation_value)
        },
    },
    SceneLimit {
        name: "profile curation repeating CONTACT's defaults",
        control: "PRFOPT",
        accepted: true,
        reason: "the project's profile stage uses these defaults; ERRHND (messages only) is not carried",
        used: |c| each_profile(c, |p| p.curation.is_some_and(|k| default_curation(&k)), curation_value),
    },
    SceneLimit {
        name: "an input group never given",
        control: "C3, D, E",
        accepted: false,
        reason: "each of POISS, GG (C3 = 2-4), DX, DS (D = 2-9), the track (Z = 1, 3), the wheelset position and velocity (E >= 2) in this or an earlier module-1 case: the scene carries no CONTACT default",
        used: missing,
    },
    SceneLimit {
        name: "the patch search's thresholds",
        control: "DQREL, A_SEP, D_SEP, D_COMB, D_TURN, G_MISS",
        accepted: true,
        reason: "A_SEP, D_SEP, D_COMB, D_TURN carried ([wheelrail] a_sep_rad, d_sep_mm, d_comb_mm, d_turn_mm; an A_SEP above pi as pi, which no two contact angles differ by): regions between D_COMB and D_SEP apart blended, separate patches up to D_TURN apart turned, as CONTACT does; G_MISS < 0 (no near misses; see the row below); DQREL is a transient step",
        used: |c| {
            let d = c.state.discretisation.as_ref()?;
            Some(format!(
                "DQREL, A_SEP, D_SEP, D_COMB, D_TURN, G_MISS = {}, {}, {}, {}, {}, {}",
                d.dqrel,
                d.a_sep_rad,
                d.d_sep_mm,
                d.d_comb_mm,
                d.d_turn_mm(),
                d.g_miss_mm
            ))
        },
    },
    SceneLimit {
        name: "the rigid slip on the actual surfaces beyond rolling and shifts of one material with the exact theory",
        control: "D, T, M, B, F",
        accepted: false,
        reason: "supported: D = 3 and 4 in steady rolling (T = 3), shifts (T = 1) and transient rolling (T = 2) with friction, the exact theory (M = 0, B = 0), one material, the pitch velocity given (F = 0) or found for a prescribed FX_WS (F = 1, not in transient rolling) or on a massless rail (F = 3): frictionless compression, simplified theories and dissimilar bodies with the rigid slip per element are not modelled (wheelrail::surface_slip)",
        used: |c| {
            let d = c.state.discretisation.as_ref()?;
            let m = c.state.material.as_ref();
            let dissimilar = m.is_some_and(|m| m.poiss[0] != m.poiss[1] || m.gg_mpa[0] != m.gg_mpa[1]);
            let other = !matches!(c.digits.t, 1..=3) || c.digits.m != 0 || c.digits.b != 0 || c.digits.f == 2 || dissimilar;
            (matches!(d.method, 3 | 4) && other).then(|| {
                format!("D = {} with T = {}, M = {}, B = {}, F = {}", d.method, c.digits.t, c.digits.m, c.digits.b, c.digits.f)
            })
        },
    },
    SceneLimit {
        name: "near misses",
        control: "G_MISS",
        accepted: false,
        reason: "supported: G_MISS < 0 (CONTACT's default, near misses ignored); patch bounds shifted towards near misses are not modelled",
        used: |c| {
            let d = c.state.discretisation.as_ref()?;
            (d.g_miss_mm >= 0.0).then(|| format!("G_MISS = {}", d.g_miss_mm))
        },
    },
    SceneLimit {
        name: "a gauge face other than the inner-most",
        control: "GAUGSQ",
        accepted: true,
        reason: "not carried: CONTACT reserves GAUGSQ and uses the inner-most face (user guide: n.y.a.), as the project",
        used: |c| match c.state.track?.placement {
            RailPlacement::Gauge { gaugsq, .. } if gaugsq != 0 => Some(format!("GAUGSQ = {gaugsq}")),
            _ => None,
        },
    },
    SceneLimit {
        name: "static friction other than kinetic friction",
        control: "FSTAT, FKIN",
        accepted: true,
        reason: "CONTACT's Coulomb law takes FSTAT (FKIN within 0.1 % of it): mu = FSTAT",
        used: |c| {
            let f = c.state.friction.as_ref()?;
            match f.sets.first()?.values {
                FrictionValues::Coulomb { fstat, fkin } if fstat != fkin => Some(format!("FSTAT = {fstat}, FKIN = {fkin}")),
                _ => None,
            }
        },
    },
    SceneLimit {
        name: "the wheelset's place along the track and its pitch angle",
        control: "S_WS, PITCH",
        accepted: true,
        reason: "not carried: one rail profile along the track and a wheel of revolution give the same contact at every S_WS and PITCH",
        used: |c| {
            let p = c.state.position?;
            let s = match p.along {
                Along::SMm(s) | Along::XMm(s) => s,
            };
            (s != 0.0 || p.pitch_rad != 0.0).then(|| format!("S_WS = {s}, PITCH = {}", p.pitch_rad))
        },
    },
];

fn gaught(p: &RailPlacement) -> f64 {
    match *p {
        RailPlacement::Gauge { gaught_mm, .. } | RailPlacement::Absolute { gaught_mm, .. } => gaught_mm,
    }
}

/// The value of the rail's and the wheel's profile where `uses` holds ("rail: …, wheel: …").
fn each_profile(
    c: &WheelRailCase,
    uses: impl Fn(&ProfileSpec) -> bool,
    value: impl Fn(&ProfileSpec) -> String,
) -> Option<String> {
    let pairs = [("rail", c.state.rail_profile.as_ref()), ("wheel", c.state.wheel_profile.as_ref())];
    let used: Vec<String> =
        pairs.iter().filter_map(|(side, p)| p.filter(|p| uses(p)).map(|p| format!("{} ({side})", value(p)))).collect();
    (!used.is_empty()).then(|| used.join(", "))
}

/// Whether a curation repeats CONTACT's defaults (angles within 1e-12 relative, as `90d` parses).
fn default_curation(k: &ProfileCuration) -> bool {
    let (ismooth, angles, max_omit) = CURATION_DEFAULT;
    let given = [k.zigthrs_rad, k.kinkhigh_rad, k.kinklow_rad, k.kinkwid_mm];
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
    k.ismooth == ismooth
        && given.iter().zip(angles).all(|(&a, b)| close(a, b))
        && k.errors.is_none_or(|(_, omit)| omit == max_omit)
}

fn curation_value(p: &ProfileSpec) -> String {
    match p.curation {
        Some(k) => format!(
            "PRFOPT = {}: ISMOOTH, ZIGTHRS, KINKHIGH, KINKLOW, KINKWID = {}, {}, {}, {}, {}{}",
            p.prfopt,
            k.ismooth,
            k.zigthrs_rad,
            k.kinkhigh_rad,
            k.kinklow_rad,
            k.kinkwid_mm,
            k.errors.map(|(e, m)| format!(", ERRHND, MAXOMIT = {e}, {m}")).unwrap_or_default()
        ),
        None => format!("PRFOPT = {}", p.prfopt),
    }
}

/// The groups the case has never been given, named.
fn missing(c: &WheelRailCase) -> Option<String> {
    let s = &c.state;
    let groups = [
        ("POISS, GG", s.material.is_none()),
        ("DX, DS", s.discretisation.is_none()),
        ("the track", s.track.is_none()),
        ("FBDIST, FBPOS, NOMRAD", s.wheelset.is_none()),
        ("the wheelset position", s.position.is_none()),
        ("the wheelset velocity", s.velocity.is_none()),
        ("the friction", s.friction.is_none()),
    ];
    let names: Vec<&str> = groups.iter().filter(|(_, m)| *m).map(|(n, _)| *n).collect();
    (!names.is_empty()).then(|| format!("never given: {}", names.join(", ")))
}

/// A case's refusals and notes, each `value: name (reason)` as module 3 names them.
pub fn assess(case: &WheelRailCase) -> (Vec<String>, Vec<String>) {
    let features = features::assess_wheelrail(case).into_iter().filter(|f| !REPLACED.contains(&f.feature));
    let limits = SCENE_LIMITS
        .iter()
        .filter_map(|l| (l.used)(case).map(|v| (l.accepted, format!("{v}: {} ({})", l.name, l.reason))));
    features::refused_and_notes(features.map(|f| (f.supported, f.to_string())).chain(limits))
}
