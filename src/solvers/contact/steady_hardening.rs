//! An interface layer that hardens or softens in steady rolling (CONTACT's M = 4 with K_TAU ≠ 0,
//! T = 3): each element's yield limit moves with the material, taken from the element upstream
//! and raised (lowered) by K_TAU times the plastic slip over the element, τc_i = τc_(i−1) +
//! K_TAU |Δu_pl,i| (dq = dx), τ_c0 entering at the grid's upstream edge, carried through the
//! elements outside the contact, as CONTACT's `stdygs` (`m_solvpt.f90`) carries `taucs` from
//! `ii + ixinc` and its `plstrc` sets each element's flow.
//!
//! The limits are a fixed point around the steady solve: with the bound min(μ pn, τc) per element
//! the solve gives each element's slip; a sweep along each row from the upstream edge sets
//! τc_i from its upstream neighbour's new limit and its own plastic slip
//! ([`Layer::plastic_slip_mm`]): all of the slip of an element at its limit below μ pn, and in a
//! hardening layer at most what raises τc to μ pn where the element slips at μ pn (the bodies
//! slip, `plstrc`'s slip branch). A softened element's own bound is τc' + K_TAU |Δu_pl| as
//! `plstrc` leaves its traction; the limit it carries on is not below 0.1 τ_c0
//! ([`Layer::hardened_mpa`]). The element's next limit is a Newton step on its own equation from
//! its trial traction t = |p| + |s|/C, C the steady self-flexibility (the diagonal of A − A_s):
//! τc = (τc' + K_TAU C t)/(1 + K_TAU C), kept between τc' and μ pn (hardening) or below τc'
//! (softening); where the largest change does not fall the update is relaxed (halved, down to
//! 1/16). It stops when max|τc_new − τc| ≤ tol · max τc over the contact.

use super::hardening::{HardeningOutcome, HardeningStep};
use super::tangential::{ElementState, StepResult};
use super::ContactError;
use crate::physics::material::Layer;

/// The smallest bound a softened element keeps, as a fraction of τ_c0 (the solver's bound is
/// positive on the contact; CONTACT's traction of a flowing element, τc' + K_TAU |Δu_pl|, is not
/// floored, only the limit it carries on).
const MIN_LIMIT: f64 = 1e-3;

/// The fixed point's iteration limit (a solve of a steady sweep is cheap beside the sweep).
pub const MAX_ITERATIONS: usize = 400;

/// The smallest relaxation of the limits' update.
const MIN_RELAXATION: f64 = 1.0 / 16.0;

/// The layer, the grid's row length and the fixed point's options.
pub struct SteadyLimits<'a> {
    pub layer: &'a Layer,
    /// Elements per grid row (the rolling direction: +x in the solver's frame, upstream at i − 1).
    pub mx: usize,
    /// The steady self-flexibility C [mm/MPa]: the diagonal of A − A_s at dq = dx.
    pub self_flexibility_mm_per_mpa: f64,
    /// Stop when max|τc_new − τc| ≤ tolerance · max τc.
    pub tolerance: f64,
}

impl SteadyLimits<'_> {
    /// The steady solution on the friction bound's pressure `pn` [MPa] at μ `mu`, starting from the
    /// limits `start` [MPa] (the last sample's, or τ_c0): `solve(bound, start)` solves steady
    /// rolling with the bound's pressure `bound` [MPa], warm started from the last iterate's
    /// tractions `start` when given. Returns the last solve, the limits its slip gives and the
    /// outcome.
    pub fn solve(
        &self,
        pn: &[f64],
        mu: f64,
        start: &[f64],
        mut solve: impl FnMut(&[f64], Option<(&[f64], &[f64])>) -> Result<StepResult, ContactError>,
    ) -> Result<HardeningStep, ContactError> {
        let n = pn.len();
        let tau_c0 = self.layer.yield_mpa.unwrap_or(f64::INFINITY);
        let (c, k_tau) = (self.self_flexibility_mm_per_mpa, self.layer.hardening_mpa_per_mm);
        let kc = k_tau * c;
        let mut tau = start.to_vec();
        let mut bound = vec![0.0; n];
        let mut last: Option<StepResult> = None;
        let (mut inner, mut omega, mut before) = (0, 1.0, f64::INFINITY);
        for it in 1..=MAX_ITERATIONS {
            for k in 0..n {
                bound[k] = if pn[k] > 0.0 { pn[k].min(tau[k].max(MIN_LIMIT * tau_c0) / mu) } else { 0.0 };
            }
            let warm = last.as_ref().map(|r| (r.px.as_slice(), r.py.as_slice()));
            let r = solve(&bound, warm)?;
            inner += r.iterations;
            let mut next = vec![tau_c0; n];
            let mut implied = vec![tau_c0; n];
            let (mut change, mut size) = (0.0f64, 0.0f64);
            for row in 0..n / self.mx {
                // The limits carried into the element (not below the floor 0.1 τ_c0), of the next
                // iterate and of the last solve's slip.
                let mut upstream = (tau_c0, tau_c0);
                for k in row * self.mx..(row + 1) * self.mx {
                    let (up_next, up_implied) = upstream;
                    if pn[k] <= 0.0 {
                        // Outside the contact the limit is carried with the material.
                        (next[k], implied[k]) = upstream;
                        continue;
                    }
                    let friction = mu * pn[k];
                    let slip = if r.state[k] == ElementState::Slip { r.sx[k].hypot(r.sy[k]) } else { 0.0 };
                    let flowed = |up: f64| up + k_tau * self.layer.plastic_slip_mm(up, friction, slip);
                    let plain = flowed(up_next);
                    implied[k] = flowed(up_implied);
                    let target = match friction > up_next && 1.0 + kc > 0.0 {
                        // The element's own Newton step from its trial traction |p| + |s|/C.
                        true => {
                            let trial = r.px[k].hypot(r.py[k]) + slip / c;
                            let newton = (up_next + kc * trial) / (1.0 + kc);
                            match k_tau > 0.0 {
                                true => newton.clamp(up_next, friction),
                                false => newton.min(up_next),
                            }
                        }
                        false => plain,
                    };
                    next[k] = tau[k] + omega * (target - tau[k]);
                    change = change.max((plain - tau[k]).abs());
                    size = size.max(plain.abs());
                    upstream = (self.layer.hardened_mpa(next[k], 0.0), self.layer.hardened_mpa(implied[k], 0.0));
                }
            }
            let converged = change <= self.tolerance * size;
            if converged || it == MAX_ITERATIONS {
                return Ok((r, implied, HardeningOutcome { iterations: it, converged, inner_iterations: inner }));
            }
            // No progress: a smaller step (an element that flips between flowing and holding).
            if change >= before {
                omega = (0.5 * omega).max(MIN_RELAXATION);
            }
            before = change;
            tau = next;
            last = Some(r);
        }
        unreachable!("the loop returns at its last iteration")
    }
}
