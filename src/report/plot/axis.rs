//! Axis ranges and ticks: finite ranges whatever the values, "nice" linear steps (1, 2, 5 × 10^k),
//! decade ticks on log axes, and tick labels that do not overlap (text extent estimated from the
//! font size and the number of characters, [`text_width`]).

/// Largest magnitude plotted: larger values are drawn at it, so that an axis span stays finite.
const PLOT_LIMIT: f64 = 1e300;
/// The widest log axis in decades (cut at the small end), so that its ends stay finite.
const LOG_DECADES: i32 = 300;
/// A span below this fraction of the values' magnitude is drawn as if all values were equal.
const NEGLIGIBLE_SPAN: f64 = 1e-9;
/// Spans and magnitudes below this are drawn as zero (steps of subnormal size underflow).
const TINY: f64 = 1e-290;
/// Font size of tick labels [px].
pub const TICK_FONT_PX: f64 = 11.0;
/// Least gap between two tick labels side by side [px].
pub const TICK_GAP_PX: f64 = 6.0;
/// Least distance between labelled ticks on a horizontal and a vertical axis [px] (a readable
/// density; labels stacked need only 1.2 font sizes not to overlap).
const MIN_TICK_SPACING_PX: (f64, f64) = (48.0, 36.0);

/// Estimated width of `text` in a sans-serif font of `font_px` (0.6 em per character: wider than
/// the digits and most letters of common sans-serif fonts).
pub fn text_width(text: &str, font_px: f64) -> f64 {
    0.6 * font_px * text.chars().count() as f64
}

/// One axis as drawn: its range and whether it is logarithmic.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scale {
    pub lo: f64,
    pub hi: f64,
    pub log: bool,
}

impl Scale {
    /// The scale over `values` (non-finite ones, and non-positive ones on a log axis, left out):
    /// finite, increasing, with a finite span; a log axis from decade to decade.
    pub fn over(values: impl Iterator<Item = f64>, log: bool) -> Scale {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in values.filter_map(|v| plottable(v, log)) {
            lo = lo.min(v);
            hi = hi.max(v);
        }
        let (lo, hi) = match (lo.is_finite(), log) {
            (false, false) => (0.0, 1.0),
            (false, true) => (1.0, 10.0),
            (true, false) => linear_range(lo, hi),
            (true, true) => decade_range(lo, hi),
        };
        Scale { lo, hi, log }
    }

    /// Where `v` falls between the ends: 0 at `lo`, 1 at `hi`.
    pub fn frac(&self, v: f64) -> f64 {
        if self.log {
            (v.log10() - self.lo.log10()) / (self.hi.log10() - self.lo.log10())
        } else {
            (v - self.lo) / (self.hi - self.lo)
        }
    }
}

/// A value as plotted: `None` when non-finite (or ≤ 0 on a log axis), clamped to
/// [`PLOT_LIMIT`] (and to 10^-[`LOG_DECADES`] from below on a log axis).
pub fn plottable(v: f64, log: bool) -> Option<f64> {
    if !v.is_finite() || (log && v <= 0.0) {
        return None;
    }
    Some(if log { v.clamp(10f64.powi(-LOG_DECADES), PLOT_LIMIT) } else { v.clamp(-PLOT_LIMIT, PLOT_LIMIT) })
}

/// A linear range over finite `lo ≤ hi` padded by 5 %; values (nearly) equal get ± half their
/// magnitude around them, or ± 1 around them when [`TINY`].
fn linear_range(lo: f64, hi: f64) -> (f64, f64) {
    let magnitude = lo.abs().max(hi.abs());
    let span = hi - lo;
    if span > NEGLIGIBLE_SPAN * magnitude && span > TINY {
        let pad = 0.05 * span;
        return (lo - pad, hi + pad);
    }
    let mid = 0.5 * (lo + hi);
    let half = if magnitude > TINY { 0.5 * magnitude } else { 1.0 };
    (mid - half, mid + half)
}

/// A log range over positive `lo ≤ hi`: from the decade at or below `lo` to the decade at or
/// above `hi` (at least one decade, at most [`LOG_DECADES`]).
fn decade_range(lo: f64, hi: f64) -> (f64, f64) {
    let d1 = (hi.log10() - 1e-9).ceil() as i32;
    let d0 = ((lo.log10() + 1e-9).floor() as i32).max(d1 - LOG_DECADES).min(d1 - 1);
    (10f64.powi(d0), 10f64.powi(d1))
}

/// An axis's ticks: labelled (major) ones and unlabelled (minor) ones.
#[derive(Debug, Clone, PartialEq)]
pub struct Ticks {
    pub major: Vec<(f64, String)>,
    pub minor: Vec<f64>,
}

/// The ticks of `scale` drawn `length_px` long, horizontal (labels side by side) or vertical
/// (labels stacked): the densest "nice" ticks at a readable spacing, else the densest of at
/// least two labels that do not overlap.
pub fn ticks(scale: &Scale, length_px: f64, horizontal: bool) -> Ticks {
    let fits = |major: &[(f64, String)], readable: bool| {
        major.windows(2).all(|w| {
            let apart = (scale.frac(w[1].0) - scale.frac(w[0].0)).abs() * length_px;
            let (least, needed) = if horizontal {
                let labels = 0.5 * (text_width(&w[0].1, TICK_FONT_PX) + text_width(&w[1].1, TICK_FONT_PX));
                (MIN_TICK_SPACING_PX.0, labels + TICK_GAP_PX)
            } else {
                (MIN_TICK_SPACING_PX.1, 1.3 * TICK_FONT_PX)
            };
            apart >= if readable { needed.max(least) } else { needed }
        })
    };
    let (candidates, minor) =
        if scale.log { log_candidates(scale) } else { (linear_candidates(scale, length_px, horizontal), Vec::new()) };
    let pick = |readable: bool| candidates.iter().find(|m| m.len() >= 2 && fits(m, readable));
    let major = pick(true).or_else(|| pick(false)).or_else(|| candidates.iter().find(|m| fits(m, false)));
    Ticks { major: major.cloned().unwrap_or_default(), minor }
}

/// Linear tick sets from denser than any labels fit to a step past the whole range.
fn linear_candidates(scale: &Scale, length_px: f64, horizontal: bool) -> Vec<Vec<(f64, String)>> {
    let target = if horizontal { length_px / 30.0 } else { length_px / 20.0 }.clamp(3.0, 20.0);
    let mut step = nice_at_least((scale.hi - scale.lo) / target);
    let mut out = Vec::new();
    for _ in 0..60 {
        out.extend(linear_majors(scale, step));
        step = next_nice(step);
    }
    out
}

/// The least of 1, 2, 5 × 10^k at least `x`.
fn nice_at_least(x: f64) -> f64 {
    let p = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 5.0, 10.0].into_iter().map(|m| m * p).find(|s| *s >= x * (1.0 - 1e-9)).unwrap_or(10.0 * p)
}

/// The next nice step after `step` (1 → 2 → 5 → 10).
fn next_nice(step: f64) -> f64 {
    let p = 10f64.powf(step.log10().floor());
    let m = (step / p).round();
    if m < 1.5 {
        2.0 * p
    } else if m < 3.5 {
        5.0 * p
    } else {
        10.0 * p
    }
}

/// The multiples of `step` within the scale, labelled (none when there would be over 200).
fn linear_majors(scale: &Scale, step: f64) -> Option<Vec<(f64, String)>> {
    let (k0, k1) = ((scale.lo / step - 1e-9).ceil(), (scale.hi / step + 1e-9).floor());
    if !(k1 - k0).is_finite() || k1 - k0 > 200.0 {
        return None;
    }
    let top = scale.lo.abs().max(scale.hi.abs());
    Some((0..=(k1 - k0) as i64).map(|i| (k0 + i as f64) * step).map(|v| (v, linear_label(v, step, top))).collect())
}

/// A linear tick's label: as many decimals as the step needs, powers of ten for very large or
/// small values, never "-0".
pub fn linear_label(v: f64, step: f64, top: f64) -> String {
    if v.abs() < 1e-6 * step {
        return "0".into();
    }
    let decimals = (-(step.log10() + 1e-9).floor()).max(0.0);
    let text = if top >= 1e6 || decimals > 8.0 {
        let digits = ((v.abs().log10().floor() - (step.log10() + 1e-9).floor()).max(0.0)) as usize;
        format!("{v:.digits$e}")
    } else {
        format!("{v:.0$}", decimals as usize)
    };
    no_negative_zero(text)
}

/// "-0", "-0.00", "-0e0" → without the sign.
fn no_negative_zero(text: String) -> String {
    let mantissa = text.split('e').next().unwrap_or("");
    if text.starts_with('-') && mantissa[1..].chars().all(|c| c == '0' || c == '.') {
        text[1..].to_string()
    } else {
        text
    }
}

/// Decade tick sets, densest first: 1, 2 and 5 times each decade on an axis of one or two
/// decades, then every decade, every 2nd, 3rd, 5th, …; and the minor ticks at 2..9 times a
/// decade on axes of up to six decades.
fn log_candidates(scale: &Scale) -> (Vec<Vec<(f64, String)>>, Vec<f64>) {
    let (d0, d1) = (scale.lo.log10().round() as i32, scale.hi.log10().round() as i32);
    let minor: Vec<f64> = if d1 - d0 <= 6 {
        (d0..d1).flat_map(|d| (2..=9).map(move |m| f64::from(m) * 10f64.powi(d))).collect()
    } else {
        Vec::new()
    };
    let mut tried: Vec<Vec<(f64, String)>> = Vec::new();
    if d1 - d0 <= 2 {
        tried.push(
            (d0..=d1)
                .flat_map(|d| [1.0, 2.0, 5.0].map(|m| m * 10f64.powi(d)))
                .filter(|v| *v <= scale.hi * (1.0 + 1e-9))
                .map(|v| (v, log_label(v)))
                .collect(),
        );
    }
    for every in [1, 2, 3, 5, 10, 20, 50, 100] {
        tried.push(
            (d0..=d1).filter(|d| d.rem_euclid(every) == 0).map(|d| 10f64.powi(d)).map(|v| (v, log_label(v))).collect(),
        );
    }
    (tried, minor)
}

/// A log tick's label: plain ("0.002", "5000") from 10^-3 to 10^5, else "2e-6".
pub fn log_label(v: f64) -> String {
    let e = (v.log10() + 1e-9).floor() as i32;
    if (-3..=5).contains(&e) {
        let decimals = (-e).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{}e{e}", (v / 10f64.powi(e)).round())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scale(lo: f64, hi: f64, log: bool) -> Scale {
        Scale::over([lo, hi].into_iter(), log)
    }

    #[test]
    fn linear_labels_have_the_steps_decimals_and_no_negative_zero() {
        let t = ticks(&scale(-0.3, 0.3, false), 320.0, false);
        let labels: Vec<&str> = t.major.iter().map(|m| m.1.as_str()).collect();
        assert_eq!(labels, ["-0.3", "-0.2", "-0.1", "0", "0.1", "0.2", "0.3"]);
        assert_eq!(linear_label(-1e-18, 0.1, 1.0), "0");
        assert_eq!(no_negative_zero("-0.00".into()), "0.00");
        assert_eq!(linear_label(2.5e6, 5e5, 3e6), "2.5e6");
        assert_eq!(linear_label(0.3999995, 5e-7, 0.4), "0.3999995");
        assert_eq!(linear_label(2e-10, 1e-10, 5e-10), "2e-10");
    }

    #[test]
    fn a_frequency_axis_has_decade_ticks_below_10_hz() {
        let s = scale(2.0, 100.0, true);
        assert_eq!((s.lo, s.hi), (1.0, 100.0));
        let t = ticks(&s, 560.0, true);
        let labels: Vec<&str> = t.major.iter().map(|m| m.1.as_str()).collect();
        assert_eq!(labels, ["1", "2", "5", "10", "20", "50", "100"]);
        assert_eq!(t.minor.len(), 2 * 8);
        let narrow = ticks(&s, 60.0, true);
        let labels: Vec<&str> = narrow.major.iter().map(|m| m.1.as_str()).collect();
        assert_eq!(labels, ["1", "100"]);
    }

    #[test]
    fn a_log_axis_within_one_decade_labels_2_and_5() {
        let t = ticks(&scale(4000.0, 9000.0, true), 560.0, true);
        let labels: Vec<&str> = t.major.iter().map(|m| m.1.as_str()).collect();
        assert_eq!(labels, ["1000", "2000", "5000", "10000"]);
    }

    #[test]
    fn wide_log_axes_label_every_few_decades_and_tiny_values_in_powers() {
        let t = ticks(&scale(1e-12, 1e-1, true), 140.0, false);
        let labels: Vec<&str> = t.major.iter().map(|m| m.1.as_str()).collect();
        assert_eq!(labels, ["1e-12", "1e-9", "1e-6", "0.001"]);
        assert_eq!(log_label(0.002), "0.002");
    }

    #[test]
    fn horizontal_labels_never_overlap() {
        for (lo, hi, log) in [(0.0, 10000.0, false), (4000.0, 10000.0, true), (-1.5e7, 3.3e7, false), (1e-5, 3e4, true)]
        {
            for len in [120.0, 210.0, 560.0] {
                let s = scale(lo, hi, log);
                let t = ticks(&s, len, true);
                assert!(t.major.len() >= 2, "{lo}..{hi} at {len}: {:?}", t.major);
                for w in t.major.windows(2) {
                    let apart = (s.frac(w[1].0) - s.frac(w[0].0)) * len;
                    let half = 0.5 * (text_width(&w[0].1, TICK_FONT_PX) + text_width(&w[1].1, TICK_FONT_PX));
                    assert!(apart >= half, "{lo}..{hi} at {len}: {:?}", t.major);
                }
            }
        }
    }
}
