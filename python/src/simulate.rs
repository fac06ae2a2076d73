//! `simulate`: a scene through the library's pipeline (its models, and Python callables run in
//! this process), kept as the stored scene the CLI writes, plus the fields on request.

use crate::{errors, model, scene};
use creepbench::comparison::compare::{self, Against};
use creepbench::comparison::references::References;
use creepbench::comparison::tolerance_file;
use creepbench::history::sample_loop;
use creepbench::pipeline;
use creepbench::problem::Problem;
use creepbench::safety::lock;
use creepbench::solvers;
use creepbench::suite::results::{self, StoredScene};
use creepbench::{commands, Error};
use numpy::ndarray::Array3;
use numpy::{IntoPyArray, PyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;

/// A history's column names and its columns as NumPy arrays.
pub(crate) type Columns<'py> = (Vec<String>, Vec<Bound<'py, PyArray1<f64>>>);

/// One scene's results (`creepbench.Simulation` wraps it).
#[pyclass(frozen, module = "creepbench._creepbench")]
pub struct Simulation {
    stored: StoredScene,
    /// The models in the order they ran.
    order: Vec<String>,
    warnings: Vec<String>,
    /// Per built-in model, the traction field of every step (with `fields=True`).
    fields: Vec<(String, Vec<sample_loop::Field>)>,
    /// Element centres [mm] along x and y.
    grid: (Vec<f64>, Vec<f64>),
}

/// Run a scene (`kind` "path", "toml" or "table") or, with `study`, every point of a study file;
/// `models` maps names to in-process models.
#[pyfunction]
#[pyo3(signature = (kind, scene, solvers, models, fields, study))]
pub fn simulate(
    py: Python<'_>,
    kind: &str,
    scene: &Bound<'_, PyAny>,
    solvers: Vec<String>,
    models: Vec<(String, Py<PyAny>)>,
    fields: bool,
    study: bool,
) -> PyResult<Vec<Simulation>> {
    let names: Vec<String> = models.iter().map(|(n, _)| n.clone()).collect();
    let problems = scene::problems(kind, scene, &solvers, &names, study)?;
    py.detach(|| problems.into_iter().map(|p| run_one(p, &models, fields)).collect::<Result<Vec<_>, Error>>())
        .map_err(errors::to_py)
}

fn run_one(problem: Problem, models: &[(String, Py<PyAny>)], fields: bool) -> Result<Simulation, Error> {
    let order = problem.solvers.clone();
    let result = model::with_in_process(models, |in_process| pipeline::run_with(problem, in_process))?;
    let p = &result.problem;
    let mut kept = Vec::new();
    if fields {
        for def in p.solvers.iter().filter_map(|s| solvers::builtin(s)) {
            let (_, f) = sample_loop::run_with_fields(p, def, &|_| true).map_err(|e| Error::Solve {
                scene: p.name.clone(),
                solver: def.name.to_string(),
                source: Box::new(e),
            })?;
            kept.push((def.name.to_string(), f));
        }
    }
    Ok(Simulation {
        stored: StoredScene::from_result(&result),
        order,
        warnings: p.warnings.clone(),
        fields: kept,
        grid: (p.grid.x_mm.clone(), p.grid.y_mm.clone()),
    })
}

#[pymethods]
impl Simulation {
    /// The scene's name.
    #[getter]
    fn name(&self) -> &str {
        &self.stored.name
    }

    /// The models in the order they ran.
    #[getter]
    fn solvers(&self) -> Vec<String> {
        self.order.clone()
    }

    /// Warnings of the scene (as the CLI prints them).
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.warnings.clone()
    }

    /// The result folder's files as the CLI writes them: `(name, text)`.
    fn files(&self) -> Vec<(String, String)> {
        self.stored.file_texts(false)
    }

    /// One model's history: column names and one float64 array per column (`step` included).
    fn history<'py>(&self, py: Python<'py>, solver: &str) -> PyResult<Columns<'py>> {
        let h = self.stored.histories.get(solver).ok_or_else(|| {
            errors::input(creepbench::InputError::new("solver", solver, format!("one of {}", self.order.join(", "))))
        })?;
        let mut names: Vec<String> = creepbench::history::COLUMNS.iter().map(|s| s.to_string()).collect();
        names.insert(8, creepbench::history::MU.to_string());
        names.extend(h.extra_columns.iter().cloned());
        let columns = names.iter().map(|n| h.column(n).unwrap_or_default().into_pyarray(py)).collect();
        Ok((names, columns))
    }

    /// Metric rows `(solver, metric, value, step)` (step `None` for a scalar metric).
    fn metrics(&self) -> Vec<(String, String, f64, Option<usize>)> {
        self.stored.metrics.iter().map(|((s, m, step), v)| (s.clone(), m.clone(), *v, *step)).collect()
    }

    /// The fields of every step per built-in model (with `fields=True`): `{model: {"step",
    /// "pn_mpa", "px_mpa", "py_mpa"}}`, the tractions as (steps, my, mx) arrays, plus "x_mm" and
    /// "y_mm" (element centres).
    fn fields<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let out = PyDict::new(py);
        let (mx, my) = (self.grid.0.len(), self.grid.1.len());
        for (model, steps) in &self.fields {
            let d = PyDict::new(py);
            d.set_item("step", steps.iter().map(|f| f.step as f64).collect::<Vec<_>>().into_pyarray(py))?;
            for (key, get) in [
                ("pn_mpa", (|f: &sample_loop::Field| &f.pn_mpa) as fn(&sample_loop::Field) -> &Vec<f64>),
                ("px_mpa", |f| &f.px_mpa),
                ("py_mpa", |f| &f.py_mpa),
            ] {
                let flat: Vec<f64> = steps.iter().flat_map(|f| get(f).iter().copied()).collect();
                let array =
                    Array3::from_shape_vec((steps.len(), my, mx), flat).map_err(|e| errors::failure(e.to_string()))?;
                d.set_item(key, array.into_pyarray(py))?;
            }
            out.set_item(model, d)?;
        }
        out.set_item("x_mm", self.grid.0.clone().into_pyarray(py))?;
        out.set_item("y_mm", self.grid.1.clone().into_pyarray(py))?;
        Ok(out)
    }

    /// Write the result folder `dir/<name>/` as `simulate --out dir` does; its path.
    fn save(&self, py: Python<'_>, dir: PathBuf) -> PyResult<PathBuf> {
        py.detach(|| {
            let _lock = lock::lock_folder(&dir, lock::DEFAULT_LOCK_WAIT)?;
            Ok::<_, Error>(results::write_scenes(&dir, std::slice::from_ref(&self.stored), false)?.remove(0))
        })
        .map_err(errors::to_py)
    }

    /// Gate this scene's results as `check` does: against the references in `reference` and, if
    /// given, a baseline folder (`baseline`: golden data, or with `previous` a folder of earlier
    /// results), with the tolerance files `tolerances` applied. Returns the findings and the
    /// loosened rules.
    #[pyo3(signature = (reference, baseline, previous, tolerances))]
    fn gate(
        &self,
        reference: PathBuf,
        baseline: Option<PathBuf>,
        previous: bool,
        tolerances: Vec<PathBuf>,
    ) -> PyResult<(Vec<crate::gate::PyFinding>, Vec<String>)> {
        let gate = || -> Result<_, Error> {
            let refs = References::load(&reference)?;
            let rules = commands::file_rules(&tolerances, &[])?;
            let kind = if previous { Against::Previous } else { Against::Golden };
            let baseline = baseline.as_deref().map(|g| (g, kind));
            let mut all = compare::evaluate(std::slice::from_ref(&self.stored), &refs, baseline)?;
            // Rules of --tolerances files only (file_rules with no suite): every scene.
            let loosened = tolerance_file::apply(&rules, &mut all, &Default::default(), |_| false)?;
            Ok((all, loosened))
        };
        let (all, loosened) = gate().map_err(errors::to_py)?;
        Ok((all.iter().map(crate::gate::PyFinding::of).collect(), loosened.iter().map(|l| l.to_string()).collect()))
    }
}
