//! Friction of the surface temperature in steady rolling (CONTACT's L = 6): its fixed point on
//! the temperature around the tangential solve (`m_stang.f90`, `stang`, the outer loop's L = 6
//! branch), the pattern of [`super::veldep`] with the temperature in place of the slip velocity.
//!
//! Per iteration: μ per element from the surface temperature T by the law
//! ([`TemperatureLaw::mu_at`]); the tangential problem with the fixed bound μ_k pn_k; T_new the
//! temperatures of that solution's frictional heat ([`super::heat`]); stop when
//! rms(T_new − T) ≤ tol·rms(T_new) over the contact (CONTACT: tol = 1e-4) or when no element
//! slips; T := T_new, damped by OMGSLP in slip elements whose μ exceeds the upstream element's
//! (before the stop, as CONTACT: body 1's reported temperature is that iterate), OMGSLP × 0.8
//! every 15 iterations while the element division changes. The first
//! iterate's T is the temperature without frictional heat (CONTACT's `calc_temp` before the loop
//! on tractions that are zero in a new steady case, P = 2). CONTACT clamps a damped T at 0 °C; a
//! temperature in °C may be negative, so this iteration does not (the same fixed point).
//! Axes as the solver's: leading edge at ix = 0, material moving to +x.

use super::tangential::{ElementState, StepResult};
use super::veldep::{inner_tolerance, onto_bound, rms_pair, VelDepOutcome};
use super::ContactError;
use crate::physics::TemperatureLaw;

/// The fixed point's options (`[contact_solver]`: `tempdep_tolerance`, `tempdep_max_iterations`,
/// `omgslp`, `veldep_solves`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TempDepOptions {
    /// Stop when rms(T_new − T) ≤ tolerance · rms(T_new) (CONTACT: a fixed 1e-4).
    pub tolerance: f64,
    /// Iteration limit (CONTACT: max(1, MAXIN − 10) + 1; `[contact_solver] tempdep_max_iterations`).
    pub max_iterations: usize,
    /// The damping OMGSLP (CONTACT's default 0.5).
    pub omgslp: f64,
    /// The tolerance of the tangential solve the fixed point ends on.
    pub solve_tolerance: f64,
    /// Early iterates solved loosely, each solve started with the last one's slip area on the
    /// new bound ([`onto_bound`]); false: CONTACT's path, every iterate at `solve_tolerance`.
    pub adaptive_solves: bool,
}

/// OMGSLP is reduced every this many iterations while the element division changes
/// (`m_stang.f90`, the L = 6 branch: `mod(itslp, 15)`; 20 for the slip velocity).
const REDUCE_EVERY: usize = 15;

/// The law, the μ field of the last solve and the fixed point's last iterate.
pub struct TempDep {
    law: TemperatureLaw,
    options: TempDepOptions,
    mx: usize,
    mu: Vec<f64>,
    /// The last iterate T [°C] (body 1, the solver's frame): the last solve's, damped.
    temperature_c: Vec<f64>,
}

impl TempDep {
    pub fn new(law: TemperatureLaw, options: TempDepOptions, mx: usize, n: usize) -> TempDep {
        TempDep { law, options, mx, mu: vec![law.fref; n], temperature_c: Vec::new() }
    }

    /// The μ field of the last solve.
    pub fn mu(&self) -> &[f64] {
        &self.mu
    }

    /// Body 1's surface temperature [°C] as the fixed point ended (the solver's frame): the last
    /// solve's, damped where it damps (CONTACT's `temp1` after its loop, which it prints as
    /// MAX(T1,T2) with body 2's undamped one); the same as the last solve's to the tolerance
    /// where the fixed point converged.
    pub fn temperature_c(&self) -> &[f64] {
        &self.temperature_c
    }

    /// Solve one steady point on pressure `pn`, `theta` the memory's weight of the upstream μ
    /// (0: none; [`crate::physics::Memory::theta`] at the slip velocity the iteration starts
    /// from, which CONTACT's L = 6 keeps, `m_stang.f90`): `unheated_c` the temperature of every element
    /// without frictional heat (the start), `heat(r)` the temperature of body 1 under solution
    /// `r` (the solver's frame), `solve(bound, start, tol)` the tangential problem with the bound
    /// μ_k pn_k [MPa] to the tolerance `tol`, warm started from `start` when given.
    pub fn step(
        &mut self,
        pn: &[f64],
        theta: f64,
        unheated_c: Vec<f64>,
        mut heat: impl FnMut(&StepResult) -> Vec<f64>,
        mut solve: impl FnMut(&[f64], Option<(&[f64], &[f64])>, f64) -> Result<StepResult, ContactError>,
    ) -> Result<(StepResult, VelDepOutcome), ContactError> {
        let n = pn.len();
        let mut t = unheated_c;
        let (mut mu, mut mu_prev, mut bound) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let mut omgslp = self.options.omgslp;
        let mut last: Option<StepResult> = None;
        let (mut inner, mut last_change) = (0, None);
        for it in 1..=self.options.max_iterations {
            self.friction_field(&t, theta, &mut mu, &mut mu_prev);
            for k in 0..n {
                bound[k] = mu[k] * pn[k];
            }
            let adaptive = self.options.adaptive_solves;
            let on_bound = last.as_ref().filter(|_| adaptive).map(|r| onto_bound(&r.px, &r.py, &r.state, &bound));
            let start = match (&on_bound, last.as_ref()) {
                (Some((x, y)), _) => Some((x.as_slice(), y.as_slice())),
                (None, Some(r)) => Some((r.px.as_slice(), r.py.as_slice())),
                (None, None) => None,
            };
            let solve_tolerance = self.options.solve_tolerance;
            let tol = if adaptive { inner_tolerance(solve_tolerance, last_change) } else { solve_tolerance };
            let r = solve(&bound, start, tol)?;
            inner += r.iterations;
            let t_new = heat(&r);
            let (dif, size) = rms_pair(pn, &t_new, &t);
            let change = if size > 0.0 { dif / size } else { 0.0 };
            // Damped before the stop, as CONTACT: its body-1 temperature is this iterate.
            for k in 0..n {
                let damp = it > 1 && r.state[k] == ElementState::Slip && mu[k] > mu_prev[k];
                t[k] = if damp { t[k] + omgslp * (t_new[k] - t[k]) } else { t_new[k] };
            }
            let tight = tol <= solve_tolerance || r.residual <= solve_tolerance;
            let converged = tight && (dif <= self.options.tolerance * size || r.n_slip == 0);
            if converged || it == self.options.max_iterations {
                self.mu.copy_from_slice(&mu);
                self.temperature_c = t;
                return Ok((r, VelDepOutcome { iterations: it, converged, change, inner_iterations: inner }));
            }
            last_change = Some(change);
            let changed = last.as_ref().is_some_and(|l| l.state != r.state);
            if changed && it % REDUCE_EVERY == 0 {
                omgslp *= 0.8;
            }
            last = Some(r);
        }
        unreachable!("the loop returns at its last iteration (max_iterations >= 1)")
    }

    /// μ per element from T, θ μ_prev + (1 − θ) μ(T), and each element's μ_prev: the upstream
    /// element's μ in its row, FREF (FSTAT) at the leading edge (`m_stang.f90`, the loop over the
    /// row with `is_ssrol`).
    fn friction_field(&self, t: &[f64], theta: f64, mu: &mut [f64], mu_prev: &mut [f64]) {
        let mx = self.mx;
        for (row, (mu_row, prev_row)) in mu.chunks_mut(mx).zip(mu_prev.chunks_mut(mx)).enumerate() {
            let mut upstream = self.law.fref;
            for i in 0..mx {
                prev_row[i] = upstream;
                let mu_t = self.law.mu_at(t[row * mx + i]);
                mu_row[i] = if theta == 0.0 { mu_t } else { theta * upstream + (1.0 - theta) * mu_t };
                upstream = mu_row[i];
            }
        }
    }
}
