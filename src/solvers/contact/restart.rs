//! The first transient step after a steady start when μ or FN changed at that step
//! (`[contact_solver] steady_restart`).
//!
//! CONTACT (TangCG, `m_solvpt.f90`) starts such a step from the steady state, which is the fixed
//! point of the transient map: the adhesion area has no slip, the residual is at the steady
//! solve's noise, and its stopping test on traction updates ends within two iterations. The jump
//! of the slip area onto the new bound μ p (step 9.2 of TangCG) is not part of the residual, so
//! the adhesion area never responds to it: CONTACT returns the steady state with the slip area
//! rescaled onto the new bound. This happens whenever its element division does not change
//! (an adhesion element above its new bound, or a slip element whose slip turns against its
//! traction, restart the full residual and CONTACT converges: a friction rise turns the slip of
//! the slip elements next to the adhesion area, envelope mu_rise). With the steady start solved
//! to EPS = 1e-10 instead of 1e-8 CONTACT converges at that step too, to the value `Converged`
//! gives (envelope mu_ramp and fn_sine_f20, step 1, 7 digits).

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
/// elements scaled onto `mu pn_mpa` (direction kept), or `None` where CONTACT converges instead:
/// the creepages changed, an element entered or left the contact, an adhesion element lies
/// outside its new bound, or a slip element's slip at the rescaled tractions turned against its
/// traction (TangCG step 11.2 moves it to adhesion; a friction rise does this). `slip_at(px, py)`
/// gives the step's slip `s = w + u' - A p` at tractions `p` (zero outside the contact).
pub fn contact_restart<E>(
    start: &SteadyStart,
    steady: &StepResult,
    at: &Sample,
    pn_mpa: &[f64],
    slip_at: impl FnOnce(&[f64], &[f64]) -> Result<(Vec<f64>, Vec<f64>), E>,
) -> Result<Option<StepResult>, E> {
    if start.creepage != (at.cx, at.cy, at.cs) {
        return Ok(None);
    }
    let mut r = steady.clone();
    for (k, &pn) in pn_mpa.iter().enumerate() {
        let g = at.mu * pn;
        match (steady.state[k], pn > 0.0) {
            (ElementState::Exterior, false) => {}
            (ElementState::Exterior, true) | (_, false) => return Ok(None),
            (ElementState::Adhesion, true) => {
                if r.px[k].hypot(r.py[k]) > g {
                    return Ok(None);
                }
            }
            (ElementState::Slip, true) => (r.px[k], r.py[k]) = scale_to_bound(r.px[k], r.py[k], g),
        }
    }
    let (sx, sy) = slip_at(&r.px, &r.py)?;
    let turned = |k: usize| sx[k] * r.px[k] + sy[k] * r.py[k] < 0.0;
    if (0..pn_mpa.len()).any(|k| steady.state[k] == ElementState::Slip && turned(k)) {
        return Ok(None);
    }
    (r.sx, r.sy) = (sx, sy);
    r.iterations = 0;
    r.residual = 0.0;
    r.termination = Termination::Direct;
    Ok(Some(r))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A steady state of two contact elements, one in adhesion and one in slip, at μ = 0.4.
    fn steady() -> StepResult {
        StepResult {
            px: vec![0.2, 0.4, 0.0],
            py: vec![0.0, 0.0, 0.0],
            sx: vec![0.0, 1e-3, 0.0],
            sy: vec![0.0; 3],
            state: vec![ElementState::Adhesion, ElementState::Slip, ElementState::Exterior],
            iterations: 7,
            residual: 1e-9,
            termination: Termination::Converged,
            n_adhesion: 1,
            n_slip: 1,
        }
    }

    fn sample(mu: f64) -> Sample {
        Sample::given(1, 0.0, 0.003, 0.0, 0.0, 1.0, mu)
    }

    #[test]
    fn restart_rescales_the_slip_area_unless_its_slip_turns() {
        let start = SteadyStart::of(&sample(0.4));
        let pn = [1.0, 1.0, 0.0];
        let slip = |sx: f64| move |_: &[f64], _: &[f64]| Ok::<_, ()>((vec![0.0, sx, 0.0], vec![0.0; 3]));
        // Friction drop: the slip area onto 0.3 p, the adhesion area untouched, the new slip kept.
        let r = contact_restart(&start, &steady(), &sample(0.3), &pn, slip(2e-3)).unwrap().unwrap();
        assert_eq!((r.px.clone(), r.sx.clone()), (vec![0.2, 0.3, 0.0], vec![0.0, 2e-3, 0.0]));
        assert_eq!((r.iterations, r.termination), (0, Termination::Direct));
        // The slip element's slip against its traction: CONTACT moves it to adhesion and solves.
        assert!(contact_restart(&start, &steady(), &sample(0.5), &pn, slip(-1e-6)).unwrap().is_none());
        // An adhesion element above its new bound, or changed creepage: solved too.
        assert!(contact_restart(&start, &steady(), &sample(0.1), &pn, slip(1e-3)).unwrap().is_none());
        let moved = Sample { cx: 0.004, ..sample(0.3) };
        assert!(contact_restart(&start, &steady(), &moved, &pn, slip(1e-3)).unwrap().is_none());
        // The slip's error passes through.
        let failing = |_: &[f64], _: &[f64]| Err::<(Vec<f64>, Vec<f64>), _>("no slip");
        assert_eq!(contact_restart(&start, &steady(), &sample(0.3), &pn, failing).unwrap_err(), "no slip");
    }
}
