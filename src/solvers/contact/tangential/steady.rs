//! Steady rolling by Anderson acceleration (Walker & Ni 2011, [`Anderson`]) of a preconditioned
//! projected Jacobi map whose fixed points are the steady solutions: local solves
//! ([`element`](super::element)) on the slip elements, and on the adhesion elements the
//! correction `(I - S)^-1 M s`, with `M` the CG preconditioner (the inverse of `A` periodised at twice the grid)
//! and `(I - S)^-1` the inverse of the shift by `dq` along the rows (`A - A_s = A (I - S)` for the
//! translation-invariant kernel, Kalker 1990, eq. 5.40), so that the transport that makes plain
//! iterations slow is inverted exactly; every mixed iterate is projected onto the traction bound.
//! Two FFT products per evaluation. It stops when the largest local change (every element's
//! local solve at the exact slip of the iterate) is below `tol`, the test of the CG solver; if it
//! stalls, diverges or produces non-finite values, Gauss–Seidel continues from the best iterate.

use super::super::anderson::Anderson;
use super::element::Local;
use super::operator::Plans;
use super::{ContactError, Layout, State, TangentialParams};
use crate::physics::bound::project_to_bound;

/// History depth of the Anderson accelerator.
const DEPTH: usize = 16;
/// At most this many map evaluations (and at most `max_iter`) before Gauss–Seidel takes over.
const MAX_EVALS: usize = 400;
/// The accelerated iteration ends (Gauss–Seidel takes over) when the best residual has not halved
/// within this many evaluations.
const STALL: usize = 40;
/// A residual above this multiple of the best one restarts the Anderson history from the best
/// map value.
const BLOWUP: f64 = 1e3;
/// Restarts allowed before Gauss–Seidel takes over.
const MAX_RESTARTS: usize = 3;

/// Work arrays of the accelerated steady solver, for one contact area. The vectors of the
/// accelerator are packed over the contact elements as `[px of each contact element..., py of
/// each...]`.
pub(super) struct SteadyWork {
    /// Iterate on the grid (input of the convolutions).
    ax: Vec<f64>,
    ay: Vec<f64>,
    /// Slip of the adhesion elements (zero on slip elements), input of the preconditioner.
    sx: Vec<f64>,
    sy: Vec<f64>,
    /// The preconditioner applied to it, `M s`.
    msx: Vec<f64>,
    msy: Vec<f64>,
    /// The correction `e = (I - S)^-1 M s` on the adhesion elements.
    ex: Vec<f64>,
    ey: Vec<f64>,
    /// Iterate, map value, residual and best map value so far (packed).
    x: Vec<f64>,
    g: Vec<f64>,
    f: Vec<f64>,
    best: Vec<f64>,
    anderson: Anderson,
}

impl SteadyWork {
    /// Work for a grid of `n` elements with `nc` contact elements.
    pub(super) fn new(n: usize, nc: usize) -> SteadyWork {
        let z = |len: usize| vec![0.0; len];
        SteadyWork {
            ax: z(n),
            ay: z(n),
            sx: z(n),
            sy: z(n),
            msx: z(n),
            msy: z(n),
            ex: z(n),
            ey: z(n),
            x: z(2 * nc),
            g: z(2 * nc),
            f: z(2 * nc),
            best: z(2 * nc),
            anderson: Anderson::new(2 * nc, DEPTH),
        }
    }
}

/// Anderson-accelerated fixed-point iteration for steady rolling: `x <- P(x_AA)`, `x_AA` the
/// Anderson mix of the map values `G(x)` of [`map`], `P` the projection onto the traction bound.
/// Starts from `(px, py)` (on or inside the bound) and leaves there the last iterate if it met
/// the stopping test, else the best map value seen (or the start, if none was finite).
/// Safeguards: a residual above [`BLOWUP`] times the best one (or non-finite) restarts the history
/// from the best map value, at most [`MAX_RESTARTS`] times; no halving of the best residual within
/// [`STALL`] evaluations ends the iteration. Returns `(map evaluations, Some(final residual) if it
/// met the test)`. Expects `max(g) > 0`.
pub(super) fn solve(
    lay: &Layout,
    plans: &mut Plans,
    st: &mut State,
    w: &mut SteadyWork,
    params: &TangentialParams,
) -> Result<(usize, Option<f64>), ContactError> {
    let stop_tol = params.tol;
    let max_evals = params.max_iter.min(MAX_EVALS);
    let mu = params.mu;
    let nc = lay.contact.len();
    w.anderson.restart();
    for (i, &k) in lay.contact.iter().enumerate() {
        w.x[i] = st.px[k];
        w.x[nc + i] = st.py[k];
    }
    let mut best_res = f64::INFINITY;
    let mut progress_res = f64::INFINITY;
    let mut progress_eval = 0;
    let mut restarts = 0;
    let mut evals = 0;
    let mut converged = None;
    while evals < max_evals {
        let res = map(lay, plans, st, w, params)?;
        evals += 1;
        if res < stop_tol {
            converged = Some(res);
            break;
        }
        if res < best_res {
            best_res = res;
            w.best.copy_from_slice(&w.g);
        }
        if best_res <= 0.5 * progress_res {
            progress_res = best_res;
            progress_eval = evals;
        } else if evals - progress_eval >= STALL {
            break;
        }
        if !res.is_finite() || res > BLOWUP * best_res {
            // Diverging or non-finite: restart from the best map value.
            restarts += 1;
            if restarts > MAX_RESTARTS || !best_res.is_finite() {
                break;
            }
            w.anderson.restart();
            w.x.copy_from_slice(&w.best);
            continue;
        }
        for i in 0..2 * nc {
            w.f[i] = w.g[i] - w.x[i];
        }
        w.anderson.step(&mut w.x, &w.g, &w.f);
        // Project the mixed iterate onto the traction bound.
        for (i, &k) in lay.contact.iter().enumerate() {
            (w.x[i], w.x[nc + i], _) = project_to_bound(w.x[i], w.x[nc + i], mu * lay.pn[k]);
        }
    }
    let result = if converged.is_some() {
        Some(&w.x)
    } else if best_res.is_finite() {
        Some(&w.best)
    } else {
        None
    };
    if let Some(v) = result {
        for (i, &k) in lay.contact.iter().enumerate() {
            st.px[k] = v[i];
            st.py[k] = v[nc + i];
        }
    }
    Ok((evals, converged))
}

/// The fixed-point map at the iterate `w.x` (packed; on or inside the bound): `w.g = G(x)`. With
/// the exact steady slip `s = w - (A - A_s) x` (one FFT product):
/// * every element's local problem is solved with the others fixed (as in Gauss–Seidel, diagonal
///   of `A - A_s`); elements whose local solution lies on the bound are slip elements and take it
///   as their map value;
/// * the adhesion elements take `x + (I - S)^-1 M s`, `M` the inverse of `A` periodised at twice the grid
///   applied to the adhesion slip (the CG preconditioner) and `(I - S)^-1` the exact inverse of
///   the shift by the rolling distance along each run of adhesion elements of a grid row (zero
///   inflow at the run's upstream end); the result is projected onto the bound.
///
/// Returns the largest local change `max|p_local - x| / max(g)` (infinite if anything is not
/// finite): the quantity whose maximum over a sweep is the Gauss–Seidel stopping test.
fn map(
    lay: &Layout,
    plans: &mut Plans,
    st: &mut State,
    w: &mut SteadyWork,
    params: &TangentialParams,
) -> Result<f64, ContactError> {
    let mu = params.mu;
    let nc = lay.contact.len();
    let mx = lay.mx;
    let d = plans.steady.diag;
    let gmax = lay.gmax(mu);
    for (i, &k) in lay.contact.iter().enumerate() {
        w.ax[k] = w.x[i];
        w.ay[k] = w.x[nc + i];
    }
    // s = w - (A - A_s) x.
    plans.convd.tangential(&w.ax, &w.ay, Some(&lay.mask), &mut st.ux, &mut st.uy)?;
    for &k in &lay.contact {
        st.sx[k] = -st.ux[k];
        st.sy[k] = -st.uy[k];
    }
    lay.add_rigid_slip(params, None, &mut st.sx, &mut st.sy);
    // Local solves; the adhesion slip goes into (w.sx, w.sy) for the preconditioner.
    let mut res = 0.0f64;
    let mut finite = true;
    for (i, &k) in lay.contact.iter().enumerate() {
        let (p0x, p0y) = (w.x[i], w.x[nc + i]);
        let (nx, ny, slips) = Local::new(st.sx[k], st.sy[k], p0x, p0y, d).solve(d, mu * lay.pn[k]);
        st.slip[k] = slips;
        (w.sx[k], w.sy[k]) = if slips { (0.0, 0.0) } else { (st.sx[k], st.sy[k]) };
        w.g[i] = nx;
        w.g[nc + i] = ny;
        let change = (nx - p0x).abs().max((ny - p0y).abs());
        finite &= change.is_finite();
        res = res.max(change);
    }
    if !finite {
        return Ok(f64::INFINITY);
    }
    plans.prec.tangential(&w.sx, &w.sy, Some(&lay.mask), &mut w.msx, &mut w.msy)?;
    // e = (I - S)^-1 M s along each run of adhesion elements of a grid row: S shifts by
    // theta = n + f elements downstream (linear interpolation; e_i - (1-f) e_(i-n) - f e_(i-n-1)
    // = (M s)_i), zero inflow at the run's start.
    let theta = lay.courant();
    let n_shift = theta.floor() as usize;
    let frac = theta - n_shift as f64;
    let mut run_lo = 0;
    for (i, &k) in lay.contact.iter().enumerate() {
        if st.slip[k] {
            continue;
        }
        let cont = i > 0 && k % mx != 0 && lay.contact[i - 1] == k - 1 && !st.slip[k - 1];
        if !cont {
            run_lo = k;
        }
        let prev = |e: &[f64], back: usize| if k >= run_lo + back { e[k - back] } else { 0.0 };
        let (ex, ey) = if n_shift == 0 {
            (prev(&w.ex, 1) + w.msx[k] / frac, prev(&w.ey, 1) + w.msy[k] / frac)
        } else {
            let (a, b) = (1.0 - frac, frac);
            (
                w.msx[k] + a * prev(&w.ex, n_shift) + b * prev(&w.ex, n_shift + 1),
                w.msy[k] + a * prev(&w.ey, n_shift) + b * prev(&w.ey, n_shift + 1),
            )
        };
        w.ex[k] = ex;
        w.ey[k] = ey;
        let (gx, gy, _) = project_to_bound(w.x[i] + ex, w.x[nc + i] + ey, mu * lay.pn[k]);
        w.g[i] = gx;
        w.g[nc + i] = gy;
    }
    Ok(res / gmax)
}
