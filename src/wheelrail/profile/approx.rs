//! CONTACT's approximating spline along a slices file (`U_INTPOL = 2`, `TH_INTPOL = 2`;
//! `m_bspline_make.f90`, `bspline_make_2d_bspline` with `use_approx`): the slices' data are the
//! control points of a cubic B-spline whose knots are the slices' positions, extended by three
//! knots at each end spaced as the first and last interval (`bspline_make_knot_vector_atmeas`
//! without replication), with a phantom control point before the first slice, 2 d₁ − d₂, and one
//! after the last, which CONTACT forms as 2 d₁ − d_{n−1} (its code takes the first slice's row
//! there, `cij(iu0+1)`, where the mirror image of the start would take the last's: reproduced as
//! it is). The surface does not pass through the slices. Written as weights on the slices' data,
//! as [`super::notaknot::NotAKnot`].

/// The knots and the count of an approximating spline through `n ≥ 4` slices.
#[derive(Debug, Clone, PartialEq)]
pub struct Approximating {
    u: Vec<f64>,
    /// n + 6 knots: u₁ − 3Δ₀, u₁ − 2Δ₀, u₁ − Δ₀, u₁ … u_n, u_n + Δ₁, u_n + 2Δ₁, u_n + 3Δ₁.
    knots: Vec<f64>,
}

impl Approximating {
    /// The spline for strictly increasing positions `u` (at least four); `None` otherwise.
    pub fn new(u: &[f64]) -> Option<Approximating> {
        let n = u.len();
        if n < 4 || u.windows(2).any(|w| !(w[1] > w[0] && (w[1] - w[0]).is_finite())) {
            return None;
        }
        let (d0, d1) = (u[1] - u[0], u[n - 1] - u[n - 2]);
        let mut knots = vec![u[0] - 3.0 * d0, u[0] - 2.0 * d0, u[0] - d0];
        knots.extend_from_slice(u);
        knots.extend([u[n - 1] + d1, u[n - 1] + 2.0 * d1, u[n - 1] + 3.0 * d1]);
        Some(Approximating { u: u.to_vec(), knots })
    }

    /// The weights of the slices' data at `u_at`, held to [u₁, u_n].
    pub fn weights(&self, u_at: f64) -> Vec<f64> {
        let (u, n, t) = (&self.u, self.u.len(), &self.knots);
        let x = u_at.clamp(u[0], u[n - 1]);
        // The knot interval [t_m, t_{m+1}) holding x, m in 3 ..= n + 1 (the last closed).
        let m = 3 + u.partition_point(|&v| v <= x).saturating_sub(1).min(n - 2);
        let b = basis(t, m, x);
        // Control point k (0 ..= n + 1) is B-spline k: phantom, slices 1 … n, phantom.
        let mut w = vec![0.0; n];
        for (r, &bv) in b.iter().enumerate() {
            match m - 3 + r {
                0 => {
                    w[0] += 2.0 * bv;
                    w[1] -= bv;
                }
                k if k == n + 1 => {
                    w[0] += 2.0 * bv;
                    w[n - 2] -= bv;
                }
                k => w[k - 1] += bv,
            }
        }
        w
    }
}

/// The four cubic B-splines nonzero on [t_m, t_{m+1}) at x: B_{m−3} … B_m (de Boor's BSPLVB).
pub(super) fn basis(t: &[f64], m: usize, x: f64) -> [f64; 4] {
    let mut b = [1.0, 0.0, 0.0, 0.0];
    let (mut left, mut right) = ([0.0; 4], [0.0; 4]);
    for j in 1..4 {
        left[j] = x - t[m + 1 - j];
        right[j] = t[m + j] - x;
        let mut saved = 0.0;
        for r in 0..j {
            let term = b[r] / (right[r + 1] + left[j - r]);
            b[r] = saved + right[r + 1] * term;
            saved = left[j - r] * term;
        }
        b[j] = saved;
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    fn value(s: &Approximating, f: &[f64], x: f64) -> f64 {
        s.weights(x).iter().zip(f).map(|(w, v)| w * v).sum()
    }

    /// The B-splines sum to one and the spline reproduces a straight line through evenly spaced
    /// slices away from the last interval (the phantoms extrapolate linearly there); it smooths
    /// data it does not pass through.
    #[test]
    fn a_line_is_kept_and_the_weights_sum_to_one() {
        let u: Vec<f64> = (0..8).map(|k| -1.0 + 0.25 * k as f64).collect();
        let s = Approximating::new(&u).unwrap();
        let f: Vec<f64> = u.iter().map(|&x| 3.0 - 2.0 * x).collect();
        for k in 0..=40 {
            let x = -1.0 + 1.25 * k as f64 / 40.0;
            let w = s.weights(x);
            assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-14);
            assert!((value(&s, &f, x) - (3.0 - 2.0 * x)).abs() < 1e-13, "x {x}");
        }
        let mut spike = vec![0.0; 8];
        spike[3] = 1.0;
        assert!((value(&s, &spike, u[3]) - 2.0 / 3.0).abs() < 1e-14);
        assert!(Approximating::new(&u[..3]).is_none());
    }
}
