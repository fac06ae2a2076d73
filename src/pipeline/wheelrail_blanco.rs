//! Blanco's conformal correction (`[material] blanco_variant`; CONTACT's C3 = 4) in the exact
//! tangential solve of a conformal wheel–rail patch in steady rolling: the solver's half-space
//! operator `A − A_s` completed to the corrected `B − B_s` ([`crate::physics::halfspace::blanco`])
//! by a slip `−((B − B_s) − (A − A_s)) (p_t, pn)` that the tractions of the last pass give (the
//! pressure's part couples the problems: a pressure displaces the curved surfaces laterally),
//! passes repeated until the tractions stand still; then the normal displacement `B_nt p_t` of
//! the tractions found, which the patch's next normal solve adds to its distance
//! (`wheelrail::NormalCache::set_blanco_coupling`): the rounds of the vertical balance alternate
//! the two problems as CONTACT's Panagiotopoulos process does.
//!
//! The solver's frame has CONTACT's x mirrored and its tangential tractions negated (those on the
//! other body, `wheelrail_exact`): a lateral traction and displacement change sign against the
//! normal ones, which turns the coupling's sign, the turn by −α ([`SOLVER_TURN`]). In every
//! variant: the half-space's kernel is the same in both frames, and each term of a corrected block
//! that couples n with x or s carries the turn's sine (odd in α), the others its cosine.

use crate::physics::halfspace::blanco::BlancoProduct;
use crate::physics::halfspace::influence::Kernel;
use crate::physics::{Grid, Material};
use crate::solvers::contact::tangential::{StepResult, TangentialParams, TangentialSolver};
use crate::solvers::contact::ContactError;

/// The solver frame's row inclinations are CONTACT's times this: its lateral tractions and
/// displacements are the negatives of CONTACT's, its normal ones CONTACT's. Measured on
/// `groove_li` case 5: with −1 every printed value of CONTACT's within its digits (NADH 928, PMAX
/// 520.6 MPa, CKSI −2.744e-4); with +1 NADH 753, PMAX 536.8 MPa, CKSI −2.718e-4.
pub const SOLVER_TURN: f64 = -1.0;

/// Passes of the tangential fixed point at most.
const PASSES: usize = 200;

/// The products of one grid: the steady operator's (`A − A_s`, the kernel shifted by dq = dx)
/// and the unshifted kernel's (the tractions' normal displacement).
pub struct BlancoTangential {
    steady: BlancoProduct,
    plain: BlancoProduct,
}

/// The products by grid size, kept per case as the solvers are.
#[derive(Default)]
pub struct BlancoCache {
    kept: Vec<((usize, usize), BlancoTangential)>,
}

/// Grids kept per case.
const KEPT: usize = 8;

impl BlancoCache {
    /// The products of `variant` on `grid` (material `m`, rolling by dq = dx) with the rows
    /// inclined by `rows_rad` (the solver's frame), taken out of the cache ([`BlancoCache::put`]
    /// returns them).
    pub fn take(
        &mut self,
        grid: &Grid,
        m: &Material,
        (rows_rad, variant): (&[f64], u8),
    ) -> Result<BlancoTangential, ContactError> {
        let key = (grid.mx, grid.my);
        let mut b = match self.kept.iter().position(|(k, _)| *k == key) {
            Some(k) => self.kept.remove(k).1,
            None => {
                let kernel = |shift| Kernel::new(grid.mx, grid.my, grid.dx_mm, grid.dy_mm, m.g_mpa, m.poisson, shift);
                let (k0, ks) = (kernel(0.0)?, kernel(grid.dx_mm)?);
                BlancoTangential {
                    steady: BlancoProduct::new(&k0.difference(&ks)?, rows_rad, variant)?,
                    plain: BlancoProduct::new(&k0, rows_rad, variant)?,
                }
            }
        };
        b.steady.set_rows(rows_rad)?;
        b.plain.set_rows(rows_rad)?;
        Ok(b)
    }

    /// The products of a grid of `(mx, my)` elements back into the cache.
    pub fn put(&mut self, key: (usize, usize), b: BlancoTangential) {
        if self.kept.len() == KEPT {
            self.kept.remove(0);
        }
        self.kept.push((key, b));
    }
}

impl BlancoTangential {
    /// Steady rolling on the corrected operator with pressure `pn_mpa` set in `solver` (the solver's
    /// frame, grid order): passes of `solver.steady` with the slip of the correction at the last
    /// pass's tractions, from `start`, until the largest change of a traction is at most the
    /// solve's tolerance times the largest bound μ pn.
    pub fn steady(
        &mut self,
        solver: &mut TangentialSolver,
        params: &TangentialParams,
        start: Option<(&[f64], &[f64])>,
        pn_mpa: &[f64],
    ) -> Result<StepResult, ContactError> {
        let n = pn_mpa.len();
        let (mut px, mut py) = start.map_or((vec![0.0; n], vec![0.0; n]), |(x, y)| (x.to_vec(), y.to_vec()));
        let bound = params.mu * pn_mpa.iter().copied().fold(0.0, f64::max);
        for _ in 0..PASSES {
            let [dx, ds, _] = self.steady.correction([&px, &py, pn_mpa])?;
            let (sx, sy): (Vec<f64>, Vec<f64>) = (dx.iter().map(|v| -v).collect(), ds.iter().map(|v| -v).collect());
            solver.set_coupled_slip(Some((&sx, &sy)))?;
            let r = solver.steady(params, Some((&px, &py)))?;
            let change = (0..n).map(|k| (r.px[k] - px[k]).hypot(r.py[k] - py[k])).fold(0.0, f64::max);
            (px, py) = (r.px.clone(), r.py.clone());
            if change <= params.tol.max(1e-12) * bound {
                solver.set_coupled_slip(None)?;
                return Ok(r);
            }
        }
        solver.set_coupled_slip(None)?;
        Err(ContactError::NotConverged { what: "Blanco's corrected tangential problem (fixed point)", passes: PASSES })
    }

    /// The normal displacement `B_nt p_t` [mm] of the tangential tractions `(px, py)` [MPa] (the
    /// solver's frame, grid order).
    pub fn traction_un(&mut self, px: &[f64], py: &[f64]) -> Result<Vec<f64>, ContactError> {
        let n = px.len();
        let (mut ux, mut us, mut un) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        self.plain.apply([px, py, &vec![0.0; n]], [&mut ux, &mut us, &mut un])?;
        Ok(un)
    }
}
