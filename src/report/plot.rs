//! SVG figures for the report: line charts (one panel, or small multiples when a single panel
//! would hold too many series or two alike) and patch maps. Every model is drawn in its own
//! colour, line style and marker, the same in every figure ([`style`]); reference data as black
//! markers.

mod axis;
mod chart;
mod patch;
pub mod style;
mod svg;
pub mod titles;

pub use patch::{patch_map, PatchCell};

/// Most series in one panel; a chart with more becomes small multiples.
pub const MAX_SERIES_PER_PANEL: usize = 6;
/// Most panels of one series each; beyond, one panel per group holds all of the group's models.
pub const MAX_PANELS: usize = 24;

/// An axis: its title (a name with its unit, e.g. `frequency [Hz]`) and whether it is logarithmic.
pub struct Axis {
    pub title: String,
    pub log: bool,
}

impl Axis {
    pub fn linear(title: impl Into<String>) -> Axis {
        Axis { title: title.into(), log: false }
    }
    pub fn log(title: impl Into<String>) -> Axis {
        Axis { title: title.into(), log: true }
    }
}

/// One curve: a model's line (drawn in the model's style) or a reference set's markers.
pub struct Series {
    /// The model's or reference set's name: its style and legend entry.
    pub name: String,
    /// The value of a study's other axes ("mu 10"; empty when none): curves of different
    /// groups go into different panels, references into the panels of their group.
    pub group: String,
    pub points: Vec<(f64, f64)>,
    pub reference: bool,
    /// Error bars, one per point (empty: none): a measured quantity's interval.
    pub bars: Vec<Bar>,
}

/// A point's error bars: its interval along x and along y (each optional).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Bar {
    pub x: Option<(f64, f64)>,
    pub y: Option<(f64, f64)>,
}

impl Series {
    /// A model's curve.
    pub fn model(name: impl Into<String>, points: Vec<(f64, f64)>) -> Series {
        Series { name: name.into(), group: String::new(), points, reference: false, bars: Vec::new() }
    }
    /// A reference set's points (CONTACT, the thesis).
    pub fn reference(name: impl Into<String>, points: Vec<(f64, f64)>) -> Series {
        Series { name: name.into(), group: String::new(), points, reference: true, bars: Vec::new() }
    }
    /// The same series in `group`.
    pub fn in_group(self, group: impl Into<String>) -> Series {
        Series { group: group.into(), ..self }
    }
    /// The same series with error bars, one per point.
    pub fn with_bars(self, bars: Vec<Bar>) -> Series {
        Series { bars, ..self }
    }
    /// The points and the ends of their error bars (what the axes must hold).
    pub fn extent(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        let ends = self.points.iter().zip(&self.bars).flat_map(|(&(x, y), b)| {
            let xs = b.x.into_iter().flat_map(move |(lo, hi)| [(lo, y), (hi, y)]);
            xs.chain(b.y.into_iter().flat_map(move |(lo, hi)| [(x, lo), (x, hi)]))
        });
        self.points.iter().copied().chain(ends)
    }
    /// How the series is drawn.
    pub fn style(&self) -> style::Style {
        style::of(&self.name, self.reference)
    }
}

/// A line chart as SVG text: one panel, or small multiples on shared axes ([`panels`]).
pub fn line_chart(title: &str, x: &Axis, y: &Axis, series: &[Series]) -> String {
    let drawn: Vec<&Series> =
        series.iter().filter(|s| s.points.iter().any(|p| p.0.is_finite() && p.1.is_finite())).collect();
    chart::draw(title, x, y, &panels(&drawn))
}

/// The panels of a chart: all series in one when there are at most
/// [`MAX_SERIES_PER_PANEL`] model curves, no two of the same model; else one panel per model
/// curve with the references of its group (at most [`MAX_PANELS`]); else one per group.
fn panels<'a>(series: &[&'a Series]) -> Vec<chart::Panel<'a>> {
    let lines: Vec<&Series> = series.iter().copied().filter(|s| !s.reference).collect();
    let alike = lines.iter().enumerate().any(|(i, a)| lines[..i].iter().any(|b| b.name == a.name));
    if lines.len() <= MAX_SERIES_PER_PANEL && !alike {
        return vec![chart::Panel { title: String::new(), series: series.to_vec() }];
    }
    let mut groups: Vec<&str> = Vec::new();
    for s in series {
        if !groups.contains(&s.group.as_str()) {
            groups.push(&s.group);
        }
    }
    let references =
        |g: &str| -> Vec<&Series> { series.iter().copied().filter(|s| s.reference && s.group == g).collect() };
    let mut out = Vec::new();
    for g in groups {
        let in_group: Vec<&Series> = lines.iter().copied().filter(|s| s.group == g).collect();
        if lines.len() <= MAX_PANELS {
            for s in in_group {
                let title = if g.is_empty() { s.name.clone() } else { format!("{}, {g}", s.name) };
                out.push(chart::Panel { title, series: std::iter::once(s).chain(references(g)).collect() });
            }
        } else {
            out.push(chart::Panel {
                title: g.to_string(),
                series: in_group.into_iter().chain(references(g)).collect(),
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    fn one(points: &[(f64, f64)]) -> Vec<Series> {
        vec![Series::model("uba", points.to_vec())]
    }

    const BIG: f64 = 1.7e308;

    /// Hostile histories: huge finite values, non-finite ones, all equal, empty.
    fn hostile() -> Vec<(&'static str, Vec<Series>)> {
        vec![
            ("±1.7e308", one(&[(0.0, -BIG), (1.0, BIG), (2.0, 0.0)])),
            ("huge x", one(&[(-BIG, 0.0), (BIG, 1.0)])),
            ("f64::MAX", one(&[(f64::MIN, f64::MIN), (f64::MAX, f64::MAX)])),
            ("NaN and inf", one(&[(f64::NAN, 1.0), (1.0, f64::INFINITY), (f64::NEG_INFINITY, 2.0)])),
            ("NaN with one finite point", one(&[(f64::NAN, f64::NAN), (3.0, 4.0)])),
            ("all equal", one(&[(1.0, 0.3), (1.0, 0.3), (1.0, 0.3)])),
            ("all zero", one(&[(0.0, 0.0), (0.0, 0.0)])),
            ("all 1e300", one(&[(1e300, 1e300), (1e300, 1e300)])),
            ("subnormal", one(&[(5e-324, 5e-324), (1e-323, -5e-324)])),
            ("huge and nearly equal", one(&[(0.0, 1e300), (1.0, 1e300 * (1.0 + 1e-15))])),
            ("empty series", one(&[])),
            ("no series", vec![]),
        ]
    }

    #[test]
    fn axis_ranges_are_finite_and_increasing_for_hostile_values() {
        for (name, s) in hostile() {
            for log in [false, true] {
                let pts = || s.iter().flat_map(|s| s.points.iter());
                let xs = axis::Scale::over(pts().map(|p| p.0), log);
                let ys = axis::Scale::over(pts().map(|p| p.1), log);
                for a in [xs, ys] {
                    let (lo, hi) = (a.lo, a.hi);
                    assert!(lo.is_finite() && hi.is_finite() && lo < hi, "{name} log={log}: {lo}..{hi}");
                    assert!((hi - lo).is_finite(), "{name}: span of {lo}..{hi}");
                    assert!(hi - lo > 1e-9 * lo.abs().max(hi.abs()), "{name}: negligible span {lo}..{hi}");
                    if log {
                        assert!(lo > 0.0 && (hi / lo).is_finite(), "{name}: log axis {lo}..{hi}");
                    }
                }
            }
        }
    }

    #[test]
    fn charts_of_hostile_values_finish_with_labelled_ticks() {
        // Drawn on another thread with a deadline: a tick search that never ends fails the test
        // instead of hanging it.
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            for (name, s) in hostile() {
                for log in [false, true] {
                    let svg = line_chart(name, &Axis::linear("x [–]"), &Axis { title: "y [–]".into(), log }, &s);
                    tx.send((name, log, svg)).unwrap();
                }
            }
        });
        for _ in 0..2 * hostile().len() {
            let (name, log, svg) = rx.recv_timeout(Duration::from_secs(30)).expect("a chart never finished");
            assert!(svg.matches(r#"class="tick x""#).count() >= 2, "{name} log={log}: {svg}");
            assert!(svg.matches(r#"class="tick y""#).count() >= 2, "{name} log={log}: {svg}");
            let drawn: String = svg.lines().filter(|l| !l.contains(r#"class="title""#)).collect();
            assert!(!drawn.contains("NaN") && !drawn.contains("inf"), "{name} log={log}: {svg}");
        }
    }

    fn names(panels: &[chart::Panel<'_>]) -> Vec<Vec<String>> {
        panels.iter().map(|p| p.series.iter().map(|s| format!("{}{}", s.name, s.group)).collect()).collect()
    }

    #[test]
    fn many_series_become_one_panel_per_model_with_the_references_of_its_group() {
        let models = ["contact", "uba", "fastsim", "linear", "she", "polach", "fastrip", "relaxation"];
        let few: Vec<Series> = models[..3].iter().map(|m| Series::model(*m, vec![])).collect();
        assert_eq!(panels(&few.iter().collect::<Vec<_>>()).len(), 1);
        let mut all: Vec<Series> = models.iter().map(|m| Series::model(*m, vec![])).collect();
        all.push(Series::reference("CONTACT", vec![]));
        let p = panels(&all.iter().collect::<Vec<_>>());
        assert_eq!(p.len(), 8);
        assert_eq!(names(&p)[1], ["uba", "CONTACT"]);
        assert_eq!(p[1].title, "uba");
        // Two groups of two models: the same model twice is never in one panel.
        let grouped: Vec<Series> = ["a", "b"]
            .iter()
            .flat_map(|g| {
                [Series::model("uba", vec![]).in_group(*g), Series::reference("CONTACT", vec![]).in_group(*g)]
            })
            .collect();
        assert_eq!(
            names(&panels(&grouped.iter().collect::<Vec<_>>())),
            [vec!["ubaa", "CONTACTa"], vec!["ubab", "CONTACTb"]]
        );
        // 20 groups of 8 models: one panel per group.
        let huge: Vec<Series> = (0..20)
            .flat_map(|g| models.iter().map(move |m| Series::model(*m, vec![]).in_group(g.to_string())))
            .collect();
        assert_eq!(panels(&huge.iter().collect::<Vec<_>>()).len(), 20);
    }

    #[test]
    fn the_legend_stands_right_of_the_plot_areas() {
        let mut s: Vec<Series> =
            ["uba", "fastsim"].iter().map(|m| Series::model(*m, vec![(1.0, 0.1), (2.0, 0.2)])).collect();
        s.push(Series::reference("CONTACT", vec![(1.5, 0.15)]));
        s.push(Series::reference("thesis", vec![(f64::NAN, 0.1)]));
        let svg = line_chart("t", &Axis::linear("t [s]"), &Axis::linear("f_x / F_N [–]"), &s);
        let legend_x: f64 = svg
            .split(r#"<g class="legend" transform="translate("#)
            .nth(1)
            .unwrap()
            .split(',')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        let panel = svg
            .split(r#"<g class="panel" data-width="560.0" data-height="320.0" transform="translate("#)
            .nth(1)
            .unwrap();
        let panel_x: f64 = panel.split(',').next().unwrap().parse().unwrap();
        assert!(legend_x >= panel_x + 560.0, "legend at {legend_x}, plot area from {panel_x}");
        assert!(svg.contains(r##"data-model="CONTACT" data-reference="true" data-color="#000000""##), "{svg}");
        assert!(!svg.contains("thesis"), "a series with nothing to draw is left out, legend too: {svg}");
    }
}
