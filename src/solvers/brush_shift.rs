//! One shift of the brush without rolling (Kalker 1990 §3.3, the simplified theory's u = L τ per
//! element; CONTACT's T = 1): each element of the material-fixed grid keeps its traction, moved by
//! its own rigid shift over the flexibilities and bounded by μ p. FASTSIM and the UBA share it:
//! they differ only in how they march a rolling contact, and a shift rolls nothing (in a sequence
//! of shifts the contact moves over the material-fixed grid, which is how it rolls there).

use super::brush::Tractions;
use crate::physics::{project_to_bound, Grid, RigidSlip};
use crate::problem::LocalContact;

/// One shift from `old` into `new` (grid order): each loaded element's traction
/// `old + gain · w(x, y) / L` (`shift`: the step's rigid shift [mm, rad] over the flexibilities,
/// [`super::brush::slip_rates`] of the shifts in place of the creepages, at the element's centre),
/// then bounded by μ p ([`project_to_bound`], thesis Eq. 2.29); an element without pressure carries
/// nothing. From rest each traction is `min(|w|/L, μ p)` along its shift (equal flexibilities).
/// Returns the elements on the bound.
pub fn shift_step(
    grid: &Grid,
    local: &LocalContact,
    mu: f64,
    shift: &RigidSlip,
    old: &Tractions,
    new: &mut Tractions,
) -> usize {
    let pressure = &local.planform.pressure_mpa;
    let mut n_slip = 0;
    for j in 0..grid.my {
        let gain = local.row_gain[j];
        for i in 0..grid.mx {
            let k = grid.index(i, j);
            let p = pressure[k];
            if p <= 0.0 {
                (new.tx[k], new.ty[k]) = (0.0, 0.0);
                continue;
            }
            let (wx, wy) = shift.at(grid.x_mm[i], grid.y_mm[j]);
            let (tx, ty, slip) = project_to_bound(old.tx[k] + gain * wx, old.ty[k] + gain * wy, mu * p);
            (new.tx[k], new.ty[k]) = (tx, ty);
            n_slip += usize::from(slip);
        }
    }
    n_slip
}
