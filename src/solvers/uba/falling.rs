//! The UBA's step with a falling friction law: the upwind update of [`super::flat::unbounded`],
//! then each element's bound μ(s) p at its own slip velocity ([`Falling`], the fixed point
//! of [`crate::physics::bound::falling_bound`]). The coefficient of the friction memory is
//! carried with the material by the same upwind difference as the tractions,
//! `μ_adv = μ + C (μ_up − μ)` (fresh material at a row's start: the static value), before the
//! memory's backward-Euler update over the sub-step's time C dx / V. [`BOUND_GROUP`] elements
//! at a time ([`ElementBound::apply_lanes`]: their bounds' iterations in step, compiled for AVX2
//! where the CPU has it, the same bits either way); the sums in the four-lane order.

use super::flat::{unbounded, Io, Lanes};
use super::{Prepared, StepSums};
use crate::simd::with_avx2;
use crate::solvers::brush::{ElementBound, Falling, Group, BOUND_GROUP};

/// The planform's pressure [MPa] and its reciprocal [1/MPa] per element.
pub(super) type Pressure<'a> = (&'a [f64], &'a [f64]);

/// One sub-step from `old` into `new` (tractions in `io`, coefficients `mu_old` into `mu_new`),
/// `k` the constants of [`super::flat::step`], `pressure` the planform's pressure and its
/// reciprocal ([`crate::physics::Planform`]).
pub(super) fn step<const GHOST: bool, const SPIN: bool>(
    p: &Prepared,
    (bound, pressure): (&Falling, Pressure),
    io: Io,
    mu: (&[f64], &mut [f64]),
    k: [f64; 5],
) -> StepSums {
    with_avx2(
        #[inline(always)]
        || groups::<GHOST, SPIN>(p, (bound, pressure), io, mu, k),
    )
}

/// [`step`] in groups of [`BOUND_GROUP`] elements ([`ElementBound::apply_lanes`]; the last group
/// padded with unloaded lanes), each element as [`crate::solvers::brush::ElementBound::apply`] would give it.
#[inline(always)]
fn groups<const GHOST: bool, const SPIN: bool>(
    p: &Prepared,
    (bound, (pressure_mpa, inv_pressure)): (&Falling, Pressure),
    (ox, oy, nx, ny): Io,
    (mu_old, mu_new): (&[f64], &mut [f64]),
    k: [f64; 5],
) -> StepSums {
    let mut sums = Lanes::default();
    let n = ox.len();
    let (c, fresh) = (k[0], bound.inflow_mu());
    for m0 in (0..n).step_by(BOUND_GROUP) {
        let len = BOUND_GROUP.min(n - m0);
        let mut e = Group::<BOUND_GROUP>::unloaded(fresh);
        for l in 0..len {
            let m = m0 + l;
            (e.p[l], e.inv_p[l]) = (pressure_mpa[m], inv_pressure[m]);
            if e.p[l] > 0.0 {
                (e.ux[l], e.uy[l]) = unbounded::<GHOST, SPIN>(p, (ox, oy), k, m);
                let mu_up = if p.upstream[m] > 0.0 { mu_old[m - 1] } else { fresh };
                e.mu_up[l] = mu_old[m] + c * (mu_up - mu_old[m]);
                // Newton from the element's own coefficient of the last sub-step.
                e.mu_start[l] = mu_old[m];
                e.gain[l] = p.gain[m];
            }
        }
        let out = ElementBound::apply_lanes(bound, &e);
        for (l, &(tx, ty, slips, mu)) in out.iter().enumerate().take(len) {
            let m = m0 + l;
            let r = if e.p[l] > 0.0 {
                mu_new[m] = mu;
                (tx, ty, slips)
            } else {
                mu_new[m] = fresh;
                (0.0, 0.0, false)
            };
            (nx[m], ny[m]) = (r.0, r.1);
            sums.add(p, m, n, r);
        }
    }
    sums.finish()
}
