//! The report's "model ladder" (issue 14): every model against the exact theory (`contact`) on
//! the same scenes, per suite — max, RMS and 95th percentile of |Δf| = |(fx, fy) − (fx, fy)_exact|
//! over every row both have, the worst delay-ratio and loop-area differences, and the cost per row.
//! Reads stored results only.

use crate::comparison::model_error::{row_diffs, summary};
use crate::report::section::Section;
use crate::suite::results::StoredScene;
use std::collections::BTreeMap;
use std::fmt::Write;

/// The model every other is measured against.
pub const EXACT: &str = crate::solvers::contact::NAME;

/// What one model gathered over one suite.
#[derive(Default)]
struct Tally {
    scenes: usize,
    diffs: Vec<f64>,
    delay: f64,
    loop_rel: f64,
    wall_s: f64,
    rows: usize,
}

/// The section's id (the calibration section follows it).
pub const ID: &str = "ladder";

/// Whether any stored scene holds the exact solver beside another model.
pub fn applies(scenes: &[StoredScene]) -> bool {
    scenes.iter().any(|s| s.histories.contains_key(EXACT) && s.histories.len() > 1)
}

/// The ladder section, if any stored scene holds the exact solver beside another model.
pub fn section(scenes: &[StoredScene]) -> Option<Section> {
    let mut tallies: BTreeMap<(String, String), Tally> = BTreeMap::new();
    for s in scenes {
        let Some(exact) = s.histories.get(EXACT) else { continue };
        for (model, h) in s.histories.iter().filter(|(m, _)| m.as_str() != EXACT) {
            let t = tallies.entry((model.clone(), s.scene.suite.clone())).or_default();
            t.scenes += 1;
            t.diffs.extend(row_diffs(h, exact));
            if let (Some(a), Some(b)) =
                (s.metric(model, crate::metrics::delay_ratio::NAME), s.metric(EXACT, crate::metrics::delay_ratio::NAME))
            {
                t.delay = t.delay.max((a - b).abs());
            }
            if let (Some(a), Some(b)) =
                (s.metric(model, crate::metrics::loop_area::NAME), s.metric(EXACT, crate::metrics::loop_area::NAME))
            {
                if b != 0.0 {
                    t.loop_rel = t.loop_rel.max(((a - b) / b).abs());
                }
            }
            if let Some(timing) = s.timing.get(model) {
                t.wall_s += timing.wall_s;
                t.rows += h.rows.len();
            }
        }
    }
    if tallies.is_empty() {
        return None;
    }
    let mut body = String::from(
        "Every model against the exact theory (`contact`) on the same scenes and grids, per suite: |Δf| = |(fx, fy)/FN − (fx, fy)/FN of `contact`| over every row both have (sweep points and time steps alike); the largest |Δ delay ratio| and relative loop-area difference over the suite's sine scenes; the wall time per row (this machine, scenes in parallel on 2 cores). Scenes without `contact` do not count.\n\n| model | suite | scenes | rows | max \\|Δf\\| | RMS \\|Δf\\| | 95 % \\|Δf\\| | max \\|Δ delay ratio\\| | max loop-area error | µs per row |\n|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for ((model, suite), t) in tallies {
        let n = t.diffs.iter().filter(|d| d.is_finite()).count();
        let [max, rms, p95] = summary(&t.diffs);
        let delay = if t.delay > 0.0 { format!("{:.4}", t.delay) } else { "—".into() };
        let loop_rel = if t.loop_rel > 0.0 { format!("{:.0} %", 100.0 * t.loop_rel) } else { "—".into() };
        let cost = if t.rows > 0 { format!("{:.1}", 1e6 * t.wall_s / t.rows as f64) } else { "—".into() };
        let _ = writeln!(
            body,
            "| {model} | {suite} | {} | {n} | {:.4} | {:.4} | {:.4} | {delay} | {loop_rel} | {cost} |",
            t.scenes, max, rms, p95,
        );
    }
    body.push_str(&by_series(scenes));
    Some(Section::new("Model ladder: every model against the exact theory", body))
}

/// Per study, per series (the study's other axes at one value each: for CONTACT's test table, one
/// a/b and spin level), every model's RMS and max |Δf| against the exact theory over the series'
/// rows.
fn by_series(scenes: &[StoredScene]) -> String {
    type Diffs = BTreeMap<String, Vec<f64>>;
    let mut studies: BTreeMap<(String, String), BTreeMap<String, Diffs>> = BTreeMap::new();
    for s in scenes {
        let Some(exact) = s.histories.get(EXACT) else { continue };
        for p in &s.scene.studies {
            let series =
                studies.entry((p.study.clone(), p.title.clone())).or_default().entry(p.series.clone()).or_default();
            for (model, h) in s.histories.iter().filter(|(m, _)| m.as_str() != EXACT) {
                series.entry(model.clone()).or_default().extend(row_diffs(h, exact));
            }
        }
    }
    let mut out = String::new();
    for ((study, title), series) in studies {
        let models: Vec<String> = series
            .values()
            .flat_map(|m| m.keys().cloned())
            .collect::<std::collections::BTreeSet<_>>()
            .into_iter()
            .collect();
        if models.is_empty() {
            continue;
        }
        let _ = write!(
            out,
            "\n**{title}** (study `{study}`): RMS / max |Δf| against `{EXACT}` per series\n\n| series | {} |\n|---|{}\n",
            models.join(" | "),
            "---|".repeat(models.len())
        );
        for (label, by_model) in series {
            let cells: Vec<String> = models
                .iter()
                .map(|m| {
                    let [max, rms, _] = summary(by_model.get(m).map_or(&[][..], Vec::as_slice));
                    if max.is_nan() {
                        return "—".into();
                    }
                    format!("{rms:.4} / {max:.4}")
                })
                .collect();
            let label = if label.is_empty() { "(one series)".to_string() } else { label };
            let _ = writeln!(out, "| {label} | {} |", cells.join(" | "));
        }
    }
    out
}
