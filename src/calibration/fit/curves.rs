//! A fit's curves for the calibration section's figures: on each fitted scene and on the held-out
//! scene the fitted values carry worst, the target's f against the scene's abscissa beside the
//! model's at the start values (before) and at the fitted values (after).

use super::objective::Case;
use super::record::CurveRecord;
use crate::comparison::model_error::{rms, row_diffs};
use crate::error::Error;
use crate::history::abscissa::{abscissa, Drawn};
use crate::history::History;
use crate::problem::Problem;
use rayon::prelude::*;
use toml::Value;

/// The `[set]` keys with their values (`FitSpec::assignments`).
type Set = [(String, Value)];

/// The model's runs on one scene before and after, with the problem they were resolved into.
struct Runs {
    problem: Problem,
    before: History,
    after: History,
}

/// The curves of the fitted scenes (all, in order) and of the held-out scene whose RMS |Δf|
/// against the target is largest after the fit (none without held-out scenes). `before` and
/// `after` are the `[set]` keys at the start and at the fitted values.
pub fn curves(
    model: &str,
    (fitted, held_out): (&[Case], &[Case]),
    (before, after): (&Set, &Set),
) -> Result<Vec<CurveRecord>, Error> {
    let run = |cases: &[Case]| -> Result<Vec<Runs>, Error> {
        cases
            .par_iter()
            .map(|c| {
                let (problem, before) = c.run(model, before)?;
                Ok(Runs { problem, before, after: c.run(model, after)?.1 })
            })
            .collect()
    };
    let mut out: Vec<CurveRecord> = fitted.iter().zip(run(fitted)?).map(|(c, r)| record(c, &r, "fitted")).collect();
    let held = run(held_out)?;
    let worst = held
        .iter()
        .zip(held_out)
        .map(|(r, c)| rms(row_diffs(&r.after, c.target()).into_iter().filter(|d| d.is_finite())))
        .enumerate()
        .filter(|(_, e)| e.is_finite())
        .fold(
            None,
            |best: Option<(usize, f64)>, (k, e)| if best.is_some_and(|b| b.1 >= e) { best } else { Some((k, e)) },
        );
    if let Some((k, _)) = worst {
        out.push(record(&held_out[k], &held[k], "held out"));
    }
    Ok(out)
}

/// One scene's record: f is fx/fn unless the target's fy/fn is the larger in magnitude.
fn record(case: &Case, runs: &Runs, set: &str) -> CurveRecord {
    let target = case.target();
    let largest = |col: &str| target.column(col).unwrap_or_default().iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let y = if largest("fy_over_fn") > largest("fx_over_fn") { "fy_over_fn" } else { "fx_over_fn" };
    let drawn = Drawn::of_problem(&runs.problem);
    let points = |h: &History| -> Vec<(f64, f64)> {
        let (_, x) = abscissa(h, drawn);
        // Finite points only: the record is JSON, which has no NaN.
        x.into_iter().zip(h.column(y).unwrap_or_default()).filter(|p| p.0.is_finite() && p.1.is_finite()).collect()
    };
    CurveRecord {
        scene: case.name.clone(),
        set: set.into(),
        x: abscissa(target, drawn).0.into(),
        y: y.into(),
        target: points(target),
        before: points(&runs.before),
        after: points(&runs.after),
    }
}
