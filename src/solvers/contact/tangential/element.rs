//! The local problem of one contact element with the other tractions fixed, as in CONTACT's
//! element solver of ConvexGS (Vollebregt & Kalker, CONTACT user guide; Kalker 1990, sec. 5.4):
//! the slip `s = t - D p` with `t = s0 + D p0` and `D = diag(D_xx, D_yy)` the operator at offset 0;
//! stick `p = D^-1 t` if that lies within the traction bound `|p| <= g`, else slip
//! `(D + lambda/g I) p = t` with `|p| = g`.

use crate::physics::bound::{scale_to_bound, within_bound};
use crate::simd::with_avx2;

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
        match self.solve_unless_slip(g) {
            Ok(solved) => solved,
            Err((tx, ty, g)) => {
                let (px, py) = slip_solve(tx, ty, d, g);
                (px, py, true)
            }
        }
    }

    /// [`Local::solve`] where it needs no iteration (stick, or `g <= 0`); else, as the error,
    /// the input `(tx, ty, g)` of the slip solution ([`slip_solve_batch`]).
    #[inline(always)]
    pub(super) fn solve_unless_slip(&self, g: f64) -> Result<(f64, f64, bool), (f64, f64, f64)> {
        if self.sticks(g) {
            Ok((self.qx, self.qy, false))
        } else if g > 0.0 {
            Err((self.tx, self.ty, g))
        } else {
            Ok((0.0, 0.0, true))
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
    let mut newton = SlipNewton::new(tx, ty, d, g);
    for _ in 0..SlipNewton::MAX_ITER {
        if !newton.step(d) {
            break;
        }
    }
    newton.traction(d)
}

/// Solves the slip problems of [`slip_solve`] for `BATCH` elements at once: `t_l = (tx, ty)` and
/// `g_l` in, `p_l` out. The elements' Newton iterations run side by side in vector lanes (AVX2
/// where the CPU has it), each lane taking [`SlipNewton::step`]'s result only while its element
/// iterates, so each element gets exactly the operations of [`slip_solve`].
#[inline(always)]
pub(super) fn slip_solve_batch(t: &[(f64, f64, f64); BATCH], d: Diag) -> [(f64, f64); BATCH] {
    with_avx2(
        #[inline(always)]
        || {
            // Plain loops rather than array maps, which would leave the AVX2 build.
            let mut newton = [SlipNewton::new(t[0].0, t[0].1, d, t[0].2); BATCH];
            for (n, &(tx, ty, g)) in newton.iter_mut().zip(t).skip(1) {
                *n = SlipNewton::new(tx, ty, d, g);
            }
            let mut running = [true; BATCH];
            for _ in 0..SlipNewton::MAX_ITER {
                for (n, r) in newton.iter_mut().zip(running.iter_mut()) {
                    let mut next = *n;
                    let more = next.step(d);
                    // Selects, not branches: the lanes stay in step.
                    *n = if *r { next } else { *n };
                    *r &= more;
                }
                if !running.iter().any(|&r| r) {
                    break;
                }
            }
            let mut p = [(0.0, 0.0); BATCH];
            for (p, n) in p.iter_mut().zip(&newton) {
                *p = n.traction(d);
            }
            p
        },
    )
}

/// Elements per [`slip_solve_batch`].
pub(super) const BATCH: usize = 4;

/// The state of [`slip_solve`]'s safeguarded Newton iteration for one element.
#[derive(Clone, Copy)]
struct SlipNewton {
    tx: f64,
    ty: f64,
    g: f64,
    lo: f64,
    hi: f64,
    m: f64,
}

impl SlipNewton {
    /// Iterations at most.
    const MAX_ITER: usize = 60;

    #[inline(always)]
    fn new(tx: f64, ty: f64, d: Diag, g: f64) -> SlipNewton {
        let (dx, dy) = (d.xx, d.yy);
        let tn = norm2(tx, ty);
        let (dmin, dmax) = (dx.min(dy), dx.max(dy));
        let lo0 = (tn / g - dmax).max(0.0);
        let (lo, hi) = (lo0, (tn / g - dmin).max(lo0));
        let d_eff = if tn > 0.0 { (tx * tx * dx + ty * ty * dy) / (tn * tn) } else { dmin };
        let m = (tn / g - d_eff).clamp(lo, hi);
        SlipNewton { tx, ty, g, lo, hi, m }
    }

    /// One safeguarded Newton step (branch-free); false once converged (`|phi|` at round-off:
    /// `m` kept, or a step at round-off: `m` the step's end).
    #[inline(always)]
    fn step(&mut self, d: Diag) -> bool {
        let (tx, ty, g, m) = (self.tx, self.ty, self.g, self.m);
        let (ax, ay) = (d.xx + m, d.yy + m);
        let (px, py) = (tx / ax, ty / ay);
        let pn2 = px * px + py * py;
        let pn = pn2.sqrt();
        let phi = 1.0 / pn - 1.0 / g;
        let at_root = phi.abs() <= 1e-15 / g;
        let (lo, hi) = if phi < 0.0 { (m, self.hi) } else { (self.lo, m) };
        // d|p|/dm = -(px^2/ax + py^2/ay)/|p|; dphi/dm = -(1/|p|^2) d|p|/dm.
        let dphi = (px * px / ax + py * py / ay) / (pn2 * pn);
        let newton = m - phi / dphi;
        let next = if newton > lo && newton < hi && newton.is_finite() { newton } else { 0.5 * (lo + hi) };
        self.lo = lo;
        self.hi = hi;
        self.m = if at_root { m } else { next };
        !at_root && (next - m).abs() > 1e-16 * (1.0 + m)
    }

    /// The traction at the current multiplier, scaled onto the bound.
    #[inline(always)]
    fn traction(&self, d: Diag) -> (f64, f64) {
        scale_to_bound(self.tx / (d.xx + self.m), self.ty / (d.yy + self.m), self.g)
    }
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
    fn batched_slip_solves_equal_the_single_ones() {
        let d = Diag { xx: 0.7, yy: 0.9 };
        // Directions all round, bounds from far below to just below |D^-1 t|, one axis case.
        let t: Vec<(f64, f64, f64)> = (0..12)
            .map(|i| {
                let a = i as f64 * 0.6;
                let (tx, ty) = (3.0 * a.cos(), 3.0 * a.sin());
                let stick = norm2(tx / d.xx, ty / d.yy);
                (tx, if i == 10 { 0.0 } else { ty }, stick * (0.05 + 0.08 * i as f64))
            })
            .collect();
        for chunk in t.chunks_exact(BATCH) {
            let batch = slip_solve_batch(&[chunk[0], chunk[1], chunk[2], chunk[3]], d);
            for (&(tx, ty, g), p) in chunk.iter().zip(batch) {
                assert_eq!(p, slip_solve(tx, ty, d, g), "bit for bit");
                assert!((norm2(p.0, p.1) - g).abs() < 1e-13 * g);
            }
        }
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
