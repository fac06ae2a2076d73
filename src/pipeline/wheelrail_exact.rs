//! The exact theory on a wheel–rail patch without a module-3 scene: the patch's solved pressure
//! handed to the tangential solver (Kalker's steady rolling, `solvers::contact::tangential`) on
//! the grid the scene would make (CONTACT's x mirrored, [`field_in_grid_order`]), its kernels and
//! FFT plans kept per grid size for the case's trial heights and rounds. The same solve as the
//! `contact` model's on the patch's scene: one steady point, the scene's default controls
//! (`[contact_solver]`), rolling along +x with dq = dx, Coulomb's μ. In a shift (CONTACT's T = 1)
//! one transient shift step ([`TangentialSolver::for_shifts`]: the creepages are the step's shifts,
//! dq = 1) from zero tractions (P = 2) or from those the case before left on the patch's grid
//! (P = 0, [`crate::wheelrail::shift`]).

use super::wheelrail::PatchForces;
use super::wheelrail_blanco::{BlancoCache, SOLVER_TURN};
use super::wheelrail_conformal;
use super::wheelrail_frame::RollingFrame;
use crate::physics::geometry::field_in_grid_order;
use crate::physics::halfspace::influence::Kernel;
use crate::physics::{moment_sum, Grid, Material};
use crate::scene::ContactSolverOptions;
use crate::solvers::contact::tangential::{StepResult, TangentialParams, TangentialSolver};
use crate::solvers::contact::ContactError;
use crate::solvers::stepper::ElementState;
use crate::wheelrail::{shift, Motion, NormalPatch, WheelRailCase};

/// Grids kept per case (the oldest dropped first).
const KEPT: usize = 8;

/// A solver and its last tractions `(px, py)` [MPa] (none before its first solve).
type Kept = ((usize, usize), TangentialSolver, Option<(Vec<f64>, Vec<f64>)>);

/// The tangential solvers of one case by grid size `(mx, ms)`, with each one's last solution
/// (the warm start of the next solve on that size: the same patch at a nearby height).
#[derive(Default)]
pub struct ExactCache {
    solvers: Vec<Kept>,
    /// The shift solvers by grid size (no warm start: each shift starts from rest).
    shifts: Vec<((usize, usize), TangentialSolver)>,
    /// The transient rolling solvers by grid size (their kernels shifted by the step's dq).
    transients: Vec<((usize, usize), TangentialSolver)>,
    /// Blanco's correction's products by grid size (`[material] blanco_variant`).
    blanco: BlancoCache,
}

impl ExactCache {
    /// The solver of an `mx × my` grid of `(dx, dy)` elements of material `m`, centred at `x`, `y`,
    /// with its last tractions.
    fn get(&mut self, grid: &Grid, m: &Material, (x, y): (&[f64], &[f64])) -> Result<&mut Kept, ContactError> {
        let key = (grid.mx, grid.my);
        let k = match self.solvers.iter().position(|(k, _, _)| *k == key) {
            Some(k) => {
                self.solvers[k].1.set_centres(x, y)?;
                k
            }
            None => {
                let (size, material) = ((grid.dx_mm, grid.dy_mm), (m.g_mpa, m.poisson));
                let k0 = Kernel::new(grid.mx, grid.my, size.0, size.1, material.0, material.1, 0.0)?;
                let ks = Kernel::new(grid.mx, grid.my, size.0, size.1, material.0, material.1, grid.dx_mm)?;
                if self.solvers.len() == KEPT {
                    self.solvers.remove(0);
                }
                self.solvers.push((key, TangentialSolver::new(&k0, &ks, x, y)?, None));
                self.solvers.len() - 1
            }
        };
        Ok(&mut self.solvers[k])
    }

    /// The shift solver of `grid` (as [`ExactCache::get`]: kernels kept per grid size); with
    /// `rolling_dq_mm` the transient rolling solver whose material moves by that step.
    fn step_solver(
        &mut self,
        grid: &Grid,
        m: &Material,
        (x, y): (&[f64], &[f64]),
        rolling_dq_mm: Option<f64>,
    ) -> Result<&mut TangentialSolver, ContactError> {
        let key = (grid.mx, grid.my);
        let kept = if rolling_dq_mm.is_some() { &mut self.transients } else { &mut self.shifts };
        let k = match kept.iter().position(|(k, _)| *k == key) {
            Some(k) => {
                kept[k].1.set_centres(x, y)?;
                k
            }
            None => {
                let k0 = Kernel::new(grid.mx, grid.my, grid.dx_mm, grid.dy_mm, m.g_mpa, m.poisson, 0.0)?;
                let solver = match rolling_dq_mm {
                    Some(dq) => {
                        let ks = Kernel::new(grid.mx, grid.my, grid.dx_mm, grid.dy_mm, m.g_mpa, m.poisson, dq)?;
                        TangentialSolver::new(&k0, &ks, x, y)?
                    }
                    None => TangentialSolver::for_shifts(&k0, x, y)?,
                };
                if kept.len() == KEPT {
                    kept.remove(0);
                }
                kept.push((key, solver));
                kept.len() - 1
            }
        };
        Ok(&mut kept[k].1)
    }
}

/// The grid of the patch's module-3 scene (`[grid]` edges, CONTACT's x mirrored) with the
/// patch's own element size (CONTACT's DX, DS; the edges' span over the count may differ from it
/// in the last bit): the kernels of every grid of the case, and of the normal solves, are then of
/// one element size, whose coefficient tables are kept across grids (`halfspace::table`).
fn patch_grid(p: &NormalPatch) -> Grid {
    let g = &p.geometry.grid;
    let (x0, x1) = (g.x0_mm, g.x0_mm + g.dx_mm * g.mx as f64);
    let edges = Grid::from_edges(g.mx, g.ms, [-x1, -x0], [g.s0_mm, g.s0_mm + g.ds_mm * g.ms as f64]);
    Grid { dx_mm: g.dx_mm, dy_mm: g.ds_mm, ..edges }
}

/// The exact theory's forces on patch `p` at Coulomb's `mu` (CONTACT's signs, the side's frame),
/// as the `contact` model gives them on the patch's scene (to its tolerance: the solve starts
/// from the last tractions found on a grid of the patch's size).
pub fn patch_forces(
    p: &NormalPatch,
    mu: Mu,
    case: &WheelRailCase,
    cache: &mut ExactCache,
) -> Result<PatchForces, ContactError> {
    let shift = matches!(case.motion, Motion::Shift { .. });
    let rolling_dq_mm = match case.motion {
        Motion::Transient { dq_mm } => Some(dq_mm),
        _ => None,
    };
    let grid = patch_grid(p);
    let c = &p.creepages;
    // Rolling towards −x: the solver takes the problem mirrored about x = 0.
    let solver_frame = RollingFrame::of(p);
    let pn = solver_frame.field(field_in_grid_order(&grid, &p.pn_mpa));
    let (x, y) = grid.centres();
    let x = solver_frame.field_x(x);
    let options = ContactSolverOptions::default();
    let dq_mm = if shift { 1.0 } else { rolling_dq_mm.unwrap_or(grid.dx_mm) };
    let bound = |pn_contact: &[f64]| match &mu {
        Mu::Rows(rows) => {
            Some(solver_frame.field(field_in_grid_order(&grid, &per_row(rows, pn_contact, p.geometry.grid.mx))))
        }
        Mu::Patch(_) => None,
    };
    let mu_solve = match mu {
        Mu::Patch(mu) => mu,
        Mu::Rows(_) => 1.0,
    };
    let sign = solver_frame.sign();
    let mut params = TangentialParams::new(mu_solve, sign * c.cksi, c.ceta, sign * c.cphi_per_mm, dq_mm);
    params.tol = options.tolerance;
    params.max_iter = options.max_iterations;
    let extra = p
        .extra_slip
        .as_ref()
        .map(|(wx, wy)| solver_frame.pair((field_in_grid_order(&grid, wx), field_in_grid_order(&grid, wy))));
    let extra = extra.as_ref().map(|(wx, wy)| (wx.as_slice(), wy.as_slice()));
    let mut blanco_un_mm = None;
    let r: StepResult = if shift || rolling_dq_mm.is_some() {
        let solver = cache.step_solver(&grid, &case.material, (&x, &y), rolling_dq_mm)?;
        solver.set_pressure(&pn)?;
        solver.set_extra_slip(extra)?;
        if let Some(g) = bound(&p.pn_mpa) {
            solver.set_bound(&g)?;
        }
        let (px0, py0) = previous_tractions(p, case);
        let (px0, py0) = solver_frame.pair((field_in_grid_order(&grid, &px0), field_in_grid_order(&grid, &py0)));
        solver.transient_step(&params, &px0, &py0, None)?
    } else {
        let mut blanco = match blanco_rows(p, case)? {
            Some((rows, variant)) => Some(cache.blanco.take(&grid, &case.material, (&rows, variant))?),
            None => None,
        };
        let (_, solver, last) = cache.get(&grid, &case.material, (&x, &y))?;
        solver.set_pressure(&pn)?;
        solver.set_extra_slip(extra)?;
        if let Some(g) = bound(&p.pn_mpa) {
            solver.set_bound(&g)?;
        }
        let start = last.as_ref().map(|(px, py)| (px.as_slice(), py.as_slice()));
        let r = match blanco.as_mut() {
            Some(b) => b.steady(solver, &params, start, &pn),
            None => solver.steady(&params, start),
        };
        let r = r.and_then(|r| {
            *last = Some((r.px.clone(), r.py.clone()));
            // The tractions' normal displacement, back in CONTACT's element order.
            let un = match blanco.as_mut() {
                Some(b) => Some(in_contact_order(&grid, &solver_frame.field(b.traction_un(&r.px, &r.py)?))),
                None => None,
            };
            Ok((r, un))
        });
        if let Some(b) = blanco {
            cache.blanco.put((grid.mx, grid.my), b);
        }
        let (r, un) = r?;
        blanco_un_mm = un;
        r
    };
    let r = solver_frame.back(r);
    // Kept for the case that continues this one: in a shift, a transient step, or the steady case
    // that starts a sequence (its `previous` empty).
    let kept = shift || rolling_dq_mm.is_some() || case.previous.is_some();
    let shift_tractions_mpa = kept.then(|| (in_contact_order(&grid, &r.px), in_contact_order(&grid, &r.py)));
    if let Some(c) = &p.geometry.curved {
        // CONTACT's tractions on the rail: its element order, the solver's negated.
        let on_rail = |f: &[f64]| in_contact_order(&grid, f).into_iter().map(|v| -v).collect::<Vec<f64>>();
        let forces = wheelrail_conformal::aggregate(&p.geometry, c, &on_rail(&r.px), &on_rail(&r.py), &p.pn_mpa);
        let forces = PatchForces {
            n_adhesion: Some(r.n_adhesion),
            n_slip: Some(r.n_slip),
            shift_tractions_mpa,
            slip: Some(slip_of(&grid, &r.state)),
            blanco_un_mm,
            ..forces.on_rail(case.side.sign())
        };
        return Ok(if case.motion.super_grid_s_mm().is_some() { about_anchor_x(forces, p) } else { forces });
    }
    let pn_sum: f64 = pn.iter().sum();
    let (fx_over_fn, fy_over_fn) = (r.px.iter().sum::<f64>() / pn_sum, r.py.iter().sum::<f64>() / pn_sum);
    let mz_nmm = moment_sum(&grid, &r.px, &r.py) * grid.element_area_mm2();
    let forces = PatchForces {
        n_adhesion: Some(r.n_adhesion),
        n_slip: Some(r.n_slip),
        shift_tractions_mpa,
        slip: Some(slip_of(&grid, &r.state)),
        ..PatchForces::on_rail(p, case, fx_over_fn, fy_over_fn, mz_nmm)
    };
    Ok(if case.motion.super_grid_s_mm().is_some() { about_anchor(forces, p, case) } else { forces })
}

/// The rows' inclinations of a conformal patch in the solver's frame where the case takes
/// Blanco's correction (CONTACT's times [`SOLVER_TURN`]) with its variant; `None`: the
/// half-space's coefficients.
fn blanco_rows(p: &NormalPatch, case: &WheelRailCase) -> Result<Option<(Vec<f64>, u8)>, ContactError> {
    let (Some(b), Some(c)) = (case.material.blanco, &p.geometry.curved) else { return Ok(None) };
    let rows = crate::wheelrail::conformal_grid::blanco_rows(&p.geometry.grid, c, b)?;
    Ok(Some((rows.into_iter().map(|a| SOLVER_TURN * a).collect(), b.variant)))
}

/// Coulomb's μ of a patch: one value, or one per grid row (a conformal patch with V = 1).
#[derive(Debug, Clone, PartialEq)]
pub enum Mu {
    Patch(f64),
    Rows(Vec<f64>),
}

/// The traction bound μ_j pn [MPa] of a field in CONTACT's element order, μ per row of `mx`.
fn per_row(mu: &[f64], pn_mpa: &[f64], mx: usize) -> Vec<f64> {
    pn_mpa.iter().enumerate().map(|(k, pn)| mu[k / mx] * pn).collect()
}

/// The tractions a shift starts from on patch `p` (CONTACT's element order): zero from rest; in a
/// sequence those of the old patches it connects to, on its grid ([`shift`]).
pub(super) fn previous_tractions(p: &NormalPatch, case: &WheelRailCase) -> (Vec<f64>, Vec<f64>) {
    let g = &p.geometry.grid;
    match case.previous.and_then(|prev| shift::inherited_by(p.geometry.extent, prev)) {
        Some(old) => shift::on_grid(&old, g),
        None => (vec![0.0; g.len()], vec![0.0; g.len()]),
    }
}

/// Whether each element slips, from the solver's states (grid order) to CONTACT's element order.
pub(super) fn slip_of(grid: &Grid, state: &[ElementState]) -> Vec<bool> {
    let slips: Vec<bool> = state.iter().map(|s| *s == ElementState::Slip).collect();
    in_contact_order(grid, &slips)
}

/// A field in the grid's flat order back in CONTACT's element order (the inverse of
/// [`field_in_grid_order`]: x mirrored).
pub(super) fn in_contact_order<T: Copy + Default>(grid: &Grid, field: &[T]) -> Vec<T> {
    let mut out = vec![T::default(); field.len()];
    for j in 0..grid.my {
        for i in 0..grid.mx {
            out[j * grid.mx + (grid.mx - 1 - i)] = field[grid.index(i, j)];
        }
    }
    out
}

/// MN about the grid's anchor instead of the reference: in a shift CONTACT's module-3 problem
/// has its origin at the super-grid's `mpot` and the reference at (SPINXO, SPINYO) from it
/// (`m_wr_solvecp`), and prints the patch's MN about that origin: MN + SPINXO FS − SPINYO FX in
/// the right-side frame (the left side's values mirrored).
pub(super) fn about_anchor(f: PatchForces, p: &NormalPatch, case: &WheelRailCase) -> PatchForces {
    let m = case.side.sign();
    let [ax, as_] = p.geometry.grid.anchor_mm;
    let (spinxo, spinyo) = (-ax, -as_);
    PatchForces { mn_nmm: f.mn_nmm + spinxo * f.fs_n - m * spinyo * f.fx_n, ..f }
}

/// A conformal patch's MN on the super-grid: CONTACT's `aggregate_forces` takes the elements' x
/// from the grid's anchor (`mpot`) and their sp from the reference, MN + SPINXO FS.
fn about_anchor_x(f: PatchForces, p: &NormalPatch) -> PatchForces {
    let spinxo = -p.geometry.grid.anchor_mm[0];
    PatchForces { mn_nmm: f.mn_nmm + spinxo * f.fs_n, ..f }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::wheelrail::{patch_forces as through_scenes, EXACT};
    use crate::pipeline::wheelrail_scene::{case_of, prepare, RailProfile, WheelProfile};
    use crate::problem::material_of_spec;
    use crate::scene::wheelrail::WheelRailScene;
    use crate::wheelrail::friction::Friction;
    use std::path::Path;

    /// The Manchester benchmark's right-wheel scene with its profiles and material.
    fn manchester_right() -> (WheelRailScene, RailProfile, WheelProfile, Material) {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/wheelrail/mbench_a22_right.toml");
        let text = std::fs::read_to_string(&path).unwrap();
        let scene = WheelRailScene::from_toml(&text, path.parent().unwrap()).unwrap();
        let (rail, wheel, _) = prepare(&scene).unwrap();
        let material = material_of_spec(&scene.material).unwrap();
        (scene, rail, wheel, material)
    }

    #[test]
    fn the_direct_solve_gives_the_contact_models_forces_on_the_patches_scenes() {
        let (scene, rail, wheel, material) = manchester_right();
        let mut cache = ExactCache::default();
        // Case 11: two patches (tread and flange), grids of two sizes; case 12 reuses them.
        for number in [11, 12] {
            let row = scene.cases.iter().find(|r| r.contact_case == number).unwrap();
            let case = case_of(&scene, row, &rail, &wheel, material);
            let normal = crate::wheelrail::normal_contact(&case, None).unwrap();
            let friction = Friction { mu: scene.mu, variation: None, frictionless: false };
            let scenes = through_scenes(&normal, EXACT, &friction, &case).unwrap();
            assert!(!normal.patches.is_empty());
            for (p, want) in normal.patches.iter().zip(&scenes) {
                let got = patch_forces(p, Mu::Patch(scene.mu), &case, &mut cache).unwrap();
                // The scenes take the patch's pressure; the tangential solve here starts warm.
                let close = |a: f64, b: f64, scale: f64| (a - b).abs() <= 1e-7 * scale;
                assert!(close(got.fx_n, want.fx_n, p.fn_n), "case {number}: FX {} vs {}", got.fx_n, want.fx_n);
                assert!(close(got.fs_n, want.fs_n, p.fn_n), "case {number}: FS {} vs {}", got.fs_n, want.fs_n);
                assert!(close(got.mn_nmm, want.mn_nmm, p.fn_n), "case {number}: MN {} vs {}", got.mn_nmm, want.mn_nmm);
                assert_eq!((got.fn_n, got.n_adhesion, got.n_slip), (want.fn_n, want.n_adhesion, want.n_slip));
            }
        }
    }

    /// A patch rolling towards −x (CHI = 180°): the direct solve (its problem mirrored in the
    /// solver, [`RollingFrame`]) and the models' patch scene (mirrored in the scene,
    /// `RollingFrame` too) give the same forces and slip; and rolling the
    /// other way changes them (the patch is not symmetric in x: right case 14's flange contact).
    #[test]
    fn a_patch_rolling_backwards_is_solved_mirrored_on_both_paths() {
        let (scene, rail, wheel, material) = manchester_right();
        let row = scene.cases.iter().find(|r| r.contact_case == 14).unwrap();
        let case = case_of(&scene, row, &rail, &wheel, material);
        let mut normal = crate::wheelrail::normal_contact(&case, None).unwrap();
        let friction = Friction { mu: scene.mu, variation: None, frictionless: false };
        let forward = through_scenes(&normal, EXACT, &friction, &case).unwrap();
        for p in &mut normal.patches {
            p.creepages.reversed = true;
        }
        let scenes = through_scenes(&normal, EXACT, &friction, &case).unwrap();
        let mut cache = ExactCache::default();
        for ((p, want), ahead) in normal.patches.iter().zip(&scenes).zip(&forward) {
            let got = patch_forces(p, Mu::Patch(scene.mu), &case, &mut cache).unwrap();
            let close = |a: f64, b: f64| (a - b).abs() <= 1e-7 * p.fn_n;
            assert!(close(got.fx_n, want.fx_n) && close(got.fs_n, want.fs_n) && close(got.mn_nmm, want.mn_nmm));
            assert_eq!((got.n_adhesion, got.n_slip, &got.slip), (want.n_adhesion, want.n_slip, &want.slip));
            let moved = (got.fx_n - ahead.fx_n).abs().max((got.mn_nmm - ahead.mn_nmm).abs());
            println!(
                "FN {:.1} N: FX {:.3} / {:.3} N, MN {:.3} / {:.3} N mm",
                p.fn_n, ahead.fx_n, got.fx_n, ahead.mn_nmm, got.mn_nmm
            );
            assert!(moved > 1e-3 * p.fn_n, "rolling backwards changed nothing: {moved}");
        }
    }
}
