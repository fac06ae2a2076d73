//! The straight path scene → resolved problem → models → histories → metrics, for one scene.

use crate::error::{Error, InputError};
use crate::history::external::External;
use crate::history::sample_loop::{self, FieldIndicator};
use crate::history::{self, History};
use crate::metrics::{self, Metric};
use crate::problem::Problem;
use crate::scene::source::SceneSource;
use crate::scene::Scene;
use crate::solvers::{self, Termination};
use std::path::Path;
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
}

/// Read, validate and resolve a scene file; `only` narrows its solver list.
pub fn load(path: &Path, only: &[String]) -> Result<Problem, Error> {
    let source = SceneSource { path: path.to_path_buf(), name: String::new(), study: None };
    load_source(&source, only)
}

/// Validate and resolve one scene of a suite (a scene file or a study's point); `only` narrows
/// its solver list. Errors name the file (and the study point).
pub fn load_source(source: &SceneSource, only: &[String]) -> Result<Problem, Error> {
    let path = &source.path;
    let place = match source.study {
        None => path.display().to_string(),
        Some(_) => format!("{} (study point {})", path.display(), source.name),
    };
    let in_file = |mut e: InputError| {
        if !e.field.starts_with(&path.display().to_string()) {
            e.field = format!("{place}: {}", e.field);
        }
        e
    };
    let scene = match &source.study {
        None => Scene::from_file(path),
        Some((doc, points)) => {
            let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
            Scene::from_table(doc, &dir).map(|s| Scene { studies: points.clone(), ..s })
        }
    }
    .map_err(in_file)?;
    let mut problem = Problem::resolve(&scene).map_err(in_file)?;
    if !only.is_empty() {
        for s in only {
            if !problem.solvers.contains(s) {
                return Err(InputError::new(
                    "--solver",
                    s,
                    format!("one of the scene's solvers: {}", problem.solvers.join(", ")),
                )
                .into());
            }
        }
        problem.solvers.retain(|s| only.contains(s));
    }
    Ok(problem)
}

/// Run the problem's models (only those it lists) and compute its metrics.
pub fn run(mut problem: Problem) -> Result<SceneResult, Error> {
    let field_metrics: Vec<FieldIndicator> =
        problem.metrics.iter().filter_map(|m| metrics::by_name(m)?.field_indicator()).collect();
    let (mut histories, mut timing, mut all_metrics) = (Vec::new(), Vec::new(), Vec::new());
    for name in &problem.solvers {
        let fail = |e: solvers::SolveError| Error::Solve {
            scene: problem.name.clone(),
            solver: name.clone(),
            source: Box::new(e),
        };
        let (h, t, field) = match solvers::builtin(name) {
            Some(def) => {
                let r = sample_loop::run(&problem, def, &field_metrics, None).map_err(fail)?;
                (r.history, Timing { wall_s: r.wall_s, setup_s: r.setup_s }, r.field_metrics)
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
                let h = External::new(spec.clone()).run(&problem)?;
                let wall_s = start.elapsed().as_secs_f64();
                (h, Timing { wall_s, setup_s: 0.0 }, Vec::new())
            }
        };
        let limit = Termination::IterationLimit.code();
        let stuck = h.column(history::TERMINATION).map_or(0, |t| t.iter().filter(|&&c| c == limit).count());
        if stuck > 0 {
            problem.warnings.push(format!(
                "{name}: {stuck} of {} solves reached the iteration limit (contact_solver.max_iterations = {}); those rows are not converged",
                h.rows.len(),
                problem.contact_solver.max_iterations
            ));
        }
        all_metrics.extend(metrics::compute(&problem.metrics, &problem.loading, &h, &field));
        histories.push(h);
        timing.push(t);
    }
    Ok(SceneResult { problem, histories, timing, metrics: all_metrics })
}
