//! A minimal SVG writer: the few elements the figures need, numbers to 0.1 px, text escaped.

use super::style::{Marker, Style};
use std::fmt::Write;

/// An SVG document being written.
pub struct Svg {
    out: String,
}

/// `text` with the XML special characters escaped.
pub fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

impl Svg {
    /// A white `width × height` page.
    pub fn new(width: f64, height: f64) -> Svg {
        let mut out = String::new();
        let _ = writeln!(
            out,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0}" height="{height:.0}" viewBox="0 0 {width:.0} {height:.0}" font-family="DejaVu Sans, Arial, Helvetica, sans-serif">"#
        );
        let _ = writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#);
        Svg { out }
    }

    /// Raw markup (an opening or closing group, a clip path).
    pub fn raw(&mut self, markup: &str) {
        self.out.push_str(markup);
        self.out.push('\n');
    }

    pub fn line(&mut self, (x0, y0): (f64, f64), (x1, y1): (f64, f64), stroke: &str, width: f64) {
        let _ = writeln!(
            self.out,
            r#"<line x1="{x0:.1}" y1="{y0:.1}" x2="{x1:.1}" y2="{y1:.1}" stroke="{stroke}" stroke-width="{width}"/>"#
        );
    }

    pub fn rect(&mut self, (x, y): (f64, f64), (w, h): (f64, f64), fill: &str, stroke: Option<(&str, f64)>) {
        let stroke = stroke.map(|(s, w)| format!(r#" stroke="{s}" stroke-width="{w}""#)).unwrap_or_default();
        let _ =
            writeln!(self.out, r#"<rect x="{x:.1}" y="{y:.1}" width="{w:.1}" height="{h:.1}" fill="{fill}"{stroke}/>"#);
    }

    /// Text at (x, y) of class `class`; `anchor` start, middle or end; `rotate` −90 for a
    /// vertical axis title.
    pub fn text(&mut self, (x, y): (f64, f64), text: &str, size: f64, anchor: &str, class: &str, rotate: bool) {
        let rot = if rotate { format!(r#" transform="rotate(-90 {x:.1} {y:.1})""#) } else { String::new() };
        let _ = writeln!(
            self.out,
            r#"<text class="{class}" x="{x:.1}" y="{y:.1}" font-size="{size}" text-anchor="{anchor}"{rot}>{}</text>"#,
            escape(text)
        );
    }

    /// A polyline of `points` [px] in the style's colour and dash.
    pub fn polyline(&mut self, points: &[(f64, f64)], style: &Style, width: f64) {
        let mut p = String::new();
        for (x, y) in points {
            let _ = write!(p, "{x:.1},{y:.1} ");
        }
        let dash = style.dash.dasharray();
        let dash = if dash.is_empty() { String::new() } else { format!(r#" stroke-dasharray="{dash}""#) };
        let _ = writeln!(
            self.out,
            r#"<polyline points="{}" fill="none" stroke="{}" stroke-width="{width}" stroke-linejoin="round"{dash}/>"#,
            p.trim_end(),
            style.color
        );
    }

    /// An error bar: the path `d` [px] in the style's colour, solid.
    pub fn bar(&mut self, d: &str, style: &Style) {
        let _ = writeln!(
            self.out,
            r#"<path class="error-bar" d="{d}" fill="none" stroke="{}" stroke-width="1.2"/>"#,
            style.color
        );
    }

    /// The style's marker centred at (x, y), `r` px from centre to edge.
    pub fn marker(&mut self, (x, y): (f64, f64), style: &Style, r: f64) {
        let fill = if style.filled { style.color } else { "white" };
        let paint = format!(r#"fill="{fill}" stroke="{}" stroke-width="1.2""#, style.color);
        let line_paint = format!(r#"fill="none" stroke="{}" stroke-width="1.8""#, style.color);
        let poly = |pts: &[(f64, f64)]| {
            let d: Vec<String> = pts.iter().map(|(dx, dy)| format!("{:.1},{:.1}", x + dx * r, y + dy * r)).collect();
            format!(r#"<polygon points="{}" {paint}/>"#, d.join(" "))
        };
        let path = |d: String| format!(r#"<path d="{d}" {line_paint}/>"#);
        let markup = match style.marker {
            Marker::Circle => format!(r#"<circle cx="{x:.1}" cy="{y:.1}" r="{r:.1}" {paint}/>"#),
            Marker::Square => poly(&[(-0.85, -0.85), (0.85, -0.85), (0.85, 0.85), (-0.85, 0.85)]),
            Marker::TriangleUp => poly(&[(0.0, -1.15), (1.0, 0.6), (-1.0, 0.6)]),
            Marker::TriangleDown => poly(&[(0.0, 1.15), (1.0, -0.6), (-1.0, -0.6)]),
            Marker::TriangleLeft => poly(&[(-1.15, 0.0), (0.6, -1.0), (0.6, 1.0)]),
            Marker::TriangleRight => poly(&[(1.15, 0.0), (-0.6, -1.0), (-0.6, 1.0)]),
            Marker::Diamond => poly(&[(0.0, -1.2), (1.0, 0.0), (0.0, 1.2), (-1.0, 0.0)]),
            Marker::Star => poly(&star()),
            Marker::Plus => path(format!(
                "M{:.1},{y:.1}H{:.1}M{x:.1},{:.1}V{:.1}",
                x - 1.2 * r,
                x + 1.2 * r,
                y - 1.2 * r,
                y + 1.2 * r
            )),
            Marker::Cross => path(format!(
                "M{:.1},{:.1}L{:.1},{:.1}M{:.1},{:.1}L{:.1},{:.1}",
                x - r,
                y - r,
                x + r,
                y + r,
                x - r,
                y + r,
                x + r,
                y - r
            )),
        };
        self.out.push_str(&markup);
        self.out.push('\n');
    }

    /// The finished document.
    pub fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }
}

/// A five-pointed star's corners around the origin (outer radius 1.25).
fn star() -> Vec<(f64, f64)> {
    (0..10)
        .map(|k| {
            let a = std::f64::consts::PI * (f64::from(k) / 5.0 - 0.5);
            let r = if k % 2 == 0 { 1.25 } else { 0.5 };
            (r * a.cos(), r * a.sin())
        })
        .collect()
}
