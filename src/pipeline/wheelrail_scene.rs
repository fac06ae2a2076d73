//! A wheel–rail scene through the stages: its profiles read once, each case (a row of its cases
//! table) solved by [`super::wheelrail::solve_with`] with every model the scene names, cases in
//! parallel (each alone, so the results do not depend on the thread count).

use super::wheelrail::{solve_with, CaseResult};
use super::wheelrail_fx::solve_fx;
use super::wheelrail_massless::solve_massless;
use super::wheelrail_shift::{solve_rolling_sequence, solve_sequence};
use crate::error::{Error, InputError};
use crate::problem::material_of_spec;
use crate::scene::wheelrail::{
    CaseRow, LongitudinalSpec, MotionSpec, PlacementSpec, ProfileSpec, SideSpec, VerticalSpec, WheelRailScene,
};
use crate::solvers;
use crate::wheelrail::friction::Friction;
use crate::wheelrail::oorwheel::WheelSlices;
use crate::wheelrail::patch::Separation;
use crate::wheelrail::profile::slices::{read_slices, Slices};
use crate::wheelrail::profile::{options::ProfileOptions, read::read_profile, Profile, ProfileKind};
use crate::wheelrail::rail::{RailPlacement, Track};
use crate::wheelrail::roller::Roller;
use crate::wheelrail::side::Side;
use crate::wheelrail::varrail::RailSlices;
use crate::wheelrail::wheel::{Pose, Velocity, WheelDeviation, WheelsetGeometry};
use crate::wheelrail::wheel_mesh::WheelSurface;
use crate::wheelrail::{Motion, Vertical, WheelRailCase};
use rayon::prelude::*;
use std::borrow::Cow;
use std::sync::Arc;

/// A scene's results: per case (in the table's order) its number and what it gave.
#[derive(Debug, Clone)]
pub struct SceneRun {
    pub name: String,
    pub models: Vec<String>,
    pub cases: Vec<(u64, CaseResult)>,
}

/// The scene's models, checked against the registry (built-in models only).
fn models(scene: &WheelRailScene) -> Result<Vec<String>, InputError> {
    for m in &scene.solvers {
        if solvers::builtin(m).is_none() {
            return Err(InputError::new(
                "solvers",
                format!("{m:?}"),
                format!("built-in models ({})", solvers::builtin_names().join(", ")),
            ));
        }
    }
    Ok(scene.solvers.clone())
}

/// The scene's rail: its profile and, where it varies along the track (a slices file), the
/// slices with `profile` their cross-section at the wheelset's S_WS `s_ws_mm` (where CONTACT
/// places the rail and makes the gap mesh: `m_wr_solvecp`, `varprof_intpol_xunif`).
#[derive(Debug, Clone)]
pub struct RailProfile {
    pub profile: Profile,
    pub slices: Option<Arc<Slices>>,
    /// The S_WS [mm] of `profile` on the slices (the scene's `[wheelrail] s_mm`, or a case's own).
    pub s_ws_mm: f64,
}

impl RailProfile {
    /// The rail of a case whose row gives its own S_WS (the cases' column `s_mm`) on a rail slices
    /// file: the cross-section there (CONTACT reads S_WS per case); else the scene's rail.
    pub fn of_case(&self, row: &CaseRow) -> Result<Cow<'_, RailProfile>, Error> {
        match (&self.slices, row.s_mm) {
            (Some(slices), Some(s_ws_mm)) if s_ws_mm != self.s_ws_mm => Ok(Cow::Owned(RailProfile {
                profile: slices.section_at(s_ws_mm)?,
                slices: Some(Arc::clone(slices)),
                s_ws_mm,
            })),
            _ => Ok(Cow::Borrowed(self)),
        }
    }
}

impl std::ops::Deref for RailProfile {
    type Target = Profile;
    fn deref(&self) -> &Profile {
        &self.profile
    }
}

/// The rail read as the scene says: a profile, or a slices file (`.slcs`) and its cross-section
/// at `s_ws_mm`.
fn rail_profile(spec: &ProfileSpec, s_ws_mm: f64) -> Result<RailProfile, Error> {
    if !spec.path.to_string_lossy().to_lowercase().ends_with(".slcs") {
        return Ok(RailProfile { profile: profile(spec, ProfileKind::Rail)?, slices: None, s_ws_mm });
    }
    let slices = read_slices(&spec.path, ProfileKind::Rail, &options(spec))?;
    let profile = slices.section_at(s_ws_mm)?;
    Ok(RailProfile { profile, slices: Some(Arc::new(slices)), s_ws_mm })
}

/// The scene's wheel: its profile and, where it is out of round (a wheel slices file, `.slcw`),
/// the slices with `profile` their first (the surface is the slices': `wheelrail::oorwheel`).
#[derive(Debug)]
pub struct WheelProfile {
    pub profile: Profile,
    pub slices: Option<Slices>,
}

impl std::ops::Deref for WheelProfile {
    type Target = Profile;
    fn deref(&self) -> &Profile {
        &self.profile
    }
}

/// The wheel read as the scene says: a profile, or a wheel slices file (`.slcw`).
fn wheel_profile(spec: &ProfileSpec) -> Result<WheelProfile, Error> {
    if !spec.path.to_string_lossy().to_lowercase().ends_with(".slcw") {
        return Ok(WheelProfile { profile: profile(spec, ProfileKind::Wheel)?, slices: None });
    }
    let slices = read_slices(&spec.path, ProfileKind::Wheel, &options(spec))?;
    let profile = slices.slice(0).clone();
    Ok(WheelProfile { profile, slices: Some(slices) })
}

/// CONTACT's profile options as the scene gives them.
fn options(spec: &ProfileSpec) -> ProfileOptions {
    ProfileOptions {
        mirror_y: i32::from(spec.mirror_y),
        mirror_z: i32::from(spec.mirror_z),
        scale: spec.scale,
        smooth: spec.smooth,
        ismooth: u8::from(spec.smooth_weighted),
        zig_thrs_rad: spec.zig_zag_rad,
        kink_high_rad: spec.kink_high_rad,
        kink_low_rad: spec.kink_low_rad,
        kink_wid_mm: spec.kink_width_mm,
        max_omit: spec.max_omit,
    }
}

/// A profile file read as the scene says.
fn profile(spec: &ProfileSpec, kind: ProfileKind) -> Result<Profile, Error> {
    Ok(read_profile(&spec.path, kind, &options(spec))?)
}

/// Read the scene's profiles and check its models: everything that can fail on input, before
/// any case runs.
pub fn prepare(scene: &WheelRailScene) -> Result<(RailProfile, WheelProfile, Vec<String>), Error> {
    let rail = rail_profile(&scene.rail, scene.s_ws_mm)?;
    let wheel = wheel_profile(&scene.wheel)?;
    Ok((rail, wheel, models(scene)?))
}

/// Solve every case of the scene (a sequence of shifts in order, each continuing the one before).
pub fn run_scene(scene: &WheelRailScene) -> Result<SceneRun, Error> {
    let (rail, wheel, models) = prepare(scene)?;
    let material = material_of_spec(&scene.material)?;
    if let MotionSpec::Shift { sequence: true, steady_start, .. } = scene.motion {
        let positions = scene.shift_positions_mm().unwrap_or_default();
        let friction =
            Friction { mu: scene.mu, variation: scene.mu_variation.as_ref(), frictionless: scene.frictionless };
        let rails = rails_of_cases(scene, &rail)?;
        let cases = scene.cases.iter().zip(&rails).zip(positions);
        let cases = cases.map(|((row, rail), s)| (case_of(scene, row, rail, &wheel, material), s));
        let on_error = |k: usize, e| in_case(&scene.name, &scene.cases[k], e);
        let results = solve_sequence(cases, steady_start, &models, &friction, on_error)?;
        let cases = scene.cases.iter().map(|r| r.contact_case).zip(results).collect();
        return Ok(SceneRun { name: scene.name.clone(), models, cases });
    }
    if let MotionSpec::RollingSequence { dq_rel, from_rest } = scene.motion {
        let friction =
            Friction { mu: scene.mu, variation: scene.mu_variation.as_ref(), frictionless: scene.frictionless };
        let rails = rails_of_cases(scene, &rail)?;
        let cases = scene.cases.iter().zip(&rails).map(|(row, rail)| case_of(scene, row, rail, &wheel, material));
        let dq_mm = dq_rel * scene.dx_mm;
        let on_error = |k: usize, e| in_case(&scene.name, &scene.cases[k], e);
        let results = solve_rolling_sequence(cases, (dq_mm, from_rest), &models, &friction, on_error)?;
        let cases = scene.cases.iter().map(|r| r.contact_case).zip(results).collect();
        return Ok(SceneRun { name: scene.name.clone(), models, cases });
    }
    // Every case's outcome in the table's order, so that a failure names the first failing case
    // whatever the threads' timing (rayon's collect into a Result keeps whichever failed first).
    let outcomes: Vec<Result<_, Error>> = scene
        .cases
        .par_iter()
        .map(|row| {
            let rail = rail.of_case(row).map_err(|e| in_case(&scene.name, row, e))?;
            let case = case_of(scene, row, &rail, &wheel, material);
            let friction =
                Friction { mu: scene.mu, variation: scene.mu_variation.as_ref(), frictionless: scene.frictionless };
            let solved = match (scene.longitudinal, &scene.massless_rail) {
                (_, Some(rail)) => solve_massless(&case, &models, &friction, rail),
                (LongitudinalSpec::Velocity, None) => solve_with(&case, &models, &friction),
                (LongitudinalSpec::Force, None) => solve_fx(&case, &models, &friction, row.velocity[5]),
            };
            solved.map(|r| (row.contact_case, r)).map_err(|e| in_case(&scene.name, row, e))
        })
        .collect();
    let cases = outcomes.into_iter().collect::<Result<Vec<_>, _>>()?;
    Ok(SceneRun { name: scene.name.clone(), models, cases })
}

/// Each case's rail ([`RailProfile::of_case`]), in the table's order.
fn rails_of_cases<'a>(scene: &WheelRailScene, rail: &'a RailProfile) -> Result<Vec<Cow<'a, RailProfile>>, Error> {
    scene.cases.iter().map(|row| rail.of_case(row).map_err(|e| in_case(&scene.name, row, e))).collect()
}

/// An error of one case, naming it.
fn in_case(scene: &str, row: &CaseRow, e: Error) -> Error {
    match e {
        Error::Input(i) => {
            let field = format!("scene {scene}, case {} (y_mm = {}): {}", row.contact_case, row.y_mm, i.field);
            InputError::new(field, i.value, i.allowed).into()
        }
        other => other,
    }
}

/// The stage's input for one row of the scene; with FX_WS given (its last velocity), VPITCH is
/// the first estimate of its search: −VS / NOMRAD.
pub fn case_of<'a>(
    s: &WheelRailScene,
    row: &CaseRow,
    rail: &'a RailProfile,
    wheel: &'a WheelProfile,
    material: crate::physics::Material,
) -> WheelRailCase<'a> {
    let [vs, vy, vz, vroll, vyaw, sixth] = row.velocity;
    let vpitch = match s.longitudinal {
        LongitudinalSpec::Velocity => sixth,
        LongitudinalSpec::Force => -vs / s.nominal_radius_mm,
    };
    // The rail's deviations are given in the track's frame, as the wheelset's: mirrored on the left.
    let m = if s.side == SideSpec::Left { -1.0 } else { 1.0 };
    let ([dy, dz, droll], [vy_r, vz_r, vroll_r]) = (s.rail_deviation.position, s.rail_deviation.velocity);
    let (vertical, z_mm) = match s.vertical {
        VerticalSpec::Force => (Vertical::Force { fz_n: row.vertical }, 0.0),
        VerticalSpec::Position => (Vertical::Position, row.vertical),
    };
    WheelRailCase {
        side: match s.side {
            SideSpec::Left => Side::Left,
            SideSpec::Right => Side::Right,
        },
        rail: &rail.profile,
        wheel: &wheel.profile,
        track: Track {
            placement: match s.placement {
                PlacementSpec::Gauge { height_mm, width_mm } => RailPlacement::Gauge { height_mm, width_mm },
                // RAILY0 is the track's y on either side (CONTACT's `wr_set_rail_marker`: the rail at
                // sgn·RAILY0 in the side's frame), not the side's own: a left wheel meets a rail
                // placed at RAILY0 < 0 (issue 45).
                PlacementSpec::Absolute { y_mm, z_mm } => RailPlacement::Absolute { y_mm: m * y_mm, z_mm },
            },
            cant_rad: s.cant_rad,
            deviation_mm_rad: [m * dy, dz, m * droll],
            deviation_velocity: [m * vy_r, vz_r, m * vroll_r],
        },
        wheelset: WheelsetGeometry {
            flange_back_distance_mm: s.flange_back_distance_mm,
            flange_back_position_mm: s.flange_back_position_mm,
            nominal_radius_mm: s.nominal_radius_mm,
            deviation: WheelDeviation { position: s.wheel_deviation.position, velocity: s.wheel_deviation.velocity },
        },
        pose: Pose { y_mm: row.y_mm, z_mm, roll_rad: row.roll_rad, yaw_rad: row.yaw_rad },
        velocity: Velocity {
            vs_mm_s: vs,
            vy_mm_s: vy,
            vz_mm_s: vz,
            vroll_rad_s: vroll,
            vyaw_rad_s: vyaw,
            vpitch_rad_s: vpitch,
        },
        vertical,
        dx_mm: s.dx_mm,
        ds_mm: s.ds_mm,
        separation: Separation {
            angle_rad: s.a_sep_rad,
            distance_mm: s.d_sep_mm,
            combine_mm: s.d_comb_mm,
            turn_mm: s.d_turn_mm,
        },
        wheel_surface: if s.wheel_mesh { WheelSurface::ContactMesh } else { WheelSurface::Exact },
        search: s.search,
        approach: s.approach,
        material,
        heat: s.material.heat,
        tangential: s.tangential,
        motion: match s.motion {
            MotionSpec::Rolling | MotionSpec::RollingSequence { .. } => Motion::Rolling,
            MotionSpec::Shift { s_ws_mm, .. } => Motion::Shift { s_ws_mm: row.s_mm.unwrap_or(s_ws_mm) },
        },
        previous: None,
        rail_slices: rail.slices.as_deref().map(|slices| RailSlices { slices, s_ws_mm: rail.s_ws_mm }),
        wheel_slices: wheel.slices.as_ref().map(|slices| WheelSlices { slices, pitch_rad: row.pitch_rad }),
        roller: s.roller.map(|r| Roller { radius_mm: r.radius_mm, vpitch_rad_s: r.vpitch_rad_s }),
    }
}
