//! Transient steps by nonlinear preconditioned conjugate gradients (TangCG type, Vollebregt,
//! CONTACT user guide, "TangCG"): CG on the adhesion tractions and on the directions of the slip
//! tractions (kept on the bound), the bound circle's curvature `lambda/g` added to the slip
//! elements' stiffness; element sets updated every [`INNER`] iterations with a restart on a
//! change. Products `A v` by FFT, the search directions' products and the preconditioner in
//! single precision (the slip is recomputed exactly in double precision every [`INNER`]
//! iterations and for the stopping test: iterative refinement). The preconditioner is the FFT
//! inverse of `A` periodised at twice the grid, blended on the slip elements with their diagonal stiffness by
//! how fast they slip ([`CgWork::apply_prec`]).
//!
//! The element passes run over every grid element in their AVX2 build ([`with_avx2`]) and leave
//! the elements outside the contact (`lay.mask` false) as they were: branch-free selects, where a
//! loop over the contact list would branch on every element. Sums in the four-lane order of
//! [`crate::physics::lanes`].

use super::super::convolution::Convolver;
use super::element::{norm2, on_bound, Diag, Local};
use super::operator::Plans;
use super::{ContactError, Layout, Outcome, State, TangentialParams};
use crate::physics::bound::{project_to_bound, scale_to_bound};
use crate::physics::lanes::{max4, sums2_by};
use crate::simd::with_avx2;

/// CG iterations between exact slip evaluations and element set updates.
const INNER: usize = 4;

/// Work arrays of the conjugate-gradient solver.
pub(super) struct CgWork {
    /// Search direction.
    vx: Vec<f64>,
    vy: Vec<f64>,
    /// `A v` (single precision product), and before that the weighted residual fed to the
    /// preconditioner.
    qx: Vec<f64>,
    qy: Vec<f64>,
    /// The reduced operator applied to `v` (slip elements: along the tangent plus curvature).
    qpx: Vec<f64>,
    qpy: Vec<f64>,
    /// Residual of the reduced problem.
    rx: Vec<f64>,
    ry: Vec<f64>,
    /// Preconditioned residual.
    zx: Vec<f64>,
    zy: Vec<f64>,
    /// FFT part of the preconditioner applied to the weighted residual.
    zrx: Vec<f64>,
    zry: Vec<f64>,
    /// Weight of the FFT part of the preconditioner: 1 on adhesion elements, on slip elements
    /// `sqrt((d - lambda/g) / d)` (0 if degenerate); set by [`CgWork::residual`].
    wt: Vec<f64>,
    /// Slip elements, set by [`CgWork::residual`]: unit tangent `t` of the bound circle at `p`,
    /// the curvature term `lambda/g` and the tangential stiffness `t.D t + lambda/g`.
    tx: Vec<f64>,
    ty: Vec<f64>,
    curv: Vec<f64>,
    stiff: Vec<f64>,
    /// Per-element magnitudes for a maximum: `|z|` in the residual (adhesion: the larger
    /// component), `max(|vx|, |vy|)` in the reduced product.
    mags: Vec<f64>,
}

impl CgWork {
    pub(super) fn new(n: usize) -> CgWork {
        let z = || vec![0.0; n];
        CgWork {
            vx: z(),
            vy: z(),
            qx: z(),
            qy: z(),
            qpx: z(),
            qpy: z(),
            rx: z(),
            ry: z(),
            zx: z(),
            zy: z(),
            zrx: z(),
            zry: z(),
            wt: z(),
            tx: z(),
            ty: z(),
            curv: z(),
            stiff: z(),
            mags: z(),
        }
    }

    /// Residual and diagonally preconditioned residual of the reduced problem (adhesion: the slip
    /// itself; slip: its component along the bound circle), into `r`, `z`, and the slip
    /// elements' tangent, curvature, stiffness and preconditioner weight (see
    /// [`CgWork::apply_prec`]). Returns `max |z|` (the change a local Gauss–Seidel solve would
    /// make, to first order) [MPa]. One pass over the grid, elements outside the contact left as
    /// they are (see the module doc).
    fn residual(&mut self, lay: &Layout, st: &State, d: Diag, mu: f64) -> f64 {
        with_avx2(
            #[inline(always)]
            || self.residual_pass(lay, st, d, mu),
        )
    }

    #[inline(always)]
    fn residual_pass(&mut self, lay: &Layout, st: &State, d: Diag, mu: f64) -> f64 {
        let n = lay.n();
        let (on, pn, slip) = (&lay.mask[..n], &lay.pn[..n], &st.slip[..n]);
        let (px, py, sx, sy) = (&st.px[..n], &st.py[..n], &st.sx[..n], &st.sy[..n]);
        let (rx, ry, zx, zy) = (&mut self.rx[..n], &mut self.ry[..n], &mut self.zx[..n], &mut self.zy[..n]);
        let (tx, ty, curv, stiff, wt) =
            (&mut self.tx[..n], &mut self.ty[..n], &mut self.curv[..n], &mut self.stiff[..n], &mut self.wt[..n]);
        let zabs = &mut self.mags[..n];
        for k in 0..n {
            // Slip: the residual along the bound circle's tangent t at p.
            let g = mu * pn[k];
            let a = norm2(px[k], py[k]);
            let (nx, ny) = (px[k] / a, py[k] / a);
            let (t_x, t_y) = (-ny, nx);
            let s_t = t_x * sx[k] + t_y * sy[k];
            let l = nx * sx[k] + ny * sy[k];
            let lam = if l > 0.0 { l } else { 0.0 };
            let c = lam / g;
            let st_k = d.xx * t_x * t_x + d.yy * t_y * t_y + c;
            let zt = s_t / st_k;
            let w_k = (1.0 - c / st_k).sqrt();
            // Per element one of: outside (unchanged), adhesion, slip, degenerate slip (zero).
            let (ad, sl) = (on[k] && !slip[k], on[k] && slip[k]);
            let ok = sl && g > 0.0 && a > 0.0;
            let bad = sl && !ok;
            let (ax, ay) = (sx[k] / d.xx, sy[k] / d.yy);
            let case = |adhesion: f64, slipping: f64, old: f64| match (ad, ok, bad) {
                (true, _, _) => adhesion,
                (_, true, _) => slipping,
                (_, _, true) => 0.0,
                _ => old,
            };
            (rx[k], ry[k]) = (case(sx[k], s_t * t_x, rx[k]), case(sy[k], s_t * t_y, ry[k]));
            (zx[k], zy[k]) = (case(ax, zt * t_x, zx[k]), case(ay, zt * t_y, zy[k]));
            (tx[k], ty[k]) = (case(tx[k], t_x, tx[k]), case(ty[k], t_y, ty[k]));
            (curv[k], stiff[k]) = (case(curv[k], c, curv[k]), case(stiff[k], st_k, stiff[k]));
            wt[k] = case(1.0, w_k, wt[k]);
            let (zax, zay) = (ax.abs(), ay.abs());
            zabs[k] = if ad {
                if zay > zax {
                    zay
                } else {
                    zax
                }
            } else if ok {
                zt.abs()
            } else {
                0.0
            };
        }
        max4(zabs)
    }

    /// Preconditioned residual `z = S M S r + (I - S^2) D_c^-1 r` into `z` (needs `r` and the
    /// weights `S` from [`CgWork::residual`]): `M` the inverse of `A` periodised at twice the grid, `D_c`
    /// the diagonal stiffness (slip elements: `t.D t + lambda/g` along the tangent `t`), `S = I`
    /// on adhesion elements and `sqrt(t.D t / (t.D t + lambda/g))` on slip elements, whose part
    /// is projected onto `t`. Symmetric positive definite: the FFT part for slip elements that
    /// barely slip (`lambda` small), the diagonal for those that slip fast.
    fn apply_prec(&mut self, lay: &Layout, slip: &[bool], prec: &mut Convolver) -> Result<(), ContactError> {
        let n = lay.n();
        with_avx2(
            #[inline(always)]
            || {
                let (on, wt, rx, ry) = (&lay.mask[..n], &self.wt[..n], &self.rx[..n], &self.ry[..n]);
                let (qx, qy) = (&mut self.qx[..n], &mut self.qy[..n]);
                for k in 0..n {
                    (qx[k], qy[k]) = if on[k] { (wt[k] * rx[k], wt[k] * ry[k]) } else { (qx[k], qy[k]) };
                }
            },
        );
        prec.tangential(&self.qx, &self.qy, Some(&lay.mask), &mut self.zrx, &mut self.zry)?;
        with_avx2(
            #[inline(always)]
            || {
                let (on, slip, wt, rx, ry) = (&lay.mask[..n], &slip[..n], &self.wt[..n], &self.rx[..n], &self.ry[..n]);
                let (tx, ty, stiff, zrx, zry) =
                    (&self.tx[..n], &self.ty[..n], &self.stiff[..n], &self.zrx[..n], &self.zry[..n]);
                let (zx, zy) = (&mut self.zx[..n], &mut self.zy[..n]);
                for k in 0..n {
                    let s = wt[k];
                    let zt = s * (tx[k] * zrx[k] + ty[k] * zry[k])
                        + (1.0 - s * s) * (tx[k] * rx[k] + ty[k] * ry[k]) / stiff[k];
                    // Adhesion: the FFT part; slip (non-degenerate): along t; else unchanged.
                    (zx[k], zy[k]) = if on[k] && !slip[k] {
                        (zrx[k], zry[k])
                    } else if on[k] && stiff[k] > 0.0 {
                        (zt * tx[k], zt * ty[k])
                    } else {
                        (zx[k], zy[k])
                    };
                }
            },
        );
        Ok(())
    }

    /// The next search direction `v = z + beta v`, conjugate to the previous one
    /// (`beta = -(z, q_old)/(v, q_old)`; 0 on a restart).
    fn direction(&mut self, lay: &Layout, restart: bool) {
        let n = lay.n();
        with_avx2(
            #[inline(always)]
            || {
                let on = &lay.mask[..n];
                let (zx, zy, qpx, qpy) = (&self.zx[..n], &self.zy[..n], &self.qpx[..n], &self.qpy[..n]);
                let (vx, vy) = (&mut self.vx[..n], &mut self.vy[..n]);
                let beta = if restart {
                    0.0
                } else {
                    let (zq, vq) = sums2_by(n, |k| {
                        if on[k] {
                            (zx[k] * qpx[k] + zy[k] * qpy[k], vx[k] * qpx[k] + vy[k] * qpy[k])
                        } else {
                            (0.0, 0.0)
                        }
                    });
                    if vq.abs() > 1e-300 {
                        -zq / vq
                    } else {
                        0.0
                    }
                };
                for k in 0..n {
                    (vx[k], vy[k]) = if on[k] { (zx[k] + beta * vx[k], zy[k] + beta * vy[k]) } else { (vx[k], vy[k]) };
                }
            },
        );
    }
}

/// Moves elements between adhesion and slip: adhesion elements above the bound go to slip
/// (projected onto it); slip elements whose local solution sticks go to adhesion. Returns
/// whether anything changed.
fn update_sets(lay: &Layout, st: &mut State, d: Diag, mu: f64) -> bool {
    let mut changed = false;
    for &k in &lay.contact {
        let g = mu * lay.pn[k];
        let (px, py) = (st.px[k], st.py[k]);
        if !st.slip[k] {
            let (x, y, above) = project_to_bound(px, py, g);
            if above {
                (st.px[k], st.py[k]) = (x, y);
                st.slip[k] = true;
                changed = true;
            }
        } else if Local::new(st.sx[k], st.sy[k], px, py, d).sticks(g) {
            st.slip[k] = false;
            changed = true;
        }
    }
    changed
}

/// The reduced operator applied to the search direction, `qp` (slip elements: `A v` along the
/// tangent plus the curvature term, from [`CgWork::residual`]; `p` has not moved since), and the
/// step's sums `(r.v, v.qp)` with `max |v|`.
#[inline(always)]
fn reduced_product(lay: &Layout, slip: &[bool], w: &mut CgWork) -> (f64, f64, f64) {
    let n = lay.n();
    let (on, slip) = (&lay.mask[..n], &slip[..n]);
    let (qx, qy, vx, vy, rx, ry) = (&w.qx[..n], &w.qy[..n], &w.vx[..n], &w.vy[..n], &w.rx[..n], &w.ry[..n]);
    let (tx, ty, curv) = (&w.tx[..n], &w.ty[..n], &w.curv[..n]);
    let (qpx, qpy) = (&mut w.qpx[..n], &mut w.qpy[..n]);
    let vabs = &mut w.mags[..n];
    for k in 0..n {
        let qt = tx[k] * qx[k] + ty[k] * qy[k];
        let sl = (qt * tx[k] + curv[k] * vx[k], qt * ty[k] + curv[k] * vy[k]);
        (qpx[k], qpy[k]) = if !on[k] {
            (qpx[k], qpy[k])
        } else if slip[k] {
            sl
        } else {
            (qx[k], qy[k])
        };
        let (ax, ay) = (vx[k].abs(), vy[k].abs());
        vabs[k] = if !on[k] {
            0.0
        } else if ay > ax {
            ay
        } else {
            ax
        };
    }
    let vmax = max4(&w.mags[..n]);
    let (qpx, qpy) = (&w.qpx[..n], &w.qpy[..n]);
    let (rv, vq) =
        sums2_by(
            n,
            |k| {
                if on[k] {
                    (rx[k] * vx[k] + ry[k] * vy[k], vx[k] * qpx[k] + vy[k] * qpy[k])
                } else {
                    (0.0, 0.0)
                }
            },
        );
    (rv, vq, vmax)
}

/// The CG step `p += alpha v`, `s -= alpha A v` on the contact elements, slip elements scaled
/// back onto their bound (the one projection).
#[inline(always)]
fn step(lay: &Layout, st: &mut State, w: &CgWork, alpha: f64, mu: f64) {
    let n = lay.n();
    let (on, pn, slip) = (&lay.mask[..n], &lay.pn[..n], &st.slip[..n]);
    let (vx, vy, qx, qy) = (&w.vx[..n], &w.vy[..n], &w.qx[..n], &w.qy[..n]);
    let (px, py, sx, sy) = (&mut st.px[..n], &mut st.py[..n], &mut st.sx[..n], &mut st.sy[..n]);
    for k in 0..n {
        let (x, y) = (px[k] + alpha * vx[k], py[k] + alpha * vy[k]);
        let g = mu * pn[k];
        let (bx, by) = scale_to_bound(x, y, g);
        let (x, y) = if slip[k] { (bx, by) } else { (x, y) };
        (px[k], py[k], sx[k], sy[k]) =
            if on[k] { (x, y, sx[k] - alpha * qx[k], sy[k] - alpha * qy[k]) } else { (px[k], py[k], sx[k], sy[k]) };
    }
}

/// The CG iteration of a transient step. Expects `(px, py)` on or inside the bound, `(sx, sy)`
/// the exact slip for them with `b = w + u'` in `(vx, vy)`, and `max(g) > 0`. Returns whether it
/// met the stopping test; if not, the caller continues with Gauss–Seidel.
pub(super) fn solve(
    lay: &Layout,
    plans: &mut Plans,
    st: &mut State,
    w: &mut CgWork,
    params: &TangentialParams,
) -> Result<Outcome, ContactError> {
    let d = plans.transient.diag;
    let mu = params.mu;
    let gmax = lay.gmax(mu);
    // Initial element division from the warm start: elements on the traction bound slip. (The
    // local problems are no guide here: the residual of a warm start is smooth, and a single
    // element's stiffness is far below the collective one.)
    for &k in &lay.contact {
        st.slip[k] = on_bound(st.px[k], st.py[k], mu * lay.pn[k]);
    }
    let mut restart = true;
    let mut since_check = 0;
    let mut iterations = 0;
    let mut residual = f64::INFINITY;
    let mut converged = false;
    while iterations < params.max_iter {
        iterations += 1;
        w.residual(lay, st, d, mu);
        w.apply_prec(lay, &st.slip, &mut plans.prec)?;
        w.direction(lay, restart);
        restart = false;
        // Search-direction product in single precision: the slip is recomputed exactly (f64)
        // every INNER iterations and for the stopping test.
        plans.conv0_f32.tangential(&w.vx, &w.vy, Some(&lay.mask), &mut w.qx, &mut w.qy)?;
        let (rv, vq, vmax) = with_avx2(
            #[inline(always)]
            || reduced_product(lay, &st.slip, w),
        );
        let alpha = if vq > 0.0 && rv.is_finite() { rv / vq } else { 0.0 };
        if !alpha.is_finite() {
            break;
        }
        with_avx2(
            #[inline(always)]
            || step(lay, st, w, alpha, mu),
        );
        let dif = (alpha * vmax).abs() / gmax;
        since_check += 1;
        if since_check >= INNER || dif < params.tol || alpha == 0.0 {
            since_check = 0;
            st.recompute_slip(lay, &mut plans.conv0)?;
            if update_sets(lay, st, d, mu) {
                st.recompute_slip(lay, &mut plans.conv0)?;
                restart = true;
                continue;
            }
            residual = w.residual(lay, st, d, mu) / gmax;
            if residual < params.tol {
                converged = true;
                break;
            }
            if alpha == 0.0 {
                break;
            }
        }
    }
    Ok(Outcome { iterations, residual, converged })
}
