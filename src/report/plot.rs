//! SVG line plots for the report (plotters, SVG backend only).

use plotters::prelude::*;

/// One curve: legend label, points, and whether it is drawn as markers (references) or a line.
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
    pub markers: bool,
}

const COLORS: [RGBColor; 6] = [
    RGBColor(0, 0, 0),
    RGBColor(214, 39, 40),
    RGBColor(31, 119, 180),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
];

/// Largest magnitude plotted: larger values are drawn at it, so that an axis span and its
/// padding stay finite (an infinite or NaN range makes plotters' tick search never end).
const PLOT_LIMIT: f64 = 1e300;
/// Smallest positive x on a log axis, and the widest log axis in decades: the ratio of the
/// ends stays finite, and so does the count of decades plotters steps through.
const LOG_DECADES: i32 = 300;
/// A span below this fraction of the values' magnitude is drawn as if all values were equal.
const NEGLIGIBLE_SPAN: f64 = 1e-9;

/// A point as plotted: `None` for non-finite values (and x ≤ 0 on a log axis), magnitudes
/// clamped to [`PLOT_LIMIT`].
fn plottable((x, y): (f64, f64), log_x: bool) -> Option<(f64, f64)> {
    if !x.is_finite() || !y.is_finite() || (log_x && x <= 0.0) {
        return None;
    }
    let x = if log_x { x.clamp(10f64.powi(-LOG_DECADES), PLOT_LIMIT) } else { x.clamp(-PLOT_LIMIT, PLOT_LIMIT) };
    Some((x, y.clamp(-PLOT_LIMIT, PLOT_LIMIT)))
}

/// Axis ranges: finite, increasing, with a finite span, whatever the values.
fn bounds(series: &[Series], log_x: bool) -> ((f64, f64), (f64, f64)) {
    let pts = series.iter().flat_map(|s| s.points.iter()).filter_map(|&p| plottable(p, log_x));
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for (x, y) in pts {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if !x0.is_finite() {
        return (if log_x { (1.0, 10.0) } else { (0.0, 1.0) }, (0.0, 1.0));
    }
    let x = if log_x { log_axis(x0, x1) } else { linear_axis(x0, x1) };
    (x, linear_axis(y0, y1))
}

/// A linear axis over finite `lo ≤ hi` (|·| ≤ [`PLOT_LIMIT`]) padded by 5 %; values (nearly)
/// equal get an axis of ± half their magnitude around them, or ± 1 around zero.
fn linear_axis(lo: f64, hi: f64) -> (f64, f64) {
    let magnitude = lo.abs().max(hi.abs());
    let span = hi - lo;
    if span > NEGLIGIBLE_SPAN * magnitude {
        let pad = 0.05 * span;
        return (lo - pad, hi + pad);
    }
    let mid = 0.5 * (lo + hi);
    let half = if magnitude > 1e-290 { 0.5 * magnitude } else { 1.0 };
    (mid - half, mid + half)
}

/// A log axis over positive `lo ≤ hi`: at most [`LOG_DECADES`] decades (cut at the small end),
/// equal values get a decade around them.
fn log_axis(lo: f64, hi: f64) -> (f64, f64) {
    let lo = lo.max(hi / 10f64.powi(LOG_DECADES));
    if hi > lo * (1.0 + NEGLIGIBLE_SPAN) {
        (lo, hi)
    } else {
        (lo / 10f64.sqrt(), hi * 10f64.sqrt())
    }
}

/// A line chart as SVG text. `log_x` puts x on a log scale (positive x only).
pub fn line_chart(title: &str, x_label: &str, y_label: &str, series: &[Series], log_x: bool) -> String {
    render((720, 420), title, |root| draw(root, title, x_label, y_label, series, log_x))
}

/// An SVG of `size` drawn by `paint`; a drawing error is a warning naming the figure `title`
/// (the figure stays, possibly incomplete).
fn render(size: (u32, u32), title: &str, paint: impl FnOnce(&Area<'_>) -> Result<(), DrawError>) -> String {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        if let Err(e) = paint(&root) {
            eprintln!("warning: figure {title:?}: {e}");
        }
        let _ = root.present();
    }
    svg
}

/// The drawing area of an SVG figure.
type Area<'a> = DrawingArea<SVGBackend<'a>, plotters::coord::Shift>;

/// Why plotters could not draw (part of) a figure: its own error type over the SVG backend's.
type DrawError = DrawingAreaErrorKind<<SVGBackend<'static> as DrawingBackend>::ErrorType>;

fn draw(root: &Area<'_>, title: &str, xl: &str, yl: &str, series: &[Series], log_x: bool) -> Result<(), DrawError> {
    root.fill(&WHITE)?;
    let ((x0, x1), (y0, y1)) = bounds(series, log_x);
    let mut builder = ChartBuilder::on(root);
    builder.caption(title, ("sans-serif", 18)).margin(12).x_label_area_size(40).y_label_area_size(70);
    macro_rules! body {
        ($chart:expr) => {{
            let mut chart = $chart;
            chart.configure_mesh().x_desc(xl).y_desc(yl).light_line_style(RGBColor(235, 235, 235)).draw()?;
            for (k, s) in series.iter().enumerate() {
                let color = COLORS[k % COLORS.len()];
                let pts: Vec<(f64, f64)> = s.points.iter().filter_map(|&p| plottable(p, log_x)).collect();
                if s.markers {
                    chart
                        .draw_series(pts.iter().map(|&p| Circle::new(p, 2, color.filled())))?
                        .label(s.label.clone())
                        .legend(move |(x, y)| Circle::new((x + 10, y), 3, color.filled()));
                } else {
                    chart
                        .draw_series(LineSeries::new(pts, color.stroke_width(2)))?
                        .label(s.label.clone())
                        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2)));
                }
            }
            chart.configure_series_labels().background_style(WHITE.mix(0.85)).border_style(BLACK).draw()?;
        }};
    }
    if log_x {
        body!(builder.build_cartesian_2d((x0..x1).log_scale(), y0..y1)?);
    } else {
        body!(builder.build_cartesian_2d(x0..x1, y0..y1)?);
    }
    Ok(())
}

/// One element of a patch map: centre (x, y) [mm], pressure [MPa], whether it slips.
pub type PatchCell = (f64, f64, f64, bool);

/// A contact patch as a map of elements `dx × dy` [mm]: the pressure as shade (white at zero,
/// dark at the largest), slipping elements outlined in red, adhesion unmarked.
pub fn patch_map(title: &str, cells: &[PatchCell], (dx, dy): (f64, f64)) -> String {
    render((520, 440), title, |root| draw_patch(root, title, cells, (dx, dy)))
}

fn draw_patch(root: &Area<'_>, title: &str, cells: &[PatchCell], (dx, dy): (f64, f64)) -> Result<(), DrawError> {
    root.fill(&WHITE)?;
    let finite: Vec<PatchCell> =
        cells.iter().copied().filter(|c| c.0.is_finite() && c.1.is_finite() && c.2.is_finite()).collect();
    let span = |f: fn(&PatchCell) -> f64, h: f64| {
        let (lo, hi) =
            finite.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| (lo.min(f(c)), hi.max(f(c))));
        if lo.is_finite() && h.is_finite() && h > 0.0 {
            (lo - h, hi + h)
        } else {
            (0.0, 1.0)
        }
    };
    let ((x0, x1), (y0, y1)) = (span(|c| c.0, dx), span(|c| c.1, dy));
    let p_max = finite.iter().fold(0.0f64, |m, c| m.max(c.2));
    let mut chart = ChartBuilder::on(root)
        .caption(format!("{title} (p max {p_max:.0} MPa)"), ("sans-serif", 15))
        .margin(10)
        .x_label_area_size(36)
        .y_label_area_size(46)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart.configure_mesh().disable_mesh().x_desc("x [mm] (CONTACT)").y_desc("y [mm]").draw()?;
    let corners = |c: &PatchCell| [(c.0 - dx / 2.0, c.1 - dy / 2.0), (c.0 + dx / 2.0, c.1 + dy / 2.0)];
    chart.draw_series(finite.iter().filter(|c| c.2 > 0.0).map(|c| {
        let t = if p_max > 0.0 { c.2 / p_max } else { 0.0 };
        let shade = (235.0 - 200.0 * t).round().clamp(0.0, 255.0) as u8;
        Rectangle::new(corners(c), RGBColor(shade, shade, shade.saturating_add(40)).filled())
    }))?;
    chart.draw_series(
        finite.iter().filter(|c| c.3).map(|c| Rectangle::new(corners(c), RGBColor(214, 39, 40).stroke_width(1))),
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    fn series(points: &[(f64, f64)]) -> Vec<Series> {
        vec![Series { label: "s".into(), points: points.to_vec(), markers: false }]
    }

    const BIG: f64 = 1.7e308;

    /// Hostile histories: huge finite values, non-finite ones, all equal, empty.
    fn hostile() -> Vec<(&'static str, Vec<Series>)> {
        vec![
            ("±1.7e308", series(&[(0.0, -BIG), (1.0, BIG), (2.0, 0.0)])),
            ("huge x", series(&[(-BIG, 0.0), (BIG, 1.0)])),
            ("f64::MAX", series(&[(f64::MIN, f64::MIN), (f64::MAX, f64::MAX)])),
            ("NaN and inf", series(&[(f64::NAN, 1.0), (1.0, f64::INFINITY), (f64::NEG_INFINITY, 2.0)])),
            ("NaN with one finite point", series(&[(f64::NAN, f64::NAN), (3.0, 4.0)])),
            ("all equal", series(&[(1.0, 0.3), (1.0, 0.3), (1.0, 0.3)])),
            ("all zero", series(&[(0.0, 0.0), (0.0, 0.0)])),
            ("all 1e300", series(&[(1e300, 1e300), (1e300, 1e300)])),
            ("subnormal", series(&[(5e-324, 5e-324), (1e-323, -5e-324)])),
            ("huge and nearly equal", series(&[(0.0, 1e300), (1.0, 1e300 * (1.0 + 1e-15))])),
            ("empty series", series(&[])),
            ("no series", vec![]),
        ]
    }

    #[test]
    fn axis_ranges_are_finite_and_increasing_for_hostile_values() {
        for (name, s) in hostile() {
            for log_x in [false, true] {
                let ((x0, x1), (y0, y1)) = bounds(&s, log_x);
                for (lo, hi) in [(x0, x1), (y0, y1)] {
                    assert!(lo.is_finite() && hi.is_finite() && lo < hi, "{name} log_x={log_x}: {lo}..{hi}");
                    assert!((hi - lo).is_finite(), "{name}: span of {lo}..{hi}");
                    assert!(hi - lo > 1e-9 * lo.abs().max(hi.abs()), "{name}: negligible span {lo}..{hi}");
                }
                if log_x {
                    assert!(x0 > 0.0 && (x1 / x0).is_finite(), "{name}: log axis {x0}..{x1}");
                }
            }
        }
    }

    #[test]
    fn charts_of_hostile_values_finish() {
        // Drawn on another thread with a deadline: a range that sends plotters' tick search into
        // an endless loop fails the test instead of hanging it.
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            for (name, s) in hostile() {
                for log_x in [false, true] {
                    let svg = line_chart(name, "x", "y", &s, log_x);
                    tx.send((name, log_x, svg.len())).unwrap();
                }
            }
        });
        for _ in 0..2 * hostile().len() {
            let (name, log_x, len) = rx.recv_timeout(Duration::from_secs(30)).expect("a chart never finished");
            assert!(len > 100, "{name} log_x={log_x}: empty svg");
        }
    }
}
