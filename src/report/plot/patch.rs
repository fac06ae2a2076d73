//! Patch maps: a contact patch's elements shaded by pressure (colour bar in MPa), slipping
//! elements outlined and struck through, with a key for adhesion and slip.

use super::axis::{self, Scale, TICK_FONT_PX};
use super::svg::Svg;

/// One element of a patch map: centre (x, y) [mm], pressure [MPa], whether it slips.
pub type PatchCell = (f64, f64, f64, bool);

/// ColorBrewer YlOrBr (sequential, colour-blind safe): light at zero pressure, dark at the largest.
const YL_OR_BR: [(u8, u8, u8); 9] = [
    (255, 255, 229),
    (255, 247, 188),
    (254, 227, 145),
    (254, 196, 79),
    (251, 154, 41),
    (236, 112, 20),
    (204, 76, 2),
    (153, 52, 4),
    (102, 37, 6),
];

/// The colour of `t` ∈ [0, 1] on the scale (linear between the stops).
fn shade(t: f64) -> String {
    let t = if t.is_finite() { t.clamp(0.0, 1.0) } else { 0.0 } * (YL_OR_BR.len() - 1) as f64;
    let k = (t.floor() as usize).min(YL_OR_BR.len() - 2);
    let f = t - k as f64;
    let mix = |a: u8, b: u8| (f64::from(a) + f * (f64::from(b) - f64::from(a))).round() as u8;
    let (a, b) = (YL_OR_BR[k], YL_OR_BR[k + 1]);
    format!("#{:02x}{:02x}{:02x}", mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

const SLIP_STROKE: &str = "#000000";
const PLOT: (f64, f64) = (380.0, 330.0);
const LEFT: f64 = 64.0;
const TOP: f64 = 46.0;
const BAR: (f64, f64) = (16.0, 220.0);

/// A contact patch as a map of elements `dx × dy` [mm] on equal x and y scales.
pub fn patch_map(title: &str, cells: &[PatchCell], (dx, dy): (f64, f64)) -> String {
    let finite: Vec<PatchCell> =
        cells.iter().copied().filter(|c| c.0.is_finite() && c.1.is_finite() && c.2.is_finite()).collect();
    let span = |f: fn(&PatchCell) -> f64, h: f64| {
        let (lo, hi) =
            finite.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| (lo.min(f(c)), hi.max(f(c))));
        if lo.is_finite() && h.is_finite() && h > 0.0 && (hi - lo + 2.0 * h).is_finite() {
            Scale { lo: lo - h, hi: hi + h, log: false }
        } else {
            Scale { lo: 0.0, hi: 1.0, log: false }
        }
    };
    let (xs, ys) = (span(|c| c.0, dx), span(|c| c.1, dy));
    let mm = (PLOT.0 / (xs.hi - xs.lo)).min(PLOT.1 / (ys.hi - ys.lo));
    let (w, h) = ((xs.hi - xs.lo) * mm, (ys.hi - ys.lo) * mm);
    let p_max = finite.iter().fold(0.0f64, |m, c| m.max(c.2));
    let (width, height) = (LEFT + PLOT.0 + 150.0, TOP + h.max(BAR.1 + 90.0) + 50.0);
    let mut svg = Svg::new(width, height);
    svg.text((width / 2.0, 24.0), &format!("{title} (p max {p_max:.0} MPa)"), 14.0, "middle", "title", false);
    svg.raw(&format!(
        r#"<g class="panel" data-width="{w:.1}" data-height="{h:.1}" transform="translate({LEFT:.1},{TOP:.1})">"#
    ));
    let (px, py) = (|v: f64| xs.frac(v) * w, |v: f64| (1.0 - ys.frac(v)) * h);
    svg.raw(r#"<g class="cells">"#);
    let corner = |c: &PatchCell| (px(c.0 - dx / 2.0), py(c.1 + dy / 2.0));
    let (cw, ch) = (dx * mm, dy * mm);
    for c in finite.iter().filter(|c| c.2 > 0.0) {
        svg.rect(corner(c), (cw, ch), &shade(if p_max > 0.0 { c.2 / p_max } else { 0.0 }), None);
    }
    for c in finite.iter().filter(|c| c.3) {
        slip_mark(&mut svg, corner(c), (cw, ch));
    }
    svg.raw("</g>");
    let xt = axis::ticks(&xs, w, true);
    let yt = axis::ticks(&ys, h, false);
    for (v, label) in &xt.major {
        svg.line((px(*v), h), (px(*v), h + 5.0), "#444444", 1.0);
        svg.text((px(*v), h + 17.0), label, TICK_FONT_PX, "middle", "tick x", false);
    }
    for (v, label) in &yt.major {
        svg.line((-5.0, py(*v)), (0.0, py(*v)), "#444444", 1.0);
        svg.text((-8.0, py(*v) + 4.0), label, TICK_FONT_PX, "end", "tick y", false);
    }
    svg.rect((0.0, 0.0), (w, h), "none", Some(("#444444", 1.0)));
    svg.raw("</g>");
    svg.text((LEFT + w / 2.0, TOP + h + 36.0), "x, rolling direction [mm]", 13.0, "middle", "axis-title x", false);
    svg.text((18.0, TOP + h / 2.0), "y [mm]", 13.0, "middle", "axis-title y", true);
    color_bar(&mut svg, (LEFT + PLOT.0 + 36.0, TOP + 14.0), p_max);
    svg.finish()
}

/// A slipping element: outlined and struck through in black.
fn slip_mark(svg: &mut Svg, (x, y): (f64, f64), (w, h): (f64, f64)) {
    svg.raw(r#"<g class="slip">"#);
    svg.rect((x, y), (w, h), "none", Some((SLIP_STROKE, 1.0)));
    svg.line((x, y + h), (x + w, y), SLIP_STROKE, 0.8);
    svg.raw("</g>");
}

/// The colour bar of pressures 0..`p_max` [MPa] at `(x, y)`, and under it the key for adhesion
/// and slip.
fn color_bar(svg: &mut Svg, (x, y): (f64, f64), p_max: f64) {
    svg.raw(&format!(r#"<g class="colorbar" transform="translate({x:.1},{y:.1})">"#));
    svg.text((0.0, -10.0), "p [MPa]", 12.0, "start", "colorbar-title", false);
    const STEPS: usize = 44;
    let band = BAR.1 / STEPS as f64;
    for k in 0..STEPS {
        let t = (k as f64 + 0.5) / STEPS as f64;
        svg.rect((0.0, BAR.1 - (k + 1) as f64 * band), (BAR.0, band + 0.3), &shade(t), None);
    }
    svg.rect((0.0, 0.0), BAR, "none", Some(("#444444", 1.0)));
    let scale = Scale { lo: 0.0, hi: if p_max > 0.0 && p_max.is_finite() { p_max } else { 1.0 }, log: false };
    for (v, label) in &axis::ticks(&scale, BAR.1, false).major {
        let ty = (1.0 - scale.frac(*v)) * BAR.1;
        svg.line((BAR.0, ty), (BAR.0 + 4.0, ty), "#444444", 1.0);
        svg.text((BAR.0 + 7.0, ty + 4.0), label, TICK_FONT_PX, "start", "tick y", false);
    }
    let key_y = BAR.1 + 30.0;
    svg.rect((0.0, key_y), (14.0, 14.0), &shade(0.5), None);
    svg.text((20.0, key_y + 11.0), "adhesion", 12.0, "start", "key", false);
    svg.rect((0.0, key_y + 22.0), (14.0, 14.0), &shade(0.5), None);
    slip_mark(svg, (0.0, key_y + 22.0), (14.0, 14.0));
    svg.text((20.0, key_y + 33.0), "slip", 12.0, "start", "key", false);
    svg.raw("</g>");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scale_runs_from_light_to_dark() {
        assert_eq!(shade(0.0), "#ffffe5");
        assert_eq!(shade(1.0), "#662506");
        assert_eq!(shade(f64::NAN), "#ffffe5");
    }

    #[test]
    fn a_patch_map_has_a_colour_bar_and_a_key() {
        let cells = [(0.0, 0.0, 900.0, false), (1.0, 0.0, 450.0, true), (f64::NAN, 0.0, 1.0, true)];
        let svg = patch_map("p", &cells, (1.0, 1.0));
        assert!(svg.contains("p [MPa]") && svg.contains(">adhesion<") && svg.contains(">slip<"), "{svg}");
        assert_eq!(svg.matches(r#"<g class="slip">"#).count(), 2, "one slipping cell and the key");
        assert!(svg.contains(">900<") || svg.contains(">800<"), "{svg}");
    }
}
