//! The cubic interpolating spline with not-a-knot ends (de Boor, "A Practical Guide to Splines",
//! ch. IV) as CONTACT builds it along the track through a slices file's slices
//! (`m_bspline_make.f90`, `bspline_make_2d_bspline` with `use_insert`: the B-spline solved
//! without knots at the second and last-but-one data sites, which are then inserted), written as
//! weights: the spline's value at u is Σ_i w_i(u) f_i for data f_i at the sites u_i, so one
//! solve serves every lateral path of the slices.

/// The system of a not-a-knot spline's interior second derivatives at `n ≥ 4` sites: the end
/// ones eliminated by the not-a-knot conditions, which leaves a tridiagonal, diagonally dominant
/// system (its rows 1 ..= n − 2).
#[derive(Debug, Clone, PartialEq)]
pub struct NotAKnot {
    u: Vec<f64>,
    /// The reduced system's sub-diagonal, diagonal and super-diagonal (index = row, 1 ..= n − 2).
    lower: Vec<f64>,
    diag: Vec<f64>,
    upper: Vec<f64>,
    /// M_0 = α M_1 + β M_2 and M_{n−1} = γ M_{n−2} + δ M_{n−3} (M‴ continuous at the second
    /// and the last-but-one site).
    ends: [f64; 4],
}

impl NotAKnot {
    /// The spline's system for strictly increasing sites `u` (at least four); `None` otherwise.
    pub fn new(u: &[f64]) -> Option<NotAKnot> {
        let n = u.len();
        if n < 4 || u.windows(2).any(|w| !(w[1] > w[0] && (w[1] - w[0]).is_finite())) {
            return None;
        }
        let h: Vec<f64> = u.windows(2).map(|w| w[1] - w[0]).collect();
        let (mut lower, mut diag, mut upper) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        for r in 1..n - 1 {
            lower[r] = h[r - 1];
            diag[r] = 2.0 * (h[r - 1] + h[r]);
            upper[r] = h[r];
        }
        let ends = [(h[0] + h[1]) / h[1], -h[0] / h[1], (h[n - 3] + h[n - 2]) / h[n - 3], -h[n - 2] / h[n - 3]];
        diag[1] += h[0] * ends[0];
        upper[1] += h[0] * ends[1];
        diag[n - 2] += h[n - 2] * ends[2];
        lower[n - 2] += h[n - 2] * ends[3];
        Some(NotAKnot { u: u.to_vec(), lower, diag, upper, ends })
    }

    /// The weights w_i(u_at) of the data at the sites: the spline's value is Σ w_i f_i. `u_at` is
    /// held to [u_1, u_n] (CONTACT's constant extrapolation beyond the first and last slice).
    pub fn weights(&self, u_at: f64) -> Vec<f64> {
        let (u, n) = (&self.u, self.u.len());
        let x = u_at.clamp(u[0], u[n - 1]);
        let k = u.partition_point(|&v| v <= x).saturating_sub(1).min(n - 2);
        let h = u[k + 1] - u[k];
        let (p, q) = ((u[k + 1] - x) / h, (x - u[k]) / h);
        // S(x) = p f_k + q f_{k+1} + h²/6 [(p³ − p) M_k + (q³ − q) M_{k+1}].
        let mut w = vec![0.0; n];
        w[k] = p;
        w[k + 1] = q;
        let mut b = vec![0.0; n];
        b[k] = h * h / 6.0 * (p * p * p - p);
        b[k + 1] = h * h / 6.0 * (q * q * q - q);
        // bᵀ M in the interior unknowns: c = b there, the ends' shares moved to their neighbours.
        let [al, be, ga, de] = self.ends;
        let mut c = b.clone();
        c[1] += b[0] * al;
        c[2] += b[0] * be;
        c[n - 2] += b[n - 1] * ga;
        c[n - 3] += b[n - 1] * de;
        // M_int = T⁻¹ R f, so bᵀ M = (Rᵀ T⁻ᵀ c)ᵀ f, R the rows' 6 × divided second differences.
        let y = self.solve_transposed(&c);
        for r in 1..n - 1 {
            let (c0, c1) = (6.0 / (u[r] - u[r - 1]), 6.0 / (u[r + 1] - u[r]));
            w[r - 1] += y[r] * c0;
            w[r] -= y[r] * (c0 + c1);
            w[r + 1] += y[r] * c1;
        }
        w
    }

    /// The spline through data `f` at the sites: its second derivatives M_i (T M = R f by
    /// Thomas's algorithm, the ends from the not-a-knot conditions).
    pub fn curve(&self, f: &[f64]) -> Curve {
        let (u, n) = (&self.u, self.u.len());
        let (mut sup, mut rhs) = (vec![0.0; n], vec![0.0; n]);
        for r in 1..n - 1 {
            let (h0, h1) = (u[r] - u[r - 1], u[r + 1] - u[r]);
            let d = 6.0 * ((f[r + 1] - f[r]) / h1 - (f[r] - f[r - 1]) / h0);
            let sub = if r > 1 { self.lower[r] } else { 0.0 };
            let den = self.diag[r] - sub * sup[r - 1];
            sup[r] = if r < n - 2 { self.upper[r] / den } else { 0.0 };
            rhs[r] = (d - sub * rhs[r - 1]) / den;
        }
        let mut m = vec![0.0; n];
        for r in (1..n - 1).rev() {
            m[r] = rhs[r] - sup[r] * m[r + 1];
        }
        let [al, be, ga, de] = self.ends;
        m[0] = al * m[1] + be * m[2];
        m[n - 1] = ga * m[n - 2] + de * m[n - 3];
        Curve { u: u.clone(), f: f.to_vec(), m }
    }

    /// y with Tᵀ y = c on rows 1 ..= n − 2 (Thomas's algorithm: Tᵀ is tridiagonal, its
    /// sub-diagonal T's super-diagonal shifted, and column diagonally dominant).
    fn solve_transposed(&self, c: &[f64]) -> Vec<f64> {
        let n = self.u.len();
        // Tᵀ row r: sub = upper[r − 1], diag[r], super = lower[r + 1].
        let (mut sup, mut rhs) = (vec![0.0; n], vec![0.0; n]);
        for r in 1..n - 1 {
            let sub = if r > 1 { self.upper[r - 1] } else { 0.0 };
            let den = self.diag[r] - sub * sup[r - 1];
            sup[r] = if r < n - 2 { self.lower[r + 1] / den } else { 0.0 };
            rhs[r] = (c[r] - sub * rhs[r - 1]) / den;
        }
        let mut y = vec![0.0; n];
        for r in (1..n - 1).rev() {
            y[r] = rhs[r] - sup[r] * y[r + 1];
        }
        y
    }
}

/// A not-a-knot spline through given data: the sites, the data and the second derivatives.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    u: Vec<f64>,
    f: Vec<f64>,
    m: Vec<f64>,
}

impl Curve {
    /// The number of segments.
    pub fn segments(&self) -> usize {
        self.u.len() - 1
    }

    /// Segment `k`'s cubic in t = x − u_k: [c0, c1, c2, c3] and its length.
    pub fn cubic(&self, k: usize) -> ([f64; 4], f64) {
        let h = self.u[k + 1] - self.u[k];
        let (mk, mk1) = (self.m[k], self.m[k + 1]);
        let c1 = (self.f[k + 1] - self.f[k]) / h - h * (2.0 * mk + mk1) / 6.0;
        ([self.f[k], c1, mk / 2.0, (mk1 - mk) / (6.0 * h)], h)
    }

    /// The second derivatives at the sites.
    pub fn second_derivatives(&self) -> &[f64] {
        &self.m
    }

    /// The value on segment `k` at t = x − u_k.
    pub fn value_on(&self, k: usize, t: f64) -> f64 {
        let ([c0, c1, c2, c3], _) = self.cubic(k);
        ((c3 * t + c2) * t + c1) * t + c0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn value(s: &NotAKnot, f: &[f64], x: f64) -> f64 {
        s.weights(x).iter().zip(f).map(|(w, v)| w * v).sum()
    }

    /// Not-a-knot ends reproduce any cubic on uneven sites (a natural spline would not), pass
    /// through the data, and hold the end values beyond the sites.
    #[test]
    fn a_cubic_is_reproduced_and_the_data_interpolated() {
        let u = [-3.0, -1.0, 0.5, 0.7, 2.0, 4.5, 5.0];
        let c = |x: f64| 1.0 - 2.0 * x + 0.3 * x * x - 0.07 * x * x * x;
        let f: Vec<f64> = u.iter().map(|&x| c(x)).collect();
        let s = NotAKnot::new(&u).unwrap();
        for k in 0..=80 {
            let x = -3.0 + 8.0 * k as f64 / 80.0;
            assert!((value(&s, &f, x) - c(x)).abs() < 1e-11, "x {x}: {} vs {}", value(&s, &f, x), c(x));
        }
        let g = [0.3, -1.0, 2.0, 0.0, 5.0, 1.0, -2.0];
        for (i, &x) in u.iter().enumerate() {
            assert!((value(&s, &g, x) - g[i]).abs() < 1e-12);
        }
        assert_eq!(value(&s, &g, -10.0), value(&s, &g, -3.0));
        assert_eq!(value(&s, &g, 9.0), value(&s, &g, 5.0));
        // Four sites: the one cubic through them.
        let s4 = NotAKnot::new(&u[..4]).unwrap();
        assert!((value(&s4, &f[..4], 0.1) - c(0.1)).abs() < 1e-12);
        assert!(NotAKnot::new(&u[..3]).is_none());
        assert!(NotAKnot::new(&[0.0, 1.0, 1.0, 2.0]).is_none());
    }

    /// Away from the ends the not-a-knot spline is a cubic spline: C² at the interior sites
    /// (second derivative by differences from both sides).
    #[test]
    fn the_spline_is_twice_continuously_differentiable() {
        let u = [0.0, 1.0, 2.5, 3.0, 4.0, 6.0];
        let f = [0.0, 1.0, -1.0, 2.0, 0.5, 0.0];
        let s = NotAKnot::new(&u).unwrap();
        let d = 1e-4;
        for &x in &u[1..5] {
            let left = (value(&s, &f, x) - 2.0 * value(&s, &f, x - d) + value(&s, &f, x - 2.0 * d)) / (d * d);
            let right = (value(&s, &f, x + 2.0 * d) - 2.0 * value(&s, &f, x + d) + value(&s, &f, x)) / (d * d);
            assert!((left - right).abs() < 1e-2 * (1.0 + left.abs()), "x {x}: {left} vs {right}");
        }
    }
}
