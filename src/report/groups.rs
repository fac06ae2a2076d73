//! The report's figures by scene group: each scene's history or sweep and, for sine scenes, its
//! hysteresis loop, CONTACT's drawn as markers.

use crate::history::abscissa::{abscissa, Drawn};
use crate::history::History;
use crate::problem::LoadingKind;
use crate::report::plot::{line_chart, titles::of as title_of, Axis, Series};
use crate::report::{Report, ReportInput};
use crate::scene::report::ReportGroup;
use crate::suite::results::StoredScene;
use std::fmt::Write;

/// A figure group of the report: its title, the declared scene groups it draws (`[report]
/// group`, [`ReportGroup`]) and how it draws them.
struct FigureGroup {
    title: &'static str,
    holds: &'static [ReportGroup],
    /// Whether its sine scenes draw their time history beside their loop (where the delay is the
    /// subject); every other scene draws its history or sweep anyway.
    sine_histories: bool,
}

const fn figures(title: &'static str, holds: &'static [ReportGroup]) -> FigureGroup {
    FigureGroup { title, holds, sine_histories: false }
}

/// The report's figure groups, in order; a scene is drawn in the one that holds its declared group.
const FIGURE_GROUPS: &[FigureGroup] = &[
    figures("Step response: friction", &[ReportGroup::StepFriction]),
    figures("Step response: load, shape and creepage", &[ReportGroup::StepLoad]),
    FigureGroup { sine_histories: true, ..figures("Sine: frequency at μ = 1", &[ReportGroup::SineFrequencyMu1]) },
    figures("Sine: frequency at μ = 0.6", &[ReportGroup::SineFrequencyMu06]),
    figures("Sine: friction at 10 Hz", &[ReportGroup::SineFriction]),
    figures("Sine: normal load", &[ReportGroup::SineLoad]),
    figures("Sine: mean creepage C0", &[ReportGroup::SineMeanCreepage]),
    FigureGroup { sine_histories: true, ..figures("Grid refinement", &[ReportGroup::GridRefinement]) },
    figures("Steady sweeps", &[ReportGroup::Steady]),
    figures("Stability and extreme cases", &[ReportGroup::Stability, ReportGroup::StabilityFalling]),
    figures("Other scenes", &[ReportGroup::FallingFriction, ReportGroup::Other]),
];

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

/// f = Fx/FN of each row against the scene's abscissa ([`abscissa`]).
fn xy(h: &History, drawn: Drawn) -> Vec<(f64, f64)> {
    abscissa(h, drawn).1.into_iter().zip(h.column("fx_over_fn").unwrap_or_default()).collect()
}

fn last_period(h: &History, period: f64) -> Vec<(f64, f64)> {
    let t_end = h.rows.last().map(|r| r.sample.t_s).unwrap_or(0.0);
    let periods = (t_end / period + 1e-9).floor();
    let t0 = (periods - 1.0) * period;
    h.rows.iter().filter(|r| r.sample.t_s >= t0 - 1e-12).map(|r| (r.sample.cx, r.fx_over_fn)).collect()
}

/// Section: a subsection per drawn group, with the figures of each of its scenes and their links.
pub fn histories_and_loops(body: &mut Report, input: &ReportInput) {
    let _ = writeln!(body.markdown, "## Histories and loops by group\n");
    for group in FIGURE_GROUPS {
        let members = members(input, group);
        if members.is_empty() {
            continue;
        }
        let _ = writeln!(body.markdown, "### {}\n", group.title);
        for sc in members {
            scene_figures(body, sc, input.refs.history(&sc.name), group.sine_histories);
        }
    }
}

/// The scenes `group` holds (by their declared group) and draws.
fn members<'a>(input: &ReportInput<'a>, group: &FigureGroup) -> Vec<&'a StoredScene> {
    // A reference set's cases drawn in a section of their own are not drawn again.
    let drawn =
        |s: &StoredScene| group.holds.contains(&s.scene.report_group) && input.refs.section_of(&s.name).is_none();
    input.scenes.iter().filter(|s| drawn(s)).collect()
}

/// A scene's figures and their links: its history or sweep, and its loop if it is a sine;
/// `contact` is CONTACT's history of it, if any.
fn scene_figures(body: &mut Report, sc: &StoredScene, contact: Option<&History>, sine_histories: bool) {
    // Sine scenes show their loop; the time history only where the delay is the subject.
    if sc.scene.period_s().is_none() || sine_histories {
        history_figure(body, sc, contact);
    }
    if let Some(period_s) = sc.scene.period_s() {
        loop_figure(body, sc, contact, period_s);
    }
    body.markdown.push('\n');
}

/// A scene's f = Fx/FN against time, or for a sweep against the quantity it moves ([`abscissa`]).
fn history_figure(body: &mut Report, sc: &StoredScene, contact: Option<&History>) {
    let sweep = sc.scene.kind == LoadingKind::Sweep;
    let drawn = Drawn::of_scene(&sc.scene);
    let x = sc.histories.values().next().map_or("t_s", |h| abscissa(h, drawn).0);
    let mut series: Vec<Series> =
        sc.histories.iter().map(|(name, h)| Series::model(name, thin(xy(h, drawn), 300))).collect();
    if let Some(c) = contact {
        series.push(Series::reference("CONTACT", thin(xy(c, drawn), 150)));
    }
    let file = format!("{}_{}.svg", sc.name, if sweep { "sweep" } else { "history" });
    let svg = line_chart(&sc.name, &Axis::linear(title_of(x)), &Axis::linear(title_of("fx_over_fn")), &series);
    figure(body, file, svg, &sc.name);
}

/// A sine scene's hysteresis loop: f = Fx/FN against cx over its last period (`period_s`).
fn loop_figure(body: &mut Report, sc: &StoredScene, contact: Option<&History>, period_s: f64) {
    let mut loops: Vec<Series> =
        sc.histories.iter().map(|(n, h)| Series::model(n, thin(last_period(h, period_s), 300))).collect();
    if let Some(c) = contact {
        loops.push(Series::reference("CONTACT", thin(last_period(c, period_s), 150)));
    }
    let file = format!("{}_loop.svg", sc.name);
    let svg = line_chart(
        &format!("{} — last period", sc.name),
        &Axis::linear("creepage c_x [–]"),
        &Axis::linear(title_of("fx_over_fn")),
        &loops,
    );
    figure(body, file, svg, &format!("{} loop", sc.name));
}

/// Add a figure (file name, SVG) to the report and its link, with the text `alt`, to the Markdown.
fn figure(body: &mut Report, file: String, svg: String, alt: &str) {
    let _ = writeln!(body.markdown, "![{alt}](figures/{file})");
    body.figures.push((file, svg));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The groups whose scenes only feed the report's sections: drawn in no figure group.
    const NOT_DRAWN: [ReportGroup; 2] = [ReportGroup::Scaling, ReportGroup::ThesisFigures];

    #[test]
    fn every_declared_group_is_drawn_in_one_figure_group_or_feeds_sections_only() {
        for g in ReportGroup::ALL {
            let holders = FIGURE_GROUPS.iter().filter(|f| f.holds.contains(&g)).count();
            assert_eq!(holders + usize::from(NOT_DRAWN.contains(&g)), 1, "{}", g.id());
        }
    }
}
