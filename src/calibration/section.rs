//! The report's "Calibration" section (issue 14): each stored fit (`<results>/fits/*.json`,
//! written by `creepbench run` from `fits/`) with its fitted values and its before/after errors
//! on the fitted and the held-out scenes. Reads stored results only.

use crate::calibration::fit::record::{CurveRecord, FitRecord};
use crate::report::plot::style::FITTED;
use crate::report::plot::{line_chart, titles, Axis, Series};
use crate::report::section::Section;
use std::fmt::Write;

/// The section's id (it follows the model ladder: [`crate::report::registry::insert_after`]).
pub const ID: &str = "calibration";

/// The section, if any fit was stored.
pub fn section(records: &[FitRecord]) -> Option<Section> {
    if records.is_empty() {
        return None;
    }
    let mut body = String::from(
        "Free parameters of a model fitted with `creepbench fit` (Nelder–Mead, argmin) to a target's histories on some scenes, and judged with the fitted values on scenes it was not fitted on (held out). Norms: RMS and max of |Δf| over every row, RMS of the delay-ratio difference and of the relative loop-area difference over the sine scenes. A fitted block is a scene `[model]` table: `creepbench fit FILE --out F` writes it.\n",
    );
    let mut figures = Vec::new();
    for r in records {
        let _ = write!(
            body,
            "\n**{}** ({}): `{}` against `{}`, minimising {}; {} iterations, {} evaluations, ended: {}.\n\n",
            r.name, r.file, r.model, r.against, r.norm, r.iterations, r.evaluations, r.ended
        );
        for line in r.param_lines() {
            let _ = writeln!(body, "- {line}");
        }
        let _ = writeln!(body, "- fitted on: {}", r.fitted.join(", "));
        if !r.held_out.is_empty() {
            let _ = writeln!(body, "- held out: {}", r.held_out.join(", "));
        }
        body.push('\n');
        body.push_str(&r.table());
        let beside = r.suite_table();
        if !beside.is_empty() {
            let _ = write!(
                body,
                "\nThe fitted variant beside the published `{}` on every scene of the suites that runs it with the exact theory (|Δf| against `contact`, the same rows; the model ladder's published rows):\n\n{beside}",
                r.model
            );
        }
        if !r.curves.is_empty() {
            let _ = writeln!(
                body,
                "\n`{m}` at the start values and `{m}{FITTED}` (dotted, outlined) against the target, on the fitted scenes and on the held-out scene the fitted values carry worst (largest RMS |Δf|):\n",
                m = r.model
            );
        }
        for c in &r.curves {
            let file = format!("fit_{}_{}.svg", r.name, c.scene);
            figures.push((file.clone(), figure(r, c)));
            let _ = writeln!(body, "![{} on {}](figures/{file})", r.name, c.scene);
        }
    }
    Some(Section { id: ID, figures, ..Section::new("Calibration: fitted parameters and how far they carry", body) })
}

/// One scene's before/after figure: the target (CONTACT's points, or the target solver's line),
/// the model at the start values and the fitted variant.
fn figure(r: &FitRecord, c: &CurveRecord) -> String {
    let target = match r.against.strip_prefix("solver:") {
        Some(solver) => Series::model(solver, c.target.clone()),
        None => Series::reference("CONTACT", c.target.clone()),
    };
    let series = [
        target,
        Series::model(&r.model, c.before.clone()),
        Series::model(format!("{}{FITTED}", r.model), c.after.clone()),
    ];
    let title = format!("{}: {} ({}) — before and after the fit", r.name, c.scene, c.set);
    line_chart(&title, &Axis::linear(titles::of(&c.x)), &Axis::linear(titles::of(&c.y)), &series)
}
