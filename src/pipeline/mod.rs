//! The straight path scene → resolved problem → models → histories → metrics, for one scene.
//! The one place that wires the stages: the scene's names are checked against the model and
//! metric registries here, each model reads its own parameters, the metrics are chosen and each
//! model's applicability checked, before anything is computed.

use crate::error::{Error, InputError};
use crate::history::external::External;
use crate::history::sample_loop::{self, FieldIndicator};
use crate::history::{self, History};
use crate::metrics::{self, Metric};
use crate::problem::{ModelParamSet, Problem};
use crate::scene::reader::Section;
use crate::scene::source::SceneSource;
use crate::scene::{is_valid_name, study, ExternalSolver, Scene};
use crate::solvers::{self, Termination};
use std::path::Path;
use std::sync::Arc;
use std::time::Instant;

/// Wall times of one model's run [s] (kept out of the CSVs, which stay deterministic).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Timing {
    /// The whole run.
    pub wall_s: f64,
    /// Building the model and loading the first contact (kernels, normal problem).
    pub setup_s: f64,
}

/// One scene's results.
#[derive(Debug, Clone)]
pub struct SceneResult {
    pub problem: Problem,
    pub histories: Vec<History>,
    /// Per model, in the order of `histories`.
    pub timing: Vec<Timing>,
    pub metrics: Vec<Metric>,
    /// What the external models printed: `(file name, text)` for the result folder.
    pub logs: Vec<(String, String)>,
}

/// Read, validate and resolve a scene file; `only` narrows its solver list.
pub fn load(path: &Path, only: &[String]) -> Result<Problem, Error> {
    let source = SceneSource { path: path.to_path_buf(), name: String::new(), study: None };
    load_source(&source, only)
}

/// Validate and resolve one scene of a suite (a scene file or a study's point); `only` narrows
/// its solver list. Errors name the file (and the study point).
pub fn load_source(source: &SceneSource, only: &[String]) -> Result<Problem, Error> {
    load_source_with(source, only, &[])
}

/// [`load_source`], where the scene may also name the models `in_process` (run in this process,
/// [`InProcess`]) in its `solvers`.
pub fn load_source_with(source: &SceneSource, only: &[String], in_process: &[String]) -> Result<Problem, Error> {
    load_parsed(source, None, only, in_process)
}

/// [`load_source_with`], where `file` is the scene file already parsed (a source that is the
/// file itself; `None`: read from its path).
pub fn load_parsed(
    source: &SceneSource,
    file: Option<&toml::Table>,
    only: &[String],
    in_process: &[String],
) -> Result<Problem, Error> {
    let path = &source.path;
    let in_file = |e: InputError| in_source(source, e);
    let scene = match (&source.study, file) {
        (None, Some(doc)) => Scene::from_table(doc, &path.parent().map(Path::to_path_buf).unwrap_or_default()),
        (None, None) => Scene::from_file(path),
        (Some((doc, points)), _) => {
            let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
            Scene::from_table(doc, &dir).map(|s| Scene { studies: points.clone(), ..s })
        }
    }
    .map_err(in_file)?;
    let mut problem = resolve_with(scene, in_process).map_err(in_file)?;
    narrow(&mut problem, only)?;
    Ok(problem)
}

/// `e`, a scene's error, naming the file it comes from (and the study point) before its field.
pub fn in_source(source: &SceneSource, mut e: InputError) -> InputError {
    let path = source.path.display().to_string();
    if !e.field.starts_with(&path) {
        let place = match source.study {
            None => path,
            Some(_) => format!("{path} (study point {})", source.name),
        };
        e.field = format!("{place}: {}", e.field);
    }
    e
}

/// Validate and resolve a scene given as a table (not read from a file: errors name the field
/// alone); `dir` resolves its relative paths; `only` and `in_process` as in [`load_source_with`].
pub fn load_table(doc: &toml::Table, dir: &Path, only: &[String], in_process: &[String]) -> Result<Problem, Error> {
    let mut problem = resolve_with(Scene::from_table(doc, dir)?, in_process)?;
    narrow(&mut problem, only)?;
    Ok(problem)
}

/// [`resolve`] a scene whose `solvers` may also name the models `in_process`.
fn resolve_with(mut scene: Scene, in_process: &[String]) -> Result<Problem, InputError> {
    scene.external.extend(in_process.iter().map(|name| ExternalSolver {
        name: name.clone(),
        command: vec![format!("<in-process {name}>")],
        timeout_s: f64::INFINITY,
    }));
    resolve(&scene)
}

/// Keep only the solvers `only` names (all when empty); each must be one of the problem's.
pub fn narrow(problem: &mut Problem, only: &[String]) -> Result<(), InputError> {
    if !only.is_empty() {
        for s in only {
            if !problem.solvers.contains(s) {
                return Err(InputError::new(
                    "--solver",
                    s,
                    format!("one of the scene's solvers: {}", problem.solvers.join(", ")),
                ));
            }
        }
        problem.solvers.retain(|s| only.contains(s));
    }
    Ok(())
}

/// Check a scene against the registries and resolve it: its external and built-in model names,
/// its metric names, the problem, the metrics that fit it and each model's applicability.
pub fn resolve(scene: &Scene) -> Result<Problem, InputError> {
    check_external_names(&scene.external)?;
    let solvers = solver_names(scene)?;
    let asked = metric_names(scene)?;
    let params = model_params(scene)?;
    let mut problem = Problem::resolve(scene, solvers, params)?;
    select_metrics(&mut problem, asked.as_deref());
    solvers::check_applicable(&problem)?;
    Ok(problem)
}

/// A study file's scenes, its `metrics` checked against the metric registry.
pub fn expand_study(doc: &toml::Table) -> Result<Vec<study::Expanded>, InputError> {
    study::expand(doc, &metrics::names())
}

/// Every `[external.NAME]` has a valid name that is not a built-in model's.
fn check_external_names(external: &[ExternalSolver]) -> Result<(), InputError> {
    match external.iter().find(|e| !is_valid_name(&e.name) || solvers::builtin(&e.name).is_some()) {
        None => Ok(()),
        Some(e) => Err(InputError::new(
            format!("external.{}", e.name),
            format!("{:?}", e.name),
            format!(
                "an external solver name of [a-z0-9_]+ other than the built-in {}",
                solvers::builtin_names().join(", ")
            ),
        )),
    }
}

/// A top-level list of strings the scene kept as given, read as the scene reader would.
fn given_list(key: &str, value: Option<&toml::Value>, allowed: &str) -> Result<Option<Vec<String>>, InputError> {
    let mut table = toml::Table::new();
    if let Some(v) = value {
        table.insert(key.to_string(), v.clone());
    }
    Section::new("", &table).opt_str_list(key, allowed)
}

/// `solvers`: distinct names of built-in models or of the scene's `[external.NAME]`.
fn solver_names(scene: &Scene) -> Result<Vec<String>, InputError> {
    let known: Vec<String> = solvers::builtin_names()
        .into_iter()
        .map(String::from)
        .chain(scene.external.iter().map(|e| e.name.clone()))
        .collect();
    let allowed = format!("a non-empty list of distinct names from {}", known.join(", "));
    let names = given_list("solvers", scene.solvers.as_ref(), &allowed)?
        .ok_or_else(|| InputError::new("solvers", "missing", allowed.clone()))?;
    if names.is_empty() {
        return Err(InputError::new("solvers", "[]", allowed));
    }
    for (n, s) in names.iter().enumerate() {
        if !known.contains(s) || names[..n].contains(s) {
            return Err(InputError::new(format!("solvers[{n}]"), format!("{s:?}"), allowed));
        }
    }
    Ok(names)
}

/// `metrics` (optional): distinct names of the metric registry.
fn metric_names(scene: &Scene) -> Result<Option<Vec<String>>, InputError> {
    let known = metrics::names().join(", ");
    let names = given_list("metrics", scene.metrics.as_ref(), &format!("names from {known}"))?;
    if let Some(ms) = &names {
        for (n, m) in ms.iter().enumerate() {
            if metrics::by_name(m).is_none() || ms[..n].contains(m) {
                return Err(InputError::new(
                    format!("metrics[{n}]"),
                    format!("{m:?}"),
                    format!("distinct names from {known}"),
                ));
            }
        }
    }
    Ok(names)
}

/// Every model's own `[model]` keys, read and validated once by its `ModelDef::params`, in
/// registry order; then a `[model]` key neither the scene nor a model reads is refused.
fn model_params(scene: &Scene) -> Result<ModelParamSet, InputError> {
    let mut md = scene.model_params.resume();
    for keys in solvers::MODEL_KEYS {
        md = md.declare(keys);
    }
    let params = solvers::MODELS
        .iter()
        .filter_map(|m| m.params)
        .map(|read| read(&mut md).map(Arc::from))
        .collect::<Result<Vec<_>, _>>()?;
    md.finish()?;
    Ok(ModelParamSet::new(params))
}

/// The metrics asked for (or all) that fit the problem's loading; one asked for that does not
/// fit is left out with a warning.
fn select_metrics(problem: &mut Problem, asked: Option<&[String]>) {
    let (chosen, skipped) = metrics::select(asked, &problem.loading, problem.rolling.dt_s);
    for (m, why) in &skipped {
        if asked.is_some_and(|a| a.contains(m)) {
            problem.warnings.push(format!("metric {m} left out: {why}"));
        }
    }
    (problem.metrics, problem.skipped_metrics) = (chosen, skipped);
}

/// A model run in this process over a whole scene (e.g. a Python callable): its name in the
/// scene (an `[external.NAME]` entry, so the scene's checks know it) and the history it gives,
/// which is validated as an external model's output is ([`history::external::validate_in_process`]).
pub type InProcess<'a> = (&'a str, &'a (dyn Fn(&Problem) -> Result<History, Error> + Sync));

/// The field indicators of the problem's field metrics (computed on every solve's field).
pub fn field_indicators(problem: &Problem) -> Vec<FieldIndicator> {
    problem.metrics.iter().filter_map(|m| metrics::by_name(m)?.field_indicator()).collect()
}

/// Run the problem's models (only those it lists) and compute its metrics.
pub fn run(problem: Problem) -> Result<SceneResult, Error> {
    run_with(problem, &[])
}

/// [`run`], with the models `in_process` run in this process instead of as external programs.
pub fn run_with(mut problem: Problem, in_process: &[InProcess]) -> Result<SceneResult, Error> {
    let field_metrics = field_indicators(&problem);
    let (mut histories, mut timing, mut all_metrics, mut logs) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for name in &problem.solvers {
        let fail = |e: solvers::SolveError| Error::Solve {
            scene: problem.name.clone(),
            solver: name.clone(),
            source: Box::new(e),
        };
        let (h, t, field) = match solvers::builtin(name) {
            Some(def) => {
                let (r, stress) = run_builtin(&problem, def, &field_metrics).map_err(fail)?;
                match stress {
                    Some(text) => logs.push((format!("{name}_stress.csv"), text)),
                    None if problem.stress.is_some() => problem
                        .warnings
                        .push(format!("{name}: no traction field at the steps of [stress] (the model has none, or no row has those steps): no {name}_stress.csv")),
                    None => {}
                }
                (r.history, Timing { wall_s: r.wall_s, setup_s: r.setup_s }, r.field_metrics)
            }
            None if in_process.iter().any(|(n, _)| n == name) => {
                let (_, model) = in_process.iter().find(|(n, _)| n == name).expect("checked just above");
                let start = Instant::now();
                let h = history::external::validate_in_process(model(&problem)?, &problem)?;
                (h, Timing { wall_s: start.elapsed().as_secs_f64(), setup_s: 0.0 }, Vec::new())
            }
            None => {
                let spec = problem.external.iter().find(|e| &e.name == name).ok_or_else(|| {
                    InputError::new(
                        "solvers",
                        name,
                        format!(
                            "a built-in model ({}) or an [external.NAME] of the scene",
                            solvers::builtin_names().join(", ")
                        ),
                    )
                })?;
                let start = Instant::now();
                let ran = External::new(spec.clone()).run(&problem)?;
                let wall_s = start.elapsed().as_secs_f64();
                logs.extend(ran.logs);
                (ran.history, Timing { wall_s, setup_s: 0.0 }, Vec::new())
            }
        };
        let limit = Termination::IterationLimit.code();
        let veldep_stuck = h.column("veldep_converged").map_or(0, |c| c.iter().filter(|&&v| v == 0.0).count());
        if veldep_stuck > 0 {
            problem.warnings.push(format!(
                "{name}: {veldep_stuck} of {} solves: the slip-velocity fixed point of the falling friction law did not converge (veldep_converged = 0; contact_solver.veldep_tolerance = {:e}); those rows are not converged",
                h.rows.len(),
                problem.contact_solver.veldep_tolerance
            ));
        }
        let tempdep_stuck = h.column("tempdep_converged").map_or(0, |c| c.iter().filter(|&&v| v == 0.0).count());
        if tempdep_stuck > 0 {
            problem.warnings.push(format!(
                "{name}: {tempdep_stuck} of {} solves: the surface-temperature fixed point of the temperature friction law did not converge (tempdep_converged = 0; contact_solver.tempdep_tolerance = {:e}); those rows are not converged",
                h.rows.len(),
                problem.contact_solver.tempdep_tolerance
            ));
        }
        let stuck = h
            .column(history::TERMINATION)
            .map_or(0, |t| t.iter().filter(|&&c| c == limit).count())
            .saturating_sub(veldep_stuck + tempdep_stuck);
        if stuck > 0 {
            problem.warnings.push(format!(
                "{name}: {stuck} of {} solves reached the iteration limit (contact_solver.max_iterations = {}); those rows are not converged",
                h.rows.len(),
                problem.contact_solver.max_iterations
            ));
        }
        let missed = Termination::ForceNotReached.code();
        let short = h.column(history::TERMINATION).map_or(0, |t| t.iter().filter(|&&c| c == missed).count());
        if short > 0 {
            problem.warnings.push(format!(
                "{name}: {short} of {} solves did not reach the prescribed force (creepage.fx_over_fn, fy_over_fn) within the outer iteration's tolerance; those rows give the force reached",
                h.rows.len()
            ));
        }
        all_metrics.extend(metrics::compute(&problem.metrics, &problem.loading, &h, &field));
        histories.push(h);
        timing.push(t);
    }
    Ok(SceneResult { problem, histories, timing, metrics: all_metrics, logs })
}

/// A built-in model's run and, when the scene asks for `[stress]`, its `<solver>_stress.csv`
/// (`None`: the model gave no field at those steps).
fn run_builtin(
    problem: &Problem,
    def: &solvers::ModelDef,
    field_metrics: &[FieldIndicator],
) -> Result<(sample_loop::ModelRun, Option<String>), solvers::SolveError> {
    let Some(at) = &problem.stress else {
        return Ok((sample_loop::run(problem, def, field_metrics, None)?, None));
    };
    let mut kept: Vec<(usize, crate::physics::Grid, [Vec<f64>; 3])> = Vec::new();
    let mut observe = |s: &crate::problem::Sample, v: &solvers::FieldView| {
        let wanted = at.steps.as_ref().is_none_or(|steps| steps.contains(&s.step));
        if at.steps.is_none() {
            kept.clear();
        }
        if wanted {
            let copy = [v.pressure_mpa.to_vec(), v.tx_mpa.to_vec(), v.ty_mpa.to_vec()];
            kept.push((s.step, v.grid.clone(), copy));
        }
    };
    let run = sample_loop::run(problem, def, field_metrics, Some(&mut observe as &mut sample_loop::Observer))?;
    if kept.is_empty() {
        return Ok((run, None));
    }
    let mut text = history::stress::header();
    for (step, grid, [pn, tx, ty]) in &kept {
        let view =
            solvers::FieldView { grid, pressure_mpa: pn, tx_mpa: tx, ty_mpa: ty, state: None, temperature_c: None };
        let rows = history::stress::rows(*step, &view, &problem.material, at)
            .map_err(|source| solvers::contact::ContactRunError::Step { step: *step, source })?;
        text.push_str(&rows);
    }
    Ok((run, Some(text)))
}

pub mod wheelrail;
pub mod wheelrail_blanco;
pub mod wheelrail_brush;
pub mod wheelrail_conformal;
pub mod wheelrail_exact;
pub mod wheelrail_frame;
pub mod wheelrail_fx;
pub mod wheelrail_massless;
pub mod wheelrail_scene;
pub mod wheelrail_shift;
pub mod wheelrail_view;
