//! The report's table of what each scene left out: the built-in solvers it did not run and the
//! metrics it did not compute.

use crate::report::linked_table::{self, Table};
use crate::report::Report;
use crate::suite::results::StoredScene;
use std::fmt::Write;

/// The section's title.
const TITLE: &str = "What each scene left out";

/// Section: a row per scene (a long table moves to its linked file), and how many scenes ran
/// every built-in model.
pub fn by_scene(body: &mut Report, scenes: &[StoredScene]) {
    let _ = writeln!(body.markdown, "## {TITLE}\n\nOnly what a scene lists is computed: solvers it does not name are not run, metrics that do not fit its creepage are not computed.\n");
    let mut table = Table::new(&["scene", "solvers not run", "metrics left out"]);
    let mut ran_all = 0;
    for sc in scenes {
        let (row, ran_every_model) = row(sc);
        ran_all += usize::from(ran_every_model);
        table.rows.push(row);
    }
    let summary = format!("{} scenes, {ran_all} of them ran every built-in model.", table.rows.len());
    let placed = linked_table::place("left_out", TITLE, &table, &summary, &[], "");
    let _ = write!(body.markdown, "{}", placed.inline);
    body.tables.extend(placed.file);
}

/// A scene's row (the built-in solvers not run, the metrics left out and why), and whether it ran
/// every built-in model.
fn row(sc: &StoredScene) -> (String, bool) {
    let ran: Vec<&str> = sc.histories.keys().map(String::as_str).collect();
    let not_run: Vec<&str> = crate::solvers::builtin_names().into_iter().filter(|s| !ran.contains(s)).collect();
    let skipped: Vec<String> = sc.scene.skipped_metrics.iter().map(|(m, why)| format!("{m} ({why})")).collect();
    let row = format!(
        "| {} | {} | {} |",
        sc.name,
        if not_run.is_empty() { "—".into() } else { not_run.join(", ") },
        if skipped.is_empty() { "—".into() } else { skipped.join("; ") }
    );
    (row, not_run.is_empty())
}
