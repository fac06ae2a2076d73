//! `loop_area` (docs/scene-format.md): |∮ f dcx| over the last full period, trapezoidal rule.

use super::{HistoryColumns, MetricDef, MetricKind, MetricValue};
use crate::problem::Loading;

/// The metric's name in scenes and metrics.csv.
pub const NAME: &str = "loop_area";

pub const METRIC: MetricDef = MetricDef {
    name: NAME,
    default: true,
    fits: |l, dt_s| super::needs_periods(l, dt_s, 1.0),
    kind: MetricKind::History(compute),
};

fn compute(l: &Loading, h: &HistoryColumns) -> Vec<MetricValue> {
    let value = l.period_s().and_then(|p| {
        let periods = (h.t.last().copied().unwrap_or(0.0) / p + 1e-9).floor();
        (periods >= 1.0).then(|| loop_integral(&h.t, &h.cx, &h.f, (periods - 1.0) * p, periods * p)).flatten()
    });
    value.map(|v| (None, v.abs())).into_iter().collect()
}

/// Signed loop integral ∮ f dcx over [t0, t1] by the trapezoidal rule, the end points linearly
/// interpolated between samples and the loop closed by the straight segment between them
/// (as the CONTACT reference README defines it). Negative = counter-clockwise (f lags cx).
pub fn loop_integral(t: &[f64], cx: &[f64], f: &[f64], t0: f64, t1: f64) -> Option<f64> {
    let interp = |y: &[f64], tt: f64| -> Option<f64> {
        let k = t.partition_point(|&x| x < tt);
        if k == 0 {
            return (t.first()? - tt).abs().lt(&1e-12).then(|| y[0]);
        }
        if k >= t.len() {
            return ((tt - t.last()?).abs() < 1e-9 * tt.abs().max(1.0)).then(|| y[t.len() - 1]);
        }
        let w = (tt - t[k - 1]) / (t[k] - t[k - 1]);
        Some(y[k - 1] + w * (y[k] - y[k - 1]))
    };
    let mut pts = vec![(interp(cx, t0)?, interp(f, t0)?)];
    pts.extend((0..t.len()).filter(|&k| t[k] > t0 && t[k] < t1).map(|k| (cx[k], f[k])));
    pts.push((interp(cx, t1)?, interp(f, t1)?));
    pts.push(pts[0]);
    Some(pts.windows(2).map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0)).sum())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loop_area_of_ellipse() {
        // cx = cos θ, f = sin θ traced counter-clockwise: ∮ f dcx = −π.
        let n = 2000;
        let t: Vec<f64> = (0..=n).map(|k| k as f64 / n as f64).collect();
        let cx: Vec<f64> = t.iter().map(|&x| (2.0 * std::f64::consts::PI * x).cos()).collect();
        let f: Vec<f64> = t.iter().map(|&x| (2.0 * std::f64::consts::PI * x).sin()).collect();
        let a = loop_integral(&t, &cx, &f, 0.0, 1.0).unwrap();
        assert!((a + std::f64::consts::PI).abs() < 1e-4, "{a}");
    }
}
