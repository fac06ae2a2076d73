//! The wheel–rail stage: profiles, track and wheelset → contact patches (CONTACT's module 1,
//! steady planar contact). It sits between the scene and the problem: each patch it finds is a
//! module-3 problem (an undeformed distance per element, creepages, a normal force) that every
//! model solves alike; the models never see a profile.
//!
//! The order of the work, one file each: [`rail`] and [`wheel`] place the surfaces,
//! [`search`] scans the contact locus for interpenetration regions, [`patch`] turns a region
//! into a reference frame, a grid and an undeformed distance, [`vertical`] finds the height for a
//! prescribed vertical force, [`creepage`] the kinematic creepages. Everything is computed on the
//! right side; [`side`] mirrors a left wheel.

pub mod brute;
pub mod conformal_grid;
pub mod conformal_reference;
pub mod creepage;
pub mod curve;
pub mod friction;
pub mod locus;
pub mod mesh_interp;
pub mod oorwheel;
pub mod patch;
pub mod profile;
pub mod rail;
pub mod roller;
pub mod search;
pub mod shift;
pub mod side;
pub mod surface_slip;
#[cfg(test)]
mod test_fixtures;
pub mod varrail;
pub mod vertical;
pub mod wheel;
pub mod wheel_mesh;

use std::sync::Arc;

use crate::physics::approximate::{self, ApproximateError, Method};
use crate::physics::halfspace::blanco::BlancoProduct;
use crate::physics::halfspace::influence::Kernel;
use crate::physics::halfspace::normal::{NormalParams, NormalSolver};
use crate::physics::halfspace::ContactError;
use crate::physics::{Grid, Material};
use crate::scene::wheelrail::{Approach, ContactSearch};
use curve::Curve;
use patch::PatchGeometry;
use rail::{PlacedRail, Track};
use side::Side;
use wheel::{PlacedWheel, Pose, Velocity, WheelsetGeometry};

/// Why a wheel–rail case has no solution.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WheelRailError {
    #[error("the rail profile has no gauge face at depth {height_mm} mm below its top")]
    NoGaugeFace { height_mm: f64 },
    #[error(
        "the rail profile's gauge-side end (its smallest y, {y_mm} mm) lies {depth_mm} mm below its top, \
         above the gauge point's depth {height_mm} mm: a profile of the other rail (`[rail] mirror_y = true` \
         mirrors it) or one cut above the gauge point"
    )]
    GaugeSideTooShallow { height_mm: f64, y_mm: f64, depth_mm: f64 },
    #[error("the wheel does not touch the rail")]
    NoContact,
    #[error("no wheelset height gives FZ = {fz_n} N (last height {z_mm} mm)")]
    VerticalNotConverged { fz_n: f64, z_mm: f64 },
    #[error("patch {patch}: the grid of {elements} elements exceeds the limit of {limit}")]
    GridTooLarge { patch: usize, elements: usize, limit: usize },
    #[error(
        "the grid search's gap mesh of {slices} x {lateral} points exceeds the limit of {limit} points (dx_mm, ds_mm too small for the wheel's arc and the rail's width)"
    )]
    GapMeshTooLarge { slices: usize, lateral: usize, limit: usize },
    #[error("patch {patch}: normal problem: {source}")]
    Normal { patch: usize, source: ContactError },
    #[error("patch {patch}: approximate normal problem: {source}")]
    Approximate { patch: usize, source: ApproximateError },
    #[error("a shift's material-fixed grid needs the rail profile's arc length (a profile file, not a closed form)")]
    NoRailArcLength,
    #[error(
        "the conformal approach's curved reference needs both profiles' splines (profile files) reaching its rows"
    )]
    NoCurvedReference,
}

/// Largest potential contact of one patch [elements].
pub const MAX_ELEMENTS: usize = 250_000;

/// Largest gap mesh of the grid search [points] (the shipped scenes' sizes: docs/wheelrail.md,
/// "Bad input").
pub const MAX_GAP_MESH_POINTS: usize = 12_000_000;

/// The vertical problem (CONTACT's N digit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Vertical {
    /// FZ prescribed (N = 1): the height z_ws is found.
    Force { fz_n: f64 },
    /// The height z_ws of the pose prescribed (N = 0).
    Position,
}

/// How the wheel moves in the case (CONTACT's T digit in module 1, with T = 0 the frictionless
/// variant of either).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Motion {
    /// Steady rolling (T = 3): the grid's element centres on multiples of DX and DS from each
    /// patch's reference, the velocities over the rolling speed are the creepages.
    #[default]
    Rolling,
    /// A shift from rest (T = 1, P = 2; user guide "Tangential quantities in case of a shift"):
    /// the velocities are the shifts of one step (dt = 1, VELOC = 1: the creepages are shifts
    /// [mm, rad]) and the grid is CONTACT's material-fixed super-grid (`set_cpatch_reference`,
    /// T = 1): element centres at track x = −S_WS + i DX and at the rail's arc length j DS.
    Shift { s_ws_mm: f64 },
    /// One transient rolling step of `dq_mm` continuing the case before (T = 2, P = 0; user guide
    /// "Module 1", `set_cpatch_reference` with T = 2): the creepages are rolling's, the grid is
    /// CONTACT's super-grid fixed laterally in the rail's material and moving with the wheelset
    /// along the track (element centres at track x = i DX from the wheelset, at the rail's arc
    /// length j DS), the tractions before it carried over and rolled by `dq_mm`.
    Transient { dq_mm: f64 },
}

impl Motion {
    /// Whether the grid is CONTACT's super-grid (T = 1, 2): its anchor's track position along x.
    pub fn super_grid_s_mm(self) -> Option<f64> {
        match self {
            Motion::Rolling => None,
            Motion::Shift { s_ws_mm } => Some(s_ws_mm),
            Motion::Transient { .. } => Some(0.0),
        }
    }
}

/// One side's case: the surfaces, their placement, the wheelset's state and the discretisation.
#[derive(Debug, Clone, Copy)]
pub struct WheelRailCase<'a> {
    pub side: Side,
    pub rail: &'a dyn Curve,
    pub wheel: &'a dyn Curve,
    pub track: Track,
    pub wheelset: WheelsetGeometry,
    /// In the side's own frame (CONTACT's input).
    pub pose: Pose,
    pub velocity: Velocity,
    pub vertical: Vertical,
    pub dx_mm: f64,
    pub ds_mm: f64,
    /// A_SEP, D_SEP, D_COMB: which interpenetration regions make one patch.
    pub separation: patch::Separation,
    /// The wheel surface the undeformed distance is measured to.
    pub wheel_surface: wheel_mesh::WheelSurface,
    /// The contact approach: planar (CONTACT's D = 2), planar with the rigid slip on the actual
    /// surfaces ([`surface_slip`], D = 3) or conformal (D = 4: each patch on a curved reference
    /// surface, [`conformal_reference`], [`conformal_grid`], its rigid slip on the surfaces).
    pub approach: Approach,
    /// The contact locus or the brute-force grid search ([`brute`], CONTACT's D = 5; D = 6 on a
    /// finer mesh for steep slopes); an out-of-round wheel takes the grid search always.
    pub search: ContactSearch,
    pub material: Material,
    /// Both bodies' thermal constants where the surface temperatures are computed (CONTACT's H = 3).
    pub heat: Option<[crate::physics::temperature::Thermal; 2]>,
    /// Friction of the surface temperature and the exact solver's options (`[friction]`,
    /// `[contact_solver]`).
    pub tangential: crate::scene::wheelrail_tangential::Tangential,
    pub motion: Motion,
    /// In a case that continues a sequence (CONTACT's P = 0, T = 1 or 2): the patches the case
    /// before left, with their tractions; `None` from rest and in steady rolling, `Some` (empty)
    /// in the steady case that starts transient rolling (its tractions are kept for the next).
    pub previous: Option<&'a shift::Previous>,
    /// A rail whose profile varies along the track (a slices file at the wheelset's S_WS); `rail`
    /// is then its cross-section at S_WS, where the rail is placed and the gap mesh made.
    pub rail_slices: Option<varrail::RailSlices<'a>>,
    /// An out-of-round wheel (a wheel slices file with the wheelset's pitch); `wheel` is then its
    /// first slice (its surface is the slices'). Searched on CONTACT's gap mesh ([`brute`]).
    pub wheel_slices: Option<oorwheel::WheelSlices<'a>>,
    /// A roller rig (CONTACT's C = 4, 5): the rail profile is the roller's, revolved about its
    /// axis ([`roller`]); the wheelset does not move forward (VS = 0), the roller turns.
    pub roller: Option<roller::Roller>,
}

/// A patch with its normal solution and creepages (right-side frame).
#[derive(Debug, Clone, PartialEq)]
pub struct NormalPatch {
    pub geometry: PatchGeometry,
    pub fn_n: f64,
    /// Pressure per element [MPa], CONTACT's element order.
    pub pn_mpa: Vec<f64>,
    /// The approach: the deepest overlap of the undeformed surfaces [mm].
    pub pen_mm: f64,
    pub creepages: creepage::Creepages,
    /// The conformal approach's extra rigid slip per element (wx, wy) [-], CONTACT's element order
    /// ([`surface_slip`]); `None` with the creepages at the reference (D = 2).
    pub extra_slip: Option<(Vec<f64>, Vec<f64>)>,
}

/// The normal contact of one case (right-side frame).
#[derive(Debug, Clone, PartialEq)]
pub struct NormalContact {
    pub side: Side,
    /// The wheelset height found (or given) [mm].
    pub z_ws_mm: f64,
    pub patches: Vec<NormalPatch>,
    /// The rail profile's origin (y, z) in track coordinates [mm] and its rotation about x [rad].
    pub rail_origin_mm: [f64; 2],
    pub rail_angle_rad: f64,
}

impl NormalContact {
    /// A track point (y, z) in the rail profile's coordinates (right-side frame).
    pub fn in_rail_mm(&self, y_mm: f64, z_mm: f64) -> [f64; 2] {
        let (s, c) = self.rail_angle_rad.sin_cos();
        let (dy, dz) = (y_mm - self.rail_origin_mm[0], z_mm - self.rail_origin_mm[1]);
        [c * dy + s * dz, -s * dy + c * dz]
    }

    /// Σ FN cos δ: the patches' normal forces' vertical part [N].
    pub fn fz_normal_n(&self) -> f64 {
        self.patches.iter().map(|p| p.fn_n * p.geometry.frame.delta_rad.cos()).sum()
    }
}

/// The normal contact of `case`; with a prescribed force, the height where the normal forces'
/// vertical parts sum to `fz_normal_n` (the vertical force less the tangential forces' part).
pub fn normal_contact(case: &WheelRailCase, fz_normal_n: Option<f64>) -> Result<NormalContact, WheelRailError> {
    normal_contact_with(case, fz_normal_n, vertical::Stop::exact(vertical::FORCE_TOL), &mut NormalCache::default())
}

/// [`normal_contact`] with the height search ended by `stop` ([`vertical::Stop`]) and the normal
/// solvers of earlier calls on the same case kept in `cache`.
pub fn normal_contact_with(
    case: &WheelRailCase,
    fz_normal_n: Option<f64>,
    stop: vertical::Stop,
    cache: &mut NormalCache,
) -> Result<NormalContact, WheelRailError> {
    let NormalCache { solvers, touch_mm, heights, rail: kept } = cache;
    let setup: &RailSetup = match kept {
        Some(r) => r,
        None => kept.insert(RailSetup::new(case)?),
    };
    let rail = setup.placed(case.rail);
    let pose = case.side.pose(&case.pose);
    let full = NormalParams::default().tol;
    let at = |z_mm: f64, normal_tol: f64, solvers: &mut NormalSolvers| {
        patches_at(case, (&rail, setup), &Pose { z_mm, ..pose }, solvers, normal_tol)
    };
    let (z_ws_mm, patches) = match (case.vertical, fz_normal_n) {
        (Vertical::Position, _) => (pose.z_mm, at(pose.z_mm, full, solvers)?),
        (Vertical::Force { fz_n }, target) => {
            let z_touch_mm = match *touch_mm {
                Some(z) => z,
                None => {
                    let mut wheel = placed_wheel(case, &Pose { z_mm: 0.0, ..pose });
                    let deepest = if uses_grid(case) {
                        Some(-grid(case, &wheel, &rail, setup)?.gap_min_mm()).filter(|d| *d > -500.0)
                    } else {
                        search::deepest_mm(&samples(case, &rail, &setup.placement.mesh, &mut wheel))
                    };
                    match deepest {
                        Some(d) => *touch_mm.insert(-d),
                        None => return Ok(apart(case, &rail)),
                    }
                }
            };
            let target = target.unwrap_or(fz_n);
            // The search ends on the height it evaluated last: its patches are the answer.
            let mut last: Option<(f64, Vec<NormalPatch>)> = None;
            let (z, _, evaluations) = vertical::solve(z_touch_mm, target, stop, *heights, |z, normal_tol| {
                // The height evaluated last again (to a tighter tolerance): its patches re-solved.
                let patches = match last.take() {
                    Some((z_last, mut patches)) if z_last == z => {
                        resolve_normal(&mut patches, &case.material, solvers, normal_tol)?;
                        patches
                    }
                    _ => at(z, normal_tol, solvers)?,
                };
                let fz = patches.iter().map(|p| p.fn_n * p.geometry.frame.delta_rad.cos()).sum();
                last = Some((z, patches));
                Ok(fz)
            })?;
            *heights = Some(evaluations);
            match last {
                Some((z_last, patches)) if z_last == z => (z, patches),
                _ => (z, at(z, full, solvers)?),
            }
        }
    };
    Ok(NormalContact {
        side: case.side,
        z_ws_mm,
        patches,
        rail_origin_mm: rail.origin_mm,
        rail_angle_rad: rail.angle_rad,
    })
}

/// The normal contact of a wheel and rail laterally apart with FZ prescribed: no patch, the
/// wheelset at height 0, as CONTACT prints it ("NO CONTACT FOUND", zero forces; a left wheel on a
/// rail placed at RAILY0 > 0, issue 45).
fn apart(case: &WheelRailCase, rail: &PlacedRail) -> NormalContact {
    NormalContact {
        side: case.side,
        z_ws_mm: 0.0,
        patches: Vec::new(),
        rail_origin_mm: rail.origin_mm,
        rail_angle_rad: rail.angle_rad,
    }
}

/// What the searches of one case keep for the next (a prescribed force's rounds): the normal
/// solvers (influence kernel and FFT plan) of the grids met, by grid size (every trial height has
/// the same element size and material, most the same number of elements); the height of first
/// touch; the last search's last two evaluations, from which the next search starts; the rail
/// placed and its gap mesh (the track's alone).
#[derive(Default)]
pub struct NormalCache {
    solvers: NormalSolvers,
    touch_mm: Option<f64>,
    heights: Option<vertical::Evaluations>,
    rail: Option<RailSetup>,
}

/// The rail placed in the track and the rail under the gap mesh: what depends on the track and
/// the grid's DS alone, made once per case (or kept with the rail's profile, [`RailPlacements`])
/// and used at every trial height of the wheelset.
#[derive(Debug)]
pub struct RailSetup {
    placement: Arc<RailPlacement>,
    /// What the grid search's last gap mesh keeps for the next trial height ([`brute::GapMeshKept`]).
    grid_heights: std::sync::Mutex<brute::GapMeshKept>,
}

/// The rail placed in the track ([`PlacedRail::place`]) and its heights under the gap mesh
/// ([`search::RailMesh`]).
#[derive(Debug)]
struct RailPlacement {
    origin_mm: [f64; 2],
    angle_rad: f64,
    mesh: search::RailMesh,
}

impl RailPlacement {
    /// The rail of `case` placed in its track and its heights under the gap mesh of its DS.
    fn of(case: &WheelRailCase) -> Result<RailPlacement, WheelRailError> {
        let rail = PlacedRail::place(case.rail, &case.track)?;
        let mesh = search::RailMesh::new(&rail, case.ds_mm);
        Ok(RailPlacement { origin_mm: rail.origin_mm, angle_rad: rail.angle_rad, mesh })
    }
}

/// The bits of what a [`RailPlacement`] depends on besides the profile: the track's placement
/// (its kind and two values), cant and deviations, and DS.
type PlacementKey = [u64; 8];

/// How many placements a profile keeps (the oldest dropped first).
const KEPT_PLACEMENTS: usize = 4;

/// The placements of one rail profile made so far, kept with the profile (`profile::Profile`)
/// by the bits of the track and DS they were made for: the cases of a scene place one rail in one
/// track, and each placement (a scan of the profile every 0.01 mm for its gauge point, the rail's
/// heights under the gap mesh) is made once, not once per case (the same numbers bit for bit).
#[derive(Default)]
pub struct RailPlacements(std::sync::Mutex<Vec<(PlacementKey, Arc<RailPlacement>)>>);

/// A memo, not a part of the profile's value: any two are equal.
impl PartialEq for RailPlacements {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl RailPlacements {
    /// The placement of `key`: the kept one, else `make`'s (kept where it succeeds).
    fn get_or_make(
        &self,
        key: PlacementKey,
        make: impl FnOnce() -> Result<RailPlacement, WheelRailError>,
    ) -> Result<Arc<RailPlacement>, WheelRailError> {
        let kept =
            self.0.lock().unwrap_or_else(|e| e.into_inner()).iter().find(|(k, _)| *k == key).map(|(_, p)| p.clone());
        if let Some(p) = kept {
            return Ok(p);
        }
        let made = Arc::new(make()?);
        let mut kept = self.0.lock().unwrap_or_else(|e| e.into_inner());
        if kept.len() == KEPT_PLACEMENTS {
            kept.remove(0);
        }
        kept.push((key, made.clone()));
        Ok(made)
    }
}

/// The key of `case`'s placement ([`PlacementKey`]).
fn placement_key(case: &WheelRailCase) -> PlacementKey {
    let t = &case.track;
    let (kind, [a, b]) = match t.placement {
        rail::RailPlacement::Gauge { height_mm, width_mm } => (0, [height_mm, width_mm]),
        rail::RailPlacement::Absolute { y_mm, z_mm } => (1, [y_mm, z_mm]),
    };
    let [dy, dz, droll] = t.deviation_mm_rad;
    [
        kind,
        a.to_bits(),
        b.to_bits(),
        t.cant_rad.to_bits(),
        dy.to_bits(),
        dz.to_bits(),
        droll.to_bits(),
        case.ds_mm.to_bits(),
    ]
}

impl RailSetup {
    /// The rail of `case` placed ([`PlacedRail::place`]) and its gap mesh: kept with the rail's
    /// profile where it keeps placements ([`Curve::placements`]), else made.
    pub fn new(case: &WheelRailCase) -> Result<RailSetup, WheelRailError> {
        let placement = match case.rail.placements() {
            Some(kept) => kept.get_or_make(placement_key(case), || RailPlacement::of(case))?,
            None => Arc::new(RailPlacement::of(case)?),
        };
        Ok(RailSetup { placement, grid_heights: Default::default() })
    }

    /// [`RailSetup::new`] made afresh whether or not the profile keeps the placement: what the
    /// first case of a scene pays (the benchmark `rail_setup`).
    pub fn afresh(case: &WheelRailCase) -> Result<RailSetup, WheelRailError> {
        Ok(RailSetup { placement: Arc::new(RailPlacement::of(case)?), grid_heights: Default::default() })
    }

    /// The placed rail of profile `curve` (the case's).
    fn placed<'a>(&self, curve: &'a dyn Curve) -> PlacedRail<'a> {
        PlacedRail { curve, origin_mm: self.placement.origin_mm, angle_rad: self.placement.angle_rad }
    }
}

impl NormalCache {
    /// A cache whose patches take the approximate normal problem `method` (CONTACT's B = 5, 6:
    /// KPEC or ANALYN at the approach the wheelset's height sets) instead of the exact one.
    pub fn approximate(method: Method) -> Self {
        NormalCache { solvers: NormalSolvers { approximate: Some(method), ..Default::default() }, ..Default::default() }
    }
}

/// The normal solvers by grid size, each with the last pressure it found (the start of the next
/// solve on that size: the same patch at a nearby height).
#[derive(Default)]
struct NormalSolvers {
    solvers: Vec<((usize, usize), NormalSolver, Vec<f64>)>,
    /// The approximate normal problem the patches take instead, if any.
    approximate: Option<Method>,
    /// Blanco's correction: its products by grid size, and each conformal patch's normal
    /// displacement of its last tangential tractions by grid ([`NormalCache::set_blanco_coupling`]).
    blanco: BlancoNormal,
}

/// What Blanco's correction keeps for the normal problems of one case.
#[derive(Default)]
struct BlancoNormal {
    products: Vec<((usize, usize), BlancoProduct)>,
    traction_un_mm: Vec<(patch::PatchGrid, Vec<f64>)>,
}

/// Passes of the fixed point on the pressure's correction `(B_nn − A_nn) pn` at most.
const BLANCO_PASSES: usize = 200;

/// Grids kept per case (the oldest dropped first).
const KEPT_SOLVERS: usize = 8;

impl BlancoNormal {
    /// The product of `variant` on grid `g`'s kernel with its rows inclined by `rows`.
    fn product(
        &mut self,
        g: &patch::PatchGrid,
        m: &Material,
        (rows, variant): (&[f64], u8),
    ) -> Result<&mut BlancoProduct, ContactError> {
        let key = (g.mx, g.ms);
        let k = match self.products.iter().position(|(k, _)| *k == key) {
            Some(k) => k,
            None => {
                let kernel = Kernel::new(g.mx, g.ms, g.dx_mm, g.ds_mm, m.g_mpa, m.poisson, 0.0)?;
                if self.products.len() == KEPT_SOLVERS {
                    self.products.remove(0);
                }
                self.products.push((key, BlancoProduct::new(&kernel, rows, variant)?));
                self.products.len() - 1
            }
        };
        let product = &mut self.products[k].1;
        product.set_rows(rows)?;
        Ok(product)
    }

    /// The normal displacement of the last tangential tractions [mm] on grid `g` (CONTACT's
    /// element order): the field a tangential solve left on a grid of the same lattice (element
    /// size and anchor) taken element by element where the grids overlap, zero elsewhere; `None`
    /// where none was left on that lattice.
    fn traction_un(&self, g: &patch::PatchGrid) -> Option<Vec<f64>> {
        let same_lattice = |o: &patch::PatchGrid| (o.dx_mm, o.ds_mm, o.anchor_mm) == (g.dx_mm, g.ds_mm, g.anchor_mm);
        let (old, un) = self.traction_un_mm.iter().find(|(o, _)| same_lattice(o))?;
        let mut out = vec![0.0; g.len()];
        for j in 0..g.ms {
            for i in 0..g.mx {
                let oi = g.first_index[0] + i as i64 - old.first_index[0];
                let oj = g.first_index[1] + j as i64 - old.first_index[1];
                if (0..old.mx as i64).contains(&oi) && (0..old.ms as i64).contains(&oj) {
                    out[j * g.mx + i] = un[oj as usize * old.mx + oi as usize];
                }
            }
        }
        Some(out)
    }
}

impl NormalCache {
    /// Blanco's correction: the normal displacements `B_nt p_t` [mm] (CONTACT's element order) of
    /// the tangential tractions each conformal patch's last solve found, by grid, for the next
    /// normal solves (CONTACT's Panagiotopoulos process); returns the largest change [mm] from
    /// those the last normal solves took (infinite where a grid had none).
    pub fn set_blanco_coupling(&mut self, fields: Vec<(patch::PatchGrid, Vec<f64>)>) -> f64 {
        let kept = &mut self.solvers.blanco;
        let mut change: f64 = 0.0;
        for (grid, un) in &fields {
            change = change.max(match kept.traction_un(grid) {
                Some(old) => old.iter().zip(un).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max),
                None => f64::INFINITY,
            });
        }
        kept.traction_un_mm = fields;
        // The force at each height changed with the distance: the next search starts afresh.
        if change > 0.0 {
            self.heights = None;
        }
        change
    }
}

impl NormalSolvers {
    /// The solver of grid `g` with material `m`.
    fn get(&mut self, g: &patch::PatchGrid, m: &Material) -> Result<(&mut NormalSolver, &mut Vec<f64>), ContactError> {
        let key = (g.mx, g.ms);
        let k = match self.solvers.iter().position(|(k, _, _)| *k == key) {
            Some(k) => k,
            None => {
                let kernel = Kernel::new(g.mx, g.ms, g.dx_mm, g.ds_mm, m.g_mpa, m.poisson, 0.0)?
                    .with_sheet(m.sheet_mm3_per_n)?;
                if self.solvers.len() == KEPT_SOLVERS {
                    self.solvers.remove(0);
                }
                self.solvers.push((key, NormalSolver::new(&kernel)?, Vec::new()));
                self.solvers.len() - 1
            }
        };
        let (_, solver, last) = &mut self.solvers[k];
        Ok((solver, last))
    }
}

/// The patches' geometry with the wheelset at height `z_ws_mm` (the case's pose otherwise): the
/// contact search, each patch's frame, grid and undeformed distance, no normal problem solved.
pub fn geometry(case: &WheelRailCase, z_ws_mm: f64) -> Result<Vec<PatchGeometry>, WheelRailError> {
    geometry_with(case, &RailSetup::new(case)?, z_ws_mm)
}

/// [`geometry`] on the rail `setup` of the case made beforehand ([`RailSetup::new`]).
pub fn geometry_with(
    case: &WheelRailCase,
    setup: &RailSetup,
    z_ws_mm: f64,
) -> Result<Vec<PatchGeometry>, WheelRailError> {
    let pose = Pose { z_mm: z_ws_mm, ..case.side.pose(&case.pose) };
    let rail = setup.placed(case.rail);
    let mut wheel = placed_wheel(case, &pose);
    geometry_at(case, (&rail, setup), &mut wheel)
}

/// The case's wheel at `pose` (in the side's frame), out of round where the case has slices.
fn placed_wheel<'a>(case: &WheelRailCase<'a>, pose: &Pose) -> PlacedWheel<'a> {
    let mut wheel = PlacedWheel::place(case.wheel, &case.side.wheelset(&case.wheelset), pose);
    wheel.oor = case.wheel_slices;
    wheel
}

/// The gap function on the mesh: the wheel's locus over the prismatic rail, or over a variable
/// rail the loci iterated on its surface (the wheel's locus spline replaced by that one).
fn samples(
    case: &WheelRailCase,
    rail: &PlacedRail,
    mesh: &search::RailMesh,
    wheel: &mut PlacedWheel,
) -> Vec<search::LocusSample> {
    if let Some(r) = &case.roller {
        return match roller::loci(r, rail, wheel) {
            Some(loci) => {
                let out = search::scan_varying(&loci, mesh);
                wheel.locus_spline = Some(loci.wheel);
                out
            }
            None => Vec::new(),
        };
    }
    let Some(slices) = &case.rail_slices else { return search::scan(wheel, mesh) };
    let frame = varrail::RailFrame { origin_mm: rail.origin_mm, angle_rad: rail.angle_rad };
    match varrail::loci(slices, frame, wheel) {
        Some(loci) => {
            let out = search::scan_varying(&loci, mesh);
            wheel.locus_spline = Some(loci.wheel);
            out
        }
        None => Vec::new(),
    }
}

/// Whether the case's search is the grid search (D = 5, 6, or an out-of-round wheel).
fn uses_grid(case: &WheelRailCase) -> bool {
    case.search.is_grid() || case.wheel_slices.is_some()
}

/// The grid search's gap mesh of the case with the wheel placed as `wheel` ([`brute::gap_mesh`]).
fn grid(
    case: &WheelRailCase,
    wheel: &PlacedWheel,
    rail: &PlacedRail,
    setup: &RailSetup,
) -> Result<brute::GapMesh, WheelRailError> {
    let steep = case.search == ContactSearch::GridSteep;
    // A poisoned lock held heights of a mesh made whole before the panic: still good.
    let mut kept = setup.grid_heights.lock().unwrap_or_else(|e| e.into_inner());
    let surface = match (&case.rail_slices, &case.roller) {
        (Some(v), _) => brute::RailSurface::Varying(v),
        (None, Some(r)) => brute::RailSurface::Roller(r),
        (None, None) => brute::RailSurface::Prismatic,
    };
    brute::gap_mesh(wheel, rail, surface, (case.dx_mm, case.ds_mm, steep), &mut kept)
}

/// The patches' geometry with the wheel placed as `wheel`.
fn geometry_at(
    case: &WheelRailCase,
    (rail, setup): (&PlacedRail, &RailSetup),
    wheel: &mut PlacedWheel,
) -> Result<Vec<PatchGeometry>, WheelRailError> {
    let candidates: Vec<_> = match uses_grid(case) {
        true => brute::candidates(&grid(case, wheel, rail, setup)?),
        false => {
            let samples = samples(case, rail, &setup.placement.mesh, wheel);
            if samples.is_empty() {
                // Laterally apart: no patch, as CONTACT finds none ("the wheel and rail are
                // LATERALLY in different places").
                return Ok(Vec::new());
            }
            let wheel_mm = case.wheelset.nominal_radius_mm;
            let radius = case.roller.map_or(wheel_mm, |r| r.gap_radius_mm(wheel_mm));
            search::regions(&samples).into_iter().filter_map(|r| patch::candidate(r, radius)).collect()
        }
    };
    let mut out = Vec::new();
    for (k, c) in patch::combine(candidates, &case.separation).iter().enumerate() {
        let geometry = patch::build(
            c,
            wheel,
            rail,
            (case.dx_mm, case.ds_mm),
            &case.separation,
            (case.wheel_surface, case.motion, case.previous, case.approach),
            (case.rail_slices.as_ref(), case.roller.as_ref()),
        )?;
        if geometry.grid.len() > MAX_ELEMENTS {
            return Err(WheelRailError::GridTooLarge {
                patch: k + 1,
                elements: geometry.grid.len(),
                limit: MAX_ELEMENTS,
            });
        }
        out.push(geometry);
    }
    Ok(out)
}

/// The patches and their normal solutions (to `normal_tol`) with the wheelset at `pose`
/// (right-side frame).
fn patches_at(
    case: &WheelRailCase,
    (rail, setup): (&PlacedRail, &RailSetup),
    pose: &Pose,
    solvers: &mut NormalSolvers,
    normal_tol: f64,
) -> Result<Vec<NormalPatch>, WheelRailError> {
    let mut wheel = placed_wheel(case, pose);
    let velocity = case.side.velocity(&case.velocity);
    let rail_motion = creepage::RailMotion { origin_mm: rail.origin_mm, velocity: case.track.deviation_velocity };
    let mut out = Vec::new();
    for (k, geometry) in geometry_at(case, (rail, setup), &mut wheel)?.into_iter().enumerate() {
        let patch = k + 1;
        let (fn_n, pn_mpa) = match solvers.approximate {
            Some(method) => solve_approximate(method, &geometry, &case.material)
                .map_err(|source| WheelRailError::Approximate { patch, source })?,
            // No element of its grid interpenetrates: the patch carries nothing and is left out
            // before any solve (CONTACT's `wr_solve_cp`: "no actual contact in patch", ncon = 0,
            // zero force; a trial height in a shift whose material-fixed grid misses a tiny overlap).
            None if no_overlap_on_grid(&geometry) => continue,
            None => solve_normal(&geometry, &case.material, solvers, normal_tol)
                .map_err(|source| WheelRailError::Normal { patch, source })?,
        };
        let pen_mm = -geometry.h_mm.iter().copied().fold(f64::INFINITY, f64::min);
        let shift = matches!(case.motion, Motion::Shift { .. });
        let step = match case.motion {
            Motion::Shift { .. } => surface_slip::SlipStep::Shift,
            Motion::Transient { dq_mm } => surface_slip::SlipStep::Rolling { dq_mm },
            Motion::Rolling => surface_slip::SlipStep::Rolling { dq_mm: case.dx_mm },
        };
        let rail_motion = (&rail_motion, case.roller.as_ref());
        let (creepages, extra_slip) =
            match surface_slip::rigid_slip(&geometry, &wheel, (&velocity, rail_motion.0, rail_motion.1), step) {
                Some(slip) => (slip.creepages, Some(slip.extra)),
                None => (creepage::at_reference(&geometry.frame, &wheel, &velocity, pen_mm, rail_motion, shift), None),
            };
        out.push(NormalPatch { geometry, fn_n, pn_mpa, pen_mm, creepages, extra_slip });
    }
    Ok(out)
}

/// Whether no element of the patch's grid interpenetrates (every undeformed distance positive).
fn no_overlap_on_grid(g: &PatchGeometry) -> bool {
    g.h_mm.iter().all(|&h| h >= 0.0)
}

/// The normal problems of `patches` solved again to `tol` (their geometry kept); an approximate
/// normal problem's solution has no tolerance and is kept.
fn resolve_normal(
    patches: &mut [NormalPatch],
    m: &Material,
    solvers: &mut NormalSolvers,
    tol: f64,
) -> Result<(), WheelRailError> {
    if solvers.approximate.is_some() {
        return Ok(());
    }
    for (k, p) in patches.iter_mut().enumerate() {
        (p.fn_n, p.pn_mpa) = solve_normal(&p.geometry, m, solvers, tol)
            .map_err(|source| WheelRailError::Normal { patch: k + 1, source })?;
    }
    Ok(())
}

/// The normal problem of one patch with the geometry's own approach (the interpenetration),
/// solved to `tol`.
fn solve_normal(
    g: &PatchGeometry,
    m: &Material,
    solvers: &mut NormalSolvers,
    tol: f64,
) -> Result<(f64, Vec<f64>), ContactError> {
    let blanco = match (m.blanco, &g.curved) {
        (Some(b), Some(c)) => Some((conformal_grid::blanco_rows(&g.grid, c, b)?, b.variant)),
        _ => None,
    };
    // Blanco's correction: the distance with the tangential tractions' normal displacement.
    let coupled_h: Option<Vec<f64>> = blanco.as_ref().map(|_| match solvers.blanco.traction_un(&g.grid) {
        Some(un) => g.h_mm.iter().zip(un).map(|(h, u)| h + u).collect(),
        None => g.h_mm.clone(),
    });
    let h_mm = coupled_h.as_deref().unwrap_or(&g.h_mm);
    let params = NormalParams { tol, ..NormalParams::default() };
    let (solver, last) = solvers.get(&g.grid, m)?;
    solver.set_blend(g.blend.clone())?;
    let start = Some(last.as_slice()).filter(|l| !l.is_empty());
    let mut pn_mpa = match (&blanco, start) {
        // Blanco's fixed point starts from the last pressure on this grid size.
        (Some(_), Some(pn)) => pn.to_vec(),
        // No pressure on this grid size yet: a trial height's loose solve of a plane patch of one
        // region from Hertz's shape over the overlap; else from the overlap itself (the solver's
        // own start: a full-tolerance solve, such as a prescribed position's, as before bit for bit).
        _ => {
            let plane = g.curved.is_none() && g.blend.is_none();
            let loose = tol > NormalParams::default().tol;
            let hertz = (start.is_none() && plane && loose).then(|| hertz_start_mpa(h_mm));
            solver.solve_approach_from(h_mm, 0.0, &params, start.or(hertz.as_deref()))?.converged_pn_mpa()?
        }
    };
    if let Some((rows, variant)) = &blanco {
        // The products held apart from the solvers while both are in use.
        let mut kept = std::mem::take(&mut solvers.blanco);
        let pn = kept.product(&g.grid, m, (rows, *variant)).and_then(|product| {
            let (solver, _) = solvers.get(&g.grid, m)?;
            blanco_pressure(solver, product, h_mm, &params, pn_mpa)
        });
        solvers.blanco = kept;
        pn_mpa = pn?;
    }
    let (_, last) = solvers.get(&g.grid, m)?;
    let fn_n = match &g.curved {
        Some(c) => conformal_grid::normal_force_n(&g.frame, &g.grid, c, &pn_mpa),
        None => pn_mpa.iter().sum::<f64>() * g.grid.dx_mm * g.grid.ds_mm,
    };
    last.clone_from(&pn_mpa);
    Ok((fn_n, pn_mpa))
}

/// A cold start of the normal problem on the undeformed distance `h_mm` [mm]: Hertz's pressure
/// shape `√(2 ov − δ)` of the overlap `ov = −h`, `δ` its largest (Johnson, "Contact Mechanics",
/// sec. 4.2: the contact radius is `√(Rδ)`, the overlap's `√(2Rδ)`, so `1 − r²/a² = (2 ov − δ)/δ`);
/// unscaled (the solver scales a start by its best factor). Its CG takes about a quarter fewer
/// iterations than from the overlap itself.
fn hertz_start_mpa(h_mm: &[f64]) -> Vec<f64> {
    let pen_mm = h_mm.iter().fold(0.0f64, |m, h| m.max(-h));
    h_mm.iter().map(|h| (2.0 * (-h).max(0.0) - pen_mm).max(0.0).sqrt()).collect()
}

/// The pressure of Blanco's corrected normal problem on the distance `h_mm` (with the tangential
/// tractions' part): the fixed point of the half-space's problem on `h_mm + (B_nn − A_nn) pn`
/// from the half-space's pressure `pn_mpa`, until the pressure changes by at most the solve's
/// tolerance relative to its largest value.
fn blanco_pressure(
    solver: &mut NormalSolver,
    product: &mut BlancoProduct,
    h_mm: &[f64],
    params: &NormalParams,
    mut pn_mpa: Vec<f64>,
) -> Result<Vec<f64>, ContactError> {
    let zero = vec![0.0; pn_mpa.len()];
    for _ in 0..BLANCO_PASSES {
        let [_, _, un] = product.correction([&zero, &zero, &pn_mpa])?;
        let h: Vec<f64> = h_mm.iter().zip(&un).map(|(h, u)| h + u).collect();
        let next = solver.solve_approach_from(&h, 0.0, params, Some(&pn_mpa))?.converged_pn_mpa()?;
        let change = next.iter().zip(&pn_mpa).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        let size = next.iter().copied().fold(0.0, f64::max);
        pn_mpa = next;
        if change <= params.tol.max(1e-12) * size {
            return Ok(pn_mpa);
        }
    }
    Err(ContactError::NotConverged { what: "Blanco's corrected pressure (fixed point)", passes: BLANCO_PASSES })
}

/// The approximate normal problem `method` of one patch at the geometry's own approach (CONTACT's
/// `snorm_kpec_wrapper`: module 1 sets the approach, N = 0 per patch), on the patch's grid in
/// CONTACT's element order.
fn solve_approximate(method: Method, g: &PatchGeometry, m: &Material) -> Result<(f64, Vec<f64>), ApproximateError> {
    let p = &g.grid;
    let x = [p.x0_mm, p.x0_mm + p.dx_mm * p.mx as f64];
    let grid = Grid::from_edges(p.mx, p.ms, x, [p.s0_mm, p.s0_mm + p.ds_mm * p.ms as f64]);
    let pn_mpa = approximate::at_approach(method, &grid, &g.h_mm, 0.0, m)?;
    let fn_n = pn_mpa.iter().sum::<f64>() * p.dx_mm * p.ds_mm;
    Ok((fn_n, pn_mpa))
}

#[cfg(test)]
mod tests;
