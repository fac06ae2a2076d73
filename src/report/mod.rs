//! The Markdown validation report with SVG plots (reports/validation.md, reports/figures/).
//! Built from stored result folders only, so shards merge into one report. Stage 8 of the stack
//! (below it: the comparison's findings and the reference sets; above it: calibration).

mod contact_error;
pub mod contact_public;
pub mod contact_wheelrail;
pub mod envelope;
pub mod falling;
mod gates;
mod groups;
pub mod ladder;
mod left_out;
pub mod linked_table;
pub mod plot;
pub mod registry;
pub mod section;
pub mod sections;
mod sines;
pub mod studies;
pub mod table;
pub mod timed;
pub mod wheelrail;
mod wheelrail_focus;
pub mod work_precision;

use crate::comparison::compare::Finding;
use crate::comparison::references::wheelrail_cases::GAP_SUFFIX;
use crate::comparison::references::References;
use crate::error::Error;
use crate::report::section::Section;
use crate::safety::{folder, whole};
use crate::suite::results::StoredScene;
pub use linked_table::anchor;
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::Path;

/// Everything the report shows: stored results and reference data only.
pub struct ReportInput<'a> {
    pub scenes: &'a [StoredScene],
    pub refs: &'a References,
    pub findings: &'a [Finding],
    /// The suite of every scene of the run, wheel–rail scenes included (scene → suite folder).
    pub suites: &'a BTreeMap<String, String>,
    /// Sections computed from the stored scenes (thesis figures beside ours, stability, timing).
    pub sections: Vec<Section>,
}

/// The report in memory: validation.md, its figures (file name, SVG) and its long tables (file
/// name, Markdown; [`linked_table`]).
pub struct Report {
    pub markdown: String,
    pub figures: Vec<(String, String)>,
    pub tables: Vec<(String, String)>,
}

/// The report's folder of figures.
pub const FIGURES: &str = "figures";

/// An error if any file or folder [`Report::write`] writes under `dir` could not be written:
/// inside `protected` (also through a link), or a folder this tool did not write. Asked before
/// any work (issue 48 item 4).
pub fn check_outputs(dir: &Path, protected: &Path) -> Result<(), Error> {
    for sub in [FIGURES, linked_table::DIR] {
        let path = dir.join(sub);
        crate::safety::guard::guard_output_dir(&path, protected)?;
        folder::check_tree_replaceable(&path).map_err(|e| {
            crate::error::InputError::new(
                "--report",
                path.display(),
                format!("none yet, or a folder creepbench wrote ({e})"),
            )
        })?;
    }
    crate::safety::guard::guard_output_file(&dir.join("validation.md"), protected)?;
    crate::safety::guard::guard_output_file(&dir.join(table::FILE), protected)?;
    Ok(())
}

impl Report {
    /// Write `dir/figures/*.svg` and `dir/tables/*.md`, each folder replaced whole and atomically
    /// (and only a folder creepbench wrote: `safety::folder`), then `dir/validation.md`, written
    /// whole — so the report never links to a half-written folder.
    pub fn write(&self, dir: &Path) -> Result<(), Error> {
        for (sub, files) in [(FIGURES, &self.figures), (linked_table::DIR, &self.tables)] {
            folder::replace_tree_atomically(&dir.join(sub), |new: &Path| -> Result<(), Error> {
                for (file, text) in files {
                    let path = new.join(file);
                    std::fs::write(&path, text).map_err(Error::io(&path))?;
                }
                Ok(())
            })?;
        }
        let md = dir.join("validation.md");
        whole::write(&md, self.markdown.as_bytes()).map_err(Error::io(&md))
    }
}

/// The one-screen verdict: gated comparisons and failures per suite, and the worst gated points.
fn verdict(input: &ReportInput) -> String {
    let mut per: BTreeMap<&str, (usize, usize)> = BTreeMap::new();
    for f in input.findings.iter().filter(|f| f.gated) {
        let e = per.entry(input.suites.get(&f.scene).map_or("(no suite)", String::as_str)).or_default();
        e.0 += 1;
        e.1 += usize::from(!f.passed());
    }
    let failed: usize = per.values().map(|v| v.1).sum();
    let mut out = format!(
        "## Verdict\n\n**{}**: {} gated comparisons, {failed} failed.\n\n| suite | gated | failed |\n|---|---|---|\n",
        if failed == 0 { "All gates pass" } else { "GATES FAIL" },
        per.values().map(|v| v.0).sum::<usize>()
    );
    for (suite, (gated, fails)) in &per {
        let _ = writeln!(out, "| {suite} | {gated} | {fails} |");
    }
    // A declared gap's case is bounded at its own measured worst value, so it sits at 1.00 by
    // construction: counted apart, the list shows the comparisons that hold to their rules.
    let gap = |f: &&Finding| f.quantity.ends_with(GAP_SUFFIX);
    let in_gaps = input.findings.iter().filter(|f| f.gated).filter(gap).count();
    if in_gaps > 0 {
        let _ = writeln!(
            out,
            "\n{in_gaps} of the gated comparisons are of declared-gap cases, each case bounded at its measured worst value and listed with its cause under [{title}](#{}).",
            anchor(contact_wheelrail::TITLE),
            title = contact_wheelrail::TITLE
        );
    }
    let mut worst: Vec<&Finding> =
        input.findings.iter().filter(|f| f.gated && f.allowed > 0.0).filter(|f| !gap(f)).collect();
    worst.sort_by(|a, b| b.severity().total_cmp(&a.severity()));
    if !worst.is_empty() {
        let _ = writeln!(out, "\nClosest to their tolerance (|diff| / allowed), declared gaps aside:\n");
    }
    for f in worst.iter().take(5) {
        let _ = writeln!(
            out,
            "- {:.2} — `{}` `{}` against {}: {}",
            f.severity(),
            f.scene,
            f.solver,
            f.against.label(),
            crate::comparison::gate_output::describe(f).replace('|', "\\|")
        );
    }
    out.push('\n');
    out
}

/// A table of contents of the `## ` sections of `md` (GitHub's heading anchors).
fn contents(md: &str) -> String {
    let mut out = String::from("## Contents\n\n");
    for title in md.lines().filter_map(|l| l.strip_prefix("## ")) {
        let _ = writeln!(out, "- [{title}](#{})", anchor(title));
    }
    out.push('\n');
    out
}

/// "N scene(s)", "N wheel–rail scene(s)" or both: the run's module-3 and wheel–rail scenes.
fn scene_count(input: &ReportInput) -> String {
    let module3 = input.scenes.len();
    match input.suites.len().saturating_sub(module3) {
        0 => format!("{module3} scene(s)"),
        w if module3 == 0 => format!("{w} wheel–rail scene(s)"),
        w => format!("{module3} scene(s) and {w} wheel–rail scene(s)"),
    }
}

/// The report's head: its title, what it was generated from (scenes, reference data, the models
/// that ran) and the verdict.
fn head(input: &ReportInput) -> String {
    // The built-in models this report's scenes ran, in registry order.
    let ran = |name: &str| input.scenes.iter().any(|s| s.histories.contains_key(name));
    let model_list: Vec<String> = crate::solvers::MODELS
        .iter()
        .filter(|m| ran(m.name))
        .map(|m| format!("`{}` ({})", m.name, m.summary))
        .collect();
    let mut head = String::new();
    let _ = writeln!(head, "# creepbench validation report\n");
    let _ = writeln!(head, "Generated by `creepbench run` from {}. Reference data: CONTACT (Vollebregt & Kalker, open version 25.2.0) on identical grids and the thesis's published figures (`reference/README.md`). Models: {}; CONTACT's own results are drawn as markers.\n", scene_count(input), model_list.join("; "));
    head.push_str(&verdict(input));
    head
}

/// Every solver the scenes ran: the built-in models in registry order, then any other by name.
fn solvers(scenes: &[StoredScene]) -> Vec<String> {
    let mut v: Vec<String> = scenes.iter().flat_map(|s| s.histories.keys().cloned()).collect();
    v.sort();
    v.dedup();
    let order = |s: &String| crate::solvers::MODELS.iter().position(|m| m.name == s).unwrap_or(usize::MAX);
    v.sort_by_key(order);
    v
}

/// The sections computed from the stored scenes, each with its figures and linked tables.
fn computed(body: &mut Report, sections: &[Section]) {
    for s in sections {
        let _ = writeln!(body.markdown, "## {}\n\n{}\n", s.title, s.body);
        body.figures.extend(s.figures.iter().cloned());
        body.tables.extend(s.tables.iter().cloned());
    }
}

/// Build the report: its head and the contents of its body, then the body's sections in order.
pub fn build(input: &ReportInput) -> Report {
    let solvers = solvers(input.scenes);
    let mut body = Report { markdown: String::new(), figures: Vec::new(), tables: Vec::new() };
    gates::summary(&mut body.markdown, input.findings);
    contact_error::worst_per_scene(&mut body, input, &solvers);
    sines::delay_ratios(&mut body.markdown, input, &solvers);
    sines::loop_areas(&mut body.markdown, input, &solvers);
    computed(&mut body, &input.sections);
    groups::histories_and_loops(&mut body, input);
    left_out::by_scene(&mut body, input.scenes);
    let head = head(input) + &contents(&body.markdown);
    Report { markdown: head + &body.markdown, ..body }
}
