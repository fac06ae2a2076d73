//! The traction bound |τ| ≤ g = μ p (thesis Eq. 2.27, 3.11) and its direction-keeping
//! projections, written once for every solver.
//!
//! One policy for degenerate input, in every routine here: a traction is inside the bound only if
//! `τx² + τy² ≤ g²` holds (so a NaN traction or a NaN bound is outside; `g` is `μ p ≥ 0`), and a
//! traction that is outside is projected to zero when the bound is not positive (`g ≤ 0` or NaN)
//! or the traction's modulus is not finite (NaN, or an overflowing square).

/// Whether the traction (τx, τy) lies on or inside the disk of radius `g` (`τx² + τy² ≤ g²`).
#[inline(always)]
pub fn within_bound(tx: f64, ty: f64, g: f64) -> bool {
    tx * tx + ty * ty <= g * g
}

/// Project the traction (τx, τy) onto the disk of radius `g = μ p` keeping its direction
/// (thesis Eq. 2.29, written without the quadrant cases: τ ← g τ/|τ| when |τ| > g).
/// Returns the projected traction and whether the bound was active (the element slips).
#[inline]
pub fn project_to_bound(tx: f64, ty: f64, g: f64) -> (f64, f64, bool) {
    if within_bound(tx, ty, g) {
        (tx, ty, false)
    } else {
        let (x, y) = scale_to_bound(tx, ty, g);
        (x, y, true)
    }
}

/// Scale the traction (τx, τy) onto the circle `|τ| = g` keeping its direction: `g τ/|τ|`
/// (thesis Eq. 2.29 for an element known to slip). The zero traction has no direction and stays
/// zero; otherwise the module policy applies (zero for `g ≤ 0`, NaN `g` or a non-finite `|τ|`).
#[inline]
pub fn scale_to_bound(tx: f64, ty: f64, g: f64) -> (f64, f64) {
    let a = (tx * tx + ty * ty).sqrt();
    if !(g > 0.0 && a.is_finite()) {
        (0.0, 0.0)
    } else if a > 0.0 {
        let s = g / a;
        (tx * s, ty * s)
    } else {
        (tx, ty)
    }
}

/// The factor `min(1, g/|τ|)` that [`project_to_bound`] applies, written branch-free from
/// `|τ|² = n2` so that a grid-wide pass vectorises (the UBA's step). For finite tractions it gives
/// the same numbers as [`project_to_bound`] to the last bit; an unloaded element (g = 0) gets 0.
#[inline(always)]
pub fn bound_factor(n2: f64, g: f64) -> f64 {
    (g / n2.sqrt()).min(1.0)
}

/// The factor `g/|τ|` that [`scale_to_bound`] applies, written branch-free from `|τ|² = n2` (a
/// grid-wide pass vectorises; FaStrip's slip area): the zero traction gets 0. For finite
/// tractions and `g ≥ 0` it gives the same numbers as [`scale_to_bound`] to the last bit.
#[inline(always)]
pub fn scale_factor(n2: f64, g: f64) -> f64 {
    // Divided unconditionally, then selected: no branch in a vectorised loop.
    let f = g / n2.sqrt();
    if n2 > 0.0 {
        f
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_direction_and_clips_modulus() {
        let (x, y, slip) = project_to_bound(3.0, -4.0, 2.5);
        assert!(slip);
        assert!(((x * x + y * y).sqrt() - 2.5).abs() < 1e-12);
        assert!((y / x - (-4.0 / 3.0)).abs() < 1e-12);
        assert_eq!(project_to_bound(0.3, 0.4, 1.0), (0.3, 0.4, false));
        assert_eq!(project_to_bound(1.0, 0.0, 0.0), (0.0, 0.0, true));
    }

    #[test]
    fn branch_free_factor_matches_the_projection() {
        let mut x = 0.3f64;
        for _ in 0..1000 {
            // A simple deterministic sequence of tractions and bounds over many magnitudes.
            x = (x * 3.7 + 0.11).fract();
            let (tx, ty, g) = ((x - 0.5) * 1e3, (0.5 - x * x) * 7e2, x * 400.0);
            let f = bound_factor(tx * tx + ty * ty, g);
            let (px, py, _) = project_to_bound(tx, ty, g);
            assert_eq!((tx * f, ty * f), (px, py), "{tx} {ty} {g}");
        }
        assert_eq!(bound_factor(4.0, 0.0), 0.0);
    }

    #[test]
    fn branch_free_scale_matches_scale_to_bound() {
        let mut x = 0.7f64;
        for _ in 0..1000 {
            x = (x * 3.7 + 0.13).fract();
            let (tx, ty, g) = ((x - 0.5) * 1e3, (0.5 - x * x) * 7e2, x * 400.0);
            let f = scale_factor(tx * tx + ty * ty, g);
            assert_eq!((tx * f, ty * f), scale_to_bound(tx, ty, g), "{tx} {ty} {g}");
        }
        assert_eq!(scale_factor(0.0, 2.0), 0.0);
        assert_eq!(scale_factor(4.0, 0.0), 0.0);
    }

    #[test]
    fn one_policy_for_degenerate_input() {
        assert_eq!(project_to_bound(0.0, 0.0, 0.0), (0.0, 0.0, false));
        assert_eq!(project_to_bound(f64::NAN, 1.0, 2.0), (0.0, 0.0, true));
        assert_eq!(project_to_bound(1.0, 1.0, f64::NAN), (0.0, 0.0, true));
        assert_eq!(project_to_bound(1e300, -1e300, 2.0), (0.0, 0.0, true));
        assert_eq!(project_to_bound(2.0, 0.0, -1.0), (0.0, 0.0, true));
        assert_eq!(scale_to_bound(0.0, 0.0, 2.0), (0.0, 0.0));
        assert_eq!(scale_to_bound(0.5, 0.0, 2.0), (2.0, 0.0));
        assert_eq!(scale_to_bound(0.5, 0.0, 0.0), (0.0, 0.0));
        assert_eq!(scale_to_bound(f64::NAN, 0.0, 1.0), (0.0, 0.0));
    }

    /// The projection scales by `g / sqrt(τx² + τy²)`: the arithmetic every solver used before.
    #[test]
    fn scale_factor_is_g_over_the_modulus() {
        let (tx, ty, g): (f64, f64, f64) = (0.7310, -1.913, 0.3127);
        let s = g / (tx * tx + ty * ty).sqrt();
        assert_eq!(project_to_bound(tx, ty, g), (tx * s, ty * s, true));
        assert_eq!(scale_to_bound(0.1 * tx, 0.1 * ty, g), {
            let s = g / ((0.1 * tx) * (0.1 * tx) + (0.1 * ty) * (0.1 * ty)).sqrt();
            (0.1 * tx * s, 0.1 * ty * s)
        });
    }
}
