//! The one sample loop (as argmin's `Executor`): it owns the stepping of every built-in model —
//! the steady initial state, sweep points, transient steps, a reload when FN (or the approach, or the undeformed distance) or μ changes — and
//! writes the history, the termination of every solve and the field indicators the scene asks for.
//! It sits at the history stage (README, "The code"): it turns a model's steps into history rows,
//! so it stands above the models it runs and below the metrics, which hand it their field
//! indicators as plain functions.

use super::{History, Row, MZ, TERMINATION};
use crate::problem::{Problem, Sample};
use crate::solvers::stepper::{ElementState, FieldView};
use crate::solvers::{ModelDef, SolveError};
use std::time::Instant;

/// A field metric's indicator: its name and its value on one solve's traction field (the run
/// keeps the largest over every solve).
pub type FieldIndicator = (&'static str, fn(&FieldView) -> f64);

/// The history of one model run, its field metrics and its timing.
#[derive(Debug, Clone)]
pub struct ModelRun {
    pub history: History,
    /// (metric, largest value over every solve) for the field metrics asked for.
    pub field_metrics: Vec<(&'static str, f64)>,
    /// Wall time of building the model and loading the first contact [s].
    pub setup_s: f64,
    /// Wall time of the whole run [s].
    pub wall_s: f64,
}

/// Something that watches each solve's field (tests, field comparisons).
pub type Observer<'o> = dyn FnMut(&Sample, &FieldView) + 'o;

/// Which solve a row is.
#[derive(Debug, Clone, Copy)]
enum Solve {
    Steady,
    Shift,
    Transient,
}

/// Run `def` over the problem's samples.
pub fn run(
    problem: &Problem,
    def: &ModelDef,
    field_metrics: &[FieldIndicator],
    observer: Option<&mut Observer>,
) -> Result<ModelRun, SolveError> {
    let start = Instant::now();
    let mut stepper = (def.build)(problem)?;
    let loading = &problem.loading;
    let first = loading.first();
    stepper.load(first)?;
    let setup_s = start.elapsed().as_secs_f64();
    let mut columns: Vec<&str> = def.extra_columns.to_vec();
    columns.extend(stepper.more_columns());
    if def.iterative {
        columns.push(TERMINATION);
    }
    columns.push(MZ);
    let mut history = History::new(def.name, &columns);
    history.rows.reserve(loading.samples.len() + 1);
    let mut field_values: Vec<(&'static str, f64)> = field_metrics.iter().map(|&(name, _)| (name, 0.0)).collect();
    let mut observer = observer;
    // The start row's normal problem may differ from the steps' (`[normal] start_pressure`).
    let key = |s: &Sample, start: bool| (s.fn_n, s.mu, s.pen_mm, s.h_coefficients, problem.normal.of_row(start));
    let mut loaded = key(first, loading.start().is_some());
    let sweep = !loading.is_transient();
    let initial =
        loading.steady_start().map(|s| (s, Solve::Steady)).or(loading.shift_start().map(|s| (s, Solve::Shift)));
    let each = if sweep { Solve::Steady } else { Solve::Transient };
    for (s, solve) in initial.into_iter().chain(loading.samples.iter().map(|s| (s, each))) {
        let start = matches!(solve, Solve::Shift) || (matches!(solve, Solve::Steady) && !sweep);
        if key(s, start) != loaded {
            stepper.load(s)?;
            loaded = key(s, start);
        }
        let step = match solve {
            Solve::Steady => stepper.steady(s)?,
            Solve::Shift => stepper.shift(s)?,
            Solve::Transient => stepper.transient(s)?,
        };
        if !(step.fx_over_fn.is_finite() && step.fy_over_fn.is_finite()) {
            return Err(SolveError::NonFinite { step: s.step });
        }
        let mut extra = step.extra;
        if def.iterative {
            extra.push(step.termination.code());
        }
        extra.push(step.mz_nmm);
        // Prescribed forces: the row reports the creepages found (and the forces reached); a
        // prescribed approach: the FN found.
        let row = match stepper.solved_creepage() {
            Some([cx, cy]) => Sample { cx, cy, ..*s },
            None => *s,
        };
        let row = Sample { fn_n: stepper.solved_fn_n().unwrap_or(row.fn_n), ..row };
        history.rows.push(Row::new(&row, step.fx_over_fn, step.fy_over_fn, extra));
        if !field_values.is_empty() || observer.is_some() {
            if let Some(view) = stepper.field() {
                for ((_, v), (_, f)) in field_values.iter_mut().zip(field_metrics) {
                    *v = v.max(f(&view));
                }
                if let Some(o) = observer.as_deref_mut() {
                    o(s, &view);
                }
            }
        }
    }
    let has_field = stepper.field().is_some();
    Ok(ModelRun {
        history,
        field_metrics: if has_field { field_values } else { Vec::new() },
        setup_s,
        wall_s: start.elapsed().as_secs_f64(),
    })
}

/// The traction field of one step, for field comparisons with CONTACT (tests, reports).
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    pub step: usize,
    pub pn_mpa: Vec<f64>,
    pub px_mpa: Vec<f64>,
    pub py_mpa: Vec<f64>,
    pub state: Vec<ElementState>,
    /// Both bodies' surface temperatures [°C] where the model computed them.
    pub temperature_c: Option<[Vec<f64>; 2]>,
}

/// Run `def` over the problem's samples, keeping the fields of the steps `keep` selects.
pub fn run_with_fields(
    problem: &Problem,
    def: &ModelDef,
    keep: &dyn Fn(usize) -> bool,
) -> Result<(History, Vec<Field>), SolveError> {
    let mut fields = Vec::new();
    let mut observe = |s: &Sample, v: &FieldView| {
        if keep(s.step) {
            fields.push(Field {
                step: s.step,
                pn_mpa: v.pressure_mpa.to_vec(),
                px_mpa: v.tx_mpa.to_vec(),
                py_mpa: v.ty_mpa.to_vec(),
                state: v.state.map(<[ElementState]>::to_vec).unwrap_or_default(),
                temperature_c: v.temperature_c.map(|t| t.map(<[f64]>::to_vec)),
            });
        }
    };
    let observer: &mut Observer = &mut observe;
    let run = run(problem, def, &[], Some(observer))?;
    Ok((run.history, fields))
}
