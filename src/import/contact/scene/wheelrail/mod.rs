//! Module-1 cases → wheel–rail scenes (docs/scene-format.md, "A wheel–rail scene"; CONTACT's
//! user guide, Chapter 3 "Module 1: wheel/rail contact"). Each case is assessed ([`limits`]); the
//! supported ones become a one-row scene each ([`case_scene`]): the side (C), the profiles and
//! their options, the track, the wheelset's dimensions, the material (POISS, GG combined as module 3
//! combines them), Coulomb's mu = FSTAT, DX, DS and the vertical problem (N), the row its position
//! and velocities. Consecutive cases whose one-row scenes agree but for the row (steady cases on a
//! rail slices file: and for S_WS, then each row's column `s_mm`) are one scene
//! (`<deck>_<first case>`, its rows in `<name>_cases.csv`, `[origin]` the deck and its first and
//! last case), written ([`write`]) and read back before anything is written.

mod heat;
mod limits;
mod paths;
mod write;

pub use limits::{SceneLimit, SCENE_LIMITS};
pub use paths::ProfilePaths;

use super::super::deck::{Case, CaseKind};
use super::super::wheelrail_deck::{
    Along, Forward, Friction, FrictionValues, FrictionVariation, PitchInput, ProfileCuration, ProfileFormat,
    RailPlacement, Side, TrackFourth, Vertical, WheelRailCase, WheelRailState,
};
use super::super::CaseStatus;
use super::{scene_name, SceneFiles};
use crate::physics::material::combine_bodies;
use crate::scene::wheelrail::{
    Approach, CaseRow, ContactSearch, LongitudinalSpec, MotionSpec, MuBy, MuVariation, PlacementSpec, ProfileSpec,
    RailDeviationSpec, SideSpec, VerticalSpec, WheelDeviationSpec, WheelRailScene,
};
use crate::scene::wheelrail_massless::MasslessRailSpec;
use crate::scene::wheelrail_profile::{RollerSpec, PROFILE_DEFAULTS};
use crate::scene::{MaterialSpec, Origin};
use crate::wheelrail::profile::slices::check_slices_file;
use crate::wheelrail::profile::ProfileKind;
use std::path::PathBuf;

/// A module-1 case's refusals and notes ([`limits::assess`]).
pub(super) fn assess(case: &WheelRailCase) -> (Vec<String>, Vec<String>) {
    limits::assess(case)
}

/// A supported module-1 case as a one-row scene: its index into the deck's cases, number and scene.
struct Member {
    k: usize,
    number: usize,
    scene: WheelRailScene,
    /// The case's S_WS [mm] (0 when never given).
    s_ws_mm: f64,
}

/// The wheel–rail scenes of the deck's supported module-1 cases; a case whose scene cannot be
/// made or read back has the reason added to its status.
pub(super) fn scenes(
    file: &str,
    stem: &str,
    cases: &[Case],
    statuses: &mut [CaseStatus],
    paths: &ProfilePaths,
) -> Vec<SceneFiles> {
    let mut members = Vec::new();
    for (k, c) in cases.iter().enumerate() {
        let CaseKind::Module1(wr) = &c.kind else { continue };
        if !statuses[k].supported() {
            continue;
        }
        match case_scene(wr, paths) {
            Ok(scene) => members.push(Member { k, number: c.number, scene, s_ws_mm: s_ws_of(&wr.state) }),
            Err(why) => statuses[k].refused.push(why),
        }
    }
    let (grouped, refused) = groups(members);
    for (k, why) in refused {
        statuses[k].refused.push(why);
    }
    let mut out = Vec::new();
    for group in grouped {
        let ks: Vec<usize> = group.iter().map(|m| m.k).collect();
        match build(file, stem, group) {
            Ok(s) => {
                for &k in &ks {
                    statuses[k].scene = Some(s.name.clone());
                }
                out.push(s);
            }
            Err((span, e)) => {
                for &k in &ks {
                    statuses[k].refused.push(format!("the project refuses the scene of {span}: {e}"));
                }
            }
        }
    }
    out
}

/// The cases whose scenes agree but for their rows, each group in the deck's order. Steady cases
/// do not depend on one another, so a deck that alternates the left and the right wheel (CONTACT's
/// performance decks) makes one scene per wheel; a case joins an earlier group only where every
/// case between them is supported (a scene's `[origin]` range holds no case refused). A shift that
/// continues the case before (T = 1, P = 0) joins that case's group, which becomes a sequence of
/// shifts starting from it ([`continues`]); one it cannot join is refused, `(index, why)`.
fn groups(members: Vec<Member>) -> (Vec<Vec<Member>>, Vec<(usize, String)>) {
    let continued: std::collections::BTreeSet<usize> =
        members.iter().filter(|m| is_continued(&m.scene)).map(|m| m.number - 1).collect();
    let mut out: Vec<Vec<Member>> = Vec::new();
    let mut refused = Vec::new();
    let mut supported = std::collections::BTreeSet::new();
    for m in members {
        if is_continued(&m.scene) {
            match out.last_mut().map(|g| continues(g, &m)) {
                Some(Ok(())) => {
                    let g = out.last_mut().expect("the group continued");
                    let s0_mm = g[0].s_ws_mm;
                    match (&mut g[0].scene.motion, m.scene.motion) {
                        (MotionSpec::Shift { sequence, .. }, _) => *sequence = true,
                        (first @ MotionSpec::Rolling, MotionSpec::Shift { .. }) => {
                            *first = MotionSpec::Shift { s_ws_mm: s0_mm, sequence: true, steady_start: true }
                        }
                        (MotionSpec::RollingSequence { from_rest: true, .. }, _) => {}
                        (first, rolling @ MotionSpec::RollingSequence { .. }) => *first = rolling,
                        _ => {}
                    }
                    supported.insert(m.number);
                    g.push(m);
                }
                Some(Err(why)) => refused.push((m.k, why)),
                None => refused.push((m.k, "T = 1, P = 0 without a shift before it in the deck".to_string())),
            }
            continue;
        }
        let joins = |g: &&mut Vec<Member>| {
            let last = g[g.len() - 1].number;
            let agrees = same_but_rows(&g[0].scene, &m.scene) || same_but_position(&g[0].scene, &m.scene);
            agrees && (last + 1..m.number).all(|n| supported.contains(&n))
        };
        // A shift the next case continues starts its own scene (a sequence of its own).
        let group = if continued.contains(&m.number) { None } else { out.iter_mut().rev().find(joins) };
        supported.insert(m.number);
        match group {
            Some(g) => g.push(m),
            None => out.push(vec![m]),
        }
    }
    (out, refused)
}

/// Whether a one-row scene continues the case before: a shift (T = 1, P = 0) or a transient
/// rolling step (T = 2, P = 0; the import refuses T = 2 otherwise).
fn is_continued(s: &WheelRailScene) -> bool {
    matches!(s.motion, MotionSpec::Shift { sequence: true, .. } | MotionSpec::RollingSequence { from_rest: false, .. })
}

/// Whether the shift `m` (P = 0) continues group `g`: `g` ends with the case just before it, starts
/// with a shift from rest followed by shifts continuing it only, and agrees with `m` but for the
/// rows (S_WS is the row's: [`build`] writes each case's where the shifts do not give it).
fn continues(g: &[Member], m: &Member) -> Result<(), String> {
    let last = &g[g.len() - 1];
    let refuse = |why: &str| Err(format!("T = 1, P = 0: a shift continuing the case before it: {why}"));
    if last.number + 1 != m.number {
        return refuse(&format!("case {} before it is not imported", m.number - 1));
    }
    if let MotionSpec::RollingSequence { .. } = m.scene.motion {
        return continues_rolling(g, m);
    }
    if let (MotionSpec::Rolling, 1) = (g[0].scene.motion, g.len()) {
        return continues_steady(g, m);
    }
    let MotionSpec::Shift { .. } = g[0].scene.motion else {
        return refuse(&format!("case {} before it is not a shift (T = 1) or steady rolling (T = 3)", last.number));
    };
    // A group's first case is a shift from rest (a continuing case only ever joins a group);
    // several cases with the first not yet a sequence are shifts from rest each.
    if g.len() > 1 && !is_continued(&g[0].scene) {
        return refuse(&format!("the scene of case {} holds shifts from rest", last.number));
    }
    if !matches!(m.scene.motion, MotionSpec::Shift { .. }) {
        return refuse("not a shift");
    }
    if !same_but_motion(&g[0].scene, &m.scene) {
        return refuse(&format!("it changes more than the position and the shifts of case {}", last.number));
    }
    Ok(())
}

/// Whether the shift `m` (T = 1, P = 0) continues the steady case (T = 3) that is group `g`: the
/// case just before it, agreeing with `m` but for the row and the motion (S_WS is the row's, as
/// in [`continues`]).
fn continues_steady(g: &[Member], m: &Member) -> Result<(), String> {
    let first = &g[0];
    let refuse = |why: &str| Err(format!("T = 1, P = 0: a shift continuing the steady case before it: {why}"));
    if !matches!(m.scene.motion, MotionSpec::Shift { .. }) {
        return refuse("not a shift");
    }
    if !same_but_motion(&first.scene, &m.scene) {
        return refuse(&format!("it changes more than the wheelset's position and velocity of case {}", first.number));
    }
    Ok(())
}

/// Whether the transient rolling step `m` (T = 2, P = 0) continues group `g`: `g` ends with the
/// case just before it and starts with a steady case (T = 3) or a transient step from rest (T = 2,
/// P = 2) followed by transient steps only, and agrees with `m` but for the rows and the motion.
fn continues_rolling(g: &[Member], m: &Member) -> Result<(), String> {
    let last = &g[g.len() - 1];
    let refuse = |why: &str| Err(format!("T = 2, P = 0: transient rolling continuing the case before it: {why}"));
    if last.number + 1 != m.number {
        return refuse(&format!("case {} before it is not imported", m.number - 1));
    }
    match g[0].scene.motion {
        MotionSpec::Rolling if g.len() == 1 => {}
        MotionSpec::RollingSequence { .. } => {}
        _ => {
            let why =
                format!("the scene of case {} is not steady rolling (T = 3) or T = 2 followed by T = 2", last.number);
            return refuse(&why);
        }
    }
    if !same_but_motion(&g[0].scene, &m.scene) {
        return refuse(&format!("it changes more than the wheelset's position and velocity of case {}", last.number));
    }
    Ok(())
}

/// Whether a continuing case's scene `b` agrees with its group's first `a` but for its rows, its
/// motion and the wheelset's position along the track (S_WS, each case's own).
fn same_but_motion(a: &WheelRailScene, b: &WheelRailScene) -> bool {
    WheelRailScene { cases: b.cases.clone(), motion: b.motion, s_ws_mm: b.s_ws_mm, ..a.clone() } == *b
}

/// Whether two steady one-row scenes on a rail slices file agree but for their rows and the
/// wheelset's position along the track (S_WS, each case's own: the cases' column `s_mm`, which
/// `[wheelrail] s_mm` and μ along the track exclude; `testbank/examples_s+c/mbench_intrup`).
fn same_but_position(a: &WheelRailScene, b: &WheelRailScene) -> bool {
    let on_slices = |s: &WheelRailScene| s.rail.path.to_string_lossy().to_lowercase().ends_with(".slcs");
    let track_mu = |s: &WheelRailScene| s.mu_variation.as_ref().is_some_and(|v| matches!(v.by, MuBy::TrackS { .. }));
    let steady = |s: &WheelRailScene| s.motion == MotionSpec::Rolling && on_slices(s) && !track_mu(s);
    steady(a) && steady(b) && same_but_rows(&WheelRailScene { s_ws_mm: b.s_ws_mm, ..a.clone() }, b)
}

/// Whether two one-row scenes agree but for their rows.
fn same_but_rows(a: &WheelRailScene, b: &WheelRailScene) -> bool {
    WheelRailScene { cases: b.cases.clone(), ..a.clone() } == *b
}

/// The scene of a group: its name, rows and `[origin]`, written and read back; or the group's
/// span and why not.
fn build(file: &str, stem: &str, group: Vec<Member>) -> Result<SceneFiles, (String, crate::error::InputError)> {
    let numbers = [group[0].number, group[group.len() - 1].number];
    let span = format!("cases {} to {}", numbers[0], numbers[1]);
    let mut scene = group[0].scene.clone();
    scene.name = scene_name(stem, numbers[0]);
    scene.cases = group.iter().flat_map(|m| m.scene.cases.iter().copied()).collect();
    given_positions(&mut scene, &group);
    steady_positions(&mut scene, &group);
    scene.origin = Some(Origin { file: file.to_string(), cases: numbers });
    let place = format!("{file}, {span}");
    let files = write::files(&scene, file).map_err(|e| (span.clone(), e))?;
    write::read_back(&scene, &files, &place).map_err(|e| (span.clone(), e))?;
    Ok(SceneFiles { name: scene.name, cases: numbers, files })
}

/// A shift's rows with each case's S_WS (the table's column `s_mm`, `[wheelrail] s_mm` then
/// left out, 0) where the positions the scene derives from the shifts are not the deck's
/// (`examples_trans/m1_catt_shift`: a shift of 4 mm from rest at S_WS = 0, then shifts of 0.2 mm
/// at S_WS = 0.2, 0.4, …).
fn given_positions(scene: &mut WheelRailScene, group: &[Member]) {
    let Some(derived) = scene.shift_positions_mm() else { return };
    let same = |a: f64, b: f64| (a - b).abs() <= 1e-9 * (1.0 + a.abs());
    if derived.iter().zip(group).all(|(&d, m)| same(d, m.s_ws_mm)) {
        return;
    }
    for (row, m) in scene.cases.iter_mut().zip(group) {
        row.s_mm = Some(m.s_ws_mm);
    }
    if let MotionSpec::Shift { s_ws_mm, .. } = &mut scene.motion {
        *s_ws_mm = 0.0;
    }
}

/// Steady rows with each case's S_WS (the table's column `s_mm`, `[wheelrail] s_mm` then left
/// out) where the group's cases stand at different positions ([`same_but_position`]).
fn steady_positions(scene: &mut WheelRailScene, group: &[Member]) {
    if scene.motion != MotionSpec::Rolling || group.iter().all(|m| m.s_ws_mm == group[0].s_ws_mm) {
        return;
    }
    for (row, m) in scene.cases.iter_mut().zip(group) {
        row.s_mm = Some(m.s_ws_mm);
    }
    scene.s_ws_mm = 0.0;
}

/// The case's S_WS [mm], 0 when never given.
fn s_ws_of(s: &WheelRailState) -> f64 {
    match s.position.map(|p| p.along) {
        Some(Along::SMm(s)) => s,
        _ => 0.0,
    }
}

/// A supported case as a scene of one row (no name, no folder; profile paths as `paths` gives
/// The massless rail of a case with F = 3 (KYRAIL, FYRAIL, KZRAIL, FZRAIL, DYSTEP0 last read).
fn massless_rail_of(c: &WheelRailCase) -> Result<Option<MasslessRailSpec>, String> {
    if c.digits.f != 3 {
        return Ok(None);
    }
    let m = c.state.massless_rail.ok_or_else(|| "F = 3 without KYRAIL, FYRAIL, KZRAIL, FZRAIL".to_string())?;
    Ok(Some(MasslessRailSpec {
        ky_n_per_mm: m.ky_n_mm,
        fy_n: m.fy_n,
        kz_n_per_mm: m.kz_n_mm,
        fz_n: m.fz_n,
        dy_step_mm: m.dystep0_mm,
    }))
}

/// them), or why it has none.
fn case_scene(c: &WheelRailCase, paths: &ProfilePaths) -> Result<WheelRailScene, String> {
    let s = &c.state;
    let never = |what: &str| format!("{what} never given");
    let (rail, wheel) =
        (s.rail_profile.as_ref().ok_or(never("RFNAME"))?, s.wheel_profile.as_ref().ok_or(never("WFNAME"))?);
    if let Some(file) = paths.deck_file(&rail.file).filter(|_| rail.format() == ProfileFormat::Slices) {
        // What the slices file itself says (perturbations, CONTACT's errors) is refused here.
        check_slices_file(&file, ProfileKind::Rail).map_err(|e| format!("the rail slices file: {e}"))?;
    }
    if let Some(file) = paths.deck_file(&wheel.file).filter(|_| wheel.format() == ProfileFormat::Slices) {
        check_slices_file(&file, ProfileKind::Wheel).map_err(|e| format!("the wheel slices file: {e}"))?;
    }
    let track = s.track.ok_or(never("the track"))?;
    let wheelset = s.wheelset.ok_or(never("FBDIST, FBPOS, NOMRAD"))?;
    let material = s.material.as_ref().ok_or(never("POISS, GG"))?;
    let disc = s.discretisation.as_ref().ok_or(never("DX, DS"))?;
    let friction = s.friction.as_ref().filter(|f| !f.sets.is_empty()).ok_or(never("the friction"))?;
    let s_ws = s_ws_of(s);
    let (mu, mu_variation) = mu_of(friction, s_ws);
    let m = combine_bodies(material.poiss, material.gg_mpa);
    let (vertical, longitudinal, mut row) = row(c)?;
    // PITCH where it matters: an out-of-round wheel (a round wheel is the same at every pitch).
    if wheel.format() == ProfileFormat::Slices {
        row.pitch_rad = s.position.map_or(0.0, |p| p.pitch_rad);
    }
    let mu_max = mu_variation.as_ref().map_or(mu, |v| v.values.iter().copied().fold(mu, f64::max));
    crate::scene::wheelrail_cases::check_longitudinal(longitudinal, c.digits.t == 0, mu_max, &[row])
        .map_err(|e| format!("FX_WS = {}: {}", e.value, e.allowed))?;
    Ok(WheelRailScene {
        name: String::new(),
        solvers: vec![model_of(c).into()],
        side: if c.digits.side() == Side::Left { SideSpec::Left } else { SideSpec::Right },
        rail: profile(rail, paths)?,
        wheel: profile(wheel, paths)?,
        placement: match track.placement {
            RailPlacement::Gauge { gaught_mm, gaugwd_mm, .. } => {
                PlacementSpec::Gauge { height_mm: gaught_mm, width_mm: gaugwd_mm }
            }
            RailPlacement::Absolute { raily0_mm, railz0_mm, .. } => {
                PlacementSpec::Absolute { y_mm: raily0_mm, z_mm: railz0_mm }
            }
        },
        cant_rad: match track.fourth {
            TrackFourth::CantRad(r) => r,
            TrackFourth::RollerRadiusMm(_) => 0.0,
        },
        roller: roller_of(c)?,
        rail_deviation: {
            let d = s.rail_deviation;
            RailDeviationSpec {
                position: [d.dy_mm, d.dz_mm, d.droll_rad],
                velocity: [d.vy_mm_s, d.vz_mm_s, d.vroll_rad_s],
            }
        },
        massless_rail: massless_rail_of(c)?,
        frictionless: c.digits.t == 0,
        flange_back_distance_mm: wheelset.fbdist_mm,
        flange_back_position_mm: wheelset.fbpos_mm,
        nominal_radius_mm: wheelset.nomrad_mm,
        wheel_deviation: s
            .wheel_deviation
            .map(|w| WheelDeviationSpec { position: w.position, velocity: w.velocity })
            .unwrap_or_default(),
        mu,
        mu_variation,
        material: MaterialSpec {
            g_mpa: Some(m.g_mpa),
            e_mpa: None,
            poisson: m.poisson,
            bodies: None,
            layer: None,
            visco: None,
            heat: heat::thermal(c),
            // B = 1 switches the sheet on with the FLXZ last read (CONTACT's `bound_eff`).
            sheet_mm3_per_n: if c.digits.b == 1 { material.flxz.unwrap_or(0.0) } else { 0.0 },
            blanco: blanco_of(material),
        },
        tangential: heat::tangential(c),
        dx_mm: disc.dx_mm,
        ds_mm: disc.ds_mm,
        // CONTACT takes any A_SEP; contact angles (in (−π/2, π/2)) never differ by π or more.
        a_sep_rad: disc.a_sep_rad.min(std::f64::consts::PI),
        d_sep_mm: disc.d_sep_mm,
        d_comb_mm: disc.d_comb_mm,
        d_turn_mm: disc.d_turn_mm(),
        // CONTACT measures the undeformed distance to its mesh of the wheel (`wr_ud_planar`), an
        // imported deck does too: on the exact surface a coarse or flange patch moves by tens of
        // half-units (docs/wheelrail.md "The wheel surface").
        wheel_mesh: true,
        search: match disc.method {
            5 => ContactSearch::Grid,
            6 => ContactSearch::GridSteep,
            _ => ContactSearch::Locus,
        },
        approach: match disc.method {
            3 => Approach::PlanarSurfaceSlip,
            4 => Approach::Conformal,
            _ => Approach::Planar,
        },
        motion: match c.digits.t {
            1 => MotionSpec::Shift { s_ws_mm: s_ws, sequence: c.digits.p == 0, steady_start: false },
            2 => MotionSpec::RollingSequence { dq_rel: disc.dqrel, from_rest: c.digits.p == 2 },
            _ => MotionSpec::Rolling,
        },
        // S_WS where the scene says it: a shift, μ along the track, a rail slices file.
        s_ws_mm: if c.digits.t == 1
            || matches!(friction.variation, FrictionVariation::AlongTrack)
            || rail.format() == ProfileFormat::Slices
        {
            s_ws
        } else {
            0.0
        },
        vertical,
        longitudinal,
        cases: vec![row],
        report: Default::default(),
        origin: None,
        dir: PathBuf::new(),
    })
}

/// The roller of a roller rig's case (C = 4, 5): NOMRAD_R and VPITCH_ROL; `None` on a track.
fn roller_of(c: &WheelRailCase) -> Result<Option<RollerSpec>, String> {
    let s = &c.state;
    let (Some(track), Some(v)) = (s.track, s.velocity) else { return Ok(None) };
    match (track.fourth, v.forward) {
        (TrackFourth::RollerRadiusMm(radius_mm), Forward::RollerPitchRadS(vpitch_rad_s)) => {
            Ok(Some(RollerSpec { radius_mm, vpitch_rad_s }))
        }
        (TrackFourth::CantRad(_), Forward::VsMmS(_)) => Ok(None),
        _ => Err("a track's and a roller rig's inputs mixed".into()),
    }
}

/// The model of the case's B, M and T digits: KPEC (B = 5) or ANALYN (B = 6) with FASTSIM or
/// frictionless, FASTSIM on the full normal problem (M = 3), else the exact theory.
fn model_of(c: &WheelRailCase) -> &'static str {
    use super::super::features::{approximate_supported, plain_fastsim};
    match c.digits.b {
        5 if approximate_supported(c) => "kpec",
        6 if approximate_supported(c) => "analyn",
        _ if plain_fastsim(c) => "fastsim",
        _ => "contact",
    }
}

/// Coulomb's mu (FSTAT) of the case, and its variation across the rail (V = 1, at ALPHA) or along
/// the track (V = 2, at SVF, the case at S_WS) where it has one.
fn mu_of(f: &Friction, s_ws_mm: f64) -> (f64, Option<MuVariation>) {
    let by = match f.variation {
        FrictionVariation::Uniform => return (f.sets[0].values.fstat(), None),
        FrictionVariation::AcrossRail => MuBy::ContactAngle,
        FrictionVariation::AlongTrack => MuBy::TrackS { s_mm: s_ws_mm },
    };
    let v = MuVariation {
        by,
        at: f.sets.iter().map(|s| s.at.unwrap_or(0.0)).collect(),
        values: f.sets.iter().map(|s| s.values.fstat()).collect(),
        temperature: temperature_values(f),
    };
    let mu = match by {
        MuBy::ContactAngle => v.values[0],
        MuBy::TrackS { s_mm } => v.at(s_mm),
    };
    (mu, Some(v))
}

/// TREF, DFHEAT and DTHEAT of every set of the temperature law (L = 6), the scene's
/// `tref_c_values`, `dfheat_values`, `dtheat_c_values`; `None` for another law.
fn temperature_values(f: &Friction) -> Option<[Vec<f64>; 3]> {
    let mut out: [Vec<f64>; 3] = Default::default();
    for s in &f.sets {
        let FrictionValues::Temperature { tref_c, dfheat, dtheat_c, .. } = s.values else { return None };
        for (list, v) in out.iter_mut().zip([tref_c, dfheat, dtheat_c]) {
            list.push(v);
        }
    }
    Some(out)
}

/// A profile as the scene takes it: the path from the scene's folder, MIRRORY = 1 as mirror_y,
/// MIRRORZ, and the options of PRFOPT ≥ 1 (CONTACT's defaults without them; ISMOOTH = 2 is
/// refused before, by the scene's limits).
fn profile(p: &super::super::wheelrail_deck::ProfileSpec, paths: &ProfilePaths) -> Result<ProfileSpec, String> {
    let [zig, high, low, width, omit] = PROFILE_DEFAULTS;
    let k = p.curation.map(|k| ProfileCuration {
        zigthrs_rad: snap(k.zigthrs_rad, zig),
        kinkhigh_rad: snap(k.kinkhigh_rad, high),
        kinklow_rad: snap(k.kinklow_rad, low),
        kinkwid_mm: snap(k.kinkwid_mm, width),
        ..k
    });
    Ok(ProfileSpec {
        path: PathBuf::from(paths.of(&p.file)?),
        mirror_y: p.mirror_y == 1,
        mirror_z: p.mirror_z.clamp(-1, 1) as i8,
        scale: p.scale,
        smooth: p.smooth,
        smooth_weighted: k.is_some_and(|k| k.ismooth == 1),
        zig_zag_rad: k.map_or(zig, |k| k.zigthrs_rad),
        kink_high_rad: k.map_or(high, |k| k.kinkhigh_rad),
        kink_low_rad: k.map_or(low, |k| k.kinklow_rad),
        kink_width_mm: k.map_or(width, |k| k.kinkwid_mm),
        max_omit: k.and_then(|k| k.errors).map_or(omit, |(_, m)| m),
    })
}

/// `v`, or `default` where `v` is within 1e-12 of it relatively (`6d` parses to 6π/180, not to
/// CONTACT's default KINKHIGH/5 to the last bit).
fn snap(v: f64, default: f64) -> f64 {
    if (v - default).abs() <= 1e-12 * default.abs() {
        default
    } else {
        v
    }
}

/// The case's row: its number, position (FZ or Z as N says) and velocities (the last VPITCH, or
/// FX_WS with F = 1).
fn row(c: &WheelRailCase) -> Result<(VerticalSpec, LongitudinalSpec, CaseRow), String> {
    let p = c.state.position.ok_or("the wheelset position never given")?;
    let v = c.state.velocity.ok_or("the wheelset velocity never given")?;
    if let Along::XMm(x) = p.along {
        if x != 0.0 {
            return Err(format!("X_WS = {x} on a roller rig (the wheelset off the roller's top)"));
        }
    }
    // On a roller rig the wheelset does not move forward (CONTACT's VS = 0): the roller turns.
    let vs = match v.forward {
        Forward::VsMmS(vs) => vs,
        Forward::RollerPitchRadS(_) => 0.0,
    };
    let (longitudinal, sixth) = match v.sixth {
        PitchInput::VpitchRadS(vpitch) => (LongitudinalSpec::Velocity, vpitch),
        PitchInput::FxWsN(fx) => (LongitudinalSpec::Force, fx),
        PitchInput::MyWsNmm(_) => return Err("MY_WS prescribed (F = 2)".into()),
    };
    let (vertical, value) = match p.vertical {
        Vertical::FzN(fz) => (VerticalSpec::Force, fz),
        Vertical::ZMm(z) => (VerticalSpec::Position, z),
    };
    let row = CaseRow {
        contact_case: c.number as u64,
        y_mm: p.y_mm,
        vertical: value,
        roll_rad: p.roll_rad,
        yaw_rad: p.yaw_rad,
        velocity: [vs, v.vy_mm_s, v.vz_mm_s, v.vroll_rad_s, v.vyaw_rad_s, sixth],
        s_mm: None,
        pitch_rad: 0.0,
    };
    Ok((vertical, longitudinal, row))
}

/// C3 = 4 with IF_METH 0 or 1 and VARIANT 1 to 4: Blanco-Lorenzo's conformal correction
/// (`[material] blanco_variant`, `blanco_inclination`); other combinations are refused by the
/// scene limits.
fn blanco_of(
    m: &crate::import::contact::wheelrail_deck::Material,
) -> Option<crate::physics::halfspace::blanco::Blanco> {
    use crate::physics::halfspace::blanco::{Blanco, Inclination, VARIANTS};
    let [if_meth, variant] = m.if_correction.filter(|_| m.influence == 4)?;
    let inclination = if if_meth == 0 { Inclination::Linear } else { Inclination::Interpolated };
    let variant = VARIANTS.into_iter().find(|v| i64::from(*v) == variant)?;
    Some(Blanco { inclination, variant })
}
