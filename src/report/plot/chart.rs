//! Line charts: one panel or a grid of small multiples on shared axes, axis titles once, the
//! legend right of the panels (outside the data).

use super::axis::{self, Scale, Ticks, TICK_FONT_PX};
use super::style::{self, Style};
use super::svg::Svg;
use super::{Axis, Series};

/// One panel of a chart: its title (empty for a single panel) and the series it draws.
pub struct Panel<'a> {
    pub title: String,
    pub series: Vec<&'a Series>,
}

/// Sizes of a layout [px].
struct Layout {
    plot: (f64, f64),
    left: f64,
    bottom: f64,
    above: f64,
    cols: usize,
}

impl Layout {
    fn of(panels: usize) -> Layout {
        if panels <= 1 {
            Layout { plot: (560.0, 320.0), left: 74.0, bottom: 34.0, above: 8.0, cols: 1 }
        } else {
            Layout { plot: (210.0, 140.0), left: 62.0, bottom: 30.0, above: 22.0, cols: panels.min(4) }
        }
    }
    fn cell(&self) -> (f64, f64) {
        (self.left + self.plot.0 + 16.0, self.above + self.plot.1 + self.bottom)
    }
}

const PAGE_LEFT: f64 = 26.0;
const PAGE_TOP: f64 = 40.0;
const PAGE_BOTTOM: f64 = 34.0;
const LEGEND_FONT_PX: f64 = 12.0;
const TITLE_FONT_PX: f64 = 15.0;
const TITLE_LINE_PX: f64 = 19.0;

/// `text` in lines of at most `width` characters, broken at spaces (a longer word stays whole).
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(line) if line.chars().count() + 1 + word.chars().count() <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

/// The chart as SVG text.
pub fn draw(title: &str, x: &Axis, y: &Axis, panels: &[Panel<'_>]) -> String {
    let layout = Layout::of(panels.len());
    let all = || panels.iter().flat_map(|p| p.series.iter());
    let xs = Scale::over(all().flat_map(|s| s.extent().map(|p| p.0)), x.log);
    let ys = Scale::over(all().flat_map(|s| s.extent().map(|p| p.1)), y.log);
    let (xt, yt) = (axis::ticks(&xs, layout.plot.0, true), axis::ticks(&ys, layout.plot.1, false));
    let legend = legend_entries(panels);
    let legend_w = legend.iter().map(|(l, _, _)| axis::text_width(l, LEGEND_FONT_PX)).fold(0.0, f64::max) + 52.0;
    let rows = panels.len().max(1).div_ceil(layout.cols);
    let (cw, ch) = layout.cell();
    let grid_w = PAGE_LEFT + layout.cols as f64 * cw;
    let legend_h = 26.0 + 18.0 * legend.len() as f64;
    let width = grid_w + legend_w + 12.0;
    let title_lines = wrap(title, ((width - 24.0) / axis::text_width("x", TITLE_FONT_PX)) as usize);
    let top = PAGE_TOP + TITLE_LINE_PX * (title_lines.len().max(1) - 1) as f64;
    let height = (top + rows as f64 * ch + PAGE_BOTTOM).max(top + legend_h);
    let mut svg = Svg::new(width, height);
    for (k, line) in title_lines.iter().enumerate() {
        svg.text((width / 2.0, 24.0 + TITLE_LINE_PX * k as f64), line, TITLE_FONT_PX, "middle", "title", false);
    }
    for (i, panel) in panels.iter().enumerate() {
        let origin = (
            PAGE_LEFT + (i % layout.cols) as f64 * cw + layout.left,
            top + (i / layout.cols) as f64 * ch + layout.above,
        );
        draw_panel(&mut svg, i, origin, &layout, panel, (&xs, &ys), (&xt, &yt));
    }
    let grid_mid = PAGE_LEFT + layout.left / 2.0 + (grid_w - PAGE_LEFT) / 2.0;
    svg.text((grid_mid, height - 10.0), &x.title, 13.0, "middle", "axis-title x", false);
    svg.text((14.0, top + rows as f64 * ch / 2.0), &y.title, 13.0, "middle", "axis-title y", true);
    draw_legend(&mut svg, (grid_w + 6.0, top), &legend);
    svg.finish()
}

/// The legend: each series name once (models first, then references) with its style.
fn legend_entries(panels: &[Panel<'_>]) -> Vec<(String, Style, bool)> {
    let mut out: Vec<(String, Style, bool)> = Vec::new();
    for reference in [false, true] {
        for s in panels.iter().flat_map(|p| p.series.iter()).filter(|s| s.reference == reference) {
            if !out.iter().any(|(n, _, r)| *n == s.name && *r == reference) {
                out.push((s.name.clone(), s.style(), reference));
            }
        }
    }
    out
}

fn draw_legend(svg: &mut Svg, (x, y): (f64, f64), entries: &[(String, Style, bool)]) {
    svg.raw(&format!(r#"<g class="legend" transform="translate({x:.1},{y:.1})">"#));
    for (k, (name, style, reference)) in entries.iter().enumerate() {
        let cy = 10.0 + 18.0 * k as f64;
        svg.raw(&format!(
            r#"<g class="legend-entry" data-model="{}" data-reference="{reference}" data-color="{}" data-marker="{}">"#,
            super::svg::escape(name),
            style.color,
            style.marker.name()
        ));
        if !reference {
            svg.polyline(&[(4.0, cy), (36.0, cy)], style, 2.0);
        }
        svg.marker((20.0, cy), style, 3.5);
        svg.text((44.0, cy + 4.0), name, LEGEND_FONT_PX, "start", "legend-label", false);
        svg.raw("</g>");
    }
    svg.raw("</g>");
}

/// One panel at `origin` (its plot area's top left corner).
fn draw_panel(
    svg: &mut Svg,
    index: usize,
    origin: (f64, f64),
    layout: &Layout,
    panel: &Panel<'_>,
    (xs, ys): (&Scale, &Scale),
    (xt, yt): (&Ticks, &Ticks),
) {
    let (w, h) = layout.plot;
    svg.raw(&format!(
        r#"<g class="panel" data-width="{w:.1}" data-height="{h:.1}" transform="translate({:.1},{:.1})">"#,
        origin.0, origin.1
    ));
    svg.raw(&format!(r#"<clipPath id="plot{index}"><rect x="0" y="0" width="{w:.1}" height="{h:.1}"/></clipPath>"#));
    let (px, py) = (|v: f64| xs.frac(v) * w, |v: f64| (1.0 - ys.frac(v)) * h);
    for (v, label) in &xt.major {
        svg.line((px(*v), 0.0), (px(*v), h), "#e6e6e6", 1.0);
        svg.line((px(*v), h), (px(*v), h + 5.0), "#444444", 1.0);
        svg.text((px(*v), h + 17.0), label, TICK_FONT_PX, "middle", "tick x", false);
    }
    for v in &xt.minor {
        svg.line((px(*v), h), (px(*v), h + 3.0), "#444444", 0.8);
    }
    for (v, label) in &yt.major {
        svg.line((0.0, py(*v)), (w, py(*v)), "#e6e6e6", 1.0);
        svg.line((-5.0, py(*v)), (0.0, py(*v)), "#444444", 1.0);
        svg.text((-8.0, py(*v) + 4.0), label, TICK_FONT_PX, "end", "tick y", false);
    }
    for v in &yt.minor {
        svg.line((-3.0, py(*v)), (0.0, py(*v)), "#444444", 0.8);
    }
    if !panel.title.is_empty() {
        svg.text((w / 2.0, -7.0), &panel.title, 12.0, "middle", "panel-title", false);
    }
    svg.raw(&format!(r#"<g clip-path="url(#plot{index})">"#));
    // References first: the models' lines stay visible over dense reference markers.
    let (references, lines): (Vec<&&Series>, Vec<&&Series>) = panel.series.iter().partition(|s| s.reference);
    for s in references.into_iter().chain(lines) {
        let style = s.style();
        let pts: Vec<(f64, f64)> = s
            .points
            .iter()
            .filter_map(|&(x, y)| Some((axis::plottable(x, xs.log)?, axis::plottable(y, ys.log)?)))
            .map(|(x, y)| (px(x), py(y)))
            .collect();
        svg.raw(&format!(
            r#"<g class="series" data-model="{}" data-reference="{}" data-color="{}" data-marker="{}">"#,
            super::svg::escape(&s.name),
            s.reference,
            style.color,
            style.marker.name()
        ));
        if !s.reference {
            svg.polyline(&pts, &style, 1.8);
        }
        draw_bars(svg, s, (xs, ys), (w, h));
        let r = match (s.reference, pts.len()) {
            (false, _) => 3.5,
            (true, n) if n <= 40 => 3.0,
            (true, _) => 2.2,
        };
        for p in marked(&pts, s.reference, &style) {
            svg.marker(p, &style, r);
        }
        svg.raw("</g>");
    }
    svg.raw("</g>");
    svg.rect((0.0, 0.0), (w, h), "none", Some(("#444444", 1.0)));
    svg.raw("</g>");
}

/// A series' error bars: a line over each interval with a cap at each end (ends off the axis
/// drawn at its edge).
fn draw_bars(svg: &mut Svg, s: &Series, (xs, ys): (&Scale, &Scale), (w, h): (f64, f64)) {
    const CAP: f64 = 3.0;
    let px = |v: f64| axis::plottable(v, xs.log).map(|v| xs.frac(v) * w);
    let py = |v: f64| axis::plottable(v, ys.log).map(|v| (1.0 - ys.frac(v)) * h);
    let style = s.style();
    for (&(x, y), bar) in s.points.iter().zip(&s.bars) {
        let (Some(cx), Some(cy)) = (px(x), py(y)) else { continue };
        if let Some((Some(a), Some(b))) = bar.x.map(|(lo, hi)| (px(lo), px(hi))) {
            svg.bar(
                &format!(
                    "M{a:.1},{cy:.1}H{b:.1}M{a:.1},{:.1}V{:.1}M{b:.1},{:.1}V{:.1}",
                    cy - CAP,
                    cy + CAP,
                    cy - CAP,
                    cy + CAP
                ),
                &style,
            );
        }
        if let Some((Some(a), Some(b))) = bar.y.map(|(lo, hi)| (py(lo), py(hi))) {
            svg.bar(
                &format!(
                    "M{cx:.1},{a:.1}V{b:.1}M{:.1},{a:.1}H{:.1}M{:.1},{b:.1}H{:.1}",
                    cx - CAP,
                    cx + CAP,
                    cx - CAP,
                    cx + CAP
                ),
                &style,
            );
        }
    }
}

/// The points that get a marker: every point of a reference or a short line, else about eight
/// along the line, offset by the marker kind so that models' markers do not stack.
fn marked(pts: &[(f64, f64)], reference: bool, style: &Style) -> Vec<(f64, f64)> {
    if reference || pts.len() <= 12 {
        return pts.to_vec();
    }
    let step = pts.len().div_ceil(8);
    let phase = style::Marker::ALL.iter().position(|m| *m == style.marker).unwrap_or(0) * step / 8;
    pts.iter().skip(phase).step_by(step).copied().collect()
}

#[cfg(test)]
mod tests {
    #[test]
    fn long_titles_wrap_at_spaces() {
        assert_eq!(super::wrap("a bb ccc dddd", 6), ["a bb", "ccc", "dddd"]);
        assert_eq!(super::wrap("short", 60), ["short"]);
    }
}
