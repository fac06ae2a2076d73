//! The report's gate summary: how many gated comparisons failed, and a row per failure.

use crate::comparison::compare::{is_no_baseline, Finding};
use std::fmt::Write;

/// Section: the number of gated comparisons and of failures, then a table of the failures.
pub fn summary(md: &mut String, findings: &[Finding]) {
    let gated = findings.iter().filter(|f| f.gated).count();
    let failed: Vec<&Finding> = findings.iter().filter(|f| f.gated && !f.passed()).collect();
    let _ = writeln!(md, "## Gates\n\n{gated} gated comparisons, {} failed.\n", failed.len());
    if failed.is_empty() {
        return;
    }
    let _ = writeln!(md, "| scene | solver | against | quantity | step | ours | theirs | allowed | note |\n|---|---|---|---|---|---|---|---|---|");
    for f in failed {
        let _ = writeln!(md, "{}", row(f));
    }
    md.push('\n');
}

/// A failed gate's row: scene, solver, reference, quantity, step, our and their values, allowed, note.
fn row(f: &Finding) -> String {
    // A scene without a baseline has no values to show: its note says so, once.
    let values = if is_no_baseline(f) {
        "— | — | —".to_string()
    } else {
        format!("{:.6} | {:.6} | {:.1e}", f.ours, f.theirs, f.allowed)
    };
    format!(
        "| {} | {} | {} | {} | {} | {values} | {} |",
        f.scene,
        f.solver,
        f.against.label(),
        f.quantity,
        f.step.map(|s| s.to_string()).unwrap_or_default(),
        f.note
    )
}
