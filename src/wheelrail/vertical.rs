//! The wheelset's height for a prescribed vertical force (CONTACT's N = 1: z_ws found by a
//! Newton–secant iteration, user guide "Wheelset geometry & state"): every patch's normal
//! problem solved at each trial height, the heights stepped by the secant of FN^(2/3), which
//! Hertz's law makes nearly linear in the height. The normal problems of trial heights far from
//! the target are solved to a looser tolerance (an inexact secant: their force need only be as
//! accurate as the step they set, Dembo, Eisenstat & Steihaug 1982); the height accepted is one
//! whose normal problem was solved to the full tolerance, but in a search whose answer only sets
//! the next round's target ([`Stop`]).

use super::WheelRailError;
use crate::physics::halfspace::normal::NormalParams;

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

/// The loosest normal tolerance a trial height is solved to.
const LOOSEST_NORMAL_TOL: f64 = 1e-4;
/// A trial height's normal tolerance as a fraction of the closest relative force miss so far: a
/// loose solve's force errs by up to about 100 times its tolerance, so this keeps that error
/// a hundredth of the miss.
const NORMAL_TOL_PER_MISS: f64 = 1e-4;

/// The normal tolerance of the next trial height when the closest evaluation so far missed the
/// target by `miss` (relative), between the full and the loosest tolerance.
fn normal_tol(miss: f64) -> f64 {
    (NORMAL_TOL_PER_MISS * miss).clamp(NormalParams::default().tol, LOOSEST_NORMAL_TOL)
}

/// How a height search ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stop {
    /// The relative force miss it accepts.
    pub tol: f64,
    /// Whether the height it accepts is evaluated to the full normal tolerance; else a trial
    /// height solved loosely whose force is within `tol` ends it as it is (a search whose answer
    /// only sets the next round's target: the first of a prescribed force's rounds).
    pub exact: bool,
}

impl Stop {
    /// Within `tol`, the height accepted evaluated to the full normal tolerance.
    pub fn exact(tol: f64) -> Stop {
        Stop { tol, exact: true }
    }
}

/// The height z where `force(z, normal_tol)` (≥ 0, increasing in z; its normal problems solved to
/// `normal_tol`) equals `target_n` within `stop.tol` (relative), from the height of first touch
/// `z_touch`, or from two earlier evaluations `start` (a search for a nearby target); returns the
/// height, the number of evaluations and the last two. The height returned was evaluated last,
/// to the full normal tolerance where `stop.exact`.
pub fn solve<F>(
    z_touch_mm: f64,
    target_n: f64,
    stop: Stop,
    start: Option<Evaluations>,
    mut force: F,
) -> Result<(f64, usize, Evaluations), WheelRailError>
where
    F: FnMut(f64, f64) -> Result<f64, WheelRailError>,
{
    let tol = stop.tol;
    let g = |f: f64| f.max(0.0).powf(2.0 / 3.0) - target_n.powf(2.0 / 3.0);
    let full = NormalParams::default().tol;
    let mut evaluations = 0;
    // The closest relative miss of the target so far; whether trial heights may be solved loosely
    // (not after a step that failed to halve the miss: the loose forces' error may be in the way).
    let mut miss = f64::INFINITY;
    let mut loose = true;
    let (mut z0, mut g0, mut z1, mut g1, mut f1) = match start {
        Some([(za, fa), (zb, fb)]) if g(fa) != g(fb) => (za, g(fa), zb, g(fb), fb),
        _ => {
            let z1 = z_touch_mm + FIRST_STEP_MM;
            let f1 = force(z1, normal_tol(miss))?;
            evaluations += 1;
            (z_touch_mm, g(0.0), z1, g(f1), f1)
        }
    };
    miss = miss.min((f1 - target_n).abs() / target_n);
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
            let f = force(z, full)?;
            return Ok((z, evaluations + 1, [(z1, f1), (z, f)]));
        }
        let z2 = next_height(z1 - g1 * (z1 - z0) / (g1 - g0), below, above, z_touch_mm);
        let step_tol = if loose { normal_tol(miss) } else { full };
        let mut f2 = force(z2, step_tol)?;
        evaluations += 1;
        if stop.exact && step_tol > full && (f2 - target_n).abs() <= tol * target_n {
            // Met on a loose solve: the same height to the full tolerance decides.
            f2 = force(z2, full)?;
            evaluations += 1;
        }
        let miss2 = (f2 - target_n).abs() / target_n;
        loose &= miss2 <= 0.5 * miss;
        miss = miss.min(miss2);
        (z0, g0, f0, z1, g1, f1) = (z1, g1, f1, z2, g(f2), f2);
        if (f2 - target_n).abs() <= tol * target_n {
            return Ok((z1, evaluations, [(z0, f0), (z1, f1)]));
        }
    }
    Err(WheelRailError::VerticalNotConverged { fz_n: target_n, z_mm: z1 })
}

/// The next trial height from the secant's `z_mm`: that where it falls strictly between the
/// highest height known below the target (at least first touch `z_touch_mm`, where the force is
/// zero) and the lowest known above it; else their midpoint, or, with none known above, the one
/// below stepped twice as far from first touch. The secant leaves them where the force is flat or
/// falls: an approximate normal problem's force stays level while its contact gains no element,
/// and drops where two patches merge into one.
fn next_height(z_mm: f64, below: f64, above: f64, z_touch_mm: f64) -> f64 {
    let below = below.max(z_touch_mm);
    if z_mm > below && z_mm < above {
        z_mm
    } else if above.is_finite() {
        0.5 * (below + above)
    } else {
        below + 2.0 * (below - z_touch_mm).max(FIRST_STEP_MM)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_height_of_a_hertzian_law() {
        // F = k (z − z0)^1.5: the secant on F^(2/3) is exact after one step.
        let (k, z_touch) = (2.0e6, 0.18);
        let (z, _, _) =
            solve(z_touch, 10000.0, Stop::exact(FORCE_TOL), None, |z, _| Ok(k * (z - z_touch).max(0.0).powf(1.5)))
                .unwrap();
        assert!((z - (z_touch + (10000.0f64 / k).powf(2.0 / 3.0))).abs() < 1e-12);
    }

    #[test]
    fn a_force_that_stays_zero_past_the_first_trial_is_stepped_through_not_extrapolated_to_infinity() {
        // An approximate normal problem may carry nothing until the wheel is 0.03 mm below first
        // touch: the first trial (0.01 mm) gives zero force, the secant through it and first
        // touch is flat, and its step was infinite (a NaN height, the contact search then hung).
        let (k, z_touch, dead) = (2.0e6, 0.18, 0.03);
        let law = |z: f64| k * (z - z_touch - dead).max(0.0).powf(1.5);
        let mut heights = Vec::new();
        let (z, _, _) = solve(z_touch, 10000.0, Stop::exact(FORCE_TOL), None, |z, _| {
            heights.push(z);
            Ok(law(z))
        })
        .unwrap();
        assert!(heights.iter().all(|z| z.is_finite()), "{heights:?}");
        assert!((law(z) - 10000.0).abs() <= FORCE_TOL * 10000.0);
    }

    #[test]
    fn a_secant_that_leaves_the_known_heights_is_not_followed() {
        let (touch, inf) = (0.1, f64::INFINITY);
        // Inside the heights known below and above the target: the secant's.
        assert!((next_height(0.15, 0.12, 0.2, touch) - (0.15)).abs() < 1e-15);
        // Bracketed, the secant outside: the midpoint.
        assert!((next_height(0.25, 0.12, 0.2, touch) - (0.16)).abs() < 1e-15);
        // Nothing known above, the secant stepping back below a height known to carry too little
        // (KPEC where its patches merge, the force falling): twice as far from first touch.
        assert!((next_height(0.11, 0.15, inf, touch) - (0.15 + 2.0 * 0.05)).abs() < 1e-15);
        // Nothing known below but first touch, the secant stepping up past a height known to
        // carry too much (the force falling as the wheel sinks): halfway down to first touch.
        assert!((next_height(0.3, f64::NEG_INFINITY, 0.2, touch) - (0.15)).abs() < 1e-15);
        // A flat secant (equal forces) has no step: on past the highest height known below.
        assert!((next_height(f64::INFINITY, 0.105, inf, touch) - (0.105 + 2.0 * FIRST_STEP_MM)).abs() < 1e-15);
        assert!((next_height(f64::NAN, 0.12, 0.2, touch) - (0.16)).abs() < 1e-15);
    }

    #[test]
    fn a_nearby_target_from_earlier_evaluations_takes_one_step_on_a_hertzian_law_confirmed_to_the_full_tolerance() {
        let (k, z_touch) = (2.0e6, 0.18);
        let law = |z: f64| k * (z - z_touch).max(0.0).powf(1.5);
        let (_, _, last) = solve(z_touch, 10000.0, Stop::exact(FORCE_TOL), None, |z, _| Ok(law(z))).unwrap();
        // One step, solved loosely (the miss before it is 1e-3), then the same height solved to
        // the full normal tolerance, which accepts it.
        let mut calls = Vec::new();
        let (z, n, _) = solve(z_touch, 9990.0, Stop::exact(FORCE_TOL), Some(last), |z, tol| {
            calls.push((z, tol));
            Ok(law(z))
        })
        .unwrap();
        assert_eq!(n, 2);
        assert_eq!(calls.len(), 2);
        assert_eq!(calls[0].0, calls[1].0);
        assert!(calls[0].1 > NormalParams::default().tol);
        assert_eq!(calls[1].1, NormalParams::default().tol);
        assert!((z - (z_touch + (9990.0f64 / k).powf(2.0 / 3.0))).abs() < 1e-12);
    }

    #[test]
    fn an_inexact_stop_ends_on_the_loose_trial_that_meets_it() {
        let (k, z_touch) = (2.0e6, 0.18);
        let law = |z: f64| k * (z - z_touch).max(0.0).powf(1.5);
        let (_, _, last) = solve(z_touch, 10000.0, Stop::exact(FORCE_TOL), None, |z, _| Ok(law(z))).unwrap();
        let mut tols = Vec::new();
        let (z, n, _) = solve(z_touch, 9990.0, Stop { tol: 1e-3, exact: false }, Some(last), |z, tol| {
            tols.push(tol);
            Ok(law(z))
        })
        .unwrap();
        assert_eq!((n, tols.len()), (1, 1));
        assert!(tols[0] > NormalParams::default().tol);
        assert!((law(z) - 9990.0).abs() <= 1e-3 * 9990.0);
    }
}
