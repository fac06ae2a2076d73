//! Normal contact problem with prescribed total force (or approach) on the element grid (Kalker 1990, sec. 5.3):
//! find pressures `pn_k >= 0` [MPa] and the approach `delta` [mm] with
//! `e_k = h_k + (Azz pn)_k - delta >= 0`, `pn_k e_k = 0`, `sum(pn) dx dy = FN` [N].
//! Solved by the bound-constrained conjugate-gradient method of Polonsky & Keer (Wear 231 (1999)
//! 206-219, sec. 3; the same scheme as CONTACT's NormCG), with `u = Azz pn` by [`Convolver`];
//! a kernel that is not symmetric (viscoelastic bodies) by active sets and direct solves
//! ([`super::normal_dense`]).

use super::blend::Blend;
use super::convolution::Convolver;
use super::influence::Kernel;
use super::normal_dense::Dense;
use super::ContactError;

/// Iteration controls of [`solve_normal`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NormalParams {
    /// Stop when `sum|pn - pn_prev| / sum(pn) < tol` (default 1e-10).
    pub tol: f64,
    /// Maximum number of CG iterations (default 2000).
    pub max_iter: usize,
}

impl Default for NormalParams {
    fn default() -> Self {
        NormalParams { tol: 1e-10, max_iter: 2000 }
    }
}

/// Result of [`solve_normal`].
#[derive(Debug, Clone, PartialEq)]
pub struct NormalSolution {
    /// Element pressures [MPa], flat index `k = j*mx + i`; contact area = elements with `pn > 0`.
    pub pn_mpa: Vec<f64>,
    /// Rigid approach `delta` [mm]: mean of `h + Azz pn` over the contact elements.
    pub approach_mm: f64,
    /// CG iterations used.
    pub iterations: usize,
    /// Final relative pressure change `sum|dpn| / sum(pn)`.
    pub residual: f64,
    /// Whether `residual < tol` was reached within `max_iter`.
    pub converged: bool,
}

impl NormalSolution {
    /// The pressures [MPa] of a converged solve; one that met its iteration limit first is an
    /// error, never a pressure taken as solved.
    pub fn converged_pn_mpa(self) -> Result<Vec<f64>, ContactError> {
        match self.converged {
            true => Ok(self.pn_mpa),
            false => Err(ContactError::NotConverged { what: "normal problem", passes: self.iterations }),
        }
    }
}

/// The normal solver of one grid: the convolver of the unshifted kernel's `zz` part, built once
/// and used for every load.
pub struct NormalSolver {
    conv: Convolver,
    n: usize,
    area_mm2: f64,
    /// Sub-patches with attenuated cross-influence, where the contact has them.
    blend: Option<Blend>,
    /// A kernel that is not symmetric (viscoelastic bodies): solved by active sets and direct
    /// solves instead of the conjugate gradients.
    dense: Option<Dense>,
}

/// `u = A p`, through the blend's sub-patches where there is one.
fn matvec(conv: &mut Convolver, blend: Option<&Blend>, p: &[f64], u: &mut [f64]) -> Result<(), ContactError> {
    match blend {
        Some(b) => b.normal(conv, p, u),
        None => conv.normal(p, None, u),
    }
}

/// Solves the normal problem for prescribed total force `fn_n` [N] and undeformed distance
/// `h_mm` [mm] per element with the (unshifted) influence kernel `kernel` (its `zz` part), building
/// the convolver for this one call (see [`NormalSolver`] to keep it).
pub fn solve_normal(
    h_mm: &[f64],
    kernel: &Kernel,
    fn_n: f64,
    params: &NormalParams,
) -> Result<NormalSolution, ContactError> {
    NormalSolver::new(kernel)?.solve(h_mm, fn_n, params)
}

impl NormalSolver {
    /// The solver for the grid of the unshifted kernel `kernel`.
    pub fn new(kernel: &Kernel) -> Result<NormalSolver, ContactError> {
        Ok(NormalSolver {
            conv: Convolver::normal_only(kernel)?,
            n: kernel.mx * kernel.my,
            area_mm2: kernel.dx_mm * kernel.dy_mm,
            blend: None,
            dense: Dense::of(kernel),
        })
    }

    /// Solve the next problems with the cross-influence of `blend`'s sub-patches attenuated (and
    /// no pressure outside them), or fully coupled (`None`).
    pub fn set_blend(&mut self, blend: Option<Blend>) -> Result<(), ContactError> {
        if let Some(b) = &blend {
            if b.part.len() != self.n {
                return Err(ContactError::SizeMismatch { name: "blend", len: b.part.len(), expected: self.n });
            }
        }
        self.blend = blend;
        Ok(())
    }

    /// Whether element `k` may carry pressure.
    fn allows(&self, k: usize) -> bool {
        self.blend.as_ref().is_none_or(|b| b.allows(k))
    }

    /// Solves the normal problem for prescribed total force `fn_n` [N] and undeformed distance
    /// `h_mm` [mm] per element. Polonsky & Keer (1999), CG steps restricted to the current
    /// contact set, negative pressures clipped, overlap elements re-entered, total force imposed
    /// by scaling after every step.
    pub fn solve(&mut self, h_mm: &[f64], fn_n: f64, params: &NormalParams) -> Result<NormalSolution, ContactError> {
        self.solve_from(h_mm, fn_n, params, None)
    }

    /// [`NormalSolver::solve`] started from the pressure `start` [MPa] (a nearby problem's
    /// solution: the same grid with a nearby undeformed distance) where it is given and carries a
    /// load, scaled to carry FN; the same solution to the tolerance, in fewer iterations.
    pub fn solve_from(
        &mut self,
        h_mm: &[f64],
        fn_n: f64,
        params: &NormalParams,
        start: Option<&[f64]>,
    ) -> Result<NormalSolution, ContactError> {
        self.check(h_mm, params)?;
        if !(fn_n.is_finite() && fn_n > 0.0) {
            return Err(ContactError::OutOfRange {
                name: "total normal force [N]",
                value: fn_n,
                requirement: "finite and > 0",
            });
        }
        // Start: the given pressure scaled to FN, else uniform pressure carrying FN on all elements.
        let p: Vec<f64> = match self.start_of(start).filter(|g| g.iter().sum::<f64>() > 0.0) {
            Some(g) => {
                let scale = fn_n / (self.area_mm2 * g.iter().sum::<f64>());
                g.iter().map(|v| v * scale).collect()
            }
            None => {
                let allowed = (0..self.n).filter(|&k| self.allows(k)).count().max(1);
                (0..self.n)
                    .map(|k| if self.allows(k) { fn_n / (self.area_mm2 * allowed as f64) } else { 0.0 })
                    .collect()
            }
        };
        let (p, iterations, residual, converged) = self.iterate(h_mm, p, Some(fn_n), params)?;
        // Approach: mean of h + u over the final contact set.
        let mut u = vec![0.0; self.n];
        matvec(&mut self.conv, self.blend.as_ref(), &p, &mut u)?;
        let (mut s, mut c) = (0.0, 0usize);
        for k in 0..self.n {
            if p[k] > 0.0 {
                s += h_mm[k] + u[k];
                c += 1;
            }
        }
        if c == 0 {
            return Err(ContactError::NoContact);
        }
        let approach_mm = s / c as f64;
        if !approach_mm.is_finite() || p.iter().any(|v| !v.is_finite()) {
            return Err(ContactError::NonFinite("normal pressure"));
        }
        Ok(NormalSolution { pn_mpa: p, approach_mm, iterations, residual, converged })
    }

    /// Solves the normal problem for the prescribed approach `approach_mm` [mm] (CONTACT's N = 0,
    /// PEN): `e = h + Azz pn − approach ≥ 0`, `pn ≥ 0`, `pn e = 0`, the total force an outcome
    /// (Polonsky & Keer 1999, sec. 3, the CG without the force constraint). Starts from the
    /// overlap `approach − h` scaled by the best factor along it; no overlap is no contact.
    pub fn solve_approach(
        &mut self,
        h_mm: &[f64],
        approach_mm: f64,
        params: &NormalParams,
    ) -> Result<NormalSolution, ContactError> {
        self.solve_approach_from(h_mm, approach_mm, params, None)
    }

    /// [`NormalSolver::solve_approach`] started from the pressure `start` [MPa] (a nearby
    /// problem's solution: the same grid at a nearby approach) where it is given and loads
    /// somewhere the contact may be, scaled by the best factor along it; the same solution to the
    /// tolerance, in fewer iterations.
    pub fn solve_approach_from(
        &mut self,
        h_mm: &[f64],
        approach_mm: f64,
        params: &NormalParams,
        start: Option<&[f64]>,
    ) -> Result<NormalSolution, ContactError> {
        self.check(h_mm, params)?;
        if !approach_mm.is_finite() {
            return Err(ContactError::OutOfRange { name: "approach [mm]", value: approach_mm, requirement: "finite" });
        }
        let gap: Vec<f64> = h_mm.iter().map(|h| h - approach_mm).collect();
        let overlap: Vec<f64> =
            gap.iter().enumerate().map(|(k, g)| if self.allows(k) { (-g).max(0.0) } else { 0.0 }).collect();
        let guess: Vec<f64> = match self.start_of(start) {
            Some(g) if Self::loads(&g, &overlap) => g,
            _ => overlap,
        };
        let mut u = vec![0.0; self.n];
        matvec(&mut self.conv, self.blend.as_ref(), &guess, &mut u)?;
        // The factor c minimising ½ pᵀAp + pᵀ(h − approach) along p = c · guess.
        let num = -guess.iter().zip(&gap).map(|(p, g)| p * g).sum::<f64>();
        let den = guess.iter().zip(&u).map(|(p, u)| p * u).sum::<f64>();
        if num <= 0.0 || den <= 0.0 {
            return Err(ContactError::NoContact);
        }
        let start: Vec<f64> = guess.iter().map(|o| o * num / den).collect();
        let (p, iterations, residual, converged) = self.iterate(&gap, start, None, params)?;
        if p.iter().any(|v| !v.is_finite()) {
            return Err(ContactError::NonFinite("normal pressure"));
        }
        Ok(NormalSolution { pn_mpa: p, approach_mm, iterations, residual, converged })
    }

    /// A given start pressure of this grid's size, kept where an element may carry pressure
    /// (non-negative, finite), zero elsewhere.
    fn start_of(&self, start: Option<&[f64]>) -> Option<Vec<f64>> {
        start.filter(|s| s.len() == self.n).map(|s| {
            (0..self.n).map(|k| if self.allows(k) && s[k].is_finite() { s[k].max(0.0) } else { 0.0 }).collect()
        })
    }

    /// Whether the pressure `p` loads an element of the overlap (a start the CG can go on from).
    fn loads(p: &[f64], overlap: &[f64]) -> bool {
        p.iter().zip(overlap).any(|(p, o)| *p > 0.0 && *o > 0.0)
    }

    /// The inputs every normal solve checks.
    fn check(&self, h_mm: &[f64], params: &NormalParams) -> Result<(), ContactError> {
        if h_mm.len() != self.n {
            return Err(ContactError::SizeMismatch { name: "h", len: h_mm.len(), expected: self.n });
        }
        if let Some(index) = h_mm.iter().position(|v| !v.is_finite()) {
            return Err(ContactError::NotFinite { name: "undeformed distance", index });
        }
        if !(params.tol.is_finite() && params.tol > 0.0) {
            return Err(ContactError::OutOfRange {
                name: "normal tol",
                value: params.tol,
                requirement: "finite and > 0",
            });
        }
        if params.max_iter == 0 {
            return Err(ContactError::OutOfRange { name: "normal max_iter", value: 0.0, requirement: ">= 1" });
        }
        Ok(())
    }

    /// Polonsky & Keer's bound-constrained CG from `p` on the gap `u + h_mm`: with `fn_n` the
    /// gap is taken relative to its mean over the contact (the approach unknown) and the total
    /// force imposed by scaling after every step; without, `h_mm` already holds `h − approach`.
    /// Returns (pressure, iterations, residual, converged).
    fn iterate(
        &mut self,
        h_mm: &[f64],
        mut p: Vec<f64>,
        fn_n: Option<f64>,
        params: &NormalParams,
    ) -> Result<(Vec<f64>, usize, f64, bool), ContactError> {
        if let Some(dense) = &self.dense {
            if self.blend.is_some() {
                return Err(ContactError::OutOfRange {
                    name: "sub-patches (blend) with a kernel that is not symmetric",
                    value: 1.0,
                    requirement: "no blend",
                });
            }
            return dense.solve(h_mm, fn_n.map(|f| (f, self.area_mm2)));
        }
        let (n, area, conv, blend) = (self.n, self.area_mm2, &mut self.conv, self.blend.as_ref());
        let allowed = |k: usize| blend.is_none_or(|b| b.allows(k));
        let mut p_old = vec![0.0; n];
        let mut u = vec![0.0; n];
        let mut g = vec![0.0; n];
        let mut t = vec![0.0; n];
        let mut r = vec![0.0; n];
        let (mut gc, mut z) = (vec![0.0; n], vec![0.0; n]);
        let mut g_old = 1.0;
        let mut delta_flag = false;
        let mut residual = f64::INFINITY;
        let mut iterations = 0;
        let mut converged = false;
        // u = A p holds for the current p (kept by the step below when no element left or
        // re-entered the contact set: then A p_new = scale (u − τ A t), one convolution saved).
        let mut u_holds = false;

        while iterations < params.max_iter {
            iterations += 1;
            if !u_holds {
                matvec(conv, blend, &p, &mut u)?;
            }
            let mut nc = 0usize;
            let mut gsum = 0.0;
            for k in 0..n {
                g[k] = u[k] + h_mm[k];
                if p[k] > 0.0 {
                    nc += 1;
                    gsum += g[k];
                }
            }
            if nc == 0 {
                return Err(ContactError::NoContact);
            }
            let gbar = if fn_n.is_some() { gsum / nc as f64 } else { 0.0 };
            let mut gg = 0.0;
            for k in 0..n {
                g[k] -= gbar;
                if p[k] > 0.0 {
                    gg += g[k] * g[k];
                }
            }
            // The search direction from the preconditioned gap where there is a preconditioner.
            let preconditioned = blend.is_none() && precondition(conv, &p, &g, fn_n.is_some(), &mut gc, &mut z)?;
            let (dir, gz) = if preconditioned {
                (&z, (0..n).filter(|&k| p[k] > 0.0).map(|k| g[k] * z[k]).sum::<f64>())
            } else {
                (&g, gg)
            };
            let beta = if delta_flag && g_old > 0.0 { gz / g_old } else { 0.0 };
            for k in 0..n {
                t[k] = if p[k] > 0.0 { dir[k] + beta * t[k] } else { 0.0 };
            }
            g_old = gz;
            matvec(conv, blend, &t, &mut r)?;
            let mut rsum = 0.0;
            for k in 0..n {
                if p[k] > 0.0 {
                    rsum += r[k];
                }
            }
            let rbar = if fn_n.is_some() { rsum / nc as f64 } else { 0.0 };
            let (mut num, mut den) = (0.0, 0.0);
            for k in 0..n {
                if p[k] > 0.0 {
                    num += g[k] * t[k];
                    den += (r[k] - rbar) * t[k];
                }
            }
            let tau = if den != 0.0 { num / den } else { 0.0 };
            if !tau.is_finite() {
                return Err(ContactError::NonFinite("normal CG step length"));
            }
            // The step on the contact set, then the overlapping elements outside it re-enter
            // (Polonsky & Keer, step 9; an element the step just took out among them), in one pass.
            let (mut n_left, mut n_overlap, mut sum) = (0usize, 0usize, 0.0);
            for k in 0..n {
                p_old[k] = p[k];
                if p[k] > 0.0 {
                    let step = p[k] - tau * t[k];
                    n_left += usize::from(step <= 0.0);
                    p[k] = step.max(0.0);
                }
                if p[k] <= 0.0 && g[k] < 0.0 && allowed(k) {
                    p[k] -= tau * g[k];
                    n_overlap += 1;
                }
                sum += p[k];
            }
            delta_flag = n_overlap == 0;
            let total: f64 = sum * area;
            if !(total.is_finite() && total > 0.0) {
                return Err(ContactError::NoContact);
            }
            let scale = fn_n.map_or(1.0, |f| f / total);
            u_holds = n_left == 0 && n_overlap == 0;
            let mut dsum = 0.0;
            let mut psum = 0.0;
            for k in 0..n {
                if fn_n.is_some() {
                    p[k] *= scale;
                }
                dsum += (p[k] - p_old[k]).abs();
                psum += p[k];
                if u_holds {
                    u[k] = scale * (u[k] - tau * r[k]);
                }
            }
            residual = dsum / psum;
            if residual < params.tol {
                converged = true;
                break;
            }
        }
        Ok((p, iterations, residual, converged))
    }
}

/// The preconditioned gap `z = M g` on the contact set (`p > 0`), less its mean there when the
/// force is prescribed (a step along it keeps the force): Vollebregt's FFT preconditioner
/// (2014, J. Comput. Phys. 257, sec. 4) on the gap `g` restricted to the set (`gc`). `false`
/// where the convolver has none (the direct path): the plain gap is the direction.
fn precondition(
    conv: &mut Convolver,
    p: &[f64],
    g: &[f64],
    force: bool,
    gc: &mut [f64],
    z: &mut [f64],
) -> Result<bool, ContactError> {
    for k in 0..p.len() {
        gc[k] = if p[k] > 0.0 { g[k] } else { 0.0 };
    }
    if !conv.normal_inverse(gc, z)? {
        return Ok(false);
    }
    let mean = match force {
        true => {
            let (mut sum, mut count) = (0.0, 0usize);
            for k in 0..p.len() {
                if p[k] > 0.0 {
                    sum += z[k];
                    count += 1;
                }
            }
            if count > 0 {
                sum / count as f64
            } else {
                0.0
            }
        }
        false => 0.0,
    };
    for k in 0..p.len() {
        z[k] = if p[k] > 0.0 { z[k] - mean } else { 0.0 };
    }
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tiny_grids_give_finite_answers_or_errors() {
        // A single element carries the whole load.
        let k = Kernel::new(1, 1, 2.0, 1.0, 82000.0, 0.28, 0.0).unwrap();
        let sol = solve_normal(&[0.0], &k, 500.0, &NormalParams::default()).unwrap();
        assert!(sol.converged && (sol.pn_mpa[0] - 250.0).abs() < 1e-12);
        assert!(sol.approach_mm.is_finite() && sol.approach_mm > 0.0);
        // Two elements, one far away: it carries nothing.
        let k = Kernel::new(2, 1, 1.0, 1.0, 82000.0, 0.28, 0.0).unwrap();
        let sol = solve_normal(&[0.0, 10.0], &k, 100.0, &NormalParams::default()).unwrap();
        assert!(sol.pn_mpa[1] == 0.0 && (sol.pn_mpa[0] - 100.0).abs() < 1e-9);
        // A kernel without stiffness cannot give a finite solution: error or flagged, never NaN.
        let mut k0 = Kernel::new(3, 3, 1.0, 1.0, 82000.0, 0.28, 0.0).unwrap();
        k0.zz.iter_mut().for_each(|v| *v = 0.0);
        match solve_normal(&[0.0; 9], &k0, 100.0, &NormalParams::default()) {
            Ok(s) => assert!(s.pn_mpa.iter().all(|v| v.is_finite())),
            Err(e) => assert!(!e.to_string().is_empty()),
        }
        assert!(solve_normal(&[0.0; 4], &k0, 100.0, &NormalParams::default()).is_err());
    }

    #[test]
    fn hertz_pressure_on_small_grid() {
        let grid = crate::physics::Grid::new(16, 16, 8.56, 4.08);
        let (fnn, g, nu) = (100_000.0, 82000.0, 0.28);
        let h = crate::physics::ContactGeometry::undeformed_distance_mm(
            &crate::physics::HertzEllipse {
                nominal: crate::physics::HertzContact { a_mm: 8.56, b_mm: 4.08, fn_n: fnn },
            },
            &grid,
            fnn,
            &crate::physics::Material::from_g(g, nu),
        );
        let k = Kernel::new(16, 16, grid.dx_mm, grid.dy_mm, g, nu, 0.0).unwrap();
        let sol = solve_normal(&h, &k, fnn, &NormalParams::default()).unwrap();
        assert!(sol.converged);
        let total: f64 = sol.pn_mpa.iter().sum::<f64>() * grid.element_area_mm2();
        assert!((total - fnn).abs() < 1e-9 * fnn);
        assert!(sol.pn_mpa.iter().all(|&v| v >= 0.0));
        let p0 = 3.0 * fnn / (2.0 * std::f64::consts::PI * 8.56 * 4.08);
        let pmax = sol.pn_mpa.iter().cloned().fold(0.0, f64::max);
        assert!((pmax / p0 - 1.0).abs() < 0.02, "pmax {pmax} p0 {p0}");
        // Errors, never NaN.
        assert!(solve_normal(&h, &k, 0.0, &NormalParams::default()).is_err());
        assert!(solve_normal(&h, &k, f64::NAN, &NormalParams::default()).is_err());
        let mut hb = h.clone();
        hb[3] = f64::NAN;
        assert!(solve_normal(&hb, &k, fnn, &NormalParams::default()).is_err());
    }

    /// A sphere of combined radius R, `h = r²/(2R)`, pressed by the approach δ on the grid
    /// `m × m` over ±1.25 a: (FN found, Hertz's FN = 4/3 E* √R δ^(3/2) with E* = G/(1 − ν) for two
    /// identical bodies; Johnson 1985, eq. 4.23), and the force solve's approach at that FN.
    fn sphere(m: usize, delta_mm: f64) -> (f64, f64, f64) {
        let (g, nu, r_mm) = (82000.0, 0.28, 300.0);
        let a_mm = (r_mm * delta_mm).sqrt();
        let grid = crate::physics::Grid::new(m, m, 1.25 * a_mm, 1.25 * a_mm);
        let (x, y) = grid.centres();
        let h: Vec<f64> = x.iter().zip(&y).map(|(x, y)| (x * x + y * y) / (2.0 * r_mm)).collect();
        let k = Kernel::new(m, m, grid.dx_mm, grid.dy_mm, g, nu, 0.0).unwrap();
        let mut solver = NormalSolver::new(&k).unwrap();
        let by_approach = solver.solve_approach(&h, delta_mm, &NormalParams::default()).unwrap();
        assert!(by_approach.converged && by_approach.pn_mpa.iter().all(|&p| p >= 0.0));
        let fn_n = by_approach.pn_mpa.iter().sum::<f64>() * grid.element_area_mm2();
        let by_force = solver.solve(&h, fn_n, &NormalParams::default()).unwrap();
        let hertz = 4.0 / 3.0 * g / (1.0 - nu) * r_mm.sqrt() * delta_mm.powf(1.5);
        (fn_n, hertz, by_force.approach_mm)
    }

    #[test]
    fn a_solve_stopped_by_its_iteration_limit_gives_no_pressure() {
        let (r_mm, m) = (300.0f64, 21);
        let half_mm = 1.25 * (r_mm * 0.01).sqrt();
        let grid = crate::physics::Grid::new(m, m, half_mm, half_mm);
        let (x, y) = grid.centres();
        let h: Vec<f64> = x.iter().zip(&y).map(|(x, y)| (x * x + y * y) / (2.0 * r_mm)).collect();
        let k = Kernel::new(m, m, grid.dx_mm, grid.dy_mm, 82000.0, 0.28, 0.0).unwrap();
        let mut solver = NormalSolver::new(&k).unwrap();
        let cut = solver.solve_approach(&h, 0.01, &NormalParams { tol: 1e-10, max_iter: 2 }).unwrap();
        assert!(!cut.converged);
        let err = cut.converged_pn_mpa().unwrap_err();
        assert!(matches!(err, ContactError::NotConverged { passes: 2, .. }), "{err}");
        let full = solver.solve_approach(&h, 0.01, &NormalParams::default()).unwrap();
        assert_eq!(full.clone().converged_pn_mpa().unwrap(), full.pn_mpa);
    }

    #[test]
    fn a_start_from_a_nearby_approach_gives_the_same_pressure_in_fewer_iterations() {
        let (g, nu, r_mm, m) = (82000.0, 0.28, 300.0f64, 41);
        let half_mm = 1.25 * (r_mm * 0.0101).sqrt();
        let grid = crate::physics::Grid::new(m, m, half_mm, half_mm);
        let (x, y) = grid.centres();
        let h: Vec<f64> = x.iter().zip(&y).map(|(x, y)| (x * x + y * y) / (2.0 * r_mm)).collect();
        let k = Kernel::new(m, m, grid.dx_mm, grid.dy_mm, g, nu, 0.0).unwrap();
        let mut solver = NormalSolver::new(&k).unwrap();
        let params = NormalParams::default();
        let near = solver.solve_approach(&h, 0.01, &params).unwrap();
        let cold = solver.solve_approach(&h, 0.0101, &params).unwrap();
        let warm = solver.solve_approach_from(&h, 0.0101, &params, Some(&near.pn_mpa)).unwrap();
        assert!(cold.converged && warm.converged);
        let pmax = cold.pn_mpa.iter().fold(0.0f64, |a, &b| a.max(b));
        let diff = cold.pn_mpa.iter().zip(&warm.pn_mpa).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        assert!(diff < 1e-8 * pmax, "{diff} MPa of {pmax}");
        assert!(warm.iterations < cold.iterations, "{} vs {}", warm.iterations, cold.iterations);
        // A start of the wrong size or loading nowhere is the cold start.
        let wrong = solver.solve_approach_from(&h, 0.0101, &params, Some(&[1.0; 3])).unwrap();
        assert_eq!(wrong, cold);
    }

    #[test]
    fn approach_prescribed_gives_hertz_force_and_inverts_the_force_solve() {
        let delta = 0.01;
        let (coarse, hertz, _) = sphere(21, delta);
        let (fine, _, back) = sphere(41, delta);
        let (e_coarse, e_fine) = ((coarse / hertz - 1.0).abs(), (fine / hertz - 1.0).abs());
        // The grid's accuracy (measured 2632.3 and 2630.9 N vs 2630.2 N): within 0.1 % on 21 x 21
        // elements over ±1.25 a, within 0.04 % and closer on 41 x 41.
        assert!(e_coarse < 1e-3 && e_fine < 4e-4 && e_fine < e_coarse, "FN {coarse}, {fine} N vs Hertz {hertz} N");
        // The force solve at the FN found gives the approach back (both converged to 1e-10).
        assert!((back - delta).abs() < 1e-8 * delta, "approach {back} mm vs {delta} mm");
        // No overlap, no contact; a non-finite approach is refused.
        let k = Kernel::new(2, 1, 1.0, 1.0, 82000.0, 0.28, 0.0).unwrap();
        let mut s = NormalSolver::new(&k).unwrap();
        assert_eq!(s.solve_approach(&[0.1, 0.2], 0.05, &NormalParams::default()), Err(ContactError::NoContact));
        assert!(s.solve_approach(&[0.1, 0.2], f64::NAN, &NormalParams::default()).is_err());
    }
}
