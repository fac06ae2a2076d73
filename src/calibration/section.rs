//! The report's "Calibration" section (issue 14): each stored fit (`<results>/fits/*.json`,
//! written by `creepbench run` from `fits/`) with its fitted values and its before/after errors
//! on the fitted and the held-out scenes. Reads stored results only.

use crate::calibration::fit::record::FitRecord;
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
    }
    Some(Section { id: ID, ..Section::new("Calibration: fitted parameters and how far they carry", body) })
}
