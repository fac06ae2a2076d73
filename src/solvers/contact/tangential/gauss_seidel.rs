//! Projected Gauss–Seidel (CONTACT's ConvexGS family; Kalker 1990, sec. 5.4): element by element,
//! with the other tractions fixed, the local problem of [`element`](super::element) is solved
//! exactly, and the slip field is kept exact by updating every contact element's slip when one
//! traction changes (cost O(n_contact^2) per sweep). The visiting order is fixed by the caller:
//! leading edge first for transient steps, trailing edge first for steady rolling (the other
//! order diverges for `A - A_s`).

use super::element::Local;
use super::operator::Operator;
use super::{ContactError, Layout, Outcome, State, TangentialParams};
use crate::physics::bound::project_to_bound;

/// Projected Gauss–Seidel sweeps on the current `(px, py)` with the slip `(sx, sy)` exact for
/// them, visiting the contact elements in `order`, until the largest traction change of a sweep
/// relative to `max(g)` is below `tol` or `max_iter` sweeps are made. With `mu = 0` every element
/// slips with zero traction.
pub(super) fn solve(
    lay: &Layout,
    op: &Operator,
    order: &[usize],
    st: &mut State,
    params: &TangentialParams,
) -> Result<Outcome, ContactError> {
    let d = op.diag;
    let mu = params.mu;
    let gmax = lay.gmax(mu);
    let mut iterations = 0;
    let mut residual = f64::INFINITY;
    let mut converged = false;
    if gmax <= 0.0 {
        // mu = 0: no traction possible, everything slips.
        for &k in &lay.contact {
            st.px[k] = 0.0;
            st.py[k] = 0.0;
            st.slip[k] = true;
        }
        residual = 0.0;
        converged = true;
    }
    // Traction changes below this are not applied (they are far below the stopping level).
    let skip = 1e-3 * params.tol * gmax;
    while !converged && iterations < params.max_iter {
        iterations += 1;
        let mut dmax = 0.0f64;
        for &k in order {
            let (p0x, p0y) = (st.px[k], st.py[k]);
            let g = mu * lay.pn[k];
            let (mut nx, mut ny, slips) = Local::new(st.sx[k], st.sy[k], p0x, p0y, d).solve(d, g);
            if !slips {
                // A sticking element moves by the increment to its stick solution; `p0 + (q - p0)`
                // may differ from `q` in the last bit, and this is the arithmetic the stored
                // results were computed with. Projected back onto the bound for that last bit.
                (nx, ny, _) = project_to_bound(p0x + (nx - p0x), p0y + (ny - p0y), g);
            }
            st.slip[k] = slips;
            let (dpx, dpy) = (nx - p0x, ny - p0y);
            let change = dpx.abs().max(dpy.abs());
            if change > dmax {
                dmax = change;
            }
            if change <= skip {
                continue;
            }
            st.px[k] = nx;
            st.py[k] = ny;
            op.update_slip(&lay.spans, &mut st.sx, &mut st.sy, k, (dpx, dpy));
        }
        if !dmax.is_finite() {
            return Err(ContactError::NonFinite("tangential Gauss-Seidel sweep"));
        }
        residual = dmax / gmax;
        if residual < params.tol {
            converged = true;
        }
    }
    Ok(Outcome { iterations, residual, converged })
}
