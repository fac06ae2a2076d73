//! A wheel–rail scene as its files (docs/scene-format.md, "A wheel–rail scene"): the scene TOML
//! and its cases table `<name>_cases.csv`, one row per CONTACT case. Every scene is read back with
//! the project's reader ([`WheelRailScene::from_toml`]) in a temporary folder before anything is
//! written, and must give the scene it was written from, every value equal.

use super::super::read_back::tempdir_for;
use crate::error::InputError;
use crate::scene::wheelrail::{
    case_columns, case_columns_with_pitch, case_columns_with_positions, Approach, CaseRow, ContactSearch,
    LongitudinalSpec, MotionSpec, MuBy, PlacementSpec, ProfileSpec, SideSpec, VerticalSpec, WheelRailScene,
};
use crate::scene::wheelrail_profile::{MIRROR_Z, PROFILE_DEFAULTS};
use std::fmt::Write;
use std::path::{Path, PathBuf};
use toml::Value;

/// The scene's files (name, contents), the scene file first; its profile paths are written as
/// the scene holds them (relative to the scene's folder).
pub(super) fn files(scene: &WheelRailScene, deck: &str) -> Result<Vec<(String, String)>, InputError> {
    let csv_name = format!("{}_cases.csv", scene.name);
    let [first, last] = scene.origin.as_ref().map_or([0, 0], |o| o.cases);
    let mut text = format!("# Imported by `creepbench import contact` from {deck}, cases {first} to {last}.\n");
    for (section, pairs) in document(scene, &csv_name)? {
        if let Some(name) = section {
            let _ = writeln!(text, "\n[{name}]");
        }
        for (key, value) in pairs {
            let _ = writeln!(text, "{key} = {value}");
        }
    }
    Ok(vec![
        (format!("{}.toml", scene.name), text),
        (csv_name, cases_csv(scene.vertical, scene.longitudinal, &scene.cases)),
    ])
}

/// A section's keys and values in the order they are written.
type Pairs = Vec<(&'static str, Value)>;

/// The scene's sections in the order of docs/scene-format.md (`None`: the top level).
fn document(s: &WheelRailScene, csv_name: &str) -> Result<Vec<(Option<&'static str>, Pairs)>, InputError> {
    let solvers = Value::Array(s.solvers.iter().map(|m| Value::String(m.clone())).collect());
    let side = if s.side == SideSpec::Left { "left" } else { "right" };
    let mut wheelrail = vec![("side", Value::String(side.into()))];
    wheelrail.extend(friction(s));
    wheelrail.extend([
        ("dx_mm", Value::Float(s.dx_mm)),
        ("ds_mm", Value::Float(s.ds_mm)),
        ("a_sep_rad", Value::Float(s.a_sep_rad)),
        ("d_sep_mm", Value::Float(s.d_sep_mm)),
        ("d_comb_mm", Value::Float(s.d_comb_mm)),
        ("d_turn_mm", Value::Float(s.d_turn_mm)),
    ]);
    if s.wheel_mesh {
        wheelrail.push(("wheel_surface", Value::String("contact_mesh".into())));
    }
    match s.search {
        ContactSearch::Locus => {}
        ContactSearch::Grid => wheelrail.push(("contact_search", Value::String("grid".into()))),
        ContactSearch::GridSteep => wheelrail.push(("contact_search", Value::String("grid_steep".into()))),
    }
    match s.approach {
        Approach::Planar => {}
        Approach::PlanarSurfaceSlip => wheelrail.push(("approach", Value::String("planar_surface_slip".into()))),
        Approach::Conformal => wheelrail.push(("approach", Value::String("conformal".into()))),
    }
    if s.frictionless {
        wheelrail.push(("frictionless", Value::Boolean(true)));
    }
    if let MotionSpec::Shift { s_ws_mm, sequence, steady_start } = s.motion {
        let motion = if sequence { "shift_sequence" } else { "shift" };
        wheelrail.push(("motion", Value::String(motion.into())));
        if steady_start {
            wheelrail.push(("start", Value::String("steady".into())));
        }
        // With mu_by = "track_s" the friction's s_mm is the same position, written once; with
        // the cases' positions, the table's column gives it.
        let by_track = matches!(s.mu_variation.as_ref().map(|v| v.by), Some(MuBy::TrackS { .. }));
        if !by_track && s.cases.iter().all(|r| r.s_mm.is_none()) {
            wheelrail.push(("s_mm", Value::Float(s_ws_mm)));
        }
    }
    let s_written = matches!(s.motion, MotionSpec::Shift { .. })
        || matches!(s.mu_variation.as_ref().map(|v| v.by), Some(MuBy::TrackS { .. }));
    if !s_written && s.s_ws_mm != 0.0 {
        // A rail slices file: where the wheelset stands on it.
        wheelrail.push(("s_mm", Value::Float(s.s_ws_mm)));
    }
    if let MotionSpec::RollingSequence { dq_rel, from_rest } = s.motion {
        wheelrail.push(("motion", Value::String("rolling_sequence".into())));
        wheelrail.push(("dq_rel", Value::Float(dq_rel)));
        if from_rest {
            wheelrail.push(("start", Value::String("rest".into())));
        }
    }
    let mut rail = profile(&s.rail, &s.name)?;
    match s.placement {
        PlacementSpec::Gauge { height_mm, width_mm } => {
            rail.push(("gauge_height_mm", Value::Float(height_mm)));
            rail.push(("gauge_width_mm", Value::Float(width_mm)));
        }
        PlacementSpec::Absolute { y_mm, z_mm } => {
            rail.push(("y_mm", Value::Float(y_mm)));
            rail.push(("z_mm", Value::Float(z_mm)));
        }
    }
    match s.roller {
        Some(r) => {
            rail.push(("roller_radius_mm", Value::Float(r.radius_mm)));
            rail.push(("roller_vpitch_rad_s", Value::Float(r.vpitch_rad_s)));
        }
        None => rail.push(("cant_rad", Value::Float(s.cant_rad))),
    }
    rail.extend(rail_deviation(s));
    let mut wheel = profile(&s.wheel, &s.name)?;
    wheel.push(("flange_back_distance_mm", Value::Float(s.flange_back_distance_mm)));
    wheel.push(("flange_back_position_mm", Value::Float(s.flange_back_position_mm)));
    wheel.push(("nominal_radius_mm", Value::Float(s.nominal_radius_mm)));
    wheel.extend(wheel_deviation(s));
    let vertical = if s.vertical == VerticalSpec::Force { "force" } else { "position" };
    let mut cases = vec![("vertical", Value::String(vertical.into()))];
    if s.longitudinal == LongitudinalSpec::Force {
        cases.push(("longitudinal", Value::String("force".into())));
    }
    cases.push(("file", Value::String(csv_name.into())));
    let mut out = vec![
        (None, vec![("name", Value::String(s.name.clone())), ("solvers", solvers)]),
        (Some("wheelrail"), wheelrail),
        (Some("rail"), rail),
        (Some("wheel"), wheel),
        (Some("material"), material(s)?),
    ];
    out.extend(super::heat::friction_pairs(s).map(|p| (Some("friction"), p)));
    out.extend(super::heat::contact_solver_pairs(s).map(|p| (Some("contact_solver"), p)));
    out.push((Some("cases"), cases));
    if let Some(m) = &s.massless_rail {
        let massless = vec![
            ("ky_n_per_mm", Value::Float(m.ky_n_per_mm)),
            ("fy_n", Value::Float(m.fy_n)),
            ("kz_n_per_mm", Value::Float(m.kz_n_per_mm)),
            ("fz_n", Value::Float(m.fz_n)),
            ("dy_step_mm", Value::Float(m.dy_step_mm)),
        ];
        out.push((Some("massless_rail"), massless));
    }
    if let Some(o) = &s.origin {
        let numbers = Value::Array(o.cases.iter().map(|&n| Value::Integer(n as i64)).collect());
        out.push((Some("origin"), vec![("file", Value::String(o.file.clone())), ("cases", numbers)]));
    }
    Ok(out)
}

/// `mu`, or `mu_by`, `mu_at`, `mu_values` (the temperature law's parameters per point: the
/// `*_values` keys; and `s_mm`) of a variation.
fn friction(s: &WheelRailScene) -> Pairs {
    let Some(v) = &s.mu_variation else { return vec![("mu", Value::Float(s.mu))] };
    let floats = |x: &[f64]| Value::Array(x.iter().map(|&f| Value::Float(f)).collect());
    let by = match v.by {
        MuBy::ContactAngle => "contact_angle",
        MuBy::TrackS { .. } => "track_s",
    };
    let mut out = vec![("mu_by", Value::String(by.into())), ("mu_at", floats(&v.at)), ("mu_values", floats(&v.values))];
    if let Some([tref, dfheat, dtheat]) = &v.temperature {
        out.extend([
            ("tref_c_values", floats(tref)),
            ("dfheat_values", floats(dfheat)),
            ("dtheat_c_values", floats(dtheat)),
        ]);
    }
    if let MuBy::TrackS { s_mm } = v.by {
        out.push(("s_mm", Value::Float(s_mm)));
    }
    out
}

/// The rail's deviation keys where they are not 0.
fn rail_deviation(s: &WheelRailScene) -> Pairs {
    const KEYS: [&str; 6] = [
        "deviation_y_mm",
        "deviation_z_mm",
        "deviation_roll_rad",
        "deviation_vy_mm_s",
        "deviation_vz_mm_s",
        "deviation_vroll_rad_s",
    ];
    let d = s.rail_deviation;
    nonzero(&KEYS, d.position.into_iter().chain(d.velocity))
}

/// The wheel's deviation keys where they are not 0.
fn wheel_deviation(s: &WheelRailScene) -> Pairs {
    const KEYS: [&str; 12] = [
        "deviation_x_mm",
        "deviation_y_mm",
        "deviation_z_mm",
        "deviation_roll_rad",
        "deviation_yaw_rad",
        "deviation_pitch_rad",
        "deviation_vx_mm_s",
        "deviation_vy_mm_s",
        "deviation_vz_mm_s",
        "deviation_vroll_rad_s",
        "deviation_vyaw_rad_s",
        "deviation_vpitch_rad_s",
    ];
    let d = s.wheel_deviation;
    nonzero(&KEYS, d.position.into_iter().chain(d.velocity))
}

/// The keys `keys` with their `values`, those that are not 0.
fn nonzero(keys: &[&'static str], values: impl Iterator<Item = f64>) -> Pairs {
    keys.iter().zip(values).filter(|(_, v)| *v != 0.0).map(|(k, v)| (*k, Value::Float(v))).collect()
}

/// A profile's keys: its path (as the scene holds it), mirror_y, scale, smooth; mirror_z,
/// smooth_weighted and the cleaning's keys where they are not CONTACT's defaults.
fn profile(p: &ProfileSpec, scene: &str) -> Result<Pairs, InputError> {
    let path = p.path.to_str().ok_or_else(|| InputError::new(scene, p.path.display(), "a UTF-8 profile path"))?;
    let mut out = vec![
        ("profile", Value::String(path.into())),
        ("mirror_y", Value::Boolean(p.mirror_y)),
        ("scale", Value::Float(p.scale)),
        ("smooth", Value::Float(p.smooth)),
    ];
    if let Some((name, _)) = MIRROR_Z.iter().find(|(_, v)| *v == p.mirror_z && *v != 0) {
        out.push(("mirror_z", Value::String((*name).into())));
    }
    if p.smooth_weighted {
        out.push(("smooth_weighted", Value::Boolean(true)));
    }
    let given = [p.zig_zag_rad, p.kink_high_rad, p.kink_low_rad, p.kink_width_mm, p.max_omit];
    let keys = ["zig_zag_rad", "kink_high_rad", "kink_low_rad", "kink_width_mm", "max_omit"];
    for ((key, v), default) in keys.into_iter().zip(given).zip(PROFILE_DEFAULTS) {
        if v != default {
            out.push((key, Value::Float(v)));
        }
    }
    Ok(out)
}

/// `[material]`: the combined G and ν, the bodies' thermal constants where the scene has them.
fn material(s: &WheelRailScene) -> Result<Pairs, InputError> {
    let g = s.material.g_mpa.ok_or_else(|| InputError::new(&s.name, "no g_mpa", "the combined shear modulus"))?;
    let mut out = vec![("g_mpa", Value::Float(g)), ("poisson", Value::Float(s.material.poisson))];
    if let Some(b) = s.material.blanco {
        out.push(("blanco_variant", Value::Integer(i64::from(b.variant))));
        let inclination = match b.inclination {
            crate::physics::halfspace::blanco::Inclination::Linear => "linear",
            crate::physics::halfspace::blanco::Inclination::Interpolated => "interpolated",
        };
        out.push(("blanco_inclination", Value::String(inclination.into())));
    }
    if s.material.sheet_mm3_per_n > 0.0 {
        out.push(("sheet_flexibility_mm3_per_n", Value::Float(s.material.sheet_mm3_per_n)));
    }
    out.extend(super::heat::material_pairs(s));
    Ok(out)
}

/// The cases table: the reader's columns ([`case_columns`]), one row per case, every value in
/// the shortest form that reads back to the same number.
fn cases_csv(vertical: VerticalSpec, longitudinal: LongitudinalSpec, rows: &[CaseRow]) -> String {
    let positions = rows.iter().all(|r| r.s_mm.is_some());
    // The pitch where a case has one (an out-of-round wheel), last.
    let pitches = !positions && rows.iter().any(|r| r.pitch_rad != 0.0);
    let columns = match (positions, pitches) {
        (true, _) => case_columns_with_positions(vertical, longitudinal),
        (false, true) => case_columns_with_pitch(vertical, longitudinal),
        (false, false) => case_columns(vertical, longitudinal),
    };
    let mut out = columns.join(",");
    out.push('\n');
    for r in rows {
        let s = r.s_mm.filter(|_| positions);
        let pitch = Some(r.pitch_rad).filter(|_| pitches);
        let values = s.into_iter().chain([r.y_mm, r.vertical, r.roll_rad, r.yaw_rad]).chain(r.velocity).chain(pitch);
        let _ = write!(out, "{}", r.contact_case);
        for v in values {
            let _ = write!(out, ",{v:?}");
        }
        out.push('\n');
    }
    out
}

/// Write `files` in a temporary folder, read the scene back with the project's reader and compare
/// it with `scene` (its folder and profile paths taken as relative to the scene file).
pub(super) fn read_back(scene: &WheelRailScene, files: &[(String, String)], place: &str) -> Result<(), InputError> {
    let dir = tempdir_for(place)?;
    let io = |e: std::io::Error| InputError::new(place, "a temporary folder", format!("writable: {e}"));
    for (name, contents) in files {
        std::fs::write(dir.path().join(name), contents).map_err(io)?;
    }
    let mut back = WheelRailScene::from_toml(&files[0].1, dir.path())?;
    let local = |p: &Path| p.strip_prefix(dir.path()).map(Path::to_path_buf).unwrap_or_else(|_| p.to_path_buf());
    back.rail.path = local(&back.rail.path);
    back.wheel.path = local(&back.wheel.path);
    back.dir = PathBuf::new();
    if back == *scene {
        return Ok(());
    }
    Err(InputError::new(place, format!("{back:?}"), format!("the scene read back as it was written: {scene:?}")))
}
