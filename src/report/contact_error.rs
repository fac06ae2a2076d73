//! The report's section of the worst error against CONTACT per scene and solver, where a scene
//! has CONTACT's history.

use crate::comparison::compare::Finding;
use crate::comparison::references::contact::{self, ContactCases};
use crate::report::linked_table::{self, Table};
use crate::report::{Report, ReportInput};
use crate::suite::results::StoredScene;
use std::fmt::Write;

/// The section's title.
const TITLE: &str = "Error against CONTACT, worst step per scene and solver";

/// A solver's largest error against CONTACT: the error, the table row it is in and its scene.
type Largest<'a> = Option<(f64, usize, &'a str)>;

/// Section: max |f − f_CONTACT| per scene and solver; a long table moves to its linked file and
/// keeps inline the rows of each solver's largest error and of any gated miss.
pub fn worst_per_scene(body: &mut Report, input: &ReportInput, solvers: &[String]) {
    let contact = input.refs.get::<ContactCases>(contact::EXACT);
    let scenes: Vec<&StoredScene> =
        input.scenes.iter().filter(|sc| contact.and_then(|c| c.history(&sc.name)).is_some()).collect();
    if scenes.is_empty() {
        return;
    }
    let _ = writeln!(body.markdown, "## {TITLE}\n\nmax |f − f_CONTACT| over every step (sweeps: every creepage point), f = Fx/FN. Gated for `contact` (≤ 1e-5) and, on `steady_fastsim_g22`, for `fastsim` and `uba` (≤ 0.0015); the simplified models are reported.\n");
    let (table, largest, mut keep) = table(&scenes, input.findings, solvers);
    let summary = summary(&table, solvers, &largest);
    keep.extend(largest.iter().flatten().map(|l| l.1));
    keep.sort_unstable();
    let placed = linked_table::place(
        "error_against_contact",
        TITLE,
        &table,
        &summary,
        &keep,
        "The rows of each solver's largest error and of any gated miss",
    );
    let _ = writeln!(body.markdown, "{}", placed.inline);
    body.tables.extend(placed.file);
}

/// The table (a row per scene, an error and its step per solver), each solver's largest error and
/// the rows with a gated miss (✗).
fn table<'a>(
    scenes: &[&'a StoredScene],
    findings: &[Finding],
    solvers: &[String],
) -> (Table, Vec<Largest<'a>>, Vec<usize>) {
    let mut cols = vec!["scene"];
    for s in solvers {
        cols.extend([s.as_str(), "step"]);
    }
    let mut table = Table::new(&cols);
    let mut largest: Vec<Largest> = vec![None; solvers.len()];
    let mut misses = Vec::new();
    for &sc in scenes {
        let at = table.rows.len();
        let mut row = format!("| {} |", sc.name);
        for (k, s) in solvers.iter().enumerate() {
            let Some(f) = finding(findings, &sc.name, s) else {
                row.push_str(" — | |");
                continue;
            };
            let miss = f.gated && !f.passed();
            if miss {
                misses.push(at);
            }
            if largest[k].is_none_or(|(d, _, _)| f.diff > d) {
                largest[k] = Some((f.diff, at, &sc.name));
            }
            let mark = if miss { " ✗" } else { "" };
            let _ = write!(row, " {}{mark} | {} |", diff(f.diff), f.step.map(|k| k.to_string()).unwrap_or_default());
        }
        table.rows.push(row);
    }
    (table, largest, misses)
}

/// The finding of `solver` in `scene` against CONTACT on f = Fx/FN, if any.
fn finding<'a>(findings: &'a [Finding], scene: &str, solver: &str) -> Option<&'a Finding> {
    findings
        .iter()
        .find(|f| f.scene == scene && f.solver == solver && f.against.is_contact() && f.quantity == "fx_over_fn")
}

/// The summary line: the number of scenes and each solver's largest error and its scene.
fn summary(table: &Table, solvers: &[String], largest: &[Largest]) -> String {
    let per_solver: Vec<String> = solvers
        .iter()
        .zip(largest)
        .filter_map(|(s, l)| {
            let (d, _, scene) = (*l)?;
            Some(format!("`{s}` {} (`{scene}`)", diff(d)))
        })
        .collect();
    format!("{} scenes; the largest per solver: {}.", table.rows.len(), per_solver.join(", "))
}

/// An error as shown: in exponent form below 1e-3, else with four decimals.
fn diff(d: f64) -> String {
    if d < 1e-3 {
        format!("{d:.1e}")
    } else {
        format!("{d:.4}")
    }
}
