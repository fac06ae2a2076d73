//! A wheel–rail case on a massless rail (CONTACT's F = 3; user guide "Massless rail model", its
//! `wr_contact_fy_brent`): the rail deflects by δy, δz on springs until
//!
//!   F_y − k_y δy + F*_y = 0,    F_z(tr) − k_z δz + F*_z = 0,
//!
//! F_y the contact force on the rail as CONTACT prints it, FY(TR) in the track's y on either side
//! (`get_f_toty`: sgn F_y of the side's mirrored frame), δy along the side's own y as the rail's DY,
//! δz downwards, each added to the rail's deviation (`wr_set_rail_marker`): on the left wheel not
//! the right one's mirror. δy is found by a secant ([`root`]), each trial a whole case. With FZ
//! prescribed (N = 1) δz follows from the second equation at F_z(tr) = FZ. With the wheelset's
//! height given (N = 0) δz is found inside each trial by a secant on F_z: the case solved for
//! FZ = F_z on the rail at its design height gives the wheelset's height over it, z(F_z); only the
//! difference of the two heights places the wheel on the rail, so δz = z_ws − z(F_z), until
//! F_z = k_z δz − F*_z. The case is then solved once more, with every model, on the deflected rail.

use super::wheelrail::{solve_with, CaseResult, EXACT};
use crate::error::{Error, InputError};
use crate::scene::wheelrail_massless::MasslessRailSpec;
use crate::wheelrail::friction::Friction;
use crate::wheelrail::{Vertical, WheelRailCase};

/// Each balance's tolerance relative to the forces in it.
const TOL: f64 = 1e-8;
/// Most trials of each search.
const MAX_TRIALS: usize = 60;

/// Solve `case` with `models` on the massless rail `rail`: the deflection found, then every model
/// on the deflected rail.
pub fn solve_massless(
    case: &WheelRailCase,
    models: &[String],
    mu: &Friction,
    rail: &MasslessRailSpec,
) -> Result<CaseResult, Error> {
    let mut fz_guess_n = None;
    let lateral = |dy_mm: f64| -> Result<Trial<f64>, Error> {
        let (dz_mm, r) = vertical_balance(&deflected(case, dy_mm, 0.0), rail, &mut fz_guess_n, mu)?;
        // FY(TR) as printed: on the left wheel not turned into the side's own y (CONTACT's
        // `get_f_toty`; issue 45: the left massless rail deflected to the wrong side).
        let fy_n = r.models[0].2.track_n[1];
        let residual = fy_n - rail.ky_n_per_mm * dy_mm + rail.fy_n;
        Ok(Trial { residual, tol: TOL * (fy_n.abs() + rail.fy_n.abs()).max(1.0), payload: dz_mm })
    };
    // CONTACT's first step: DYSTEP0 towards the balance (the spring's force falls as δy grows).
    let first = |r: f64| rail.dy_step_mm * r.signum();
    let (dy_mm, dz_mm) = root(lateral, 0.0, first, f64::NEG_INFINITY).map_err(|e| e.on("ky_n_per_mm", "lateral"))?;
    let mut result = solve_with(&deflected(case, dy_mm, dz_mm), models, mu)?;
    result.rail_deflection_mm = Some([dy_mm, dz_mm]);
    Ok(result)
}

/// The case on the rail deflected further by `dy_mm` (the side's own y, as the rail's DY: CONTACT
/// places the rail at sgn (DY + DY_DEFL), `wr_set_rail_marker`) and `dz_mm` (downwards).
fn deflected<'a>(case: &WheelRailCase<'a>, dy_mm: f64, dz_mm: f64) -> WheelRailCase<'a> {
    let mut out = *case;
    // The case's deviation is the right-side frame's (the scene's DY times the side's sign).
    out.track.deviation_mm_rad[0] += case.side.sign() * dy_mm;
    out.track.deviation_mm_rad[1] += dz_mm;
    out
}

/// The vertical deflection δz of `case` (its rail deflected laterally already) and the exact
/// theory's solution with it: with FZ prescribed δz = (FZ + F*_z) / k_z (0 without a vertical
/// spring); with the height given, the secant on F_z of the module's doc, from the F_z of the last
/// lateral trial (`fz_guess_n`, updated).
fn vertical_balance(
    case: &WheelRailCase,
    rail: &MasslessRailSpec,
    fz_guess_n: &mut Option<f64>,
    mu: &Friction,
) -> Result<(f64, CaseResult), Error> {
    let exact = [EXACT.to_string()];
    if let Vertical::Force { fz_n } = case.vertical {
        let dz_mm = if rail.kz_n_per_mm > 0.0 { (fz_n + rail.fz_n) / rail.kz_n_per_mm } else { 0.0 };
        return Ok((dz_mm, solve_with(&deflected(case, 0.0, dz_mm), &exact, mu)?));
    }
    let z_ws_mm = case.pose.z_mm;
    let balance = |fz_n: f64| -> Result<Trial<(f64, CaseResult)>, Error> {
        let r = solve_with(&WheelRailCase { vertical: Vertical::Force { fz_n }, ..*case }, &exact, mu)?;
        let dz_mm = z_ws_mm - r.normal.z_ws_mm;
        let residual = fz_n - rail.kz_n_per_mm * dz_mm + rail.fz_n;
        Ok(Trial { residual, tol: TOL * fz_n, payload: (dz_mm, r) })
    };
    // A first F_z that pushes the rail down by F*_z alone where F*_z pulls it up (F*_z < 0).
    let start = fz_guess_n.unwrap_or(if rail.fz_n < 0.0 { -rail.fz_n } else { rail.kz_n_per_mm });
    // The residual grows with F_z at least as fast as F_z: Newton's step on slope 1 is the
    // longest (kept above zero by `root`).
    let first = |r: f64| -r;
    let (fz_n, (dz_mm, r)) = root(balance, start, first, 0.0).map_err(|e| e.on("kz_n_per_mm", "vertical"))?;
    *fz_guess_n = Some(fz_n);
    Ok((dz_mm, r))
}

/// One evaluation of a balance: its residual [N], the tolerance it is met within, and what else
/// the trial gave.
struct Trial<T> {
    residual: f64,
    tol: f64,
    payload: T,
}

/// Why a search stopped without a balance.
enum Failed {
    /// A trial's case failed (no contact, no height, …).
    Case(Error),
    /// No trial met the tolerance; the last trial's position.
    Trials(f64),
}

impl Failed {
    /// The error a user reads, naming the spring of the balance.
    fn on(self, key: &str, which: &str) -> Error {
        match self {
            Failed::Case(e) => e,
            Failed::Trials(x) => InputError::new(
                format!("massless_rail.{key}"),
                x,
                format!("springs whose {which} balance with the contact forces is found within {MAX_TRIALS} trials (CONTACT's F = 3)"),
            )
            .into(),
        }
    }
}

/// The x where `f`'s residual vanishes (within its trial's tolerance) and the payload there, from
/// `x0`: the first step `first(residual)`, then secants; once the residual has changed sign,
/// within that bracket (regula falsi with the Illinois halving, a bisection where a secant leaves
/// it). Every x stays above `lower` (a step that would cross it goes a quarter of the way). A trial
/// whose case fails (a patch beyond the profiles, no contact) is tried again halfway back towards
/// the last good one (from `x0`, towards `lower`).
fn root<T>(
    mut f: impl FnMut(f64) -> Result<Trial<T>, Error>,
    x0: f64,
    first: impl Fn(f64) -> f64,
    lower: f64,
) -> Result<(f64, T), Failed> {
    let (mut x1, mut t1) = towards(&mut f, x0, lower)?;
    let (mut x_prev, mut r_prev) = (f64::NAN, f64::NAN);
    // The bracket's other end (x, residual) once the residual has changed sign.
    let mut other: Option<(f64, f64)> = None;
    for _ in 0..MAX_TRIALS {
        if t1.residual.abs() <= t1.tol {
            return Ok((x1, t1.payload));
        }
        let r1 = t1.residual;
        let mut next = match other {
            Some((xb, rb)) => {
                let secant = x1 - r1 * (x1 - xb) / (r1 - rb);
                let (lo, hi) = (x1.min(xb), x1.max(xb));
                if secant > lo && secant < hi {
                    secant
                } else {
                    0.5 * (lo + hi)
                }
            }
            None if x_prev.is_nan() => x1 + first(r1),
            None => x1 - r1 * (x1 - x_prev) / (r1 - r_prev),
        };
        if !next.is_finite() {
            next = x1 + first(r1);
        }
        if next <= lower {
            next = lower + 0.25 * (x1 - lower);
        }
        let (next, t) = towards(&mut f, next, x1)?;
        other = match other {
            // Keep the end whose residual has the other sign; halve a kept end's residual
            // (Illinois) so that it does not stick.
            Some((xb, rb)) if (t.residual > 0.0) == (r1 > 0.0) => Some((xb, 0.5 * rb)),
            Some(_) => Some((x1, r1)),
            None if (t.residual > 0.0) != (r1 > 0.0) => Some((x1, r1)),
            None => None,
        };
        (x_prev, r_prev) = (x1, r1);
        (x1, t1) = (next, t);
    }
    Err(Failed::Trials(x1))
}

/// Times a failed trial is tried again closer to a good one.
const RETRIES: usize = 8;

/// The trial at `x`, or where its case fails, at points halfway back towards `good` (a finite
/// position where a trial succeeded or may), [`RETRIES`] times at most.
fn towards<T>(
    f: &mut impl FnMut(f64) -> Result<Trial<T>, Error>,
    mut x: f64,
    good: f64,
) -> Result<(f64, Trial<T>), Failed> {
    let mut retries = 0;
    loop {
        match f(x) {
            Ok(t) => return Ok((x, t)),
            Err(e) if retries == RETRIES || !good.is_finite() => return Err(Failed::Case(e)),
            Err(_) => {
                x = 0.5 * (x + good);
                retries += 1;
            }
        }
    }
}
