//! An interface layer that hardens or softens in the exact solver (CONTACT's M = 4 with
//! K_TAU ≠ 0): each element's yield limit τc moves with its accumulated plastic slip,
//! τc = τc' + K_TAU |Δu_pl| from the last step's τc' ([`Layer::hardened_mpa`]), so the traction
//! bound min(μ pn, τc) of a step depends on the step's own plastic slip: a fixed point per step
//! around the tangential solve, as CONTACT's `plstrc` (`m_solvpt.f90`) solves it per element
//! within its Gauss–Seidel sweeps.
//!
//! Per iteration: the bound's pressure min(pn, τc/μ); the tangential solve; each slipping
//! element's plastic slip ([`Layer::plastic_slip_mm`]) gives τc_new = τc' + K_TAU |Δu_pl|; stop
//! when max|τc_new − τc| ≤ tol · max τc over the contact. The next τc is a Newton step on the
//! element's own equation, its slip falling by the self-flexibility C per MPa the limit rises
//! (exact for one element): τc ← (τc_new + K_TAU C τc)/(1 + K_TAU C), kept where the slip can
//! take it ([`Layer::reachable_mpa`]). The limits the last solve's slip gives, τc' + K_TAU |Δu_pl|,
//! are kept for the next step (as CONTACT's `taucs`), so that a change per step below the
//! tolerance still accumulates. In transient rolling the kept limits move with the material by
//! dq before the step ([`Hardening::carry`]), τ_c0 entering at the leading edge, as CONTACT's
//! `set_prev_data` (`m_sdis.f90`) shifts `taucs` to `taucv`.

use super::steady_hardening::SteadyLimits;
use super::tangential::{ElementState, StepResult};
use super::ContactError;
use crate::physics::material::Layer;

/// The fixed point's iteration limit.
pub const MAX_ITERATIONS: usize = 100;

/// How one step's fixed point ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HardeningOutcome {
    pub iterations: usize,
    pub converged: bool,
    /// Tangential iterations summed over the fixed point's solves.
    pub inner_iterations: usize,
}

/// The layer, each element's yield limit after the last step, and the solve's options.
pub struct Hardening {
    layer: Layer,
    /// τc [MPa] per element after the last step (CONTACT's `taucv`); τ_c0 at the start.
    tau_mpa: Vec<f64>,
    /// The element's tangential self-flexibility C [mm/MPa] (the half-spaces' and the layer's).
    self_flexibility_mm_per_mpa: f64,
    /// Stop when max|τc_new − τc| ≤ tolerance · max τc.
    tolerance: f64,
    /// The last step's limits where they stood before [`Hardening::carry`] moved them with the
    /// material: the next rolling step's first iterate in a hardening layer (the limits stand
    /// still in the contact frame in steady state, so that near it they are close to its solution).
    uncarried_mpa: Option<Vec<f64>>,
}

/// The step's tractions, the yield limits its slip gives, how the fixed point ended.
pub type HardeningStep = (StepResult, Vec<f64>, HardeningOutcome);

impl Hardening {
    /// A layer with a yield limit (τ_c0 on every element) on a grid of `n` elements.
    pub fn new(layer: Layer, n: usize, self_flexibility_mm_per_mpa: f64, tolerance: f64) -> Option<Hardening> {
        let tau_c0 = layer.yield_mpa.filter(|_| layer.hardens())?;
        Some(Hardening { layer, tau_mpa: vec![tau_c0; n], self_flexibility_mm_per_mpa, tolerance, uncarried_mpa: None })
    }

    /// The yield limits after the last step [MPa].
    pub fn tau_mpa(&self) -> &[f64] {
        &self.tau_mpa
    }

    /// Steady rolling on the friction bound's pressure `pn` [MPa] at μ `mu` on a grid of rows of
    /// `mx` elements, the steady self-flexibility `c_mm_per_mpa` (A − A_s's diagonal): the limits
    /// carried from the element upstream ([`super::steady_hardening`]), starting from the last
    /// sample's. `solve` as for [`Hardening::step`]; nothing is kept here.
    pub fn steady(
        &self,
        pn: &[f64],
        mu: f64,
        (mx, c_mm_per_mpa): (usize, f64),
        solve: impl FnMut(&[f64], Option<(&[f64], &[f64])>) -> Result<StepResult, ContactError>,
    ) -> Result<HardeningStep, ContactError> {
        let limits = SteadyLimits {
            layer: &self.layer,
            mx,
            self_flexibility_mm_per_mpa: c_mm_per_mpa,
            tolerance: self.tolerance,
        };
        limits.solve(pn, mu, &self.tau_mpa, solve)
    }

    /// Keeps `tau_mpa` (a step's, [`Hardening::step`]) as the next step's previous limits.
    pub fn keep(&mut self, tau_mpa: Vec<f64>) {
        self.tau_mpa = tau_mpa;
        self.uncarried_mpa = None;
    }

    /// Moves the kept limits with the material before a transient rolling step of `courant` =
    /// dq/dx elements along +x (the solver's frame, upstream at i − 1) on rows of `mx` elements:
    /// each element takes the limit of the material that arrives there, linearly between the two
    /// elements it came from, τ_c0 where it entered the grid, as CONTACT's `set_prev_data` moves
    /// `taucs` to `taucv` (`m_sdis.f90`, `gf3_dq_shift` with TAU_C0 outside).
    pub fn carry(&mut self, mx: usize, courant: f64) {
        let tau_c0 = self.layer.yield_mpa.unwrap_or(f64::INFINITY);
        let moved = carried(&self.tau_mpa, mx, courant, tau_c0);
        self.uncarried_mpa = Some(std::mem::replace(&mut self.tau_mpa, moved));
    }

    /// The fixed point's first iterate of a step on the friction bound μ `pn`: in a hardening
    /// layer after [`Hardening::carry`], the limits before they were carried, each kept where the
    /// step's plastic slip can take it from its previous limit ([`Layer::reachable_mpa`]); else the
    /// previous limits. The fixed point is the same from either start (a hardening layer's is
    /// unique: the plastic slip falls as the limit rises); a rolling step near steady state starts
    /// near it.
    fn first_iterate(&self, pn: &[f64], mu: f64) -> Vec<f64> {
        let previous = &self.tau_mpa;
        match &self.uncarried_mpa {
            Some(guess) if self.layer.hardening_mpa_per_mm > 0.0 => (0..pn.len())
                .map(|k| match pn[k] > 0.0 {
                    true => self.layer.reachable_mpa(previous[k], mu * pn[k], guess[k]),
                    false => previous[k],
                })
                .collect(),
            _ => previous.clone(),
        }
    }

    /// One step on the friction bound's pressure `pn` [MPa] at μ `mu`: `solve(bound, start,
    /// tol)` solves the step with the bound's pressure `bound` [MPa] to the tolerance `tol`, warm
    /// started from the last iterate's tractions `start` when given. The early iterates' solves
    /// are loose (as the falling-friction fixed point's adaptive solves,
    /// [`super::veldep::inner_tolerance`] of the last relative change of the limits, never below
    /// `solve_tol`): they are farther from the fixed point than a tight solve's error; the step
    /// ends only on a solve at `solve_tol` (or whose residual is within it). Returns the last
    /// solve, the limits its slip gives (to [`Hardening::keep`] once the step is final) and the
    /// outcome; nothing is kept here.
    pub fn step(
        &self,
        pn: &[f64],
        mu: f64,
        solve_tol: f64,
        mut solve: impl FnMut(&[f64], Option<(&[f64], &[f64])>, f64) -> Result<StepResult, ContactError>,
    ) -> Result<HardeningStep, ContactError> {
        let n = pn.len();
        let previous = &self.tau_mpa;
        let mut tau = self.first_iterate(pn, mu);
        let mut bound = vec![0.0; n];
        let mut last: Option<StepResult> = None;
        let (mut inner, mut last_change) = (0, None);
        let k_tau = self.layer.hardening_mpa_per_mm;
        let kc = k_tau * self.self_flexibility_mm_per_mpa;
        for it in 1..=MAX_ITERATIONS {
            for k in 0..n {
                bound[k] = if pn[k] > 0.0 { pn[k].min(tau[k] / mu) } else { 0.0 };
            }
            let start = last.as_ref().map(|r| (r.px.as_slice(), r.py.as_slice()));
            let tol = super::veldep::inner_tolerance(solve_tol, last_change);
            let r = solve(&bound, start, tol)?;
            inner += r.iterations;
            let mut next = tau.clone();
            let mut implied = previous.clone();
            let (mut change, mut size) = (0.0f64, 0.0f64);
            for k in (0..n).filter(|&k| pn[k] > 0.0) {
                let friction = mu * pn[k];
                let slip = if r.state[k] == ElementState::Slip { r.sx[k].hypot(r.sy[k]) } else { 0.0 };
                let plastic = self.layer.plastic_slip_mm(previous[k], friction, slip);
                let plain = self.layer.hardened_mpa(previous[k], plastic);
                implied[k] = plain;
                // All of the slip plastic: the element's own Newton step.
                let newton = plastic > 0.0 && plastic == slip && 1.0 + kc > 0.0;
                next[k] = match newton {
                    true => self.layer.reachable_mpa(previous[k], friction, (plain + kc * tau[k]) / (1.0 + kc)),
                    false => plain,
                };
                change = change.max((plain - tau[k]).abs());
                size = size.max(plain.abs());
            }
            let tight = tol <= solve_tol || r.residual <= solve_tol;
            let converged = tight && change <= self.tolerance * size;
            if converged || it == MAX_ITERATIONS {
                return Ok((r, implied, HardeningOutcome { iterations: it, converged, inner_iterations: inner }));
            }
            last_change = Some(if size > 0.0 { change / size } else { 0.0 });
            tau = next;
            last = Some(r);
        }
        unreachable!("the loop returns at its last iteration")
    }
}

/// `field` on rows of `mx` elements moved `courant` elements along +x: element i takes the value
/// at i − courant, linear between the two elements around it, `outside` beyond the row's
/// upstream edge (CONTACT's `gf3_dq_shift` at CHI = 0, `m_gridfunc.f90`).
pub fn carried(field: &[f64], mx: usize, courant: f64, outside: f64) -> Vec<f64> {
    let whole = courant.floor();
    let (k, frac) = (whole as isize, courant - whole);
    let at = |row: usize, i: isize| if (0..mx as isize).contains(&i) { field[row * mx + i as usize] } else { outside };
    (0..field.len())
        .map(|n| {
            let (row, i) = (n / mx, (n % mx) as isize);
            let near = at(row, i - k);
            if frac == 0.0 {
                near
            } else {
                (1.0 - frac) * near + frac * at(row, i - k - 1)
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One element sheared by a trial traction `trial` [MPa] (μ = 0.7) under the bound's pressure
    /// `bound`: beyond its limit the slip is (trial − limit)·C, the closed form of one element.
    fn one_element(c: f64, trial: f64, bound: &[f64]) -> Result<StepResult, ContactError> {
        let g = 0.7 * bound[0];
        let (p, state) = if trial <= g { (trial, ElementState::Adhesion) } else { (g, ElementState::Slip) };
        Ok(StepResult {
            px: vec![p],
            py: vec![0.0],
            sx: vec![(trial - p) * c],
            sy: vec![0.0],
            state: vec![state],
            iterations: 1,
            residual: 0.0,
            termination: crate::solvers::Termination::Converged,
            n_adhesion: usize::from(state == ElementState::Adhesion),
            n_slip: usize::from(state == ElementState::Slip),
        })
    }

    fn layer(tau_c0: f64, k: f64) -> Layer {
        Layer { g_mpa: 106.25, thickness_mm: 0.02, yield_mpa: Some(tau_c0), hardening_mpa_per_mm: k }
    }

    /// Hardening and softening of one element: τc = (τc' + K C trial)/(1 + K C), the fixed point of
    /// τc = τc' + K (trial − τc) C, in two solves (the Newton step is exact for one element).
    #[test]
    fn one_element_reaches_its_closed_form_in_two_solves() {
        let c = 2.0e-4;
        for (tau_c0, k, trial) in [(200.0, 435.0, 400.0), (400.0, -195.0, 800.0), (20.0, 20.4, 60.0)] {
            let h = Hardening::new(layer(tau_c0, k), 1, c, 1e-12).unwrap();
            let (r, tau, o) = h.step(&[900.0], 0.7, 1e-9, |b, _, _| one_element(c, trial, b)).unwrap();
            let closed = (tau_c0 + k * c * trial) / (1.0 + k * c);
            assert!((tau[0] - closed).abs() <= 1e-12 * closed, "{tau:?} against {closed}");
            assert!((r.px[0] - closed).abs() <= 1e-12 * closed);
            assert_eq!((o.iterations, o.converged), (2, true), "{o:?}");
        }
    }

    /// A hardening limit stops at μ pn (beyond it the bodies slip), a softening one at 0.1 τ_c0;
    /// an element that holds keeps its limit.
    #[test]
    fn the_limit_stays_between_the_floor_and_the_friction_bound() {
        let c = 2.0e-4;
        let h = Hardening::new(layer(200.0, 1e6), 1, c, 1e-12).unwrap();
        let (_, tau, o) = h.step(&[900.0], 0.7, 1e-9, |b, _, _| one_element(c, 5000.0, b)).unwrap();
        assert!(o.converged && (tau[0] - 630.0).abs() <= 1e-9, "{tau:?}");
        let h = Hardening::new(layer(400.0, -1e6), 1, c, 1e-12).unwrap();
        let (_, tau, o) = h.step(&[900.0], 0.7, 1e-9, |b, _, _| one_element(c, 800.0, b)).unwrap();
        assert!(o.converged && (tau[0] - 40.0).abs() <= 1e-9, "{tau:?}");
        let h = Hardening::new(layer(200.0, 435.0), 1, c, 1e-12).unwrap();
        let (_, tau, o) = h.step(&[900.0], 0.7, 1e-9, |b, _, _| one_element(c, 150.0, b)).unwrap();
        assert_eq!((tau[0], o.iterations), (200.0, 1));
    }

    /// Many elements of a layer alone (half-spaces of G = 1e12 MPa, ~1e-9 of the layer's
    /// flexibility) under a pressure that varies per element, sheared by three shifts: each
    /// element is the one-element problem of flexibility h3/G3, elastic within min(μ pn, τc),
    /// slipping at μ pn where μ pn ≤ τc', else flowing to τc = (τc' + K C t)/(1 + K C) (at most
    /// μ pn) for the trial traction t. The solver's tractions and limits give it within 1e-6.
    #[test]
    fn a_layer_alone_hardens_and_softens_element_by_element() {
        use super::super::influence::Kernel;
        use super::super::tangential::{TangentialParams, TangentialSolver};
        let (mx, my, mu, flx) = (6, 5, 0.5, 1.25 / 8200.0);
        let grid = crate::physics::Grid::new(mx, my, 3.0, 2.5);
        let (x, y) = grid.centres();
        let k0 =
            Kernel::new(mx, my, grid.dx_mm, grid.dy_mm, 1e12, 0.28, 0.0).unwrap().with_layer(flx, [0.0; 2]).unwrap();
        let pn: Vec<f64> = (0..mx * my).map(|k| 100.0 + 20.0 * k as f64).collect();
        for k_tau in [435.0, -195.0] {
            let mut solver = TangentialSolver::for_shifts(&k0, &x, &y).unwrap();
            solver.set_pressure(&pn).unwrap();
            let own = k0.xx[k0.index(0, 0)];
            let mut h = Hardening::new(layer(150.0, k_tau), mx * my, own, 1e-12).unwrap();
            let (mut px, mut py) = (vec![0.0; mx * my], vec![0.0; mx * my]);
            let (mut p_closed, mut tau_closed) = (vec![0.0; mx * my], vec![150.0; mx * my]);
            for shift_mm in [0.02, 0.02, 0.03] {
                let mut params = TangentialParams::new(mu, shift_mm, 0.0, 0.0, 1.0);
                params.tol = 1e-13;
                let (r, tau, o) = h
                    .step(&pn, mu, params.tol, |bound, start, tol| {
                        solver.set_bound(bound)?;
                        let params = TangentialParams { tol, ..params };
                        match start {
                            Some(start) => solver.transient_resolve_from(&params, start),
                            None => solver.transient_step(&params, &px, &py, None),
                        }
                    })
                    .unwrap();
                assert!(o.converged, "{o:?}");
                for k in 0..mx * my {
                    let (friction, trial) = (mu * pn[k], p_closed[k] + shift_mm / flx);
                    let t0 = tau_closed[k];
                    p_closed[k] = if trial <= friction.min(t0) {
                        trial
                    } else if friction <= t0 {
                        friction
                    } else {
                        let flowed = ((t0 + k_tau * flx * trial) / (1.0 + k_tau * flx)).max(15.0).min(friction);
                        tau_closed[k] = flowed;
                        flowed
                    };
                    assert!(
                        (r.px[k] - p_closed[k]).abs() <= 1e-6 * friction,
                        "K {k_tau}, {k}: {} against {}",
                        r.px[k],
                        p_closed[k]
                    );
                    assert!(
                        (tau[k] - tau_closed[k]).abs() <= 1e-6 * friction,
                        "K {k_tau}, {k}: τc {} against {}",
                        tau[k],
                        tau_closed[k]
                    );
                }
                h.keep(tau);
                (px, py) = (r.px, r.py);
            }
            // Both kinds happened: elements that flowed, and elements that slipped by friction.
            assert!(tau_closed.iter().any(|&t| t != 150.0) && pn.iter().any(|&p| mu * p < 150.0));
        }
    }

    /// The limits move with the material: one element per dq = dx, τ_c0 entering upstream; half
    /// an element, halfway between the two.
    #[test]
    fn the_limits_move_with_the_material() {
        let field = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        assert_eq!(carried(&field, 3, 1.0, 9.0), [9.0, 1.0, 2.0, 9.0, 4.0, 5.0]);
        assert_eq!(carried(&field, 3, 0.0, 9.0), field);
        assert_eq!(carried(&field, 3, 0.5, 9.0), [5.0, 1.5, 2.5, 6.5, 4.5, 5.5]);
        assert_eq!(carried(&field, 3, 2.0, 9.0), [9.0, 9.0, 1.0, 9.0, 9.0, 4.0]);
    }

    /// A change of the limit below the fixed point's tolerance is kept all the same: the limit the
    /// step's slip gives, τc' + K (trial − τc') C, so that slow hardening accumulates step by step.
    #[test]
    fn a_change_below_the_tolerance_accumulates() {
        let (c, k, trial) = (2.0e-4, 1e-3, 400.0);
        let mut h = Hardening::new(layer(200.0, k), 1, c, 1e-6).unwrap();
        let (_, tau, o) = h.step(&[900.0], 0.7, 1e-9, |b, _, _| one_element(c, trial, b)).unwrap();
        assert_eq!(o.iterations, 1, "{o:?}");
        assert_eq!(tau[0], 200.0 + k * (trial - 200.0) * c);
        h.keep(tau);
        let (_, tau, _) = h.step(&[900.0], 0.7, 1e-9, |b, _, _| one_element(c, trial, b)).unwrap();
        assert!(tau[0] > h.tau_mpa()[0] && h.tau_mpa()[0] > 200.0, "{tau:?}");
    }
}
