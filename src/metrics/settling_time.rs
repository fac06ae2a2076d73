//! `settling_time_s` (docs/scene-format.md): step kind only, the first time after which |f − f_last|
//! stays within 1 % of |f_last|, from the first step after the initial state.

use super::{HistoryColumns, MetricDef, MetricKind, MetricValue};
use crate::problem::{Loading, LoadingKind};

/// The metric's name in scenes and metrics.csv.
pub const NAME: &str = "settling_time_s";

pub const METRIC: MetricDef = MetricDef {
    name: NAME,
    default: true,
    fits: |l, _| if l.kind == LoadingKind::Step { Ok(()) } else { Err(super::Unfit::StepOnly) },
    kind: MetricKind::History(compute),
};

fn compute(_: &Loading, h: &HistoryColumns) -> Vec<MetricValue> {
    let k0 = h.first_step;
    settling_time(&h.t[k0..], &h.f[k0..]).map(|v| (None, v)).into_iter().collect()
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settling() {
        let t = [1.0, 2.0, 3.0, 4.0, 5.0];
        let f = [0.0, 0.5, 0.995, 1.0, 1.0];
        assert_eq!(settling_time(&t, &f), Some(3.0));
    }
}
