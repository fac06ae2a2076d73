//! The first transient step after a steady start when μ or FN changed at that step
//! (`[contact_solver] steady_restart`).
//!
//! CONTACT (TangCG, `m_solvpt.f90`) starts such a step from the steady state, which is the fixed
//! point of the transient map: the adhesion area has no slip, the residual is at the steady
//! solve's noise, and its stopping test on traction updates ends within two iterations. The jump
//! of the slip area onto the new bound μ p (step 9.2 of TangCG) is not part of the residual, so
//! the adhesion area never responds to it: CONTACT returns the steady state with the slip area
//! rescaled onto the new bound. This happens whenever its element division does not change
//! (an adhesion element above its new bound, or a slip element whose slip turns, restart the
//! full residual and CONTACT converges). With the steady start solved to EPS = 1e-10 instead of
//! 1e-8 CONTACT converges at that step too, to the value `Converged` gives (envelope mu_ramp and
//! fn_sine_f20, step 1, 7 digits).

use super::tangential::{ElementState, StepResult};
use crate::physics::bound::scale_to_bound;
use crate::problem::Sample;
pub use crate::scene::SteadyRestart;
use crate::solvers::termination::Termination;

/// The loading of the steady start the restart compares with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteadyStart {
    pub mu: f64,
    pub fn_n: f64,
    pub creepage: (f64, f64, f64),
}

impl SteadyStart {
    pub fn of(s: &Sample) -> Self {
        SteadyStart { mu: s.mu, fn_n: s.fn_n, creepage: (s.cx, s.cy, s.cs) }
    }

    /// Whether μ or FN changed at `at` (else the steady state is the step's own solution).
    pub fn load_changed(&self, at: &Sample) -> bool {
        (self.mu, self.fn_n) != (at.mu, at.fn_n)
    }
}

/// CONTACT's restart ([`SteadyRestart::Contact`]): the steady state `steady` with its slip
/// elements scaled onto `mu pn_mpa` (direction kept), or `None` where CONTACT converges instead
/// (the creepages changed, an element entered or left the contact, or an adhesion element lies
/// outside its new bound).
pub fn contact_restart(start: &SteadyStart, steady: &StepResult, at: &Sample, pn_mpa: &[f64]) -> Option<StepResult> {
    if start.creepage != (at.cx, at.cy, at.cs) {
        return None;
    }
    let mut r = steady.clone();
    for (k, &pn) in pn_mpa.iter().enumerate() {
        let g = at.mu * pn;
        match (steady.state[k], pn > 0.0) {
            (ElementState::Exterior, false) => {}
            (ElementState::Exterior, true) | (_, false) => return None,
            (ElementState::Adhesion, true) => {
                if r.px[k].hypot(r.py[k]) > g {
                    return None;
                }
            }
            (ElementState::Slip, true) => (r.px[k], r.py[k]) = scale_to_bound(r.px[k], r.py[k], g),
        }
    }
    r.iterations = 0;
    r.residual = 0.0;
    r.termination = Termination::Direct;
    Some(r)
}
