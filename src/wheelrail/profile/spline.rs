//! The parametric spline CONTACT fits through a profile (`m_spline_make.f90`:
//! `ppspline_make_spline_kink`, `ppspline_make_simple_kink`, `ppspline_make_simple_sec_intpol`,
//! `ppspline_make_simple_sec_smoothing`; `m_spline_def.f90`: `spline_eval`; `m_profile.f90`:
//! `profile_finish_grid`): y(s) and z(s), each a cubic per segment in the arc length s (the summed
//! chord length of the points), made section by section between the kinks with free ends
//! (second derivative zero) at every section end. With λ = 0 each is the natural interpolating
//! spline; with λ > 0 the smoothing spline minimising Σ w_i (f_i − f(s_i))² + (2/3) λ ∫ f″² … in
//! CONTACT's discrete form (its `kappa = 2/3 λ`, weights `σ = 1/w`).
//!
//! The systems are written with CONTACT's 1-based local indices (index 0 unused), loop by loop as
//! its routines have them, so that the two can be read side by side.
#![allow(clippy::needless_range_loop)]

/// The coefficients of one function f(s) per node: on segment i (s_i ≤ s < s_{i+1}),
/// f = a0 + a1 t + a2 t² + a3 t³ with t = s − s_i. The node of a kink holds the next section's.
#[derive(Debug, Clone, PartialEq)]
pub struct Cubic {
    pub a0: Vec<f64>,
    pub a1: Vec<f64>,
    pub a2: Vec<f64>,
    pub a3: Vec<f64>,
}

impl Cubic {
    fn zeros(n: usize) -> Cubic {
        Cubic { a0: vec![0.0; n], a1: vec![0.0; n], a2: vec![0.0; n], a3: vec![0.0; n] }
    }

    /// f, f′, f″ on segment `i` at local coordinate `t`.
    pub fn eval(&self, i: usize, t: f64) -> [f64; 3] {
        let (a0, a1, a2, a3) = (self.a0[i], self.a1[i], self.a2[i], self.a3[i]);
        [((a3 * t + a2) * t + a1) * t + a0, (3.0 * a3 * t + 2.0 * a2) * t + a1, 6.0 * a3 * t + 2.0 * a2]
    }
}

/// The segment lengths h_k (1-based k = 1..nseg, index 0 unused) of section [ip0, ip1] (0-based).
fn steps(s: &[f64], ip0: usize, ip1: usize) -> Vec<f64> {
    let mut h = vec![0.0; ip1 - ip0 + 1];
    for k in 1..=ip1 - ip0 {
        h[k] = s[ip0 + k] - s[ip0 + k - 1];
    }
    h
}

/// CONTACT's matrix Q (1-based rows k = 1..nseg): column 1 its diagonal, column 2 the next.
fn q_matrix(h: &[f64]) -> Vec<[f64; 2]> {
    let nseg = h.len() - 1;
    let mut q = vec![[0.0; 2]; nseg + 1];
    for k in 1..=nseg {
        q[k][0] = if k > 1 { -3.0 / h[k] - 3.0 / h[k - 1] } else { 0.0 };
        q[k][1] = 3.0 / h[k];
    }
    q
}

/// a3 and a1 from a0 and a2 on a section (common to both constructions).
fn finish_section(c: &mut Cubic, iofs: usize, h: &[f64]) {
    let nseg = h.len() - 1;
    let npnt = nseg + 1;
    let g = |i: usize| iofs + i - 1; // local 1-based → global 0-based
    for iseg in 1..=nseg {
        c.a3[g(iseg)] = (c.a2[g(iseg + 1)] - c.a2[g(iseg)]) / (3.0 * h[iseg]);
    }
    c.a3[g(npnt)] = 0.0;
    for iseg in 1..=nseg {
        let hk = h[iseg];
        c.a1[g(iseg)] = (c.a0[g(iseg + 1)] - c.a0[g(iseg)]) / hk - c.a3[g(iseg)] * (hk * hk) - c.a2[g(iseg)] * hk;
    }
    let hn = h[nseg];
    c.a1[g(npnt)] = 3.0 * c.a3[g(nseg)] * (hn * hn) + 2.0 * c.a2[g(nseg)] * hn + c.a1[g(nseg)];
}

/// The natural cubic interpolating spline on section [ip0, ip1] (CONTACT's
/// `ppspline_make_simple_sec_intpol`): a tridiagonal system for a2, solved by LDLᵀ.
fn section_interpolating(s: &[f64], f: &[f64], ip0: usize, ip1: usize, c: &mut Cubic) {
    let h = steps(s, ip0, ip1);
    let q = q_matrix(&h);
    let npnt = ip1 - ip0 + 1;
    let neqs = npnt - 2;
    let y = |i: usize| f[ip0 + i - 1];
    let (mut d, mut l, mut rhs) = (vec![0.0; neqs + 1], vec![0.0; neqs + 1], vec![0.0; neqs + 1]);
    for j in 1..=neqs {
        let (diag, off) = (2.0 * (h[j] + h[j + 1]), h[j + 1]);
        rhs[j] = q[j][1] * y(j) + q[j + 1][0] * y(j + 1) + q[j + 1][1] * y(j + 2);
        d[j] = diag;
        if j > 1 {
            d[j] -= d[j - 1] * l[j - 1] * l[j - 1];
        }
        l[j] = off / d[j];
    }
    for j in 2..=neqs {
        rhs[j] -= l[j - 1] * rhs[j - 1];
    }
    for j in 1..=neqs {
        rhs[j] /= d[j];
    }
    let g = |i: usize| ip0 + i - 1;
    c.a2[g(npnt)] = 0.0;
    for j in (1..=neqs).rev() {
        let i = j + 1;
        c.a2[g(i)] = rhs[j];
        if j < neqs {
            c.a2[g(i)] -= l[j] * c.a2[g(i + 1)];
        }
    }
    c.a2[g(1)] = 0.0;
    for i in 1..=npnt {
        c.a0[g(i)] = y(i);
    }
    finish_section(c, ip0, &h);
}

/// The cubic smoothing spline on section [ip0, ip1] with parameter `lambda` and weights `wgt`
/// (CONTACT's `ppspline_make_simple_sec_smoothing`): a pentadiagonal system for a2, solved by LDLᵀ.
fn section_smoothing(s: &[f64], f: &[f64], ip0: usize, ip1: usize, lambda: f64, wgt: &[f64], c: &mut Cubic) {
    let h = steps(s, ip0, ip1);
    let q = q_matrix(&h);
    let npnt = ip1 - ip0 + 1;
    let neqs = npnt - 2;
    let kappa = 2.0 / 3.0 * lambda;
    let y = |i: usize| f[ip0 + i - 1];
    let sigma: Vec<f64> =
        (0..=npnt).map(|i| if i == 0 { 0.0 } else { 1.0 / wgt[ip0 + i - 1].abs().max(1e-10) }).collect();
    let mut a = vec![[0.0; 3]; neqs + 1];
    let mut rhs = vec![0.0; neqs + 1];
    for j in 1..=neqs {
        a[j][0] = 2.0 * (h[j] + h[j + 1])
            + kappa
                * (q[j + 1][0] * sigma[j + 1] * q[j + 1][0]
                    + q[j][1] * sigma[j] * q[j][1]
                    + q[j + 1][1] * sigma[j + 2] * q[j + 1][1]);
        a[j][1] = if j < neqs {
            h[j + 1] + kappa * (q[j + 1][0] * sigma[j + 1] * q[j + 1][1] + q[j + 1][1] * sigma[j + 2] * q[j + 2][0])
        } else {
            h[j + 1]
        };
        a[j][2] = if j + 2 <= neqs { kappa * q[j + 1][1] * sigma[j + 2] * q[j + 2][1] } else { 0.0 };
        rhs[j] = q[j][1] * y(j) + q[j + 1][0] * y(j + 1) + q[j + 1][1] * y(j + 2);
    }
    // LDLᵀ: l1 the second subdiagonal, l2 the first.
    let (mut d, mut l1, mut l2) = (vec![0.0; neqs + 1], vec![0.0; neqs + 1], vec![0.0; neqs + 1]);
    for j in 1..=neqs {
        d[j] = a[j][0];
        if j > 2 {
            d[j] -= d[j - 2] * l1[j - 2] * l1[j - 2];
        }
        if j > 1 {
            d[j] -= d[j - 1] * l2[j - 1] * l2[j - 1];
        }
        l2[j] = a[j][1];
        if j > 1 {
            l2[j] -= d[j - 1] * l2[j - 1] * l1[j - 1];
        }
        l2[j] /= d[j];
        l1[j] = a[j][2] / d[j];
    }
    for j in 1..=neqs {
        if j > 1 {
            rhs[j] -= l2[j - 1] * rhs[j - 1];
        }
        if j > 2 {
            rhs[j] -= l1[j - 2] * rhs[j - 2];
        }
    }
    for j in 1..=neqs {
        rhs[j] /= d[j];
    }
    let g = |i: usize| ip0 + i - 1;
    c.a2[g(npnt)] = 0.0;
    for j in (1..=neqs).rev() {
        let i = j + 1;
        c.a2[g(i)] = rhs[j];
        if j < neqs {
            c.a2[g(i)] -= l2[j] * c.a2[g(i + 1)];
        }
        if j + 2 <= neqs {
            c.a2[g(i)] -= l1[j] * c.a2[g(i + 2)];
        }
    }
    c.a2[g(1)] = 0.0;
    for i in 1..=npnt {
        let mut v = y(i);
        if i >= 3 {
            v -= kappa * sigma[i] * q[i - 1][1] * c.a2[g(i - 1)];
        }
        if i >= 2 && i <= neqs + 1 {
            v -= kappa * sigma[i] * q[i][0] * c.a2[g(i)];
        }
        if i <= neqs {
            v -= kappa * sigma[i] * q[i][1] * c.a2[g(i + 1)];
        }
        c.a0[g(i)] = v;
    }
    finish_section(c, ip0, &h);
}

/// The data weights of the smoothing spline (CONTACT's `ppspline_make_spline_kink`): 1 each, or
/// the spacing ds_i (20 times at the two ends) when `use_spacing`; 100 times at interior breaks.
pub fn weights(s: &[f64], breaks: &[usize], use_spacing: bool) -> Vec<f64> {
    let n = s.len();
    let mut w = vec![1.0; n];
    if use_spacing {
        w[0] = s[1] - s[0];
        for i in 1..n - 1 {
            w[i] = 0.5 * (s[i + 1] - s[i - 1]);
        }
        w[n - 1] = s[n - 1] - s[n - 2];
        w[0] *= 20.0;
        w[n - 1] *= 20.0;
    }
    for &b in &breaks[1..breaks.len() - 1] {
        w[b] *= 100.0;
    }
    w
}

/// One function's spline over all sections between `breaks` (0-based, first and last point
/// included): interpolating where |λ| ≤ 1e-10, smoothing otherwise (CONTACT's
/// `ppspline_make_simple_kink`).
pub fn fit(s: &[f64], f: &[f64], breaks: &[usize], lambda: f64, wgt: &[f64]) -> Cubic {
    let mut c = Cubic::zeros(s.len());
    for w in breaks.windows(2) {
        if lambda.abs() <= 1e-10 {
            section_interpolating(s, f, w[0], w[1], &mut c);
        } else {
            section_smoothing(s, f, w[0], w[1], lambda, wgt, &mut c);
        }
    }
    c
}

/// The parametric spline (y(s), z(s)) of a profile.
#[derive(Debug, Clone, PartialEq)]
pub struct ParamSpline {
    /// The arc length at each node, mm (strictly increasing).
    pub s: Vec<f64>,
    pub y: Cubic,
    pub z: Cubic,
}

impl ParamSpline {
    /// The segment holding `s` (CONTACT's `locate_segment`: s_i ≤ s < s_{i+1}, the last segment
    /// at the last node); `None` outside [s_first, s_last].
    pub fn segment(&self, s: f64) -> Option<usize> {
        let n = self.s.len();
        if !(s >= self.s[0] && s <= self.s[n - 1]) {
            return None;
        }
        Some(self.s.partition_point(|&x| x <= s).saturating_sub(1).min(n - 2))
    }

    /// (y, y′, y″) and (z, z′, z″) at `s` on segment `i`.
    pub fn eval_on(&self, i: usize, s: f64) -> ([f64; 3], [f64; 3]) {
        let t = s - self.s[i];
        (self.y.eval(i, t), self.z.eval(i, t))
    }

    /// Every s on segment `i` where y(s) = `y` (each monotone piece of the cubic searched).
    pub fn s_at_y_on(&self, i: usize, y: f64) -> Vec<f64> {
        let mut out = Vec::new();
        self.each_s_at_y_on(i, y, |s| out.push(s));
        out
    }

    /// [`Self::s_at_y_on`] without allocating: `found` is called with each s, ascending.
    pub fn each_s_at_y_on(&self, i: usize, y: f64, found: impl FnMut(f64)) {
        self.each_s_at_y_in(i, &self.monotone_pieces(i), y, found)
    }

    /// The pieces of segment `i` where y(s) is monotone.
    pub fn monotone_pieces(&self, i: usize) -> Pieces {
        let h = self.s[i + 1] - self.s[i];
        let (roots, n) = critical_points(&self.y, i, h);
        let mut cuts = [0.0; 4];
        cuts[1..=n].copy_from_slice(&roots[..n]);
        cuts[n + 1] = h;
        Pieces { cuts, n, y: cuts.map(|t| self.y.eval(i, t)[0]) }
    }

    /// [`Self::each_s_at_y_on`] with the segment's monotone pieces given ([`Self::monotone_pieces`]).
    pub fn each_s_at_y_in(&self, i: usize, pieces: &Pieces, y: f64, mut found: impl FnMut(f64)) {
        let g = |t: f64| {
            let [f, df, _] = self.y.eval(i, t);
            (f - y, df)
        };
        let Pieces { cuts, n, y: at } = pieces;
        for k in 0..n + 1 {
            if let Some(t) = bracketed_root(&g, (cuts[k], at[k] - y), (cuts[k + 1], at[k + 1] - y)) {
                found(self.s[i] + t);
            }
        }
    }
}

/// The pieces of a segment where y(s) is monotone: local coordinates 0, the zeros of y′ inside,
/// the segment's length (the first `n + 2` of `cuts`), and y at each.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pieces {
    cuts: [f64; 4],
    n: usize,
    y: [f64; 4],
}

impl Pieces {
    /// The segment's y-range, its interior extrema included: y at its ends and turning points.
    pub fn y_bounds(&self) -> (f64, f64) {
        let (first, last) = (self.y[0], self.y[self.n + 1]);
        let inside = &self.y[1..=self.n];
        inside.iter().fold((first.min(last), first.max(last)), |(lo, hi), &v| (lo.min(v), hi.max(v)))
    }
}

/// The zeros of f′ on segment `i` strictly inside (0, h), ascending: the first `n` of the array.
fn critical_points(c: &Cubic, i: usize, h: f64) -> ([f64; 2], usize) {
    let (a1, a2, a3) = (c.a1[i], c.a2[i], c.a3[i]);
    // 3 a3 t² + 2 a2 t + a1 = 0
    let mut roots = [0.0; 2];
    let mut n = 0;
    let mut keep = |t: f64| {
        if t > 0.0 && t < h {
            roots[n] = t;
            n += 1;
        }
    };
    if a3.abs() < 1e-300 {
        if a2 != 0.0 {
            keep(-a1 / (2.0 * a2));
        }
    } else {
        let disc = 4.0 * a2 * a2 - 12.0 * a3 * a1;
        if disc >= 0.0 {
            let r = disc.sqrt();
            // The stable form of the two roots.
            let qv = -0.5 * (2.0 * a2 + r.copysign(a2));
            if qv != 0.0 {
                keep(qv / (3.0 * a3));
                keep(a1 / qv);
            } else {
                keep(0.0);
            }
        }
    }
    if n == 2 && roots[0].total_cmp(&roots[1]).is_gt() {
        roots.swap(0, 1);
    }
    (roots, n)
}

/// A zero of the monotone `g` on [lo, hi] if it changes sign there (ends included): Newton's
/// steps from the chord's zero, kept inside the bracket of the sign change (bisection where a step
/// would leave it), to a step of a few units in the last place of the segment's length.
/// `g` returns the value and the derivative; its values at the ends are given with them.
pub(super) fn bracketed_root(
    g: &impl Fn(f64) -> (f64, f64),
    (lo, glo): (f64, f64),
    (hi, ghi): (f64, f64),
) -> Option<f64> {
    if glo == 0.0 {
        return Some(lo);
    }
    if ghi == 0.0 {
        return Some(hi);
    }
    if glo.signum() == ghi.signum() {
        return None;
    }
    let tol = 4.0 * f64::EPSILON * lo.abs().max(hi.abs());
    // Below and above zero.
    let (mut a, mut b) = if glo < 0.0 { (lo, hi) } else { (hi, lo) };
    let mut t = (lo - glo * (hi - lo) / (ghi - glo)).clamp(lo, hi);
    for _ in 0..200 {
        let (gt, dg) = g(t);
        if gt == 0.0 {
            return Some(t);
        }
        if gt < 0.0 {
            a = t;
        } else {
            b = t;
        }
        let (l, h) = (a.min(b), a.max(b));
        let newton = t - gt / dg;
        let next = if newton > l && newton < h { newton } else { 0.5 * (l + h) };
        if (next - t).abs() <= tol || h - l <= tol {
            return Some(next);
        }
        t = next;
    }
    Some(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_interpolating_spline_passes_through_the_points_with_free_ends() {
        let s: Vec<f64> = (0..8).map(|i| i as f64 * 0.7).collect();
        let f: Vec<f64> = s.iter().map(|x| x.sin()).collect();
        let c = fit(&s, &f, &[0, 7], 0.0, &[1.0; 8]);
        for i in 0..7 {
            let h = s[i + 1] - s[i];
            assert!((c.eval(i, h)[0] - f[i + 1]).abs() < 1e-12, "segment {i} meets the next point");
            assert!((c.eval(i, h)[1] - c.a1[i + 1]).abs() < 1e-12, "slopes continuous at {i}");
        }
        assert_eq!(c.a2[0], 0.0);
        assert!(c.eval(6, s[7] - s[6])[2].abs() < 1e-12, "f'' = 0 at the free end");
    }

    #[test]
    fn a_straight_line_stays_straight_and_smoothing_keeps_it() {
        let s: Vec<f64> = (0..6).map(|i| i as f64).collect();
        let f: Vec<f64> = s.iter().map(|x| 2.0 * x + 1.0).collect();
        for lambda in [0.0, 5.0] {
            let c = fit(&s, &f, &[0, 5], lambda, &weights(&s, &[0, 5], true));
            for i in 0..6 {
                assert!((c.a0[i] - f[i]).abs() < 1e-12 && (c.a1[i] - 2.0).abs() < 1e-12, "lambda {lambda}");
            }
        }
    }

    /// Noisy samples of a smooth curve at uneven spacing, and their arc-length-like parameter.
    fn noisy() -> (Vec<f64>, Vec<f64>) {
        let s: Vec<f64> = (0..40).map(|i| i as f64 * 0.5 + 0.1 * (i as f64 * 1.7).sin()).collect();
        let f: Vec<f64> =
            s.iter().enumerate().map(|(i, x)| 0.3 * x + (0.4 * x).sin() + 0.05 * (i as f64 * 2.3).cos()).collect();
        (s, f)
    }

    #[test]
    fn smoothing_with_lambda_to_zero_reproduces_the_points() {
        // The smoothing spline's residual is (2/3) λ σ_i (Q a2)_i (Reinsch): λ → 0 interpolates.
        let (s, f) = noisy();
        let n = s.len();
        let exact = fit(&s, &f, &[0, n - 1], 0.0, &[1.0; 40]);
        for lambda in [1e-8, 1e-6] {
            let c = fit(&s, &f, &[0, n - 1], lambda, &weights(&s, &[0, n - 1], false));
            let worst = (0..n).map(|i| (c.a0[i] - f[i]).abs()).fold(0.0, f64::max);
            assert!(worst < 10.0 * lambda, "lambda {lambda}: worst residual {worst}");
            let slope = (0..n).map(|i| (c.a1[i] - exact.a1[i]).abs()).fold(0.0, f64::max);
            assert!(slope < 1e3 * lambda, "lambda {lambda}: slopes off the interpolating spline's by {slope}");
        }
    }

    #[test]
    fn smoothing_with_lambda_to_infinity_gives_the_weighted_least_squares_line() {
        // With ∫ f″² penalised without bound the spline is a straight line: the one minimising
        // Σ w_i (f_i − a − b s_i)², computed here in closed form from the normal equations.
        let (s, f) = noisy();
        let n = s.len();
        for use_spacing in [false, true] {
            let w = weights(&s, &[0, n - 1], use_spacing);
            let (sw, sws, swf) = (w.iter().sum::<f64>(), dot(&w, &s), dot(&w, &f));
            let sws2: f64 = w.iter().zip(&s).map(|(w, x)| w * x * x).sum();
            let swsf: f64 = w.iter().zip(&s).zip(&f).map(|((w, x), y)| w * x * y).sum();
            let b = (sw * swsf - sws * swf) / (sw * sws2 - sws * sws);
            let a = (swf - b * sws) / sw;
            let c = fit(&s, &f, &[0, n - 1], 1e14, &w);
            for i in 0..n {
                let line = a + b * s[i];
                assert!((c.a0[i] - line).abs() < 1e-6, "spacing {use_spacing}, point {i}: {} vs {line}", c.a0[i]);
                assert!((c.a1[i] - b).abs() < 1e-6 && c.a2[i].abs() < 1e-8, "spacing {use_spacing}, point {i}");
            }
        }
    }

    #[test]
    fn moderate_smoothing_lowers_the_roughness_and_keeps_the_mean() {
        // Between the two limits: less ∫ f″² than the interpolant, and (unit weights, free ends)
        // the residuals sum to zero (the penalty does not see constants or lines).
        let (s, f) = noisy();
        let n = s.len();
        let w = weights(&s, &[0, n - 1], false);
        let rough = |c: &Cubic| -> f64 {
            (0..n - 1)
                .map(|i| {
                    let h = s[i + 1] - s[i];
                    let (p, q) = (c.eval(i, 0.0)[2], c.eval(i, h)[2]);
                    h * (p * p + p * q + q * q) / 3.0
                })
                .sum()
        };
        let interp = fit(&s, &f, &[0, n - 1], 0.0, &w);
        let smooth = fit(&s, &f, &[0, n - 1], 1.0, &w);
        assert!(rough(&smooth) < 0.2 * rough(&interp), "{} vs {}", rough(&smooth), rough(&interp));
        let sum: f64 = (0..n).map(|i| f[i] - smooth.a0[i]).sum();
        let first_moment: f64 = (0..n).map(|i| (f[i] - smooth.a0[i]) * s[i]).sum();
        assert!(sum.abs() < 1e-9 && first_moment.abs() < 1e-8, "{sum} {first_moment}");
    }

    fn dot(a: &[f64], b: &[f64]) -> f64 {
        a.iter().zip(b).map(|(x, y)| x * y).sum()
    }

    #[test]
    fn roots_are_found_on_every_monotone_piece() {
        let c = Cubic { a0: vec![0.0, 0.0], a1: vec![-1.0, 0.0], a2: vec![0.0, 0.0], a3: vec![1.0, 0.0] };
        let sp = ParamSpline { s: vec![0.0, 2.0], y: c.clone(), z: c };
        // y = t³ − t on [0, 2]: y = 0 at t = 0 and t = 1.
        let r = sp.s_at_y_on(0, 0.0);
        assert_eq!(r.len(), 2);
        assert!(r[0].abs() < 1e-15 && (r[1] - 1.0).abs() < 1e-14, "{r:?}");
        let (lo, hi) = sp.monotone_pieces(0).y_bounds();
        assert!((lo + 2.0 / (3.0 * 3f64.sqrt())).abs() < 1e-14 && (hi - 6.0).abs() < 1e-14);
    }
}
