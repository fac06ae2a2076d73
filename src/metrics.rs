//! Step 5 of the pipeline: metrics of a history (interface.md, "Metric definitions").

use crate::history::History;
use crate::problem::{LoadingKind, Problem};

/// One metric value; `step` is set for per-point metrics (a sweep's steady values).
#[derive(Debug, Clone, PartialEq)]
pub struct Metric {
    pub solver: String,
    pub name: String,
    pub value: f64,
    pub step: Option<usize>,
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
/// its two neighbours. `None` if the window holds no sample.
pub fn peak_time(t: &[f64], y: &[f64], t0: f64, t1: f64) -> Option<f64> {
    let eps = 1e-12 * t1.abs().max(1e-30);
    let idx = (0..t.len())
        .filter(|&k| t[k] >= t0 - eps && t[k] < t1 - eps)
        .max_by(|&a, &b| y[a].total_cmp(&y[b]).then(b.cmp(&a)))?;
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

/// Settling time: the first time after which |f − f_last| stays within 1 % of |f_last|.
pub fn settling_time(t: &[f64], f: &[f64]) -> Option<f64> {
    let last = *f.last()?;
    let band = 0.01 * last.abs();
    let outside = (0..f.len()).rev().find(|&k| (f[k] - last).abs() > band);
    Some(match outside {
        None => t[0],
        Some(k) => t[(k + 1).min(f.len() - 1)],
    })
}

/// Number of turns in a sequence: sign changes between consecutive first differences larger than
/// `tiny`, smaller ones skipped (so a rounded extremum counts once even when its middle
/// difference is tiny, and jitter below `tiny` counts nothing). Shared by the oscillation and
/// sawtooth indicators.
pub fn turns(values: impl IntoIterator<Item = f64>, tiny: f64) -> usize {
    let mut it = values.into_iter();
    let Some(mut prev) = it.next() else { return 0 };
    let mut last_sign = 0.0f64;
    let mut n = 0;
    for v in it {
        let d = v - prev;
        prev = v;
        if d.abs() > tiny {
            let sign = d.signum();
            n += usize::from(last_sign != 0.0 && sign != last_sign);
            last_sign = sign;
        }
    }
    n
}

/// Oscillation index of a time history: the fraction of interior steps where f turns. A smooth
/// response scores about 2 per period (its extrema); a step-to-step sawtooth scores ~1.
/// Differences count only above [`OSCILLATION_FLOOR`] of `max |f|` (and above 1e-9 of the range
/// of f): an iterative solver converged to its tolerance (the exact-theory solver's default
/// 1e-7 of the traction bound) leaves a jitter of that order on a plateau, which is not an
/// oscillation.
pub fn oscillation_index(f: &[f64]) -> f64 {
    if f.len() < 3 {
        return 0.0;
    }
    let (lo, hi) = f.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
    let scale = lo.abs().max(hi.abs());
    let tiny = (1e-9 * (hi - lo)).max(OSCILLATION_FLOOR * scale).max(f64::MIN_POSITIVE);
    turns(f.iter().copied(), tiny) as f64 / (f.len() - 2) as f64
}

/// Noise floor of [`oscillation_index`], relative to `max |f|`: ten times the exact-theory
/// solver's default tolerance.
pub const OSCILLATION_FLOOR: f64 = 1e-6;

/// The metrics the problem asks for, computed on one history.
pub fn compute(problem: &Problem, h: &History) -> Vec<Metric> {
    let t = h.column("t_s").unwrap_or_default();
    let cx = h.column("cx").unwrap_or_default();
    let f = h.column("fx_over_fn").unwrap_or_default();
    let mut out = Vec::new();
    let mut push = |name: &str, value: Option<f64>, step: Option<usize>| {
        if let Some(value) = value {
            out.push(Metric { solver: h.solver.clone(), name: name.into(), value, step });
        }
    };
    for m in &problem.metrics {
        match m.as_str() {
            "delay_ratio" => push(m, problem.period_s().and_then(|p| delay_ratio(&t, &cx, &f, p)), None),
            "loop_area" => {
                let value = problem.period_s().and_then(|p| {
                    let periods = (t.last().copied().unwrap_or(0.0) / p + 1e-9).floor();
                    (periods >= 1.0).then(|| loop_integral(&t, &cx, &f, (periods - 1.0) * p, periods * p)).flatten()
                });
                push(m, value.map(f64::abs), None)
            }
            "steady_value" if problem.kind == LoadingKind::Sweep => {
                for r in &h.rows {
                    push(m, Some(r.fx_over_fn), Some(r.step));
                }
            }
            "steady_value" => push(m, f.last().copied(), None),
            "settling_time_s" => {
                // From the first step after the initial state.
                let k0 = h.rows.iter().position(|r| r.step >= 1).unwrap_or(0);
                push(m, settling_time(&t[k0..], &f[k0..]), None)
            }
            "oscillation_index" => {
                let k0 = h.rows.iter().position(|r| r.step >= 1).unwrap_or(0);
                push(m, Some(oscillation_index(&f[k0..])), None)
            }
            _ => {}
        }
    }
    out
}

/// metrics.csv text: `solver,metric,value,step` (step empty for scalar metrics).
pub fn to_csv(metrics: &[Metric]) -> String {
    let mut s = String::from("solver,metric,value,step\n");
    for m in metrics {
        let step = m.step.map(|k| k.to_string()).unwrap_or_default();
        s.push_str(&format!("{},{},{},{}\n", m.solver, m.name, m.value, step));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn oscillation_index_sees_sawtooth_not_convergence_jitter() {
        // A plateau at 0.4 with solver jitter of 1e-11 (tolerance level): no turns.
        let jitter: Vec<f64> = (0..40).map(|i| 0.4 + if i % 2 == 0 { 1e-11 } else { -1e-11 }).collect();
        assert_eq!(oscillation_index(&jitter), 0.0);
        // The same plateau with a 1e-4 sawtooth: every interior step turns.
        let saw: Vec<f64> = (0..40).map(|i| 0.4 + if i % 2 == 0 { 1e-4 } else { -1e-4 }).collect();
        assert!((oscillation_index(&saw) - 1.0).abs() < 1e-12);
        // A smooth sine over 3 periods of 60 steps: 6 extrema in 178 interior steps.
        let sine: Vec<f64> =
            (0..180).map(|i| 0.3 + 0.1 * (2.0 * std::f64::consts::PI * (i as f64 + 0.3) / 60.0).sin()).collect();
        assert!((oscillation_index(&sine) - 6.0 / 178.0).abs() < 1e-12, "{}", oscillation_index(&sine));
        // A rounded peak whose middle difference is below the floor still counts once.
        assert_eq!(turns([0.0, 0.5, 1.0, 1.0 + 1e-9, 0.5, 0.0], 1e-6), 1);
    }

    #[test]
    fn parabola_recovers_sine_peak() {
        let dt = 0.013;
        let t: Vec<f64> = (0..400).map(|k| k as f64 * dt).collect();
        let y: Vec<f64> = t.iter().map(|&x| (2.0 * std::f64::consts::PI * (x - 0.1)).sin()).collect();
        let tp = peak_time(&t, &y, 1.0, 2.0).unwrap();
        assert!((tp - 1.35).abs() < 2e-4, "{tp}");
    }

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

    #[test]
    fn settling() {
        let t = [1.0, 2.0, 3.0, 4.0, 5.0];
        let f = [0.0, 0.5, 0.995, 1.0, 1.0];
        assert_eq!(settling_time(&t, &f), Some(3.0));
    }
}
