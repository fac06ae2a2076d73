//! `delay_ratio` (docs/scene-format.md): time from a maximum of cx to the next maximum of f in the second
//! period (peaks by parabolic interpolation through the three samples around each maximum), over
//! the period.

use super::{HistoryColumns, MetricDef, MetricKind, MetricValue, OSCILLATION_FLOOR};
use crate::problem::Loading;

/// The metric's name in scenes and metrics.csv.
pub const NAME: &str = "delay_ratio";

pub const METRIC: MetricDef = MetricDef {
    name: NAME,
    default: true,
    fits: |l, dt_s| super::needs_periods(l, dt_s, 2.0),
    kind: MetricKind::History(compute),
};

fn compute(l: &Loading, h: &HistoryColumns) -> Vec<MetricValue> {
    l.period_s().and_then(|p| delay_ratio(&h.t, &h.cx, &h.f, p)).map(|v| (None, v)).into_iter().collect()
}

/// Vertex of the parabola through (t−h, y0), (t, y1), (t+h, y2): (offset in units of h, peak value).
fn parabola_peak(y0: f64, y1: f64, y2: f64) -> (f64, f64) {
    let den = y0 - 2.0 * y1 + y2;
    if den >= 0.0 {
        return (0.0, y1); // not a strict maximum: take the sample
    }
    let off = (0.5 * (y0 - y2) / den).clamp(-1.0, 1.0);
    (off, y1 - 0.25 * (y0 - y2) * off)
}

/// Time of the largest sample of `y` with t in [t0, t1), refined by a parabola through it and
/// its two neighbours. Samples within [`OSCILLATION_FLOOR`] of the largest (relative to it) tie
/// and the earliest wins: on a flat top (f saturated at μ) the peak is where the top begins,
/// not wherever round-off puts the largest sample. `None` if the window holds no sample.
pub fn peak_time(t: &[f64], y: &[f64], t0: f64, t1: f64) -> Option<f64> {
    let eps = 1e-12 * t1.abs().max(1e-30);
    let window = || (0..t.len()).filter(|&k| t[k] >= t0 - eps && t[k] < t1 - eps);
    let top = window().map(|k| y[k]).max_by(f64::total_cmp)?;
    let tie = OSCILLATION_FLOOR * top.abs();
    let idx = window().find(|&k| y[k] >= top - tie)?;
    if idx == 0 || idx + 1 >= t.len() {
        return Some(t[idx]);
    }
    let (off, _) = parabola_peak(y[idx - 1], y[idx], y[idx + 1]);
    let h = if off >= 0.0 { t[idx + 1] - t[idx] } else { t[idx] - t[idx - 1] };
    Some(t[idx] + off * h)
}

/// Delay ratio: time from the maximum of cx in the second period to the next maximum of f,
/// each refined by a parabola, divided by the period. The f maximum is sought in one period
/// starting a tenth of a period before the cx maximum, so that a model without memory (delay 0,
/// peaks on the same sample) gives ≈ 0 rather than a whole period.
pub fn delay_ratio(t: &[f64], cx: &[f64], f: &[f64], period_s: f64) -> Option<f64> {
    let tc = peak_time(t, cx, period_s, 2.0 * period_s)?;
    let tf = peak_time(t, f, tc - 0.1 * period_s, tc + 0.9 * period_s)?;
    Some((tf - tc) / period_s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parabola_recovers_sine_peak() {
        let dt = 0.013;
        let t: Vec<f64> = (0..400).map(|k| k as f64 * dt).collect();
        let y: Vec<f64> = t.iter().map(|&x| (2.0 * std::f64::consts::PI * (x - 0.1)).sin()).collect();
        let tp = peak_time(&t, &y, 1.0, 2.0).unwrap();
        assert!((tp - 1.35).abs() < 2e-4, "{tp}");
    }
}

#[cfg(test)]
mod tests_delay {
    use super::*;

    #[test]
    fn delay_of_shifted_sine() {
        let (per, dt) = (0.1, 0.0007781818182);
        let t: Vec<f64> = (0..400).map(|k| k as f64 * dt).collect();
        let w = 2.0 * std::f64::consts::PI / per;
        let cx: Vec<f64> = t.iter().map(|&x| (w * x).sin()).collect();
        let f: Vec<f64> = t.iter().map(|&x| 0.3 * (w * (x - 0.004)).sin()).collect();
        let d = delay_ratio(&t, &cx, &f, per).unwrap();
        assert!((d - 0.04).abs() < 2e-4, "{d}");
    }
}
