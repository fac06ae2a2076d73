//! Calibration (`creepbench fit`, issue 14): fit a model's free parameters — any scene keys, e.g.
//! `[model] slope_reduction` or `relaxation_length_mm` — to another model's or the references'
//! histories over chosen scenes, minimising a stated norm with argmin's Nelder–Mead (bounded by a
//! sine transform), and judge the fitted values on held-out scenes as well as on the fitted ones.
//! The result is a scene `[model]` block (the `[set]` keys with the fitted values).

mod curves;
pub mod objective;
pub mod record;
pub mod spec;

use crate::comparison::references::References;
use crate::error::{Error, FitError, InputError};
use crate::suite;
use argmin::core::{Executor, State, TerminationReason};
use argmin::solver::neldermead::NelderMead;
use objective::{Case, Objective, SetErrors};
use spec::FitSpec;
use std::fmt::Write;

/// The simplex's first step in each coordinate [rad of the sine transform].
const SIMPLEX_STEP: f64 = 0.5;
/// Nelder–Mead stops when the costs at the simplex's vertices have a standard deviation below this.
const COST_SD_TOLERANCE: f64 = 1e-10;

/// What a fit found.
#[derive(Debug, Clone)]
pub struct FitOutcome {
    pub spec: FitSpec,
    pub fitted: Vec<String>,
    pub held_out: Vec<String>,
    /// The fitted values, in the order of `spec.params`.
    pub values: Vec<f64>,
    pub before_fit: SetErrors,
    pub after_fit: SetErrors,
    pub before_holdout: Option<SetErrors>,
    pub after_holdout: Option<SetErrors>,
    pub iterations: u64,
    pub evaluations: u64,
    /// How the search ended (argmin's termination reason).
    pub ended: String,
    /// The before/after curves ([`curves::curves`]).
    pub curves: Vec<record::CurveRecord>,
}

/// Run a fit: load the scenes and targets, search, and measure before and after.
pub fn fit(spec: &FitSpec, refs: &References) -> Result<FitOutcome, Error> {
    let sources = suite::scene_files(&spec.suites, None)?;
    let (fitted, held_out) = select(spec, &sources)?;
    let load = |names: &[String]| -> Result<Vec<Case>, Error> {
        sources.iter().filter(|s| names.contains(&s.name)).map(|s| Case::load(spec, s, refs)).collect()
    };
    let (fit_cases, holdout_cases) = (load(&fitted)?, load(&held_out)?);
    let start: Vec<f64> = spec.params.iter().map(|p| p.start).collect();
    let measure = |cases: &[Case], values: &[f64]| objective::errors(&spec.model, cases, &spec.assignments(values));
    let before_fit = measure(&fit_cases, &start)?;
    if !before_fit.norm(spec.norm).is_finite() {
        return Err(InputError::new(
            format!("{}: fit.norm", spec.file.display()),
            spec.norm.name(),
            "a norm the fitted scenes have (delay_ratio and loop_area need sine loadings)",
        )
        .into());
    }
    refuse_ignored(spec, before_fit.norm(spec.norm), |values| Ok(measure(&fit_cases, values)?.norm(spec.norm)))?;
    let found = search(spec, &fit_cases)?;
    let values = spec.values(&found.best);
    let before_holdout = (!holdout_cases.is_empty()).then(|| measure(&holdout_cases, &start)).transpose()?;
    let after_holdout = (!holdout_cases.is_empty()).then(|| measure(&holdout_cases, &values)).transpose()?;
    let sets = (spec.assignments(&start), spec.assignments(&values));
    let curves = curves::curves(&spec.model, (&fit_cases, &holdout_cases), (&sets.0, &sets.1))?;
    Ok(FitOutcome {
        spec: spec.clone(),
        fitted,
        held_out,
        after_fit: measure(&fit_cases, &values)?,
        values,
        before_fit,
        before_holdout,
        after_holdout,
        iterations: found.iterations,
        evaluations: found.evaluations,
        ended: found.ended,
        curves,
    })
}

/// An error if every parameter's bounds leave the objective (`at_start` at the start)
/// bit-identical: the model ignores the keys the fit sets, and the search would end at once with
/// no word (issue 48 item 8). Parameters are moved one at a time: one that acts only with another
/// (a slope reduction's alpha while beta is 0) is not ignored as long as some parameter acts.
fn refuse_ignored(
    spec: &FitSpec,
    at_start: f64,
    mut measure: impl FnMut(&[f64]) -> Result<f64, Error>,
) -> Result<(), Error> {
    let start: Vec<f64> = spec.params.iter().map(|p| p.start).collect();
    for (i, p) in spec.params.iter().enumerate() {
        let mut moved = |x: f64| {
            let mut v = start.clone();
            v[i] = x;
            measure(&v)
        };
        if moved(p.min)? != at_start || moved(p.max)? != at_start {
            return Ok(());
        }
    }
    let names: Vec<&str> = spec.params.iter().map(|p| p.name.as_str()).collect();
    let keys: Vec<&str> = spec.set.iter().map(|(k, _)| k.as_str()).collect();
    Err(InputError::new(
        format!("{}: fit.param {}", spec.file.display(), names.join(", ")),
        "no effect at the bounds",
        format!(
            "parameters that change the fit's {} (it is the same at the start and with each parameter at each bound: model `{}` ignores the keys they set: {})",
            spec.norm.name(),
            spec.model,
            keys.join(", ")
        ),
    )
    .into())
}

/// The scenes of the spec's suites it fits and holds out, by name; a pattern that matches nothing
/// is a typo, not an empty set (README: names or patterns), and the fitted set may not be empty.
fn select(spec: &FitSpec, sources: &[suite::SceneSource]) -> Result<(Vec<String>, Vec<String>), Error> {
    let names: Vec<String> = sources.iter().map(|s| s.name.clone()).collect();
    let suites = || spec.suites.iter().map(|s| s.display().to_string()).collect::<Vec<_>>().join(", ");
    if let Some((key, pattern)) = spec.unmatched(&names) {
        return Err(InputError::new(
            format!("{}: fit.{key}", spec.file.display()),
            format!("{pattern:?}"),
            format!("a name or pattern (* and ?) matching a scene of {}", suites()),
        )
        .into());
    }
    let (fitted, held_out) = (spec.select(&names, false), spec.select(&names, true));
    if fitted.is_empty() {
        return Err(InputError::new(
            format!("{}: fit.fit", spec.file.display()),
            spec.fit.join(", "),
            format!("names or patterns matching scenes of {}", suites()),
        )
        .into());
    }
    Ok((fitted, held_out))
}

/// What the search found: the best point in the search coordinates, why it ended, its
/// iterations and the objective's evaluations.
struct Found {
    best: Vec<f64>,
    ended: String,
    iterations: u64,
    evaluations: u64,
}

/// Nelder–Mead from the spec's start (a simplex of [`SIMPLEX_STEP`] along each coordinate) over
/// the fitted cases, run by argmin's executor until the cost's spread is below
/// [`COST_SD_TOLERANCE`] or `max_iterations`.
fn search(spec: &FitSpec, fit_cases: &[Case]) -> Result<Found, Error> {
    // A model that fails inside the search leaves its typed error here (argmin's errors are untyped).
    let failure = std::sync::Mutex::new(None);
    let problem = Objective { spec, cases: fit_cases, failure: &failure };
    let z0: Vec<f64> = spec.params.iter().map(|p| p.coordinate(p.start)).collect();
    let mut simplex = vec![z0.clone()];
    for i in 0..z0.len() {
        let mut v = z0.clone();
        v[i] += SIMPLEX_STEP;
        simplex.push(v);
    }
    let optimiser_error =
        |e: argmin::core::Error| Error::Fit { fit: spec.name.clone(), source: FitError::Optimiser(e) };
    let solver = NelderMead::new(simplex).with_sd_tolerance(COST_SD_TOLERANCE).map_err(optimiser_error)?;
    let result = Executor::new(problem, solver).configure(|s| s.max_iters(spec.max_iterations)).timer(false).run();
    let result = match result {
        Ok(r) => r,
        Err(e) => {
            let typed = failure.lock().ok().and_then(|mut f| f.take());
            return Err(typed.unwrap_or_else(|| optimiser_error(e)));
        }
    };
    let state = result.state();
    Ok(Found {
        best: state.get_best_param().cloned().unwrap_or(z0),
        ended: state.get_termination_reason().map_or("unknown", TerminationReason::text).to_string(),
        iterations: state.get_iter(),
        evaluations: result.problem().counts.get("cost_count").copied().unwrap_or(0),
    })
}

/// The fitted values as a scene block: the `[set]` keys with the values in place, headed by
/// comments that say how they were found and what they do (TOML).
pub fn render(o: &FitOutcome) -> Result<String, Error> {
    let mut doc = toml::Table::new();
    for (k, v) in o.spec.assignments(&o.values) {
        crate::scene::study::set(&mut doc, &k, v, "set")?;
    }
    let spec = &o.spec;
    let mut s = format!(
        "# Fitted by `creepbench fit {}`: model {} against {}, norm {}, Nelder–Mead (argmin), {} iterations, {} evaluations, ended: {}.\n",
        spec.file.display(),
        spec.model,
        spec.target.label(),
        spec.norm.name(),
        o.iterations,
        o.evaluations,
        o.ended
    );
    let record = record::FitRecord::of(o);
    for line in record.param_lines() {
        let _ = writeln!(s, "# {line}");
    }
    let _ = writeln!(s, "# fitted on: {}", o.fitted.join(", "));
    if !o.held_out.is_empty() {
        let _ = writeln!(s, "# held out: {}", o.held_out.join(", "));
    }
    for line in record.table().lines() {
        let _ = writeln!(s, "# {line}");
    }
    s.push_str(&toml::to_string(&doc).map_err(|e| Error::Fit { fit: spec.name.clone(), source: e.into() })?);
    Ok(s)
}

/// The fitted variant beside the published model on every stored scene that holds both the model
/// and the exact theory (`ladder::EXACT`), per suite: |Δf| against the exact theory over the same
/// rows. The variant runs on the scene's source with the fit's `[set]` at the fitted values;
/// scenes run in parallel, statistics are taken in the scenes' order.
pub fn across_suites(
    o: &FitOutcome,
    stored: &[crate::suite::results::StoredScene],
    sources: &[crate::suite::SceneSource],
) -> Result<Vec<record::SuiteRecord>, Error> {
    use crate::comparison::model_error::{row_diffs, summary};
    use crate::report::ladder::EXACT;
    use rayon::prelude::*;
    let set = o.spec.assignments(&o.values);
    let pairs: Vec<_> = stored
        .iter()
        .filter_map(|s| {
            let (ours, exact) = (s.histories.get(&o.spec.model)?, s.histories.get(EXACT)?);
            let source = sources.iter().find(|src| src.name == s.name)?;
            Some((s, ours, exact, source))
        })
        .collect();
    let diffs = pairs
        .par_iter()
        .map(|(_, ours, exact, source)| {
            let fitted = objective::run_model(source, &o.spec.model, &set)?;
            Ok((row_diffs(ours, exact), row_diffs(&fitted, exact)))
        })
        .collect::<Result<Vec<_>, Error>>()?;
    let mut by_suite: std::collections::BTreeMap<&str, (usize, Vec<f64>, Vec<f64>)> = Default::default();
    for ((s, ..), (published, fitted)) in pairs.iter().zip(diffs) {
        let e = by_suite.entry(s.scene.suite.as_str()).or_default();
        e.0 += 1;
        e.1.extend(published.into_iter().filter(|d| d.is_finite()));
        e.2.extend(fitted.into_iter().filter(|d| d.is_finite()));
    }
    Ok(by_suite
        .into_iter()
        .map(|(suite, (scenes, p, f))| record::SuiteRecord {
            suite: suite.to_string(),
            scenes,
            rows: p.len(),
            published: summary(&p),
            fitted: summary(&f),
        })
        .collect())
}
