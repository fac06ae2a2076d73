//! Anderson acceleration of fixed-point iterations (Walker & Ni 2011, "Anderson acceleration for
//! fixed-point iterations", SIAM J. Numer. Anal. 49(4), 1715-1735), written for any map on
//! vectors of `f64`: the steady tangential solver accelerates its projected map with it.

use crate::physics::lanes::sum_by;
use crate::simd::with_avx2;

/// Dot product in the four-lane order of [`crate::physics::lanes`] (vectorisable; fixed
/// summation order, so the result is deterministic).
#[inline(always)]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    sum_by(n, |k| a[k] * b[k])
}

/// Anderson acceleration of type II for a fixed-point map `x -> g(x)` on vectors of length `len`
/// (Walker & Ni 2011, sec. 3, with the QR factorisation of sec. 4 updated by column append and
/// Givens deletion of the oldest column).
pub struct Anderson {
    len: usize,
    depth: usize,
    /// Columns in use.
    m: usize,
    /// Orthonormal `Q` of the residual differences `dF = Q R`, column `c` at `q[c*len..]`.
    q: Vec<f64>,
    /// Upper triangular `R`, `depth x depth`, row-major.
    r: Vec<f64>,
    /// Differences of the map values, oldest first (same column order as `Q`).
    dg: std::collections::VecDeque<Vec<f64>>,
    spare: Vec<Vec<f64>>,
    f_prev: Vec<f64>,
    g_prev: Vec<f64>,
    have_prev: bool,
    work: Vec<f64>,
    gamma: Vec<f64>,
}

impl Anderson {
    /// Columns whose orthogonal part is below this fraction of their norm are not added.
    const DEPENDENT: f64 = 1e-10;
    /// The oldest columns are dropped while `max|R_ii| / min|R_ii|` exceeds this (a cheap
    /// condition estimate of `R`; Walker & Ni's `droptol` safeguard).
    const MAX_COND: f64 = 1e10;

    /// An accelerator for vectors of length `len` keeping at most `depth` differences.
    pub fn new(len: usize, depth: usize) -> Anderson {
        Anderson {
            len,
            depth,
            m: 0,
            q: vec![0.0; len * depth],
            r: vec![0.0; depth * depth],
            dg: Default::default(),
            spare: Vec::new(),
            f_prev: vec![0.0; len],
            g_prev: vec![0.0; len],
            have_prev: false,
            work: vec![0.0; len],
            gamma: vec![0.0; depth],
        }
    }

    /// Forgets the history (the next step is the plain fixed-point step).
    pub fn restart(&mut self) {
        while let Some(v) = self.dg.pop_front() {
            self.spare.push(v);
        }
        self.m = 0;
        self.have_prev = false;
    }

    /// Removes the oldest column: `R` without its first column is upper Hessenberg; Givens
    /// rotations of rows `(i, i+1)` make it triangular again and are applied to the columns of `Q`.
    #[inline(always)]
    fn delete_oldest(&mut self) {
        let (m, d, len) = (self.m, self.depth, self.len);
        if m == 0 {
            return;
        }
        for row in 0..m {
            for c in 0..m - 1 {
                self.r[row * d + c] = self.r[row * d + c + 1];
            }
            self.r[row * d + m - 1] = 0.0;
        }
        for i in 0..m - 1 {
            let (a, b) = (self.r[i * d + i], self.r[(i + 1) * d + i]);
            let h = a.hypot(b);
            if h == 0.0 {
                continue;
            }
            let (c, s) = (a / h, b / h);
            for col in i..m - 1 {
                let (x, y) = (self.r[i * d + col], self.r[(i + 1) * d + col]);
                self.r[i * d + col] = c * x + s * y;
                self.r[(i + 1) * d + col] = -s * x + c * y;
            }
            let (qi, qn) = self.q[i * len..(i + 2) * len].split_at_mut(len);
            for (x, y) in qi.iter_mut().zip(qn.iter_mut()) {
                let (u, v) = (*x, *y);
                *x = c * u + s * v;
                *y = -s * u + c * v;
            }
        }
        for c in 0..d {
            self.r[(m - 1) * d + c] = 0.0;
        }
        self.m -= 1;
        if let Some(v) = self.dg.pop_front() {
            self.spare.push(v);
        }
    }

    /// One Anderson step: given the iterate `x`, its map value `g` and residual `f = g - x`,
    /// appends the differences to the history and overwrites `x` with
    /// `g - dG gamma`, `gamma = argmin |f - dF gamma|`.
    pub fn step(&mut self, x: &mut [f64], g: &[f64], f: &[f64]) {
        // The same operations in the same order in both builds (no fused multiply-adds; `dot`
        // keeps its four partial sums), so bit-identical results.
        with_avx2(
            #[inline(always)]
            || self.step_impl(x, g, f),
        )
    }

    #[inline(always)]
    fn step_impl(&mut self, x: &mut [f64], g: &[f64], f: &[f64]) {
        let (d, len) = (self.depth, self.len);
        if self.have_prev && d > 0 {
            if self.m == d {
                self.delete_oldest();
            }
            let m = self.m;
            // Modified Gram-Schmidt of df = f - f_prev against Q.
            let mut v = std::mem::take(&mut self.work);
            for i in 0..len {
                v[i] = f[i] - self.f_prev[i];
            }
            let norm0 = dot(&v, &v).sqrt();
            for c in 0..m {
                let qc = &self.q[c * len..(c + 1) * len];
                let h = dot(qc, &v);
                self.r[c * d + m] = h;
                for (a, b) in v.iter_mut().zip(qc) {
                    *a -= h * b;
                }
            }
            let nrm = dot(&v, &v).sqrt();
            if nrm > Self::DEPENDENT * norm0 && nrm.is_finite() {
                self.r[m * d + m] = nrm;
                for (a, b) in self.q[m * len..(m + 1) * len].iter_mut().zip(&v) {
                    *a = b / nrm;
                }
                let mut dgv = self.spare.pop().unwrap_or_else(|| vec![0.0; len]);
                for i in 0..len {
                    dgv[i] = g[i] - self.g_prev[i];
                }
                self.dg.push_back(dgv);
                self.m += 1;
            } else {
                for c in 0..m {
                    self.r[c * d + m] = 0.0;
                }
            }
            self.work = v;
            while self.m > 1 {
                let diag = (0..self.m).map(|i| self.r[i * d + i].abs());
                let (lo, hi) = diag.fold((f64::INFINITY, 0.0f64), |(lo, hi), a| (lo.min(a), hi.max(a)));
                if hi <= Self::MAX_COND * lo {
                    break;
                }
                self.delete_oldest();
            }
        }
        self.f_prev.copy_from_slice(f);
        self.g_prev.copy_from_slice(g);
        self.have_prev = true;
        let m = self.m;
        for c in 0..m {
            self.gamma[c] = dot(&self.q[c * len..(c + 1) * len], f);
        }
        for i in (0..m).rev() {
            let mut t = self.gamma[i];
            for l in i + 1..m {
                t -= self.r[i * d + l] * self.gamma[l];
            }
            self.gamma[i] = t / self.r[i * d + i];
        }
        x.copy_from_slice(g);
        if self.gamma[..m].iter().all(|v| v.is_finite()) {
            for (gc, col) in self.gamma[..m].iter().zip(&self.dg) {
                for (a, b) in x.iter_mut().zip(col) {
                    *a -= gc * b;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The linear contraction `x = M x + b` with a known solution `x*` (`b = x* - M x*`):
    /// `M = rho Q diag(c_i) Q^T` with `Q` a Householder reflection and `c_i` in `(-1, 1)`.
    fn contraction(n: usize, rho: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let v: Vec<f64> = (0..n).map(|i| 1.0 + ((i * 7919) % 13) as f64 / 13.0).collect();
        let vv: f64 = v.iter().map(|a| a * a).sum();
        let q = |i: usize, j: usize| f64::from(u8::from(i == j)) - 2.0 * v[i] * v[j] / vv;
        let c: Vec<f64> = (0..n).map(|i| if i % 3 == 1 { -1.0 } else { 1.0 } * (i + 1) as f64 / n as f64).collect();
        let mut m = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                m[i * n + j] = rho * (0..n).map(|l| q(i, l) * c[l] * q(j, l)).sum::<f64>();
            }
        }
        let x_star: Vec<f64> = (0..n).map(|i| (i as f64 * 0.37).sin()).collect();
        let b: Vec<f64> = (0..n).map(|i| x_star[i] - (0..n).map(|j| m[i * n + j] * x_star[j]).sum::<f64>()).collect();
        (m, b, x_star)
    }

    /// The solution of `(I - M) x = b` by Gaussian elimination with partial pivoting.
    fn direct(m: &[f64], b: &[f64]) -> Vec<f64> {
        let n = b.len();
        let mut a: Vec<f64> = (0..n * n).map(|k| f64::from(u8::from(k / n == k % n)) - m[k]).collect();
        let mut x = b.to_vec();
        for c in 0..n {
            let p = (c..n).max_by(|&i, &j| a[i * n + c].abs().total_cmp(&a[j * n + c].abs())).unwrap();
            for l in 0..n {
                a.swap(c * n + l, p * n + l);
            }
            x.swap(c, p);
            for r in c + 1..n {
                let f = a[r * n + c] / a[c * n + c];
                for l in c..n {
                    a[r * n + l] -= f * a[c * n + l];
                }
                x[r] -= f * x[c];
            }
        }
        for c in (0..n).rev() {
            let s: f64 = (c + 1..n).map(|l| a[c * n + l] * x[l]).sum();
            x[c] = (x[c] - s) / a[c * n + c];
        }
        x
    }

    /// Iterations until `|g(x) - x|_inf < tol`, accelerated or plain, and the final iterate.
    fn iterate(m: &[f64], b: &[f64], depth: Option<usize>, tol: f64) -> (usize, Vec<f64>) {
        let n = b.len();
        let mut aa = depth.map(|d| Anderson::new(n, d));
        let (mut x, mut g, mut f) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        for it in 1..=100_000 {
            for i in 0..n {
                g[i] = b[i] + (0..n).map(|j| m[i * n + j] * x[j]).sum::<f64>();
                f[i] = g[i] - x[i];
            }
            if f.iter().all(|v| v.abs() < tol) {
                return (it, g);
            }
            match aa.as_mut() {
                Some(a) => a.step(&mut x, &g, &f),
                None => x.copy_from_slice(&g),
            }
        }
        panic!("no convergence");
    }

    #[test]
    fn solves_a_linear_contraction_faster_than_plain_iteration() {
        let (m, b, x_star) = contraction(12, 0.95);
        let x_direct = direct(&m, &b);
        let err = x_direct.iter().zip(&x_star).fold(0.0f64, |e, (a, b)| e.max((a - b).abs()));
        assert!(err < 1e-12, "direct solution off by {err}");
        let (n_plain, x_plain) = iterate(&m, &b, None, 1e-11);
        // Depth above the dimension: Anderson is GMRES on a linear map (Walker & Ni, sec. 4),
        // exact after at most n + 1 steps up to round-off.
        let (n_aa, x_aa) = iterate(&m, &b, Some(16), 1e-11);
        // A short history still beats plain iteration.
        let (n_short, x_short) = iterate(&m, &b, Some(4), 1e-11);
        for x in [&x_plain, &x_aa, &x_short] {
            let e = x.iter().zip(&x_direct).fold(0.0f64, |e, (a, b)| e.max((a - b).abs()));
            assert!(e < 1e-9, "off the direct solution by {e}");
        }
        assert!(n_aa <= 12 + 3, "depth 16: {n_aa} iterations");
        assert!(10 * n_aa < n_plain && n_short < n_plain, "Anderson {n_aa} / {n_short}, plain {n_plain}");
        // A restart forgets the history: the next step is the plain one.
        let mut a = Anderson::new(2, 3);
        let mut x = vec![0.0, 0.0];
        a.step(&mut x, &[1.0, 2.0], &[1.0, 2.0]);
        a.restart();
        a.step(&mut x, &[3.0, 4.0], &[2.0, 2.0]);
        assert_eq!(x, [3.0, 4.0]);
    }
}
