//! One wheel–rail case through the stages: the wheel–rail geometry gives the patches with their
//! exact normal solution; each patch becomes a module-3 scene that every model solves in steady
//! rolling (the same grid, undeformed distance, FN and creepages for all); the patches' forces sum
//! to the totals on the rail. With FZ prescribed the height is found with the exact theory's
//! tangential forces included (CONTACT's N = 1 solves the full problem at each height): the
//! normal forces' vertical parts must carry FZ less the tangential forces' vertical parts, found
//! by rounds of a height search for the normal share ([`normal_share`]: a secant on the tangential
//! forces' vertical part through the last two rounds, FZ / (1 + Fz_tangential / Fz_normal) at
//! first), the first search loose.
//!
//! Signs and frames are CONTACT's module-1 output's: forces on the rail; each patch's FX along the
//! track, FS in its tangent plane (lateral), FN along its normal; totals in track and wheelset
//! coordinates, y to the right on both sides.

use super::resolve;
use super::wheelrail_exact::{self, ExactCache};
use super::wheelrail_frame::RollingFrame;
use crate::error::{Error, InputError};
use crate::history::sample_loop::{run_with_fields, Field};
use crate::physics::geometry::{Extent, GeometrySpec};
use crate::physics::halfspace::blend::Blend;
use crate::problem::Problem;
use crate::scene::wheelrail::{moving_allowed, Approach, SHIFT_MODELS, TRANSIENT_ROLLING_MODELS};
use crate::scene::wheelrail_tangential::Tangential;
use crate::scene::Scene;
use crate::solvers;
use crate::solvers::brush::Tractions;
use crate::wheelrail::friction::Friction;
use crate::wheelrail::shift::Previous;
use crate::wheelrail::vertical::{Stop, FORCE_TOL};
use crate::wheelrail::{self, Motion, NormalContact, NormalPatch, Vertical, WheelRailCase};
use nalgebra::{Rotation3, Vector3};
use std::path::Path;

/// The model whose tangential forces enter the vertical balance: the exact theory.
pub const EXACT: &str = "contact";
/// Rounds of the vertical balance with the tangential forces (each a height search).
const VERTICAL_ROUNDS: usize = 20;
/// The first height search's relative force tolerance where rounds with the tangential forces
/// follow (each later search is made to [`FORCE_TOL`]): the rounds move its target by the
/// tangential forces' vertical part (0.07 to 0.5 % of FZ on the Manchester decks), so a miss of a
/// fifth of that or less costs the later searches nothing that a tighter first search would not.
/// Nor need its height's normal problems be solved again to the full tolerance (a re-solve of 4 to
/// 14 CG iterations per case on the Manchester decks): the first round's tangential forces take
/// the pressure of the trial height that met it, solved loosely, and only set the next target.
const FIRST_SEARCH_TOL: f64 = 1e-3;
/// Blanco's correction: the rounds end when the tangential tractions' normal displacement moved by
/// at most this times the deepest approach since the normal solves took it.
const BLANCO_UN_TOL: f64 = 1e-8;
/// The least change of the normal forces between two rounds, relative to FZ, for a secant of the
/// tangential ones (below it the tangential solves' tolerance would dominate their difference).
const SECANT_SPAN: f64 = 1e-6;

/// One model's forces on one patch, CONTACT's signs (on the rail), the side's frame.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchForces {
    pub fn_n: f64,
    pub fx_n: f64,
    pub fs_n: f64,
    pub mn_nmm: f64,
    /// Elements in adhesion and in slip, where the model tells them apart.
    pub n_adhesion: Option<usize>,
    pub n_slip: Option<usize>,
    /// In a shift, the exact theory's tractions `(px, py)` per element [MPa] (CONTACT's element
    /// order, the solver's signs, the patch's own frame, never mirrored): what the next case of a
    /// sequence of shifts continues from.
    pub shift_tractions_mpa: Option<(Vec<f64>, Vec<f64>)>,
    /// Per element (CONTACT's element order) whether it slips, where the model tells adhesion
    /// from slip on the patch's own grid: what the report's patch maps draw, from this solve.
    pub slip: Option<Vec<bool>>,
    /// The largest surface temperature of both bodies on the patch [°C] (CONTACT's MAX(T1,T2)),
    /// where the scene computes them (`[material]`'s heat keys).
    pub temp_max_c: Option<f64>,
    /// Blanco's correction (`[material] blanco_variant`): the normal displacement `B_nt p_t` [mm]
    /// of the exact theory's tangential tractions per element (CONTACT's element order), which
    /// the next normal solve of the patch adds to its distance.
    pub blanco_un_mm: Option<Vec<f64>>,
}

impl PatchForces {
    /// A module-3 solution on patch `p` (forces on body 2, the right-side frame: Fx/FN, Fy/FN,
    /// MZ) turned to CONTACT's module-1 signs (on the rail) and the side's frame.
    pub fn on_rail(p: &NormalPatch, case: &WheelRailCase, fx_over_fn: f64, fy_over_fn: f64, mz_nmm: f64) -> Self {
        let m = case.side.sign();
        PatchForces {
            fn_n: p.fn_n,
            fx_n: -fx_over_fn * p.fn_n,
            fs_n: -m * fy_over_fn * p.fn_n,
            mn_nmm: -m * mz_nmm,
            n_adhesion: None,
            n_slip: None,
            shift_tractions_mpa: None,
            slip: None,
            temp_max_c: None,
            blanco_un_mm: None,
        }
    }
}

/// The forces on the rail summed over the patches [N]: track and wheelset coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Totals {
    pub track_n: [f64; 3],
    pub wheelset_n: [f64; 3],
}

/// A case solved: its patches (normal contact) and per model the patches' forces and totals.
#[derive(Debug, Clone)]
pub struct CaseResult {
    /// The exact theory's patches, which every model without a normal problem of its own shares
    /// (with none such asked for: the first model's own).
    pub normal: NormalContact,
    /// The patches of the models that solve their own normal problem ([`solvers::ModelDef::own_normal`]).
    pub own_normals: Vec<(String, NormalContact)>,
    /// `(model, forces per patch, totals)` in the order of the models asked for.
    pub models: Vec<(String, Vec<PatchForces>, Totals)>,
    /// The pitch velocity the case was solved at.
    pub pitch: Pitch,
    /// On a massless rail (CONTACT's F = 3), the rail's deflection found: DY_DEFL along the side's
    /// own y, DZ_DEFL downwards [mm] ([`super::wheelrail_massless`]).
    pub rail_deflection_mm: Option<[f64; 2]>,
}

/// The wheelset's pitch velocity VPITCH [rad/s]: given (CONTACT's F = 0), or found for a
/// prescribed FX_WS (F = 1, [`super::wheelrail_fx`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pitch {
    Given(f64),
    /// Found, with how far it moves per newton of FX(WS) [rad/s/N] (the secant's slope there)
    /// and μ of the patch of largest FN (CONTACT's stopping tolerance is EPS·μ·FZ).
    Found {
        rad_s: f64,
        per_fx_rad_s_n: f64,
        mu: f64,
    },
}

impl CaseResult {
    /// The patches `model`'s forces are on.
    pub fn normal_of(&self, model: &str) -> &NormalContact {
        self.own_normals.iter().find(|(m, _)| m == model).map_or(&self.normal, |(_, n)| n)
    }
}

impl Pitch {
    pub fn rad_s(self) -> f64 {
        match self {
            Pitch::Given(v) | Pitch::Found { rad_s: v, .. } => v,
        }
    }
}

/// Solve `case` with `models` (names of the registry) at Coulomb friction `mu`.
pub fn solve(case: &WheelRailCase, models: &[String], mu: f64) -> Result<CaseResult, Error> {
    solve_with(case, models, &Friction { mu, variation: None, frictionless: false })
}

/// Solve `case` with `models`, each patch at its Coulomb friction (varying across the rail or
/// along the track where `mu` says so). The models that solve their own approximate normal problem
/// (KPEC, ANALYN) take their own patches and height; every other model the exact theory's.
pub fn solve_with(case: &WheelRailCase, models: &[String], mu: &Friction) -> Result<CaseResult, Error> {
    solve_step(case, models, mu, &[])
}

/// [`solve_with`] in a sequence: each model other than the exact theory continues its own
/// `histories` (the patches the case before left with its tractions, [`super::wheelrail_brush`]);
/// in a shift or transient rolling a model without one starts from rest. The exact theory's are
/// the case's `previous`.
pub fn solve_step(
    case: &WheelRailCase,
    models: &[String],
    mu: &Friction,
    histories: &[(String, Previous)],
) -> Result<CaseResult, Error> {
    refuse_in_shifts(case, models)?;
    refuse_on_surfaces(case, models, mu)?;
    let own = |m: &str| solvers::builtin(m).and_then(|d| d.own_normal);
    let mut exact_cache = ExactCache::default();
    let mut shared = None;
    if models.iter().any(|m| own(m).is_none()) {
        let exact = |n: &NormalContact| exact_forces(n, mu, case, &mut exact_cache);
        shared = Some(balanced(case, mu, &mut wheelrail::NormalCache::default(), exact)?);
    }
    let mut out = Vec::new();
    let mut own_normals = Vec::new();
    for model in models {
        let (forces, totals) = match own(model) {
            Some(method) => {
                let theirs = |n: &NormalContact| patch_forces(n, model, mu, case);
                let (normal, forces) = balanced(case, mu, &mut wheelrail::NormalCache::approximate(method), theirs)?;
                let forces = match forces {
                    Some(f) => f,
                    None => patch_forces(&normal, model, mu, case)?,
                };
                let totals = totals(&normal, &forces, case);
                own_normals.push((model.clone(), normal));
                (forces, totals)
            }
            None => {
                let (normal, found) = shared.as_mut().expect("the shared normal contact is solved for this model");
                let forces = match found.take_if(|_| model == EXACT) {
                    Some(exact) => exact,
                    None if model == EXACT => exact_forces(normal, mu, case, &mut exact_cache)?,
                    None if case.motion != Motion::Rolling
                        || (case.previous.is_some() && SHIFT_MODELS.contains(&model.as_str())) =>
                    {
                        let history = histories.iter().find(|(m, _)| m == model).map(|(_, h)| h);
                        brush_forces(normal, model, mu, case, history)?
                    }
                    None => patch_forces(normal, model, mu, case)?,
                };
                let totals = totals(normal, &forces, case);
                (forces, totals)
            }
        };
        out.push((model.clone(), forces, totals));
    }
    let normal = match shared {
        Some((n, _)) => n,
        None => own_normals[0].1.clone(),
    };
    Ok(CaseResult {
        normal,
        own_normals,
        models: out,
        pitch: Pitch::Given(case.velocity.vpitch_rad_s),
        rail_deflection_mm: None,
    })
}

/// The normal contact of `case` with the normal problem of `cache` (exact or approximate): with FZ
/// prescribed and friction, the height where the normal forces' and `forces`' vertical parts
/// carry FZ (rounds of height searches, [`normal_share`]), and the forces found there; frictionless,
/// every patch's normal force alone.
fn balanced(
    case: &WheelRailCase,
    mu: &Friction,
    cache: &mut wheelrail::NormalCache,
    mut forces: impl FnMut(&NormalContact) -> Result<Vec<PatchForces>, Error>,
) -> Result<(NormalContact, Option<Vec<PatchForces>>), Error> {
    let geometry = |e: wheelrail::WheelRailError| {
        Error::from(InputError::new(
            "contact geometry",
            "no solution",
            format!("{e}; a wheel that touches the rail, at a height that carries FZ, with patches within the grid limit (docs/wheelrail.md)"),
        ))
    };
    // With the tangential forces to balance, the first height search need not be tight: the
    // rounds move its target by their vertical part.
    let rounds = matches!(case.vertical, Vertical::Force { .. }) && !mu.frictionless;
    let first = match rounds {
        true => Stop { tol: FIRST_SEARCH_TOL, exact: false },
        false => Stop::exact(FORCE_TOL),
    };
    let mut normal = wheelrail::normal_contact_with(case, None, first, cache).map_err(geometry)?;
    if mu.frictionless {
        let forces = normal.patches.iter().map(frictionless).collect();
        return Ok((normal, Some(forces)));
    }
    let Vertical::Force { fz_n } = case.vertical else { return Ok((normal, None)) };
    // The last round's normal and tangential vertical forces (the secant's other point).
    let mut last: Option<(f64, f64)> = None;
    // Whether the normal solution's height was solved to the full tolerance (not the first
    // search's loose end): only such a one is an answer.
    let mut exact = first.exact;
    for _ in 0..VERTICAL_ROUNDS {
        let found = forces(&normal)?;
        let normal_z = normal.fz_normal_n();
        let tangential_z: f64 = normal
            .patches
            .iter()
            .zip(&found)
            .map(|(p, f)| {
                // A conformal patch's FN holds the tractions' part besides the pressure's.
                let delta = p.geometry.frame.delta_rad;
                (f.fn_n - p.fn_n) * delta.cos() + case.side.sign() * f.fs_n * delta.sin()
            })
            .sum();
        // Blanco's correction: the tractions' normal displacement for the next normal solves, and
        // whether it moved since the last (CONTACT's Panagiotopoulos process).
        let coupled = blanco_coupled(&normal, &found, cache);
        let balanced = coupled && (normal_z + tangential_z - fz_n).abs() <= 2.0 * FORCE_TOL * fz_n;
        if (exact && balanced) || normal_z <= 0.0 {
            return Ok((normal, Some(found)));
        }
        let target = normal_share(fz_n, (normal_z, tangential_z), last.take());
        last = Some((normal_z, tangential_z));
        normal = wheelrail::normal_contact_with(case, Some(target), Stop::exact(FORCE_TOL), cache).map_err(geometry)?;
        exact = true;
    }
    Ok((normal, None))
}

/// Blanco's correction (the patches' forces carry `blanco_un_mm`): hands each patch's normal
/// displacement of its tangential tractions to the next normal solves; whether the ones the last
/// normal solves took moved by at most [`BLANCO_UN_TOL`] of the deepest approach (true without the
/// correction).
fn blanco_coupled(normal: &NormalContact, found: &[PatchForces], cache: &mut wheelrail::NormalCache) -> bool {
    if found.iter().all(|f| f.blanco_un_mm.is_none()) {
        return true;
    }
    let fields = normal
        .patches
        .iter()
        .zip(found)
        .filter_map(|(p, f)| Some((p.geometry.grid.clone(), f.blanco_un_mm.clone()?)))
        .collect();
    let pen_mm = normal.patches.iter().map(|p| p.pen_mm).fold(0.0, f64::max);
    cache.set_blanco_coupling(fields) <= BLANCO_UN_TOL * pen_mm
}

/// A shift (CONTACT's T = 1) or a transient rolling step (T = 2) is solved by the models that
/// carry their history through it ([`SHIFT_MODELS`], [`TRANSIENT_ROLLING_MODELS`]), for bodies
/// of one material.
fn refuse_in_shifts(case: &WheelRailCase, models: &[String]) -> Result<(), Error> {
    let (able, motion) = match case.motion {
        Motion::Rolling => return Ok(()),
        Motion::Shift { .. } if case.previous.is_some() => (SHIFT_MODELS, "shift_sequence"),
        Motion::Shift { .. } => (SHIFT_MODELS, "shift"),
        Motion::Transient { .. } => (TRANSIENT_ROLLING_MODELS, "rolling_sequence"),
    };
    if let Some(m) = models.iter().find(|m| !able.contains(&m.as_str())) {
        return Err(InputError::new("solvers", format!("{m:?}"), moving_allowed(able, motion)).into());
    }
    if case.material.coupled() {
        let value = format!("G {} MPa, nu {}", case.material.g_mpa, case.material.poisson);
        return Err(
            InputError::new("material", value, "one material for both bodies in a shift or transient rolling").into()
        );
    }
    Ok(())
}

/// The rigid slip on the actual surfaces (CONTACT's D = 3 and the conformal approach, D = 4) is
/// solved by the exact theory alone (the extra rigid slip per element), in steady rolling, shifts
/// or transient rolling with friction, for bodies of one material without surface temperatures,
/// on the contact locus of prismatic profiles, with the solver's default options.
fn refuse_on_surfaces(case: &WheelRailCase, models: &[String], mu: &Friction) -> Result<(), Error> {
    let name = match case.approach {
        Approach::Planar => return Ok(()),
        Approach::PlanarSurfaceSlip => "planar_surface_slip",
        Approach::Conformal => "conformal",
    };
    if let Some(m) = models.iter().find(|m| m.as_str() != EXACT) {
        let allowed = format!("the exact theory alone (solvers = [\"contact\"]) with approach = {name:?}");
        return Err(InputError::new("solvers", format!("{m:?}"), allowed).into());
    }
    let unsupported = [
        (mu.frictionless, "wheelrail.frictionless", "friction (the tractions turn the pressure's force)"),
        (case.material.coupled(), "material", "one material for both bodies"),
        (case.heat.is_some(), "material", "no surface temperatures"),
        (case.tangential != Default::default(), "friction / contact_solver", "Coulomb's law, the solver's defaults"),
        (case.search.is_grid(), "wheelrail.contact_search", "the contact locus (\"locus\")"),
        (
            case.rail_slices.is_some() || case.wheel_slices.is_some(),
            "rail / wheel profile",
            "prismatic profiles (no slices files)",
        ),
    ];
    match unsupported.iter().find(|(used, _, _)| *used) {
        Some((_, field, allowed)) => Err(InputError::new(
            *field,
            format!("with approach = {name:?}"),
            format!("{allowed} with approach = {name:?}"),
        )
        .into()),
        None => Ok(()),
    }
}

/// One model on the patches of `normal`: its forces per patch and their totals.
pub(super) fn model_forces(
    normal: &NormalContact,
    model: &str,
    mu: &Friction,
    case: &WheelRailCase,
) -> Result<(Vec<PatchForces>, Totals), Error> {
    let forces = patch_forces(normal, model, mu, case)?;
    let totals = totals(normal, &forces, case);
    Ok((forces, totals))
}

/// The normal forces' vertical share of `fz_n` for the next round from this round's normal and
/// tangential vertical forces `(n, t)` and the last round's: the tangential forces grow with the
/// normal ones, so N + T(N) = FZ is solved for N by the secant of T through the two rounds
/// (exact where T is linear in N), or, from one round or two too close for a secant, with T in
/// proportion to N (full slip): N = FZ / (1 + T / N).
fn normal_share(fz_n: f64, (n, t): (f64, f64), last: Option<(f64, f64)>) -> f64 {
    let proportional = fz_n / (1.0 + t / n);
    let Some((n0, t0)) = last.filter(|(n0, _)| (n - n0).abs() > SECANT_SPAN * fz_n) else { return proportional };
    let slope = (t - t0) / (n - n0);
    let share = (fz_n - t + slope * n) / (1.0 + slope);
    if share.is_finite() && share > 0.0 && slope > -0.5 {
        share
    } else {
        proportional
    }
}

/// A patch in frictionless compression (CONTACT's T = 0): its normal force only, every element in
/// contact counted as adhering, as CONTACT prints it.
fn frictionless(p: &NormalPatch) -> PatchForces {
    let ncon = p.pn_mpa.iter().filter(|&&pn| pn > 0.0).count();
    PatchForces {
        fn_n: p.fn_n,
        fx_n: 0.0,
        fs_n: 0.0,
        mn_nmm: 0.0,
        n_adhesion: Some(ncon),
        n_slip: Some(0),
        shift_tractions_mpa: None,
        slip: Some(vec![false; p.pn_mpa.len()]),
        temp_max_c: None,
        blanco_un_mm: None,
    }
}

/// One model's forces on every patch.
pub(crate) fn patch_forces(
    normal: &NormalContact,
    model: &str,
    mu: &Friction,
    case: &WheelRailCase,
) -> Result<Vec<PatchForces>, Error> {
    let solve = |p: &NormalPatch| match mu.temperature_law_of(p, case) {
        Some(law) => {
            let tangential = Tangential { temperature_law: Some(law), ..case.tangential };
            patch_solve(p, model, mu.of_patch(p, case), &WheelRailCase { tangential, ..*case })
        }
        None => patch_solve(p, model, mu.of_patch(p, case), case),
    };
    normal.patches.iter().map(solve).collect()
}

/// A model that carries its history ([`super::wheelrail_brush`]) on every patch of a case that
/// moves in time, or of the steady case that starts such a sequence.
fn brush_forces(
    normal: &NormalContact,
    model: &str,
    mu: &Friction,
    case: &WheelRailCase,
    history: Option<&Previous>,
) -> Result<Vec<PatchForces>, Error> {
    let solve = |p: &NormalPatch| super::wheelrail_brush::patch_forces(p, model, mu.of_patch(p, case), case, history);
    normal.patches.iter().map(solve).collect()
}

/// The exact theory's forces on every patch, solved on the patches directly
/// ([`wheelrail_exact`]: the patches' pressure, kernels kept per grid size); through each patch's
/// scene where the bodies are dissimilar (the coupled solver's outer iteration), the surface
/// temperatures are computed, friction is the temperature's or the solver's options are given.
fn exact_forces(
    normal: &NormalContact,
    mu: &Friction,
    case: &WheelRailCase,
    cache: &mut ExactCache,
) -> Result<Vec<PatchForces>, Error> {
    if case.material.coupled()
        || case.heat.is_some()
        || case.tangential != Default::default()
        || mu.temperature_varies()
    {
        return patch_forces(normal, EXACT, mu, case);
    }
    let failed = |e| Error::Solve { scene: "patch".into(), solver: EXACT.into(), source: Box::new(e) };
    normal
        .patches
        .iter()
        .map(|p| {
            let mu = mu.of_rows(p).map_or(wheelrail_exact::Mu::Patch(mu.of_patch(p, case)), wheelrail_exact::Mu::Rows);
            wheelrail_exact::patch_forces(p, mu, case, cache).map_err(failed)
        })
        .collect()
}

/// The module-3 scene text of a patch with `contact` (its geometry's keys) and `grid` tables.
fn scene_text(p: &NormalPatch, model: &str, mu: f64, case: &WheelRailCase, contact: &str, grid: &str) -> String {
    let (c, sign) = (&p.creepages, RollingFrame::of(p).sign());
    format!(
        "name = \"patch\"\nsolvers = [\"{model}\"]\n\
         [contact]\n{contact}\nfn_n = {fn_n}\nmu = {mu}\n\
         [material]\ng_mpa = {g}\npoisson = {nu}\n\
         [grid]\n{grid}\n\
         [rolling]\nv_mm_s = {v}\n\
         [creepage]\nkind = \"sweep\"\nat = [0.0]\ncx = {cx}\ncy = {cy}\ncs = {cs}\n",
        fn_n = p.fn_n,
        g = case.material.g_mpa,
        nu = case.material.poisson,
        v = c.veloc_mm_s,
        cx = sign * c.cksi,
        cy = c.ceta,
        cs = sign * c.cphi_per_mm,
    )
}

/// The patch as a module-3 scene on its own grid: its undeformed distance per element (CONTACT's
/// element order), FN, creepages and rolling speed, one steady sweep point; with `exact`, the
/// patch's pressure the exact normal problem's (its geometry then takes it instead of solving
/// the normal problem again at FN: the same pressure to the normal solver's tolerance).
fn field_scene(p: &NormalPatch, model: &str, mu: f64, case: &WheelRailCase) -> Result<Scene, InputError> {
    let g = &p.geometry.grid;
    let text = scene_text(p, model, mu, case, "a_mm = 1.0\nb_mm = 1.0", &format!("mx = {}\nmy = {}", g.mx, g.ms));
    let mut scene = Scene::from_toml(&text, Path::new("."))?;
    // The wheel–rail scene's heat, temperature law and solver options, as module 3 holds them.
    scene.material.heat = case.heat;
    if let Some(law) = case.tangential.temperature_law {
        scene.friction = crate::physics::FrictionLaw::Temperature(law);
    }
    scene.contact_solver = case.tangential.contact_solver;
    let frame = RollingFrame::of(p);
    let h_mm = frame.field(p.geometry.h_mm.to_vec());
    let blend = p.geometry.blend.clone().map(|b| Blend { part: frame.field(b.part), ..b });
    // The patch's solved pressure (the exact one's, or the model's own normal problem's: KPEC,
    // ANALYN) is the field's: the normal problem is not solved again for the module-3 problem.
    scene.geometry = GeometrySpec::Field { h_mm, blend, pn_mpa: Some(frame.field(p.pn_mpa.to_vec())) };
    let x_mm = [g.x0_mm, g.x0_mm + g.dx_mm * g.mx as f64];
    scene.extent = Extent::Edges { x_mm: frame.extent_x(x_mm), y_mm: [g.s0_mm, g.s0_mm + g.ds_mm * g.ms as f64] };
    Ok(scene)
}

/// The patch for a model that needs Hertz's ellipse (FaStrip): the equivalent ellipse of its
/// exact contact (Kik & Piotrowski: the same area and length-to-width ratio, CONTACT's
/// `equiv_ellipse`) at the patch's FN, its bounding box in elements of the patch's size.
fn ellipse_scene(
    field: &Problem,
    p: &NormalPatch,
    model: &str,
    mu: f64,
    case: &WheelRailCase,
) -> Result<Scene, InputError> {
    let e = field.hertz();
    let g = &p.geometry.grid;
    let elements = |length_mm: f64, size_mm: f64| ((length_mm / size_mm).ceil() as usize).clamp(8, 512);
    let grid = format!("mx = {}\nmy = {}", elements(2.0 * e.a_mm, g.dx_mm), elements(2.0 * e.b_mm, g.ds_mm));
    let text = scene_text(p, model, mu, case, &format!("a_mm = {}\nb_mm = {}", e.a_mm, e.b_mm), &grid);
    Scene::from_toml(&text, Path::new("."))
}

/// The problem a model solves on a patch: the patch's own grid and undeformed distance where the
/// model takes a contact given per element, else the equivalent ellipse; in the patch's rolling
/// frame ([`RollingFrame`]: mirrored about x = 0 for a patch rolling towards −x).
pub(super) fn patch_problem(p: &NormalPatch, model: &str, mu: f64, case: &WheelRailCase) -> Result<Problem, Error> {
    let refused = match resolve(&field_scene(p, model, mu, case)?) {
        Ok(problem) => return Ok(problem),
        Err(e) => e,
    };
    let exact = resolve(&field_scene(p, EXACT, mu, case)?)?;
    match solvers::builtin(model).map(|def| (def.check)(&exact)) {
        Some(Err(_)) => Ok(resolve(&ellipse_scene(&exact, p, model, mu, case)?)?),
        _ => Err(refused.into()),
    }
}

/// One model on one patch, its forces turned to CONTACT's signs and the side's frame.
pub(super) fn patch_solve(p: &NormalPatch, model: &str, mu: f64, case: &WheelRailCase) -> Result<PatchForces, Error> {
    let problem = patch_problem(p, model, mu, case)?;
    let def = solvers::builtin(model).ok_or_else(|| InputError::new("solvers", model, "a built-in model"))?;
    let failed = |e| Error::Solve { scene: "patch".into(), solver: model.into(), source: Box::new(e) };
    let (h, fields) = run_with_fields(&problem, def, &|_| true).map_err(failed)?;
    let row = &h.rows[0];
    let count = |name: &str| h.column(name).map(|c| c[0] as usize);
    let mz_nmm = h.column(crate::history::MZ).map_or(f64::NAN, |c| c[0]);
    let temperatures: Vec<f64> =
        solvers::contact::heat::COLUMNS.iter().filter_map(|n| h.column(n).map(|c| c[0])).collect();
    // The problem is in the patch's rolling frame (`field_scene`): its solution mapped back.
    let frame = RollingFrame::of(p);
    let (fx_over_fn, fy_over_fn, mz_nmm) = frame.totals((row.fx_over_fn, row.fy_over_fn, mz_nmm));
    Ok(PatchForces {
        n_adhesion: count("n_adhesion"),
        n_slip: count("n_slip"),
        temp_max_c: (!temperatures.is_empty()).then(|| temperatures.iter().copied().fold(f64::MIN, f64::max)),
        slip: fields.last().and_then(|f| slip_on_patch(p, &problem, f, count("n_slip"))).map(|s| frame.field(s)),
        ..PatchForces::on_rail(p, case, fx_over_fn, fy_over_fn, mz_nmm)
    })
}

/// A model's slip per element of patch `p` (CONTACT's element order) from its field on the
/// patch's module-3 problem, if the model solves on the patch's grid and tells adhesion from slip:
/// by its element states, or else by its traction on the bound where it counts `n_slip` so.
fn slip_on_patch(p: &NormalPatch, problem: &Problem, f: &Field, n_slip: Option<usize>) -> Option<Vec<bool>> {
    let n = p.geometry.grid.len();
    if problem.grid.len() != n || f.pn_mpa.len() != n {
        return None;
    }
    if f.state.len() == n {
        return Some(wheelrail_exact::slip_of(&problem.grid, &f.state));
    }
    let t = Tractions { tx: f.px_mpa.clone(), ty: f.py_mpa.clone() };
    let slip = on_bound_counted(&t, &f.pn_mpa, problem.loading.first().mu, n_slip?)?;
    Some(wheelrail_exact::in_contact_order(&problem.grid, &slip))
}

/// Per element (grid order) whether a brush model's traction sits on its bound μ p, if exactly
/// `n_slip` do (the model's own count of its slipping elements).
pub(super) fn on_bound_counted(t: &Tractions, pressure_mpa: &[f64], mu: f64, n_slip: usize) -> Option<Vec<bool>> {
    let slip = t.slipping(pressure_mpa, mu);
    (slip.iter().filter(|&&s| s).count() == n_slip).then_some(slip)
}

/// The totals on the rail in track and wheelset coordinates (the side's frame).
fn totals(normal: &NormalContact, forces: &[PatchForces], case: &WheelRailCase) -> Totals {
    let m = case.side.sign();
    let mut f = Vector3::zeros();
    for (p, pf) in normal.patches.iter().zip(forces) {
        let frame = &p.geometry.frame;
        // Right-side frame: FS along e_s, FN along n; pf.fs_n is in the side's sign.
        f += Vector3::x() * pf.fx_n + frame.e_s() * (m * pf.fs_n) + frame.n() * pf.fn_n;
    }
    let side = |v: Vector3<f64>| [v.x, m * v.y, v.z];
    let pose = case.side.pose(&case.pose);
    let rotation = Rotation3::from_axis_angle(&Vector3::x_axis(), pose.roll_rad)
        * Rotation3::from_axis_angle(&Vector3::z_axis(), pose.yaw_rad);
    Totals { track_n: side(f), wheelset_n: side(rotation.inverse() * f) }
}

#[cfg(test)]
mod tests {
    use super::normal_share;

    #[test]
    fn the_normal_share_is_exact_for_tangential_forces_linear_in_the_normal_ones() {
        // T(N) = −0.004 N − 10: N + T(N) = FZ at N = (FZ + 10) / 0.996.
        let t = |n: f64| -0.004 * n - 10.0;
        let fz = 10000.0;
        let share = normal_share(fz, (10040.0, t(10040.0)), Some((10000.0, t(10000.0))));
        assert!((share - (fz + 10.0) / 0.996).abs() < 1e-9 * fz, "{share}");
        // One round, or two too close for a secant: T in proportion to N.
        let proportional = fz / (1.0 + t(10040.0) / 10040.0);
        assert_eq!(normal_share(fz, (10040.0, t(10040.0)), None), proportional);
        assert_eq!(normal_share(fz, (10040.0, t(10040.0)), Some((10040.0 - 1e-4, t(10040.0)))), proportional);
    }
}
