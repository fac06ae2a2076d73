//! The fit's objective: the model run on a set of scenes with given parameter values and measured
//! against the target's histories (|Δf| per row as the model ladder, delay-ratio and loop-area
//! differences), and the argmin cost function over the fitted set.

use super::spec::{FitSpec, Norm, Target};
use crate::comparison::model_error::{rms, row_diffs};
use crate::comparison::references::References;
use crate::error::{Error, InputError};
use crate::history::History;
use crate::metrics;
use crate::pipeline;
use crate::scene::study;
use crate::suite::SceneSource;
use rayon::prelude::*;
use toml::{Table, Value};

/// One scene of a fit: its table and the target's history and metrics there.
pub struct Case {
    pub name: String,
    source: SceneSource,
    doc: Table,
    target: History,
    /// The target's delay ratio and loop area, where the scene has them.
    target_delay: Option<f64>,
    target_loop: Option<f64>,
}

/// The errors of the model over a set of scenes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SetErrors {
    pub scenes: usize,
    pub rows: usize,
    pub rms_df: f64,
    pub max_df: f64,
    /// RMS over the scenes with a delay ratio (NaN if none has one).
    pub delay_ratio: f64,
    /// RMS over the scenes with a loop area of (ours − target)/target (NaN if none).
    pub loop_area: f64,
}

impl SetErrors {
    pub fn norm(&self, n: Norm) -> f64 {
        match n {
            Norm::RmsDf => self.rms_df,
            Norm::MaxDf => self.max_df,
            Norm::DelayRatio => self.delay_ratio,
            Norm::LoopArea => self.loop_area,
        }
    }
}

/// The scalar metric `name` of a history (None where the scene's loading has none).
fn metric(problem: &crate::problem::Problem, h: &History, name: &str) -> Option<f64> {
    if !problem.metrics.iter().any(|m| m == name) {
        return None;
    }
    metrics::compute(&[name.to_string()], &problem.loading, h, &[])
        .into_iter()
        .find(|m| m.step.is_none())
        .map(|m| m.value)
        .filter(|v| v.is_finite())
}

/// `doc` running only `solver`, with `set` applied.
fn with(doc: &Table, solver: &str, set: &[(String, Value)], field: &str) -> Result<Table, InputError> {
    let mut doc = doc.clone();
    doc.insert("solvers".into(), Value::Array(vec![Value::String(solver.into())]));
    for (k, v) in set {
        study::set(&mut doc, k, v.clone(), field)?;
    }
    Ok(doc)
}

/// Run `doc` (one model) as the scene of `source`: its history and its problem.
fn run_one(source: &SceneSource, doc: Table) -> Result<(crate::problem::Problem, History), Error> {
    let point = SceneSource { study: Some((doc, Vec::new())), ..source.clone() };
    let problem = pipeline::load_source(&point, &[])?;
    let mut result = pipeline::run(problem)?;
    let h = result
        .histories
        .pop()
        .ok_or_else(|| InputError::new(format!("{}: solvers", source.path.display()), "none", "the fitted model"))?;
    Ok((result.problem, h))
}

impl Case {
    /// The scene and its target (run once, or read from the references).
    pub fn load(spec: &FitSpec, source: &SceneSource, refs: &References) -> Result<Case, Error> {
        let doc = source.table()?;
        // The scene must accept the parameters anywhere in their bounds (the start, and each
        // parameter at its bounds): checked before any run, so that bad input stops the fit early.
        for values in spec.probes() {
            let at: Vec<String> = spec.params.iter().zip(&values).map(|(p, v)| format!("{} = {v}", p.name)).collect();
            let in_fit = |mut e: InputError| {
                e.field = format!("{}: [set] with {}: {}", spec.file.display(), at.join(", "), e.field);
                e
            };
            let doc = with(&doc, &spec.model, &spec.assignments(&values), "set").map_err(in_fit)?;
            match pipeline::load_source(&SceneSource { study: Some((doc, Vec::new())), ..source.clone() }, &[]) {
                Err(Error::Input(e)) => return Err(in_fit(e).into()),
                other => other?,
            };
        }
        let (problem, target) = match &spec.target {
            Target::Solver(s) => run_one(source, with(&doc, s, &[], "against")?)?,
            Target::Reference => {
                let problem = pipeline::load_source(
                    &SceneSource { study: Some((doc.clone(), Vec::new())), ..source.clone() },
                    &[],
                )?;
                let h = refs.history(&source.name).cloned().ok_or_else(|| {
                    InputError::new(
                        format!("{}: fit", spec.file.display()),
                        &source.name,
                        "scenes the reference data hold (against = \"reference\")",
                    )
                })?;
                (problem, h)
            }
        };
        Ok(Case {
            name: source.name.clone(),
            source: source.clone(),
            target_delay: metric(&problem, &target, crate::metrics::delay_ratio::NAME),
            target_loop: metric(&problem, &target, crate::metrics::loop_area::NAME),
            doc,
            target,
        })
    }
}

impl Case {
    /// The model on this scene with the set keys `set`: the resolved problem and the history.
    pub fn run(&self, model: &str, set: &[(String, Value)]) -> Result<(crate::problem::Problem, History), Error> {
        run_one(&self.source, with(&self.doc, model, set, "set")?)
    }

    /// The target's history on this scene.
    pub fn target(&self) -> &History {
        &self.target
    }
}

/// The model on `cases` with the set keys `set`: its errors against the targets. The scenes run
/// in parallel; the sums are taken in the cases' order (the same bits for any thread count).
pub fn errors(model: &str, cases: &[Case], set: &[(String, Value)]) -> Result<SetErrors, Error> {
    struct One {
        diffs: Vec<f64>,
        delay: Option<f64>,
        loop_rel: Option<f64>,
    }
    let each = cases
        .par_iter()
        .map(|c| {
            let (problem, h) = c.run(model, set)?;
            let delay = c.target_delay.zip(metric(&problem, &h, crate::metrics::delay_ratio::NAME)).map(|(t, o)| o - t);
            let loop_rel =
                c.target_loop.zip(metric(&problem, &h, crate::metrics::loop_area::NAME)).map(|(t, o)| (o - t) / t);
            Ok(One { diffs: row_diffs(&h, &c.target), delay, loop_rel })
        })
        .collect::<Result<Vec<One>, Error>>()?;
    let rows = each.iter().map(|o| o.diffs.len()).sum();
    Ok(SetErrors {
        scenes: cases.len(),
        rows,
        rms_df: rms(each.iter().flat_map(|o| o.diffs.iter().copied())),
        max_df: each.iter().flat_map(|o| o.diffs.iter().copied()).fold(0.0, f64::max),
        delay_ratio: rms(each.iter().filter_map(|o| o.delay)),
        loop_area: rms(each.iter().filter_map(|o| o.loop_rel)),
    })
}

/// The model's history on the scene of `source` with the set keys `set` (the scene's other
/// solvers left out).
pub fn run_model(source: &SceneSource, model: &str, set: &[(String, Value)]) -> Result<History, Error> {
    Ok(run_one(source, with(&source.table()?, model, set, "set")?)?.1)
}

/// The argmin problem: the norm over the fitted scenes as a function of the parameters'
/// unbounded coordinates.
pub struct Objective<'a> {
    pub spec: &'a FitSpec,
    pub cases: &'a [Case],
    /// The first model failure, kept typed for the caller.
    pub failure: &'a std::sync::Mutex<Option<Error>>,
}

impl argmin::core::CostFunction for Objective<'_> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, z: &Vec<f64>) -> Result<f64, argmin::core::Error> {
        let set = self.spec.assignments(&self.spec.values(z));
        match errors(&self.spec.model, self.cases, &set) {
            Ok(e) => Ok(e.norm(self.spec.norm)),
            Err(e) => {
                let message = e.to_string();
                if let Ok(mut f) = self.failure.lock() {
                    f.get_or_insert(e);
                }
                Err(argmin::core::Error::msg(message))
            }
        }
    }
}
