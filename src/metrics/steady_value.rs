//! `steady_value` (docs/scene-format.md): f at the last step (step and sine kinds) or at each point
//! (sweep, with the point's step).

use super::{HistoryColumns, MetricDef, MetricKind, MetricValue};
use crate::problem::{Loading, LoadingKind};

/// The metric's name in scenes and metrics.csv.
pub const NAME: &str = "steady_value";

pub const METRIC: MetricDef =
    MetricDef { name: NAME, default: true, fits: |_, _| Ok(()), kind: MetricKind::History(compute) };

fn compute(l: &Loading, h: &HistoryColumns) -> Vec<MetricValue> {
    if l.kind == LoadingKind::Sweep {
        h.steps.iter().zip(&h.f).map(|(k, v)| (Some(*k), *v)).collect()
    } else {
        h.f.last().map(|v| (None, *v)).into_iter().collect()
    }
}
