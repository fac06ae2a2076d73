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

/// A metric's curves keyed by (series label, model or reference set): (x, value) points.
type Curves = BTreeMap<(String, String), Vec<(f64, f64)>>;

/// One study, ready to draw: its id, its points in series and x order, the models its scenes
/// ran, and each point's reference values ([`reference_values`]).
struct Study<'a> {
    id: &'a str,
    points: Points<'a>,
    solvers: Vec<&'a str>,
    references: Vec<Vec<(&'static str, String, f64)>>,
}

impl<'a> Study<'a> {
    /// The study's points sorted by series then x, with its models and reference values.
    fn new(id: &'a str, mut points: Points<'a>, refs: &References) -> Study<'a> {
        points.sort_by(|a, b| a.1.series.cmp(&b.1.series).then(a.1.x.total_cmp(&b.1.x)));
        let mut solvers: Vec<&str> = points.iter().flat_map(|(s, _)| s.histories.keys().map(String::as_str)).collect();
        solvers.sort();
        solvers.dedup();
        let references = points.iter().map(|(s, _)| reference_values(refs, s)).collect();
        Study { id, points, solvers, references }
    }

    /// The study's title, as its first point gives it.
    fn title(&self) -> &'a str {
        &self.points[0].1.title
    }

    /// The scene key the study varies (its x axis).
    fn x_key(&self) -> &'a str {
        &self.points[0].1.x_key
    }
}

/// The studies section, if any stored scene is a study point.
pub fn section(scenes: &[StoredScene], refs: &References) -> Option<Section> {
    let studies = group(scenes);
    if studies.is_empty() {
        return None;
    }
    let mut body = String::from(
        "Each study is one file (a scene template and the values it varies, `scenes/*/` files with a `[study]` table; README \"Studies\"), expanded into scenes that run and are gated like any other. Per study and metric: the metric against the varied parameter, one curve per model (and per value of the other axes), the references' values of the same scene as markers.\n",
    );
    let mut figures = Vec::new();
    for (id, points) in studies {
        study_part(&Study::new(id, points, refs), &mut body, &mut figures);
    }
    Some(Section { figures, ..Section::new("Parameter studies", body) })
}

/// The stored scenes' study points, by study id.
fn group(scenes: &[StoredScene]) -> BTreeMap<&str, Points<'_>> {
    let mut studies: BTreeMap<&str, Points> = BTreeMap::new();
    for s in scenes {
        for p in &s.scene.studies {
            studies.entry(p.study.as_str()).or_default().push((s, p));
        }
    }
    studies
}

/// A study's heading, then a table and a figure per metric.
fn study_part(study: &Study, body: &mut String, figures: &mut Vec<(String, String)>) {
    let _ = writeln!(
        body,
        "\n### {}\n\nStudy `{}`: {} scenes, x = `{}`.\n",
        study.title(),
        study.id,
        study.points.len(),
        study.x_key()
    );
    for metric in metrics_of(&study.points) {
        metric_part(study, &metric, body, figures);
    }
}

/// A metric's table and figure; nothing for a metric no point has as one number (a sweep's
/// per-point values).
fn metric_part(study: &Study, metric: &str, body: &mut String, figures: &mut Vec<(String, String)>) {
    let has_number = |(s, _): &(&StoredScene, &StudyPoint)| {
        study.solvers.iter().any(|m| s.metric(m, metric).is_some_and(f64::is_finite))
    };
    if !study.points.iter().any(has_number) {
        return;
    }
    let (table, series, marks) = metric_table(study, metric);
    body.push_str(&table);
    if series.is_empty() {
        return;
    }
    let file = format!("study_{}_{metric}.svg", study.id);
    let svg = metric_chart(study, metric, series, marks);
    let _ = writeln!(body, "\n![{} {metric}](figures/{file})\n", study.id);
    figures.push((file, svg));
}

/// A metric's table, a row per point, and the curves it draws: the models' and the references'.
fn metric_table(study: &Study, metric: &str) -> (String, Curves, Curves) {
    let mut table = format!(
        "**{metric}**\n\n| {} | series | {} | reference |\n|{}\n",
        study.x_key(),
        study.solvers.join(" | "),
        "---|".repeat(study.solvers.len() + 3)
    );
    let (mut series, mut marks) = (Curves::new(), Curves::new());
    for ((s, p), references) in study.points.iter().zip(&study.references) {
        let cells = model_cells(&study.solvers, s, p, metric, &mut series);
        let reference = reference_cell(references, p, metric, &mut marks);
        let series_cell = if p.series.is_empty() { "—" } else { p.series.as_str() };
        let _ = writeln!(table, "| {} | {series_cell} | {} | {reference} |", p.x, cells.join(" | "));
    }
    (table, series, marks)
}

/// A point's value of the metric for each model (— where none), each finite one added to `series`.
fn model_cells(solvers: &[&str], s: &StoredScene, p: &StudyPoint, metric: &str, series: &mut Curves) -> Vec<String> {
    let mut cells = Vec::new();
    for solver in solvers {
        let v = s.metric(solver, metric);
        if let Some(v) = v.filter(|v| v.is_finite()) {
            series.entry((p.series.clone(), solver.to_string())).or_default().push((p.x, v));
        }
        cells.push(value(v));
    }
    cells
}

/// A point's reference values of the metric ("set value, …", — where none), each added to `marks`.
fn reference_cell(
    references: &[(&'static str, String, f64)],
    p: &StudyPoint,
    metric: &str,
    marks: &mut Curves,
) -> String {
    let refs_here: Vec<(&str, f64)> =
        references.iter().filter(|(_, q, _)| *q == metric).map(|(l, _, v)| (*l, *v)).collect();
    for (label, v) in &refs_here {
        marks.entry((p.series.clone(), label.to_string())).or_default().push((p.x, *v));
    }
    let reference: Vec<String> = refs_here.iter().map(|(l, v)| format!("{l} {v:.4}")).collect();
    if reference.is_empty() {
        "—".into()
    } else {
        reference.join(", ")
    }
}

/// The metric against the study's parameter: the models' curves and the references' markers.
fn metric_chart(study: &Study, metric: &str, series: Curves, marks: Curves) -> String {
    let plotted: Vec<Series> = series
        .into_iter()
        .map(|((group, name), points)| Series::model(name, points).in_group(group))
        .chain(marks.into_iter().map(|((group, name), points)| Series::reference(name, points).in_group(group)))
        .collect();
    line_chart(
        &format!("{} — {}", study.title(), titles::of(metric)),
        &Axis { title: titles::of(study.x_key()), log: log_x(&study.points) },
        &Axis::linear(titles::of(metric)),
        &plotted,
    )
}

/// A log x axis when every x is positive and they span more than 20×.
fn log_x(points: &Points) -> bool {
    let positive = points.iter().all(|(_, p)| p.x > 0.0);
    let ratio = points.iter().map(|(_, p)| p.x).fold(0.0, f64::max)
        / points.iter().map(|(_, p)| p.x).fold(f64::INFINITY, f64::min);
    positive && ratio > 20.0
}
