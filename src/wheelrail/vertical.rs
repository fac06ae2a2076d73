//! The wheelset's height for a prescribed vertical force (CONTACT's N = 1: z_ws found by a
//! Newton–secant iteration, user guide "Wheelset geometry & state"): every patch's normal
//! problem solved at each trial height, the heights stepped by the secant of FN^(2/3), which
//! Hertz's law makes nearly linear in the height.

use super::WheelRailError;

/// Relative force tolerance of the height iteration.
pub const FORCE_TOL: f64 = 1e-9;
const MAX_ITER: usize = 100;
/// The height span [mm] within which a force that still misses its target has jumped over it.
const JUMP_MM: f64 = 1e-12;
/// The first trial height below first touch [mm]: a small patch (a cheap normal problem) whose
/// force the secant on FN^(2/3) extrapolates.
const FIRST_STEP_MM: f64 = 0.01;

/// Two evaluations of the force: `(z [mm], force [N])`, the later second.
pub type Evaluations = [(f64, f64); 2];

/// The height z where `force(z)` (≥ 0, increasing in z) equals `target_n` within `tol` (relative),
/// from the height of first touch `z_touch`, or from two earlier evaluations `start` (a search for
/// a nearby target); returns the height, the number of evaluations and the last two.
pub fn solve<F>(
    z_touch_mm: f64,
    target_n: f64,
    tol: f64,
    start: Option<Evaluations>,
    mut force: F,
) -> Result<(f64, usize, Evaluations), WheelRailError>
where
    F: FnMut(f64) -> Result<f64, WheelRailError>,
{
    let g = |f: f64| f.max(0.0).powf(2.0 / 3.0) - target_n.powf(2.0 / 3.0);
    let mut evaluations = 0;
    let (mut z0, mut g0, mut z1, mut g1, mut f1) = match start {
        Some([(za, fa), (zb, fb)]) if g(fa) != g(fb) => (za, g(fa), zb, g(fb), fb),
        _ => {
            let z1 = z_touch_mm + FIRST_STEP_MM;
            let f1 = force(z1)?;
            evaluations += 1;
            (z_touch_mm, g(0.0), z1, g(f1), f1)
        }
    };
    let mut f0: f64;
    // The heights known below and above the target (the force may jump where an approximate
    // normal problem's contact gains a row): a secant step outside them is a bisection.
    let (mut below, mut above) = (f64::NEG_INFINITY, f64::INFINITY);
    for _ in 0..MAX_ITER {
        for (z, gz) in [(z0, g0), (z1, g1)] {
            if gz < 0.0 {
                below = below.max(z);
            } else {
                above = above.min(z);
            }
        }
        if above - below <= JUMP_MM {
            // The force jumps over the target within a height span of rounding: the upper side's.
            let z = above;
            let f = force(z)?;
            return Ok((z, evaluations + 1, [(z1, f1), (z, f)]));
        }
        let mut z2 = z1 - g1 * (z1 - z0) / (g1 - g0);
        if !(z2 > below && z2 < above) && below.is_finite() && above.is_finite() {
            z2 = 0.5 * (below + above);
        }
        let f2 = force(z2)?;
        evaluations += 1;
        (z0, g0, f0, z1, g1, f1) = (z1, g1, f1, z2, g(f2), f2);
        if (f2 - target_n).abs() <= tol * target_n {
            return Ok((z1, evaluations, [(z0, f0), (z1, f1)]));
        }
    }
    Err(WheelRailError::VerticalNotConverged { fz_n: target_n, z_mm: z1 })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_height_of_a_hertzian_law() {
        // F = k (z − z0)^1.5: the secant on F^(2/3) is exact after one step.
        let (k, z_touch) = (2.0e6, 0.18);
        let (z, _, _) = solve(z_touch, 10000.0, FORCE_TOL, None, |z| Ok(k * (z - z_touch).max(0.0).powf(1.5))).unwrap();
        assert!((z - (z_touch + (10000.0f64 / k).powf(2.0 / 3.0))).abs() < 1e-12);
    }

    #[test]
    fn a_nearby_target_from_earlier_evaluations_takes_one_step_on_a_hertzian_law() {
        let (k, z_touch) = (2.0e6, 0.18);
        let law = |z: f64| k * (z - z_touch).max(0.0).powf(1.5);
        let (_, _, last) = solve(z_touch, 10000.0, FORCE_TOL, None, |z| Ok(law(z))).unwrap();
        let mut calls = 0;
        let (z, n, _) = solve(z_touch, 9990.0, FORCE_TOL, Some(last), |z| {
            calls += 1;
            Ok(law(z))
        })
        .unwrap();
        assert_eq!((n, calls), (1, 1));
        assert!((z - (z_touch + (9990.0f64 / k).powf(2.0 / 3.0))).abs() < 1e-12);
    }
}
