//! The report's section on parameter studies ([`crate::scene::study`]): per study and metric, the
//! metric against the varied parameter, one curve per model (and per value of the other axes),
//! with the references' values of the same metric as markers where a reference holds the scene.
//! Reads stored results (scene.json `studies`, metrics.csv) and reference data only.

use crate::comparison::references::References;
use crate::report::plot::{line_chart, titles, Axis, Series};
use crate::report::section::Section;
use crate::scene::study::StudyPoint;
use crate::suite::results::StoredScene;
use std::collections::BTreeMap;
use std::fmt::Write;

/// One study's points: (scene, its place in the study).
type Points<'a> = Vec<(&'a StoredScene, &'a StudyPoint)>;

/// The metrics a study draws: those it names, else every scalar metric its scenes hold.
fn metrics_of(points: &Points) -> Vec<String> {
    if let Some((_, p)) = points.iter().find(|(_, p)| !p.metrics.is_empty()) {
        return p.metrics.clone();
    }
    let mut names: Vec<String> =
        points.iter().flat_map(|(s, _)| s.metrics.keys().filter(|k| k.2.is_none()).map(|k| k.1.clone())).collect();
    names.sort();
    names.dedup();
    names
}

/// (set label, quantity, reference value) of the first comparison per quantity the references make for a
/// scene, computed once per scene.
fn reference_values(refs: &References, scene: &StoredScene) -> Vec<(&'static str, String, f64)> {
    let mut out: Vec<(&'static str, String, f64)> = Vec::new();
    for set in refs.sets() {
        for f in
            set.compare(scene, crate::comparison::tolerances::defaults()).into_iter().filter(|f| f.theirs.is_finite())
        {
            if !out.iter().any(|(l, q, _)| *l == set.label() && *q == f.quantity) {
                out.push((set.label(), f.quantity, f.theirs));
            }
        }
    }
    out
}

fn value(v: Option<f64>) -> String {
    match v {
        Some(x) if x.is_finite() => format!("{x:.4}"),
        _ => "—".into(),
    }
}

/// The studies section, if any stored scene is a study point.
pub fn section(scenes: &[StoredScene], refs: &References) -> Option<Section> {
    let mut studies: BTreeMap<&str, Points> = BTreeMap::new();
    for s in scenes {
        for p in &s.scene.studies {
            studies.entry(p.study.as_str()).or_default().push((s, p));
        }
    }
    if studies.is_empty() {
        return None;
    }
    let mut body = String::from(
        "Each study is one file (a scene template and the values it varies, `scenes/*/` files with a `[study]` table; README \"Studies\"), expanded into scenes that run and are gated like any other. Per study and metric: the metric against the varied parameter, one curve per model (and per value of the other axes), the references' values of the same scene as markers.\n",
    );
    let mut figures = Vec::new();
    for (id, mut points) in studies {
        points.sort_by(|a, b| a.1.series.cmp(&b.1.series).then(a.1.x.total_cmp(&b.1.x)));
        let (title, x_key) = (&points[0].1.title, &points[0].1.x_key);
        let _ = writeln!(body, "\n### {title}\n\nStudy `{id}`: {} scenes, x = `{x_key}`.\n", points.len());
        let mut solvers: Vec<&str> = points.iter().flat_map(|(s, _)| s.histories.keys().map(String::as_str)).collect();
        solvers.sort();
        solvers.dedup();
        let references: Vec<_> = points.iter().map(|(s, _)| reference_values(refs, s)).collect();
        for metric in metrics_of(&points) {
            // Curves keyed by (series label, model or reference set).
            let mut series: BTreeMap<(String, String), Vec<(f64, f64)>> = BTreeMap::new();
            let mut marks: BTreeMap<(String, String), Vec<(f64, f64)>> = BTreeMap::new();
            // A metric no point has as one number (a sweep's per-point values) gets no table.
            if !points.iter().any(|(s, _)| solvers.iter().any(|m| s.metric(m, &metric).is_some_and(f64::is_finite))) {
                continue;
            }
            let mut table = format!(
                "**{metric}**\n\n| {x_key} | series | {} | reference |\n|{}\n",
                solvers.join(" | "),
                "---|".repeat(solvers.len() + 3)
            );
            for ((s, p), references) in points.iter().zip(&references) {
                let tag = |name: &str| (p.series.clone(), name.to_string());
                let mut cells = Vec::new();
                for solver in &solvers {
                    let v = s.metric(solver, &metric);
                    if let Some(v) = v.filter(|v| v.is_finite()) {
                        series.entry(tag(solver)).or_default().push((p.x, v));
                    }
                    cells.push(value(v));
                }
                let refs_here: Vec<(&str, f64)> =
                    references.iter().filter(|(_, q, _)| *q == metric).map(|(l, _, v)| (*l, *v)).collect();
                for (label, v) in &refs_here {
                    marks.entry(tag(label)).or_default().push((p.x, *v));
                }
                let reference: Vec<String> = refs_here.iter().map(|(l, v)| format!("{l} {v:.4}")).collect();
                let series_cell = if p.series.is_empty() { "—" } else { p.series.as_str() };
                let _ = writeln!(
                    table,
                    "| {} | {series_cell} | {} | {} |",
                    p.x,
                    cells.join(" | "),
                    if reference.is_empty() { "—".into() } else { reference.join(", ") }
                );
            }
            body.push_str(&table);
            if series.is_empty() {
                continue;
            }
            let plotted: Vec<Series> = series
                .into_iter()
                .map(|((group, name), points)| Series::model(name, points).in_group(group))
                .chain(marks.into_iter().map(|((group, name), points)| Series::reference(name, points).in_group(group)))
                .collect();
            let positive = points.iter().all(|(_, p)| p.x > 0.0);
            let ratio = points.iter().map(|(_, p)| p.x).fold(0.0, f64::max)
                / points.iter().map(|(_, p)| p.x).fold(f64::INFINITY, f64::min);
            let log_x = positive && ratio > 20.0;
            let file = format!("study_{id}_{metric}.svg");
            let svg = line_chart(
                &format!("{title} — {}", titles::of(&metric)),
                &Axis { title: titles::of(x_key), log: log_x },
                &Axis::linear(titles::of(&metric)),
                &plotted,
            );
            let _ = writeln!(body, "\n![{id} {metric}](figures/{file})\n");
            figures.push((file, svg));
        }
    }
    Some(Section { figures, ..Section::new("Parameter studies", body) })
}
