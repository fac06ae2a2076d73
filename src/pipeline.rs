//! The straight path scene → resolved problem → solver → history → metrics, for one scene.

use crate::error::{Error, InputError};
use crate::history::History;
use crate::metrics::{self, Metric};
use crate::problem::Problem;
use crate::scene::Scene;
use crate::solvers;
use std::path::Path;
use std::time::Instant;

/// One scene's results.
#[derive(Debug, Clone)]
pub struct SceneResult {
    pub problem: Problem,
    pub histories: Vec<History>,
    /// Wall time per solver [s] (not written to the CSVs, which stay deterministic).
    pub wall_s: Vec<f64>,
    pub metrics: Vec<Metric>,
}

/// Read, validate and resolve a scene file; `only` narrows its solver list.
pub fn load(path: &Path, only: &[String]) -> Result<Problem, Error> {
    let scene = Scene::from_file(path)?;
    let mut problem = Problem::resolve(&scene)?;
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

/// Run the problem's solvers (only those it lists) and compute its metrics.
pub fn run(problem: Problem) -> Result<SceneResult, Error> {
    let mut histories = Vec::new();
    let mut wall_s = Vec::new();
    let mut all_metrics = Vec::new();
    for name in &problem.solvers {
        let solver = solvers::by_name(name, &problem).ok_or_else(|| Error::other(format!("unknown solver {name}")))?;
        let start = Instant::now();
        let h = solver.run(&problem)?;
        wall_s.push(start.elapsed().as_secs_f64());
        all_metrics.extend(metrics::compute(&problem, &h));
        histories.push(h);
    }
    Ok(SceneResult { problem, histories, wall_s, metrics: all_metrics })
}
