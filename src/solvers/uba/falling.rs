//! The UBA's step with a falling friction law: the upwind update of [`super::flat::unbounded`],
//! then each element's bound μ(s) p at its own slip velocity ([`brush::Falling`], the fixed point
//! of [`crate::physics::bound::falling_bound`]). The coefficient of the friction memory is
//! carried with the material by the same upwind difference as the tractions,
//! `μ_adv = μ + C (μ_up − μ)` (fresh material at a row's start: the static value), before the
//! memory's backward-Euler update over the sub-step's time C dx / V. Element by element (no AVX
//! path: the bound is an iteration per slipping element); the sums in the four-lane order.

use super::flat::{unbounded, Io, Lanes};
use super::{Prepared, StepSums};
use crate::solvers::brush::{ElementBound, Falling};

/// One sub-step from `old` into `new` (tractions in `io`, coefficients `mu_old` into `mu_new`),
/// `k` the constants of [`super::flat::step`], `pressure_mpa` the planform's pressure.
pub(super) fn step<const GHOST: bool, const SPIN: bool>(
    p: &Prepared,
    (bound, pressure_mpa): (&Falling, &[f64]),
    (ox, oy, nx, ny): Io,
    (mu_old, mu_new): (&[f64], &mut [f64]),
    k: [f64; 5],
) -> StepSums {
    let mut sums = Lanes::default();
    let n = ox.len();
    let (c, fresh) = (k[0], bound.inflow_mu());
    for m in 0..n {
        let pm = pressure_mpa[m];
        let r = if pm > 0.0 {
            let (vx, vy) = unbounded::<GHOST, SPIN>(p, (ox, oy), k, m);
            let mu_up = if p.upstream[m] > 0.0 { mu_old[m - 1] } else { fresh };
            let mu_adv = mu_old[m] + c * (mu_up - mu_old[m]);
            let (tx, ty, slips, mu) = bound.apply(vx, vy, pm, p.gain[m], mu_adv);
            mu_new[m] = mu;
            (tx, ty, slips)
        } else {
            mu_new[m] = fresh;
            (0.0, 0.0, false)
        };
        (nx[m], ny[m]) = (r.0, r.1);
        sums.add(p, m, n, r);
    }
    sums.finish()
}
