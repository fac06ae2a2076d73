//! The local problem of one contact element with the other tractions fixed, as in CONTACT's
//! element solver of ConvexGS (Vollebregt & Kalker, CONTACT user guide; Kalker 1990, sec. 5.4):
//! the slip `s = t - D p` with `t = s0 + D p0` and `D = diag(D_xx, D_yy)` the operator at offset 0;
//! stick `p = D^-1 t` if that lies within the traction bound `|p| <= g`, else slip
//! `(D + lambda/g I) p = t` with `|p| = g`.

use crate::physics::bound::{scale_to_bound, within_bound};

/// Euclidean norm of `(a, b)` (no overflow guard needed at traction magnitudes).
#[inline(always)]
pub(super) fn norm2(a: f64, b: f64) -> f64 {
    (a * a + b * b).sqrt()
}

/// Diagonal of an operator at offset 0, `(D_xx, D_yy)` [mm/MPa], both positive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Diag {
    pub xx: f64,
    pub yy: f64,
}

/// The local problem of one element: `t = s + D p` for its current slip `s` and traction `p`,
/// and the stick solution `q = D^-1 t`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Local {
    tx: f64,
    ty: f64,
    qx: f64,
    qy: f64,
}

impl Local {
    #[inline(always)]
    pub(super) fn new(sx: f64, sy: f64, px: f64, py: f64, d: Diag) -> Local {
        let tx = sx + d.xx * px;
        let ty = sy + d.yy * py;
        Local { tx, ty, qx: tx / d.xx, qy: ty / d.yy }
    }

    /// Whether the element sticks: the stick solution lies within the bound `g`.
    #[inline(always)]
    pub(super) fn sticks(&self, g: f64) -> bool {
        within_bound(self.qx, self.qy, g)
    }

    /// The element's new traction and whether it slips: the stick solution if it lies within
    /// the bound, else the slip solution on the bound (zero for `g <= 0`).
    #[inline(always)]
    pub(super) fn solve(&self, d: Diag, g: f64) -> (f64, f64, bool) {
        if self.sticks(g) {
            (self.qx, self.qy, false)
        } else if g > 0.0 {
            let (px, py) = slip_solve(self.tx, self.ty, d, g);
            (px, py, true)
        } else {
            (0.0, 0.0, true)
        }
    }
}

/// Whether a traction lies on the bound to round-off (`|p| >= g (1 - 1e-12)`, or `g <= 0`): the
/// element state the CG solver starts from.
#[inline(always)]
pub(super) fn on_bound(px: f64, py: f64, g: f64) -> bool {
    g <= 0.0 || norm2(px, py) >= g * (1.0 - 1e-12)
}

/// Solves `(D + m I) p = t`, `|p| = g` for `m >= 0`, given `|D^-1 t| > g > 0`: returns `p`.
/// Newton on `phi(m) = 1/|p(m)| - 1/g` (exactly linear when `D_xx = D_yy`), safeguarded by
/// bisection on the bracket `[max(0, |t|/g - max d), |t|/g - min d]` (from
/// `|t|/(max d + m) <= |p(m)| <= |t|/(min d + m)`), started at `|t|/g - d_eff` with the weighted
/// mean `d_eff = (tx^2 D_xx + ty^2 D_yy)/|t|^2`.
fn slip_solve(tx: f64, ty: f64, d: Diag, g: f64) -> (f64, f64) {
    let (dx, dy) = (d.xx, d.yy);
    let tn = norm2(tx, ty);
    let (dmin, dmax) = (dx.min(dy), dx.max(dy));
    let lo0 = (tn / g - dmax).max(0.0);
    let (mut lo, mut hi) = (lo0, (tn / g - dmin).max(lo0));
    let d_eff = if tn > 0.0 { (tx * tx * dx + ty * ty * dy) / (tn * tn) } else { dmin };
    let mut m = (tn / g - d_eff).clamp(lo, hi);
    for _ in 0..60 {
        let (ax, ay) = (dx + m, dy + m);
        let (px, py) = (tx / ax, ty / ay);
        let pn2 = px * px + py * py;
        let pn = pn2.sqrt();
        let phi = 1.0 / pn - 1.0 / g;
        if phi.abs() <= 1e-15 / g {
            break;
        }
        if phi < 0.0 {
            lo = m;
        } else {
            hi = m;
        }
        // d|p|/dm = -(px^2/ax + py^2/ay)/|p|; dphi/dm = -(1/|p|^2) d|p|/dm.
        let dphi = (px * px / ax + py * py / ay) / (pn2 * pn);
        let mut next = m - phi / dphi;
        if !(next > lo && next < hi && next.is_finite()) {
            next = 0.5 * (lo + hi);
        }
        if (next - m).abs() <= 1e-16 * (1.0 + m) {
            m = next;
            break;
        }
        m = next;
    }
    scale_to_bound(tx / (dx + m), ty / (dy + m), g)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slip_solve_hits_bound_and_direction() {
        let (tx, ty, d, g) = (3.0, -1.0, Diag { xx: 0.7, yy: 0.9 }, 1.5);
        let (px, py) = slip_solve(tx, ty, d, g);
        assert!((norm2(px, py) - g).abs() < 1e-13);
        // (D + m I) p = t for one m >= 0 in both components.
        let mx = tx / px - d.xx;
        let my = ty / py - d.yy;
        assert!(mx >= 0.0 && (mx - my).abs() < 1e-10, "{mx} {my}");
    }

    #[test]
    fn local_solve_sticks_inside_and_slips_outside() {
        let d = Diag { xx: 2.0, yy: 4.0 };
        // t = s + D p = (1, 2): stick solution (0.5, 0.5), |q| = 0.707.
        let local = Local::new(1.0, 2.0, 0.0, 0.0, d);
        assert!(local.sticks(1.0));
        assert_eq!(local.solve(d, 1.0), (0.5, 0.5, false));
        let (px, py, slips) = local.solve(d, 0.5);
        assert!(slips && (norm2(px, py) - 0.5).abs() < 1e-14);
        assert_eq!(local.solve(d, 0.0), (0.0, 0.0, true));
        assert!(on_bound(0.3, 0.4, 0.5) && !on_bound(0.3, 0.39, 0.5) && on_bound(0.0, 0.0, 0.0));
    }
}
