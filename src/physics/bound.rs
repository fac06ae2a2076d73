//! The traction bound |τ| ≤ μ p (thesis Eq. 2.27, 3.11) and its direction-keeping projection.

/// Project the traction (τx, τy) onto the disk of radius `g = μ p` keeping its direction
/// (thesis Eq. 2.29, written without the quadrant cases: τ ← g τ/|τ| when |τ| > g).
/// Returns the projected traction and whether the bound was active (the element slips).
#[inline]
pub fn project_to_bound(tx: f64, ty: f64, g: f64) -> (f64, f64, bool) {
    let n2 = tx * tx + ty * ty;
    if n2 > g * g {
        if g <= 0.0 {
            return (0.0, 0.0, true);
        }
        let s = g / n2.sqrt();
        (tx * s, ty * s, true)
    } else {
        (tx, ty, false)
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
}
