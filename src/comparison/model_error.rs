//! How far one model's history is from a target's (the exact solver's or a reference's): |Δf|
//! row by row and the nearest-rank quantile of such errors. Shared by the model ladder and the fit.

use crate::history::History;
use std::collections::BTreeMap;

/// |Δf| = |(fx, fy)/FN − (fx, fy)/FN of the target| per row of `ours` that the target has
/// (rows matched by step).
pub fn row_diffs(ours: &History, target: &History) -> Vec<f64> {
    let by_step: BTreeMap<usize, (f64, f64)> =
        target.rows.iter().map(|r| (r.sample.step, (r.fx_over_fn, r.fy_over_fn))).collect();
    ours.rows
        .iter()
        .filter_map(|r| by_step.get(&r.sample.step).map(|(x, y)| (r.fx_over_fn - x).hypot(r.fy_over_fn - y)))
        .collect()
}

/// The root mean square of values, summed in their order (NaN for none).
pub fn rms(values: impl IntoIterator<Item = f64>) -> f64 {
    let (s, n) = values.into_iter().fold((0.0, 0usize), |(s, n), x| (s + x * x, n + 1));
    if n == 0 {
        f64::NAN
    } else {
        (s / n as f64).sqrt()
    }
}

/// Max, RMS and 95th percentile of the finite |Δf| values (NaN each for none).
pub fn summary(diffs: &[f64]) -> [f64; 3] {
    let mut d: Vec<f64> = diffs.iter().copied().filter(|x| x.is_finite()).collect();
    d.sort_by(f64::total_cmp);
    [d.last().copied().unwrap_or(f64::NAN), rms(d.iter().copied()), quantile(&d, 0.95)]
}

/// The value at quantile `q` of sorted values (nearest rank; NaN for none).
pub fn quantile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let k = ((q * sorted.len() as f64).ceil() as usize).clamp(1, sorted.len());
    sorted[k - 1]
}

#[cfg(test)]
mod tests {
    use super::quantile;

    #[test]
    fn nearest_rank_quantile() {
        let v: Vec<f64> = (1..=20).map(f64::from).collect();
        assert_eq!(quantile(&v, 0.95), 19.0);
        assert_eq!(quantile(&v, 1.0), 20.0);
        assert_eq!(quantile(&v, 0.0), 1.0);
        assert!(quantile(&[], 0.5).is_nan());
    }

    #[test]
    fn summary_of_finite_values() {
        let s = super::summary(&[3.0, f64::NAN, 4.0, 0.0]);
        assert_eq!(s[0], 4.0);
        assert!((s[1] - (25.0f64 / 3.0).sqrt()).abs() < 1e-15);
        assert_eq!(s[2], 4.0);
        assert!(super::summary(&[]).iter().all(|v| v.is_nan()));
    }
}
