//! Step 5 of the pipeline: metrics, registered in one place (docs/scene-format.md, "metrics.csv").
//! A metric is a [`MetricDef`]: its name, whether it is computed by default, when it fits a
//! loading, and how it is computed — from a history, or from the traction field at every solve
//! (field metrics, computed by the sample loop for the models that have a field).

pub mod delay_ratio;
pub mod loop_area;
pub mod oscillation_index;
pub mod sawtooth_index;
pub mod settling_time;
pub mod steady_value;

pub use delay_ratio::{delay_ratio, peak_time};
pub use loop_area::loop_integral;
pub use oscillation_index::{oscillation_index, turns, OSCILLATION_FLOOR};
pub use settling_time::settling_time;

use crate::history::sample_loop::FieldIndicator;
use crate::history::History;
use crate::problem::Loading;
use crate::solvers::FieldView;

/// A value and, for per-point metrics (a sweep's steady values), its step.
pub type MetricValue = (Option<usize>, f64);

/// How a metric is computed.
#[derive(Clone, Copy)]
pub enum MetricKind {
    /// From a model's history.
    History(fn(&Loading, &HistoryColumns) -> Vec<MetricValue>),
    /// The largest value, over every solve, of an indicator of the traction field.
    Field(fn(&FieldView) -> f64),
}

/// A metric: everything the tool needs to know of it.
pub struct MetricDef {
    pub name: &'static str,
    /// Computed unless the scene lists its metrics; the others (diagnostics) only when listed.
    pub default: bool,
    /// Why the metric does not fit this loading (with time step `dt_s`), if it does not.
    pub fits: fn(&Loading, f64) -> Result<(), Unfit>,
    pub kind: MetricKind,
}

/// Every metric, in the order of metrics.csv. Adding one: its file and one line here.
pub const METRICS: &[&MetricDef] = &[
    &delay_ratio::METRIC,
    &loop_area::METRIC,
    &steady_value::METRIC,
    &settling_time::METRIC,
    &oscillation_index::METRIC,
    &sawtooth_index::METRIC,
];

impl MetricDef {
    /// The indicator the sample loop evaluates on every solve, for a field metric.
    pub fn field_indicator(&self) -> Option<FieldIndicator> {
        match self.kind {
            MetricKind::Field(f) => Some((self.name, f)),
            MetricKind::History(_) => None,
        }
    }
}

/// The metric of that name.
pub fn by_name(name: &str) -> Option<&'static MetricDef> {
    METRICS.iter().copied().find(|m| m.name == name)
}

/// Names of every metric.
pub fn names() -> Vec<&'static str> {
    METRICS.iter().map(|m| m.name).collect()
}

/// Why a metric does not fit a loading.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum Unfit {
    #[error("needs a sine creepage")]
    NeedsSine,
    #[error("needs at least {need} periods, the history has {have:.2}")]
    TooFewPeriods { need: f64, have: f64 },
    #[error("step creepage only")]
    StepOnly,
    #[error("time histories only")]
    TimeHistoryOnly,
}

/// A sine needs `need` periods in its history.
fn needs_periods(l: &Loading, dt_s: f64, need: f64) -> Result<(), Unfit> {
    let Some(f) = l.freq_hz else { return Err(Unfit::NeedsSine) };
    let have = l.samples.len() as f64 * dt_s * f;
    if have + 1e-9 < need {
        return Err(Unfit::TooFewPeriods { need, have });
    }
    Ok(())
}

/// The metrics a scene gets: those it lists that fit (in its order), or by default every default
/// metric that fits; and the others with the reason they are left out.
pub fn select(asked: Option<&[String]>, loading: &Loading, dt_s: f64) -> (Vec<String>, Vec<(String, String)>) {
    let (mut take, mut skip) = (Vec::new(), Vec::new());
    match asked {
        Some(asked) => {
            for m in asked {
                match by_name(m).map(|d| (d.fits)(loading, dt_s)) {
                    Some(Ok(())) => take.push(m.clone()),
                    Some(Err(why)) => skip.push((m.clone(), why.to_string())),
                    None => skip.push((m.clone(), "unknown metric".into())),
                }
            }
            for m in METRICS.iter().filter(|m| !asked.iter().any(|a| a == m.name)) {
                skip.push((m.name.to_string(), "not listed by the scene".into()));
            }
        }
        None => {
            for m in METRICS {
                match (m.fits)(loading, dt_s) {
                    Ok(()) if m.default => take.push(m.name.to_string()),
                    Ok(()) => skip.push((m.name.to_string(), "a diagnostic, computed when the scene lists it".into())),
                    Err(why) => skip.push((m.name.to_string(), why.to_string())),
                }
            }
        }
    }
    (take, skip)
}

/// The columns of a history that metrics read.
pub struct HistoryColumns {
    pub steps: Vec<usize>,
    pub t: Vec<f64>,
    pub cx: Vec<f64>,
    pub f: Vec<f64>,
    /// Index of the first row after the initial state.
    pub first_step: usize,
}

impl HistoryColumns {
    pub fn of(h: &History) -> Self {
        HistoryColumns {
            steps: h.rows.iter().map(|r| r.sample.step).collect(),
            t: h.rows.iter().map(|r| r.sample.t_s).collect(),
            cx: h.rows.iter().map(|r| r.sample.cx).collect(),
            f: h.rows.iter().map(|r| r.fx_over_fn).collect(),
            first_step: h.rows.iter().position(|r| r.sample.step >= 1).unwrap_or(0),
        }
    }
}

/// One metric value of one model.
#[derive(Debug, Clone, PartialEq)]
pub struct Metric {
    pub solver: String,
    pub name: String,
    pub value: f64,
    pub step: Option<usize>,
}

/// The metrics `names` of one history, in that order; field metrics from `field` (the sample
/// loop's values: absent for models without a field).
pub fn compute(names: &[String], loading: &Loading, h: &History, field: &[(&'static str, f64)]) -> Vec<Metric> {
    let cols = HistoryColumns::of(h);
    let mut out = Vec::new();
    for def in names.iter().filter_map(|n| by_name(n)) {
        let values = match def.kind {
            MetricKind::History(f) => f(loading, &cols),
            MetricKind::Field(_) => field.iter().filter(|(n, _)| *n == def.name).map(|(_, v)| (None, *v)).collect(),
        };
        out.extend(values.into_iter().map(|(step, value)| Metric {
            solver: h.solver.clone(),
            name: def.name.into(),
            value,
            step,
        }));
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
