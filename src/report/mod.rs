//! The Markdown validation report with SVG plots (reports/validation.md, reports/figures/).
//! Built from stored result folders only, so shards merge into one report. Stage 8 of the stack
//! (below it: the comparison's findings and the reference sets; above it: calibration).

pub mod contact_public;
pub mod envelope;
pub mod falling;
pub mod ladder;
pub mod linked_table;
pub mod plot;
pub mod registry;
pub mod section;
pub mod sections;
pub mod studies;
pub mod table;
pub mod work_precision;

use crate::comparison::compare::Finding;
use crate::comparison::delay;
use crate::comparison::references::contact::{self, ContactCases};
use crate::comparison::references::thesis::{self, ThesisTables};
use crate::comparison::references::References;
use crate::error::Error;
use crate::history::History;
use crate::problem::LoadingKind;
use crate::report::plot::{line_chart, titles::of as title_of, Axis, Series};
use crate::report::section::Section;
use crate::safety::{folder, whole};
use crate::suite::results::StoredScene;
pub use linked_table::anchor;
use linked_table::Table;
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::Path;

/// A scene group of the report: its title, which scenes it holds, and how they are drawn.
struct Group {
    title: &'static str,
    member: fn(&str) -> bool,
    /// Whether its sine scenes draw their time history beside their loop (where the delay is the
    /// subject); every other scene draws its history or sweep anyway.
    sine_histories: bool,
    /// Whether it is drawn at all (a group whose scenes only feed the report's sections is not).
    drawn: bool,
}

const fn group(title: &'static str, member: fn(&str) -> bool) -> Group {
    Group { title, member, sine_histories: false, drawn: true }
}

/// Scene groups of the report; a scene belongs to the first that holds it, the last holds any.
const GROUPS: &[Group] = &[
    group("Step response: friction", |n| n.starts_with("step_mu")),
    group("Step response: load, shape and creepage", |n| n.starts_with("step_") && !n.starts_with("step_mu")),
    Group {
        sine_histories: true,
        ..group("Sine: frequency at μ = 1", |n| n.starts_with("sine_f") && n.ends_with("_mu10"))
    },
    group("Sine: frequency at μ = 0.6", |n| n.starts_with("sine_f") && n.ends_with("_mu06")),
    group("Sine: friction at 10 Hz", |n| n.starts_with("sine_f10_mu0")),
    group("Sine: normal load", |n| n.starts_with("sine_f") && n.contains("_fn")),
    group("Sine: mean creepage C0", |n| n.starts_with("sine_f10_c0_")),
    Group {
        sine_histories: true,
        ..group("Grid refinement", |n| n.starts_with("sine") && (n.ends_with("_g44") || n.ends_with("_g88")))
    },
    group("Steady sweeps", |n| n.starts_with("steady_")),
    group("Stability and extreme cases", |n| n.starts_with(sections::STABILITY_SCENES)),
    Group { drawn: false, ..group("Studies behind the report's sections", |n| n.starts_with("report_")) },
    group("Other scenes", |_| true),
];

/// The index in [`GROUPS`] of the group that holds a scene.
fn group_of(name: &str) -> usize {
    GROUPS.iter().position(|g| (g.member)(name)).unwrap_or(GROUPS.len() - 1)
}

/// Down-sample a curve to at most `n` points (keeps the plot files small).
fn thin(points: Vec<(f64, f64)>, n: usize) -> Vec<(f64, f64)> {
    if points.len() <= n {
        return points;
    }
    let step = points.len() as f64 / n as f64;
    let mut out: Vec<(f64, f64)> = (0..n).map(|k| points[(k as f64 * step) as usize]).collect();
    out.push(*points.last().unwrap());
    out
}

fn xy(h: &History, x: &str, y: &str) -> Vec<(f64, f64)> {
    h.column(x).unwrap_or_default().into_iter().zip(h.column(y).unwrap_or_default()).collect()
}

/// A sweep's plot axis: the creepage its direction moves most ((cx, cy, cs) order on ties).
fn swept_axis(direction: [f64; 3]) -> (&'static str, &'static str) {
    let axes = [("cx", "creepage c_x [–]"), ("cy", "creepage c_y [–]"), ("cs", "spin creepage c_s [1/mm]")];
    let k = (1..3).fold(0, |k, i| if direction[i].abs() > direction[k].abs() { i } else { k });
    axes[k]
}

fn last_period(h: &History, period: f64) -> Vec<(f64, f64)> {
    let t_end = h.rows.last().map(|r| r.sample.t_s).unwrap_or(0.0);
    let periods = (t_end / period + 1e-9).floor();
    let t0 = (periods - 1.0) * period;
    h.rows.iter().filter(|r| r.sample.t_s >= t0 - 1e-12).map(|r| (r.sample.cx, r.fx_over_fn)).collect()
}

fn fmt(v: Option<f64>, digits: usize) -> String {
    match v {
        Some(x) if x.is_finite() => format!("{x:.digits$}"),
        _ => "—".into(),
    }
}

/// A Markdown table header: the fixed columns, then one per solver.
fn table_head(md: &mut String, fixed: &[&str], solvers: &[String]) {
    let cols: Vec<&str> = fixed.iter().copied().chain(solvers.iter().map(String::as_str)).collect();
    let _ = writeln!(md, "| {} |\n|{}", cols.join(" | "), "---|".repeat(cols.len()));
}

/// Everything the report shows: stored results and reference data only.
pub struct ReportInput<'a> {
    pub scenes: &'a [StoredScene],
    pub refs: &'a References,
    pub findings: &'a [Finding],
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

/// The title of the section of the worst error against CONTACT per scene and solver.
const ERROR_SECTION: &str = "Error against CONTACT, worst step per scene and solver";

/// The one-screen verdict: gated comparisons and failures per suite, and the worst gated points.
fn verdict(input: &ReportInput) -> String {
    let suite_of: BTreeMap<&str, &str> =
        input.scenes.iter().map(|s| (s.name.as_str(), s.scene.suite.as_str())).collect();
    let mut per: BTreeMap<&str, (usize, usize)> = BTreeMap::new();
    for f in input.findings.iter().filter(|f| f.gated) {
        let e = per.entry(suite_of.get(f.scene.as_str()).copied().unwrap_or("?")).or_default();
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
    let mut worst: Vec<&Finding> = input.findings.iter().filter(|f| f.gated && f.allowed > 0.0).collect();
    worst.sort_by(|a, b| b.severity().total_cmp(&a.severity()));
    if !worst.is_empty() {
        let _ = writeln!(out, "\nClosest to their tolerance (|diff| / allowed):\n");
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

/// Build the report.
pub fn build(input: &ReportInput) -> Report {
    let mut md = String::new();
    let mut figures: Vec<(String, String)> = Vec::new();
    let mut tables: Vec<(String, String)> = Vec::new();
    // The built-in models this report's scenes ran, in registry order.
    let ran = |name: &str| input.scenes.iter().any(|s| s.histories.contains_key(name));
    let model_list: Vec<String> = crate::solvers::MODELS
        .iter()
        .filter(|m| ran(m.name))
        .map(|m| format!("`{}` ({})", m.name, m.summary))
        .collect();
    let mut head = String::new();
    let _ = writeln!(head, "# creepbench validation report\n");
    let _ = writeln!(head, "Generated by `creepbench run` from {} scene(s). Reference data: CONTACT (Vollebregt & Kalker, open version 25.2.0) on identical grids and the thesis's published figures (`reference/README.md`). Models: {}; CONTACT's own results are drawn as markers.\n", input.scenes.len(), model_list.join("; "));
    head.push_str(&verdict(input));

    // Gate summary.
    let gated: Vec<&Finding> = input.findings.iter().filter(|f| f.gated).collect();
    let failed: Vec<&Finding> = gated.iter().copied().filter(|f| !f.passed()).collect();
    let _ = writeln!(md, "## Gates\n\n{} gated comparisons, {} failed.\n", gated.len(), failed.len());
    if !failed.is_empty() {
        let _ = writeln!(md, "| scene | solver | against | quantity | step | ours | theirs | allowed | note |\n|---|---|---|---|---|---|---|---|---|");
        for f in &failed {
            // A scene without a baseline has no values to show: its note says so, once.
            let values = if crate::comparison::compare::is_no_baseline(f) {
                "— | — | —".to_string()
            } else {
                format!("{:.6} | {:.6} | {:.1e}", f.ours, f.theirs, f.allowed)
            };
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {} | {values} | {} |",
                f.scene,
                f.solver,
                f.against.label(),
                f.quantity,
                f.step.map(|s| s.to_string()).unwrap_or_default(),
                f.note
            );
        }
        md.push('\n');
    }

    let solvers: Vec<String> = {
        let mut v: Vec<String> = input.scenes.iter().flat_map(|s| s.histories.keys().cloned()).collect();
        v.sort();
        v.dedup();
        let order = |s: &String| crate::solvers::MODELS.iter().position(|m| m.name == s).unwrap_or(usize::MAX);
        v.sort_by_key(order);
        v
    };
    let thesis = input.refs.get::<ThesisTables>(thesis::AGAINST);
    // Worst point per scene and solver against CONTACT, where a scene has CONTACT's history.
    let contact = input.refs.get::<ContactCases>(contact::EXACT);
    if input.scenes.iter().any(|sc| contact.and_then(|c| c.history(&sc.name)).is_some()) {
        let _ = writeln!(md, "## {ERROR_SECTION}\n\nmax |f − f_CONTACT| over every step (sweeps: every creepage point), f = Fx/FN. Gated for `contact` (≤ 1e-5) and, on `steady_fastsim_g22`, for `fastsim` and `uba` (≤ 0.0015); the simplified models are reported.\n");
        let mut cols = vec!["scene"];
        for s in &solvers {
            cols.extend([s.as_str(), "step"]);
        }
        let mut table = Table::new(&cols);
        // Per solver: its largest error and the row it is in; rows with a gated miss.
        let mut largest: Vec<Option<(f64, usize, &str)>> = vec![None; solvers.len()];
        let mut keep = Vec::new();
        for sc in input.scenes {
            if contact.and_then(|c| c.history(&sc.name)).is_none() {
                continue;
            }
            let mut row = format!("| {} |", sc.name);
            for (k, s) in solvers.iter().enumerate() {
                let f = input.findings.iter().find(|f| {
                    f.scene == sc.name && &f.solver == s && f.against.is_contact() && f.quantity == "fx_over_fn"
                });
                match f {
                    Some(f) => {
                        let miss = f.gated && !f.passed();
                        if miss {
                            keep.push(table.rows.len());
                        }
                        if largest[k].is_none_or(|(d, _, _)| f.diff > d) {
                            largest[k] = Some((f.diff, table.rows.len(), &sc.name));
                        }
                        let v = if f.diff < 1e-3 { format!("{:.1e}", f.diff) } else { format!("{:.4}", f.diff) };
                        let mark = if miss { " ✗" } else { "" };
                        let _ = write!(row, " {v}{mark} | {} |", f.step.map(|k| k.to_string()).unwrap_or_default());
                    }
                    None => row.push_str(" — | |"),
                }
            }
            table.rows.push(row);
        }
        let per_solver: Vec<String> = solvers
            .iter()
            .zip(&largest)
            .filter_map(|(s, l)| {
                let (d, _, scene) = (*l)?;
                Some(format!("`{s}` {} (`{scene}`)", if d < 1e-3 { format!("{d:.1e}") } else { format!("{d:.4}") }))
            })
            .collect();
        keep.extend(largest.iter().flatten().map(|l| l.1));
        keep.sort_unstable();
        let summary = format!("{} scenes; the largest per solver: {}.", table.rows.len(), per_solver.join(", "));
        let placed = linked_table::place(
            "error_against_contact",
            ERROR_SECTION,
            &table,
            &summary,
            &keep,
            "The rows of each solver's largest error and of any gated miss",
        );
        let _ = writeln!(md, "{}", placed.inline);
        tables.extend(placed.file);
    }

    // Delay ratios and loop areas.
    let sines: Vec<&StoredScene> = input.scenes.iter().filter(|s| s.scene.period_s().is_some()).collect();
    if !sines.is_empty() {
        let _ = writeln!(md, "## Delay ratios\n\nTime from the maximum of cx to the next maximum of f in the second period, over the period (parabolic peak interpolation). Thesis Table 4.2 (CONTACT, μ = 1, 22×22): 0.040 / 0.128 / 0.220 at 10 / 30 / 60 Hz. † f reaches μ (within 3 %): the maximum is a flat top and the delay ill-defined (reported, not gated).\n");
        table_head(&mut md, &["scene", "thesis", "CONTACT"], &solvers);
        for sc in &sines {
            let p = sc.scene.period_s().unwrap_or(1.0);
            let thesis = thesis.and_then(|t| t.delay_for(sc));
            let contact = contact.and_then(|c| c.history(&sc.name)).and_then(|h| delay::of_history(h, p));
            let _ = write!(md, "| {} | {} | {} |", sc.name, fmt(thesis, 3), fmt(contact, 4));
            for s in &solvers {
                let flat = sc
                    .histories
                    .get(s)
                    .is_some_and(|h| h.rows.iter().any(|r| delay::saturates(r.fx_over_fn.abs(), r.sample.mu)));
                let d = fmt(sc.metrics.get(&(s.clone(), crate::metrics::delay_ratio::NAME.into(), None)).copied(), 4);
                let _ = write!(md, " {d}{} |", if flat { " †" } else { "" });
            }
            md.push('\n');
        }
        let _ = writeln!(md, "\n## Hysteresis loop areas\n\n|∮ f dcx| over the last full period (trapezoidal; CONTACT's value from `cases.csv`). In brackets: relative difference to CONTACT.\n");
        table_head(&mut md, &["scene", "CONTACT"], &solvers);
        for sc in &sines {
            let c = contact.and_then(|c| c.cases.get(&sc.name)).and_then(|c| c.loop_area).map(f64::abs);
            let _ = write!(md, "| {} | {} |", sc.name, fmt(c, 6));
            for s in &solvers {
                let v = sc.metrics.get(&(s.clone(), crate::metrics::loop_area::NAME.into(), None)).copied();
                let rel = match (v, c) {
                    (Some(v), Some(c)) if c > 0.0 => format!(" ({:+.1} %)", 100.0 * (v / c - 1.0)),
                    _ => String::new(),
                };
                let _ = write!(md, " {}{rel} |", fmt(v, 6));
            }
            md.push('\n');
        }
        md.push('\n');
    }

    // Sections computed from the stored scenes.
    for s in &input.sections {
        let _ = writeln!(md, "## {}\n\n{}\n", s.title, s.body);
        figures.extend(s.figures.iter().cloned());
        tables.extend(s.tables.iter().cloned());
    }

    // Groups with plots.
    let _ = writeln!(md, "## Histories and loops by group\n");
    for (k, group) in GROUPS.iter().enumerate() {
        // A reference set's cases drawn in a section of their own are not drawn again.
        let members: Vec<&StoredScene> = input
            .scenes
            .iter()
            .filter(|s| group_of(&s.name) == k && input.refs.section_of(&s.name).is_none())
            .collect();
        if members.is_empty() || !group.drawn {
            continue;
        }
        let title = group.title;
        let _ = writeln!(md, "### {title}\n");
        for sc in members {
            let contact = input.refs.history(&sc.name);
            let mut series: Vec<Series> = Vec::new();
            let sweep = sc.scene.kind == LoadingKind::Sweep;
            let (x, xl) =
                if sweep { swept_axis(sc.scene.sweep_direction.unwrap_or([1.0, 0.0, 0.0])) } else { ("t_s", "t [s]") };
            for (name, h) in &sc.histories {
                series.push(Series::model(name, thin(xy(h, x, "fx_over_fn"), 300)));
            }
            if let Some(c) = &contact {
                series.push(Series::reference("CONTACT", thin(xy(c, x, "fx_over_fn"), 150)));
            }
            // Sine scenes show their loop; the time history only where the delay is the subject.
            if sc.scene.period_s().is_none() || group.sine_histories {
                let file = format!("{}_{}.svg", sc.name, if sweep { "sweep" } else { "history" });
                figures.push((
                    file.clone(),
                    line_chart(&sc.name, &Axis::linear(xl), &Axis::linear(title_of("fx_over_fn")), &series),
                ));
                let _ = writeln!(md, "![{}](figures/{file})", sc.name);
            }
            if let Some(p) = sc.scene.period_s() {
                let mut loops: Vec<Series> =
                    sc.histories.iter().map(|(n, h)| Series::model(n, thin(last_period(h, p), 300))).collect();
                if let Some(c) = &contact {
                    loops.push(Series::reference("CONTACT", thin(last_period(c, p), 150)));
                }
                let file = format!("{}_loop.svg", sc.name);
                figures.push((
                    file.clone(),
                    line_chart(
                        &format!("{} — last period", sc.name),
                        &Axis::linear("creepage c_x [–]"),
                        &Axis::linear(title_of("fx_over_fn")),
                        &loops,
                    ),
                ));
                let _ = writeln!(md, "![{} loop](figures/{file})", sc.name);
            }
            md.push('\n');
        }
    }

    // What each scene left out.
    const LEFT_OUT: &str = "What each scene left out";
    let _ = writeln!(md, "## {LEFT_OUT}\n\nOnly what a scene lists is computed: solvers it does not name are not run, metrics that do not fit its creepage are not computed.\n");
    let mut table = Table::new(&["scene", "solvers not run", "metrics left out"]);
    let mut ran_all = 0;
    for sc in input.scenes {
        let ran: Vec<&str> = sc.histories.keys().map(String::as_str).collect();
        let not_run: Vec<&str> = crate::solvers::builtin_names().into_iter().filter(|s| !ran.contains(s)).collect();
        let skipped: Vec<String> = sc.scene.skipped_metrics.iter().map(|(m, why)| format!("{m} ({why})")).collect();
        ran_all += usize::from(not_run.is_empty());
        table.rows.push(format!(
            "| {} | {} | {} |",
            sc.name,
            if not_run.is_empty() { "—".into() } else { not_run.join(", ") },
            if skipped.is_empty() { "—".into() } else { skipped.join("; ") }
        ));
    }
    let summary = format!("{} scenes, {ran_all} of them ran every built-in model.", table.rows.len());
    let placed = linked_table::place("left_out", LEFT_OUT, &table, &summary, &[], "");
    let _ = write!(md, "{}", placed.inline);
    tables.extend(placed.file);
    head.push_str(&contents(&md));
    Report { markdown: head + &md, figures, tables }
}
