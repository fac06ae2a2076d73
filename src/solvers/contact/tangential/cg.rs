//! Transient steps by nonlinear preconditioned conjugate gradients (TangCG type, Vollebregt,
//! CONTACT user guide, "TangCG"): CG on the adhesion tractions and on the directions of the slip
//! tractions (kept on the bound), the bound circle's curvature `lambda/g` added to the slip
//! elements' stiffness; element sets updated every [`INNER`] iterations with a restart on a
//! change. Products `A v` by FFT, the search directions' products and the preconditioner in
//! single precision (the slip is recomputed exactly in double precision every [`INNER`]
//! iterations and for the stopping test: iterative refinement). The preconditioner is the FFT
//! inverse of the periodised `A`, blended on the slip elements with their diagonal stiffness by
//! how fast they slip ([`CgWork::apply_prec`]).

use super::super::convolution::Convolver;
use super::element::{norm2, on_bound, Diag, Local};
use super::operator::Plans;
use super::{ContactError, Layout, Outcome, State, TangentialParams};
use crate::physics::bound::{project_to_bound, scale_to_bound};

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
        }
    }

    /// Residual and diagonally preconditioned residual of the reduced problem (adhesion: the slip
    /// itself; slip: its component along the bound circle), into `r`, `z`, and the slip
    /// elements' tangent, curvature, stiffness and preconditioner weight (see
    /// [`CgWork::apply_prec`]). Returns `max |z|` (the change a local Gauss–Seidel solve would
    /// make, to first order) [MPa].
    fn residual(&mut self, lay: &Layout, st: &State, d: Diag, mu: f64) -> f64 {
        let mut zmax = 0.0f64;
        for &k in &lay.contact {
            let (sx, sy) = (st.sx[k], st.sy[k]);
            if st.slip[k] {
                let g = mu * lay.pn[k];
                let a = norm2(st.px[k], st.py[k]);
                if g <= 0.0 || a <= 0.0 {
                    self.rx[k] = 0.0;
                    self.ry[k] = 0.0;
                    self.zx[k] = 0.0;
                    self.zy[k] = 0.0;
                    (self.tx[k], self.ty[k], self.curv[k], self.stiff[k], self.wt[k]) = (0.0, 0.0, 0.0, 0.0, 0.0);
                    continue;
                }
                let (nx, ny) = (st.px[k] / a, st.py[k] / a);
                let (tx, ty) = (-ny, nx);
                let s_t = tx * sx + ty * sy;
                let lam = (nx * sx + ny * sy).max(0.0);
                self.rx[k] = s_t * tx;
                self.ry[k] = s_t * ty;
                let stiff = d.xx * tx * tx + d.yy * ty * ty + lam / g;
                let curv = lam / g;
                (self.tx[k], self.ty[k], self.curv[k], self.stiff[k]) = (tx, ty, curv, stiff);
                self.wt[k] = (1.0 - curv / stiff).sqrt();
                let zt = s_t / stiff;
                self.zx[k] = zt * tx;
                self.zy[k] = zt * ty;
                zmax = zmax.max(zt.abs());
            } else {
                self.wt[k] = 1.0;
                self.rx[k] = sx;
                self.ry[k] = sy;
                self.zx[k] = sx / d.xx;
                self.zy[k] = sy / d.yy;
                zmax = zmax.max(self.zx[k].abs()).max(self.zy[k].abs());
            }
        }
        zmax
    }

    /// Preconditioned residual `z = S M S r + (I - S^2) D_c^-1 r` into `z` (needs `r` and the
    /// weights `S` from [`CgWork::residual`]): `M` the FFT inverse of the periodised `A`, `D_c`
    /// the diagonal stiffness (slip elements: `t.D t + lambda/g` along the tangent `t`), `S = I`
    /// on adhesion elements and `sqrt(t.D t / (t.D t + lambda/g))` on slip elements, whose part
    /// is projected onto `t`. Symmetric positive definite: the FFT part for slip elements that
    /// barely slip (`lambda` small), the diagonal for those that slip fast.
    fn apply_prec(&mut self, lay: &Layout, slip: &[bool], prec: &mut Convolver) -> Result<(), ContactError> {
        for &k in &lay.contact {
            self.qx[k] = self.wt[k] * self.rx[k];
            self.qy[k] = self.wt[k] * self.ry[k];
        }
        prec.tangential(&self.qx, &self.qy, Some(&lay.mask), &mut self.zrx, &mut self.zry)?;
        for &k in &lay.contact {
            if !slip[k] {
                self.zx[k] = self.zrx[k];
                self.zy[k] = self.zry[k];
            } else if self.stiff[k] > 0.0 {
                let (tx, ty, s) = (self.tx[k], self.ty[k], self.wt[k]);
                let zt = s * (tx * self.zrx[k] + ty * self.zry[k])
                    + (1.0 - s * s) * (tx * self.rx[k] + ty * self.ry[k]) / self.stiff[k];
                self.zx[k] = zt * tx;
                self.zy[k] = zt * ty;
            }
        }
        Ok(())
    }

    /// The next search direction `v = z + beta v`, conjugate to the previous one
    /// (`beta = -(z, q_old)/(v, q_old)`; 0 on a restart).
    fn direction(&mut self, lay: &Layout, restart: bool) {
        let beta = if restart {
            0.0
        } else {
            let (mut zq, mut vq) = (0.0, 0.0);
            for &k in &lay.contact {
                zq += self.zx[k] * self.qpx[k] + self.zy[k] * self.qpy[k];
                vq += self.vx[k] * self.qpx[k] + self.vy[k] * self.qpy[k];
            }
            if vq.abs() > 1e-300 {
                -zq / vq
            } else {
                0.0
            }
        };
        for &k in &lay.contact {
            self.vx[k] = self.zx[k] + beta * self.vx[k];
            self.vy[k] = self.zy[k] + beta * self.vy[k];
        }
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
        let (mut rv, mut vq) = (0.0, 0.0);
        let mut vmax = 0.0f64;
        for &k in &lay.contact {
            let (qx, qy) = (w.qx[k], w.qy[k]);
            let (qpx, qpy) = if st.slip[k] {
                // Tangent and curvature from `residual` (p has not moved since).
                let (tx, ty, c) = (w.tx[k], w.ty[k], w.curv[k]);
                let qt = tx * qx + ty * qy;
                (qt * tx + c * w.vx[k], qt * ty + c * w.vy[k])
            } else {
                (qx, qy)
            };
            w.qpx[k] = qpx;
            w.qpy[k] = qpy;
            rv += w.rx[k] * w.vx[k] + w.ry[k] * w.vy[k];
            vq += w.vx[k] * qpx + w.vy[k] * qpy;
            vmax = vmax.max(w.vx[k].abs()).max(w.vy[k].abs());
        }
        let alpha = if vq > 0.0 && rv.is_finite() { rv / vq } else { 0.0 };
        if !alpha.is_finite() {
            break;
        }
        for &k in &lay.contact {
            st.px[k] += alpha * w.vx[k];
            st.py[k] += alpha * w.vy[k];
            st.sx[k] -= alpha * w.qx[k];
            st.sy[k] -= alpha * w.qy[k];
            if st.slip[k] {
                (st.px[k], st.py[k]) = scale_to_bound(st.px[k], st.py[k], mu * lay.pn[k]);
            }
        }
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
