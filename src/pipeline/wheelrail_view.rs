//! What the report draws of a solved wheel–rail scene beyond its result files: the contact point
//! on the wheel profile per case and patch, the profiles placed in the track with the contact
//! areas at the scene's `patch_cases`, and the models' patch maps there (pressure and adhesion or
//! slip per element). Everything in CONTACT's printed frame: y to the right on both sides, z
//! downwards.

use super::wheelrail::CaseResult;
use super::wheelrail_scene::{case_of, prepare, SceneRun};
use crate::error::Error;
use crate::problem::material_of_spec;
use crate::scene::wheelrail::WheelRailScene;
use crate::wheelrail::rail::PlacedRail;
use crate::wheelrail::wheel::{PlacedWheel, Pose};
use crate::wheelrail::{NormalPatch, WheelRailError};

/// Points along a profile drawn.
const PROFILE_POINTS: usize = 400;

/// One case's profiles in the track (y, z) [mm]: the rail, the wheel at the case's pose and
/// height, each patch's contact area along the rail surface and its reference point.
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    pub contact_case: u64,
    pub rail_mm: Vec<(f64, f64)>,
    pub wheel_mm: Vec<(f64, f64)>,
    pub areas_mm: Vec<Vec<(f64, f64)>>,
    pub points_mm: Vec<(f64, f64)>,
}

/// One model's map of one patch: per element (x, s) [mm], pressure [MPa], whether it slips.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchMap {
    pub contact_case: u64,
    /// From 1, CONTACT's order.
    pub patch: usize,
    pub model: String,
    pub cells: Vec<(f64, f64, f64, bool)>,
    pub element_mm: (f64, f64),
}

/// A solved wheel–rail scene as the report draws it.
#[derive(Debug, Clone)]
pub struct WheelRailView {
    pub scene: WheelRailScene,
    pub run: SceneRun,
    /// Per case (the run's order) and patch: the reference point's lateral place on the wheel
    /// profile, YCP(W) [mm].
    pub ycp_w_mm: Vec<Vec<f64>>,
    pub outlines: Vec<Outline>,
    pub maps: Vec<PatchMap>,
}

/// The view of `run`, the result of `scene`: the profiles read again, the cases of
/// `patch_cases` placed, with every model's patch maps as its solve left them.
pub fn view(scene: &WheelRailScene, run: SceneRun) -> Result<WheelRailView, Error> {
    let (rail, wheel, _) = prepare(scene)?;
    let material = material_of_spec(&scene.material)?;
    let geometry =
        |e: WheelRailError| Error::from(crate::error::InputError::new("wheelrail", "the case", e.to_string()));
    let (mut ycp_w_mm, mut outlines, mut maps) = (Vec::new(), Vec::new(), Vec::new());
    let patch_cases = scene.patch_cases();
    for (row, (number, result)) in scene.cases.iter().zip(&run.cases) {
        let rail = rail.of_case(row)?;
        let case = case_of(scene, row, &rail, &wheel, material);
        let m = case.side.sign();
        let pose = Pose { z_mm: result.normal.z_ws_mm, ..case.side.pose(&case.pose) };
        let placed = PlacedWheel::place(case.wheel, &case.side.wheelset(&case.wheelset), &pose);
        ycp_w_mm.push(result.normal.patches.iter().map(|p| m * wheel_y_mm(&placed, p)).collect());
        if !patch_cases.contains(number) {
            continue;
        }
        let placed_rail = PlacedRail::place(case.rail, &case.track).map_err(geometry)?;
        outlines.push(outline(*number, m, &placed_rail, &placed, &result.normal.patches));
        maps.extend(case_maps(*number, m, result));
    }
    Ok(WheelRailView { scene: scene.clone(), run, ycp_w_mm, outlines, maps })
}

/// The patch maps of one solved case: every model that kept its slip per element, on the patches
/// its forces are on (`m`: y's sign in the side's printed frame).
fn case_maps(case: u64, m: f64, result: &CaseResult) -> Vec<PatchMap> {
    let mut maps = Vec::new();
    for (model, forces, _) in &result.models {
        for (k, (p, f)) in result.normal_of(model).patches.iter().zip(forces).enumerate() {
            let Some(slip) = &f.slip else { continue };
            let g = &p.geometry.grid;
            let cells = (0..g.len())
                .map(|e| {
                    let (x, s) = g.centre(e % g.mx, e / g.mx);
                    (x, m * s, p.pn_mpa[e], slip[e])
                })
                .collect();
            let element_mm = (g.dx_mm, g.ds_mm);
            maps.push(PatchMap { contact_case: case, patch: k + 1, model: model.clone(), cells, element_mm });
        }
    }
    maps
}

/// The patch's reference point in the wheel profile's lateral coordinate (CONTACT's YCP(W): the
/// point itself expressed in the wheelset's frame less the profile's offset; right-side frame).
fn wheel_y_mm(wheel: &PlacedWheel, p: &NormalPatch) -> f64 {
    let q = wheel.rotation.inverse() * (p.geometry.frame.origin - wheel.centre);
    q.y - wheel.y_offset_mm
}

/// Evenly spaced values over `[lo, hi]`.
fn spaced([lo, hi]: [f64; 2], n: usize) -> impl Iterator<Item = f64> {
    (0..n).map(move |k| lo + (hi - lo) * k as f64 / (n - 1) as f64)
}

/// One case's profiles and contact areas in the side's printed frame (`m`: y's sign).
fn outline(case: u64, m: f64, rail: &PlacedRail, wheel: &PlacedWheel, patches: &[NormalPatch]) -> Outline {
    let rail_mm = spaced(rail.y_range_mm(), PROFILE_POINTS).filter_map(|y| Some((m * y, rail.z_mm(y)?))).collect();
    let wheel_mm = spaced(wheel.curve.y_range_mm(), PROFILE_POINTS)
        .filter_map(|y_w| wheel.locus(y_w))
        .map(|p| (m * p.y, p.z))
        .collect();
    let areas_mm = patches
        .iter()
        .map(|p| {
            let g = &p.geometry.grid;
            let s: Vec<f64> = (0..g.len()).filter(|&e| p.pn_mpa[e] > 0.0).map(|e| g.centre(0, e / g.mx).1).collect();
            let lo = s.iter().copied().fold(f64::INFINITY, f64::min) - 0.5 * g.ds_mm;
            let hi = s.iter().copied().fold(f64::NEG_INFINITY, f64::max) + 0.5 * g.ds_mm;
            let at = |s: f64| p.geometry.frame.at(0.0, s);
            if !(lo.is_finite() && hi.is_finite()) {
                return Vec::new();
            }
            spaced([lo, hi], 12).map(at).map(|q| (m * q.y, q.z)).collect()
        })
        .collect();
    let points_mm = patches.iter().map(|p| (m * p.geometry.frame.origin.y, p.geometry.frame.origin.z)).collect();
    Outline { contact_case: case, rail_mm, wheel_mm, areas_mm, points_mm }
}
