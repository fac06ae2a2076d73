//! A wheel–rail case with the longitudinal force prescribed instead of the pitch velocity
//! (CONTACT's F = 1 with N = 1, user guide "F_1 - FORCE"; its secant iteration on VPITCH with
//! FZ's iteration inside, `wr_contact_fx_secant`): VPITCH is found so that the exact theory's
//! total force on the rail along the wheelset's x, FX(WS), equals the given FX_WS, every trial
//! pitch velocity a whole case with FZ prescribed ([`super::wheelrail::solve_with`]). The other
//! models then solve the patches of that solution, at its creepages (the models compare on the
//! same kinematics; each model's FX(WS) then shows its own error against the given force).

use super::wheelrail::{model_forces, solve_with, CaseResult, Pitch, EXACT};
use crate::error::{Error, InputError};
use crate::solvers;
use crate::wheelrail::friction::Friction;
use crate::wheelrail::{Vertical, WheelRailCase};

/// Tolerance on FX(WS) relative to FZ (CONTACT stops at EPS·μ, 3e-6 in its examples).
pub const FX_TOL: f64 = 1e-8;
/// Most trial pitch velocities.
const MAX_TRIALS: usize = 60;
/// The first step of VPITCH relative to its start (a creepage of 1e-5).
const FIRST_STEP: f64 = 1e-5;
/// The largest step of VPITCH relative to its start (a creepage of 0.5 %).
const MAX_STEP: f64 = 5e-3;
/// How far VPITCH is searched from its start, relative (a creepage of 10 %: far in full slip).
const MAX_CREEP: f64 = 0.1;

/// Solve `case` with FX(WS) = `fx_ws_n`, from the case's pitch velocity as the first estimate
/// (−VS / NOMRAD for a scene); the result's pitch is the one found.
pub fn solve_fx(case: &WheelRailCase, models: &[String], mu: &Friction, fx_ws_n: f64) -> Result<CaseResult, Error> {
    let Vertical::Force { fz_n } = case.vertical else {
        return Err(InputError::new("cases.longitudinal", "\"force\"", "vertical = \"force\" (FZ prescribed)").into());
    };
    let start = case.velocity.vpitch_rad_s;
    let eval = |vpitch: f64| -> Result<(CaseResult, f64), Error> {
        let mut trial = *case;
        trial.velocity.vpitch_rad_s = vpitch;
        let r = solve_with(&trial, &[EXACT.to_string()], mu)?;
        let fx = r.models[0].2.wheelset_n[0];
        Ok((r, fx - fx_ws_n))
    };
    let tol = FX_TOL * fz_n;
    let (mut x1, (mut r1, mut g1)) = (start, eval(start)?);
    let mut x0 = start + FIRST_STEP * start.abs();
    let mut g0 = f64::NAN;
    // The bracket [lo, hi] of VPITCH with residuals of opposite signs, once found.
    let mut bracket: Option<[(f64, f64); 2]> = None;
    let mut largest = (g1 + fx_ws_n).abs();
    for _ in 0..MAX_TRIALS {
        if g1.abs() <= tol {
            let per_fx = if g0.is_finite() && g1 != g0 { (x1 - x0) / (g1 - g0) } else { f64::NAN };
            let largest = r1.normal.patches.iter().max_by(|a, b| a.fn_n.total_cmp(&b.fn_n));
            let mu_largest = largest.map_or(mu.mu, |p| mu.of_patch(p, case));
            let pitch = Pitch::Found { rad_s: x1, per_fx_rad_s_n: per_fx.abs(), mu: mu_largest };
            return finish(r1, pitch, case, models, mu);
        }
        let next = match (g0.is_finite(), bracket) {
            // The first step: a small creepage towards the force.
            (false, _) => x0,
            (true, _) => {
                let secant = x1 - g1 * (x1 - x0) / (g1 - g0);
                let limit = MAX_STEP * start.abs();
                match bracket {
                    Some([(a, _), (b, _)]) => {
                        let (lo, hi) = (a.min(b), a.max(b));
                        if secant.is_finite() && secant > lo && secant < hi {
                            secant
                        } else {
                            0.5 * (lo + hi)
                        }
                    }
                    None if secant.is_finite() && (secant - x1).abs() <= limit => secant,
                    // A flat or wrong-signed secant (full slip): a limited step downhill.
                    None => x1 + limit * (secant - x1).signum() * if secant.is_finite() { 1.0 } else { 0.0 },
                }
            }
        };
        if (next - start).abs() > MAX_CREEP * start.abs() || next == x1 {
            break;
        }
        let (r, g) = eval(next)?;
        largest = largest.max((g + fx_ws_n).abs());
        bracket = match bracket {
            Some([a, b]) => Some(if (g > 0.0) == (a.1 > 0.0) { [(next, g), b] } else { [a, (next, g)] }),
            None if (g > 0.0) != (g1 > 0.0) => Some([(x1, g1), (next, g)]),
            None => None,
        };
        (x0, g0, x1, g1, r1) = (x1, g1, next, g, r);
    }
    Err(InputError::new(
        "fx_ws_n",
        fx_ws_n,
        format!(
            "a force the contact carries: no pitch velocity gives FX(WS) = {fx_ws_n} N within {tol:e} N (the largest found {largest:.1} N; the wheel slides)"
        ),
    )
    .into())
}

/// The solution at the pitch velocity found: the exact theory's forces kept, every other model
/// on its patches.
fn finish(
    exact: CaseResult,
    pitch: Pitch,
    case: &WheelRailCase,
    models: &[String],
    mu: &Friction,
) -> Result<CaseResult, Error> {
    let mut at = *case;
    at.velocity.vpitch_rad_s = pitch.rad_s();
    let (normal, mut computed, mut own_normals) = (exact.normal, exact.models, exact.own_normals);
    let mut out = Vec::with_capacity(models.len());
    for m in models {
        match computed.iter().position(|(name, _, _)| name == m) {
            Some(k) => out.push(computed.swap_remove(k)),
            None if solvers::builtin(m).is_some_and(|d| d.own_normal.is_some()) => {
                let mut theirs = solve_with(&at, std::slice::from_ref(m), mu)?;
                own_normals.append(&mut theirs.own_normals);
                out.append(&mut theirs.models);
            }
            None => {
                let (forces, totals) = model_forces(&normal, m, mu, &at)?;
                out.push((m.clone(), forces, totals));
            }
        }
    }
    Ok(CaseResult { normal, own_normals, models: out, pitch, rail_deflection_mm: None })
}
