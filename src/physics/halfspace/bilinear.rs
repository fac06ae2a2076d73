//! Influence integrals of a piecewise BILINEAR traction (CONTACT's C = 3; user guide, "C3 -
//! INFLCF"; Vollebregt 2009, memo m09002): the traction of node (0, 0) is the hat
//! φ(ξ, η) = (1 − |ξ|/dx)(1 − |η|/dy) on [−dx, dx] × [−dy, dy] (value 1 at the node, 0 at its
//! neighbours: the nodal values interpolate bilinearly), and the displacement at the offset (X, Y)
//! is `∫∫ K(X − ξ, Y − η) φ(ξ, η) dξ dη` for the Boussinesq/Cerruti integrands K = s²/r³, t²/r³,
//! st/r³ (and 1/r = s²/r³ + t²/r³).
//!
//! On each quadrant of the hat, φ is a product of linear factors; in the integration variables
//! s = X − ξ, t = Y − η it is (c0 + c1 s)(d0 + d1 t), so each quadrant's integral is the corner
//! double difference over its rectangle of c0 d0 F00 + c1 d0 F10 + c0 d1 F01 + c1 d1 F11, F_kl the
//! antiderivative (∂²/∂s∂t) of s^k t^l K. The logarithms ln(t + r), ln(s + r) are written as
//! asinh(t/|s|), asinh(s/|t|): the dropped g(s) ln|s| (g(t) ln|t|) depend on one variable only
//! and cancel in the double difference, and the asinh form has no cancellation where t + r → 0.

use super::influence::RectIntegrals;

/// ln(t + r) less ln|s|: asinh(t/|s|), multiplied by a power of s that vanishes with s.
fn log_t(s: f64, t: f64) -> f64 {
    if s == 0.0 {
        0.0
    } else {
        (t / s.abs()).asinh()
    }
}

/// ln(s + r) less ln|t| (see [`log_t`]).
fn log_s(s: f64, t: f64) -> f64 {
    log_t(t, s)
}

/// Antiderivatives of s^k t^l s²/r³, `[F00, F10, F01, F11]`.
fn f_ss(s: f64, t: f64) -> [f64; 4] {
    let r = s.hypot(t);
    let ls = log_s(s, t);
    [t * ls, t * r, 0.5 * (t * t * ls - s * r), r * (2.0 * t * t - s * s) / 3.0]
}

/// Antiderivatives of s^k t^l t²/r³, `[F00, F10, F01, F11]` (s ↔ t of [`f_ss`]).
fn f_tt(s: f64, t: f64) -> [f64; 4] {
    let [a, b, c, d] = f_ss(t, s);
    [a, c, b, d]
}

/// Antiderivatives of s^k t^l st/r³, `[F00, F10, F01, F11]`.
fn f_st(s: f64, t: f64) -> [f64; 4] {
    let r = s.hypot(t);
    let (lt, ls) = (log_t(s, t), log_s(s, t));
    [-r, 0.5 * (t * t * ls - s * r), 0.5 * (s * s * lt - t * r), (s * s * s * lt + t * t * t * ls - s * t * r) / 3.0]
}

/// `∫∫ K φ` over one quadrant: ξ in [ξ0, ξ1] where φ_x = 1 + bx ξ, η in [η0, η1] where
/// φ_y = 1 + by η; `f` gives the antiderivatives of s^k t^l K.
fn quadrant(
    f: fn(f64, f64) -> [f64; 4],
    (x, y): (f64, f64),
    (xi, bx): ([f64; 2], f64),
    (eta, by): ([f64; 2], f64),
) -> f64 {
    // In s = X − ξ: φ_x = (1 + bx X) − bx s; likewise in t.
    let (c0, c1, d0, d1) = (1.0 + bx * x, -bx, 1.0 + by * y, -by);
    let at = |s: f64, t: f64| {
        let [f00, f10, f01, f11] = f(s, t);
        c0 * d0 * f00 + c1 * d0 * f10 + c0 * d1 * f01 + c1 * d1 * f11
    };
    let (s_lo, s_hi, t_lo, t_hi) = (x - xi[1], x - xi[0], y - eta[1], y - eta[0]);
    (at(s_hi, t_hi) - at(s_lo, t_hi)) - (at(s_hi, t_lo) - at(s_lo, t_lo))
}

/// `∫∫ K φ` over the hat's four quadrants.
fn hat(f: fn(f64, f64) -> [f64; 4], x: f64, y: f64, dx: f64, dy: f64) -> f64 {
    let xs = [([0.0, dx], -1.0 / dx), ([-dx, 0.0], 1.0 / dx)];
    let ys = [([0.0, dy], -1.0 / dy), ([-dy, 0.0], 1.0 / dy)];
    let mut sum = 0.0;
    for qx in xs {
        for qy in ys {
            sum += quadrant(f, (x, y), qx, qy);
        }
    }
    sum
}

/// The hat integrals of node (0, 0) at the offset `(x, y)` [mm] from it, for `dx × dy` [mm]
/// elements; each in mm, as [`super::influence::rect_integrals`] of a uniform element (whose
/// values they approach far from the node: the hat's area is dx·dy, as the element's).
pub fn hat_integrals(x: f64, y: f64, dx: f64, dy: f64) -> RectIntegrals {
    let xx = hat(f_ss, x, y, dx, dy);
    let yy = hat(f_tt, x, y, dx, dy);
    RectIntegrals { one_over_r: xx + yy, xx, yy, xy: hat(f_st, x, y, dx, dy) }
}

#[cfg(test)]
mod tests {
    use super::super::influence::rect_integrals;
    use super::*;

    /// Each antiderivative's mixed derivative ∂²F/∂s∂t (central differences) is its integrand.
    #[test]
    fn antiderivatives_differentiate_to_their_integrands() {
        let h = 1e-4;
        for &(s, t) in &[(0.7f64, 0.3f64), (-1.3, 0.45), (0.2, -2.1), (-0.8, -0.9), (2.5, 0.05)] {
            let r3 = s.hypot(t).powi(3);
            type Antiderivatives = fn(f64, f64) -> [f64; 4];
            let cases: [(Antiderivatives, f64); 3] = [(f_ss, s * s / r3), (f_tt, t * t / r3), (f_st, s * t / r3)];
            for (f, k) in cases {
                let mixed = |j: usize| {
                    (f(s + h, t + h)[j] - f(s - h, t + h)[j] - f(s + h, t - h)[j] + f(s - h, t - h)[j]) / (4.0 * h * h)
                };
                let want = [k, s * k, t * k, s * t * k];
                for (j, want) in want.into_iter().enumerate() {
                    assert!(
                        (mixed(j) - want).abs() < 1e-6 * (1.0 + want.abs()),
                        "F{j} at ({s}, {t}): {} vs {want}",
                        mixed(j),
                    );
                }
            }
        }
    }

    /// Gauss–Legendre (16 points) on each quadrant of the hat, where the field point is outside
    /// the hat's support (a smooth integrand): the closed form to 1e-12.
    #[test]
    fn hat_integrals_match_quadrature_off_the_support() {
        const N: usize = 16;
        // Nodes/weights of 16-point Gauss–Legendre by Newton on P_16 (no table to mistype).
        let (mut xg, mut wg) = ([0.0; N], [0.0; N]);
        // P_16(z) and its derivative by the three-term recurrence.
        let legendre = |z: f64| {
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=N {
                let p2 = ((2 * k - 1) as f64 * z * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            (p1, N as f64 * (z * p1 - p0) / (z * z - 1.0))
        };
        for i in 0..N {
            let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (N as f64 + 0.5)).cos();
            for _ in 0..100 {
                let (p, dp) = legendre(z);
                let dz = p / dp;
                z -= dz;
                if dz.abs() < 1e-16 {
                    let (_, dp) = legendre(z);
                    xg[i] = z;
                    wg[i] = 2.0 / ((1.0 - z * z) * dp * dp);
                    break;
                }
            }
        }
        let (dx, dy): (f64, f64) = (0.6, 0.35);
        for &(x, y) in &[(2.0 * dx, 0.0), (-2.5 * dx, 1.5 * dy), (0.3 * dx, -3.0 * dy), (5.0 * dx, 4.0 * dy)] {
            let quad = |k: &dyn Fn(f64, f64) -> f64| {
                let mut sum = 0.0;
                for (x0, x1) in [(-dx, 0.0), (0.0, dx)] {
                    for (y0, y1) in [(-dy, 0.0), (0.0, dy)] {
                        for a in 0..N {
                            for b in 0..N {
                                let xi = 0.5 * (x0 + x1) + 0.5 * (x1 - x0) * xg[a];
                                let eta = 0.5 * (y0 + y1) + 0.5 * (y1 - y0) * xg[b];
                                let phi = (1.0 - xi.abs() / dx) * (1.0 - eta.abs() / dy);
                                sum += 0.25 * (x1 - x0) * (y1 - y0) * wg[a] * wg[b] * phi * k(x - xi, y - eta);
                            }
                        }
                    }
                }
                sum
            };
            let r3 = |s: f64, t: f64| s.hypot(t).powi(3);
            let h = hat_integrals(x, y, dx, dy);
            let pairs = [
                (h.xx, quad(&|s, t| s * s / r3(s, t))),
                (h.yy, quad(&|s, t| t * t / r3(s, t))),
                (h.xy, quad(&|s, t| s * t / r3(s, t))),
                (h.one_over_r, quad(&|s, t| 1.0 / s.hypot(t))),
            ];
            for (got, want) in pairs {
                assert!((got - want).abs() < 1e-12 * h.one_over_r, "({x}, {y}): {got} vs {want}");
            }
        }
    }

    /// Symmetries of the half-space: xx, yy, 1/r even in X and in Y, xy odd in each; with dx = dy
    /// the xx of (X, Y) is the yy of (Y, X). Far from the node (r ≫ dx) every integral tends to
    /// the uniform element's (both carry dx·dy, centred at the node): the difference falls as
    /// (dx/r)², so 40 elements away it is below 1e-3 of the value.
    #[test]
    fn symmetric_and_the_uniform_element_far_away() {
        let (dx, dy): (f64, f64) = (0.5, 0.5);
        for &(x, y) in &[(0.0, 0.0), (0.5, 0.0), (1.0, 1.5), (2.5, -0.5), (0.25, 0.75)] {
            let h = hat_integrals(x, y, dx, dy);
            let mx = hat_integrals(-x, y, dx, dy);
            let my = hat_integrals(x, -y, dx, dy);
            let swap = hat_integrals(y, x, dx, dy);
            // The double differences of r³-sized antiderivatives cancel a few digits.
            let tol = 1e-11 * h.one_over_r;
            assert!(
                (h.xx - mx.xx).abs() < tol && (h.xx - my.xx).abs() < tol,
                "({x}, {y}): {} {} {}",
                h.xx,
                mx.xx,
                my.xx
            );
            assert!((h.one_over_r - mx.one_over_r).abs() < tol);
            assert!((h.xy + mx.xy).abs() < tol && (h.xy + my.xy).abs() < tol, "({x}, {y})");
            assert!((h.xx - swap.yy).abs() < tol, "({x}, {y}): {} {} {}", h.xx, swap.yy, h.one_over_r);
        }
        let (dx, dy): (f64, f64) = (0.4, 0.3);
        for &(x, y) in &[(40.0 * dx, 0.0), (-25.0 * dx, 30.0 * dy), (3.0 * dx, -45.0 * dy)] {
            let (h, c) = (hat_integrals(x, y, dx, dy), rect_integrals(x, y, dx, dy));
            let scale = c.one_over_r;
            for (a, b) in [(h.one_over_r, c.one_over_r), (h.xx, c.xx), (h.yy, c.yy), (h.xy, c.xy)] {
                assert!((a - b).abs() < 1e-3 * scale, "({x}, {y}): {a} vs {b}");
            }
            // The point load's value there, times the area: 1/r dx dy.
            assert!((h.one_over_r - dx * dy / x.hypot(y)).abs() < 1e-3 * scale);
        }
        // A unit traction at every node of a 41 × 41 block is 1 inside the block (the hats sum to
        // one): at its centre the displacement is the uniform elements' but for the block's rim,
        // where the hats taper over dx and the elements end at dx/2 (equal load, moved outward).
        let (mut hats, mut elements) = ([0.0; 4], [0.0; 4]);
        for j in -20..=20 {
            for i in -20..=20 {
                let (x, y) = (f64::from(i) * dx, f64::from(j) * dy);
                let (h, c) = (hat_integrals(x, y, dx, dy), rect_integrals(x, y, dx, dy));
                for (k, (a, b)) in
                    [(h.one_over_r, c.one_over_r), (h.xx, c.xx), (h.yy, c.yy), (h.xy, c.xy)].iter().enumerate()
                {
                    hats[k] += a;
                    elements[k] += b;
                }
            }
        }
        for k in 0..3 {
            assert!((hats[k] - elements[k]).abs() < 2e-4 * elements[k], "{k}: {} vs {}", hats[k], elements[k]);
        }
        assert!(hats[3].abs() < 1e-12 * hats[0] && elements[3].abs() < 1e-12 * elements[0]);
        // The hat is larger than its element: at the node, more load sits farther away.
        assert!(hat_integrals(0.0, 0.0, dx, dy).one_over_r < rect_integrals(0.0, 0.0, dx, dy).one_over_r);
    }
}
