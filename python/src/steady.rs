//! `steady`: a built-in model's steady forces and moment for many creepages in one call, in
//! parallel (rayon, one stepper per fixed chunk of consecutive rows) with the GIL released.

use crate::errors;
use creepbench::pipeline;
use creepbench::problem::{Problem, Sample};
use creepbench::solvers::{self, ModelDef, SolveError};
use creepbench::{Error, InputError};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2, PyReadonlyArray2};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;
use std::path::Path;

/// The names of the built-in models, in registry order.
#[pyfunction]
pub fn model_names() -> Vec<&'static str> {
    solvers::builtin_names()
}

/// The problem of a scene table (its `solvers` naming one built-in model) and that model.
pub fn model_problem(model: &str, table: &Bound<'_, PyDict>) -> PyResult<(Problem, &'static ModelDef)> {
    let def = solvers::builtin(model).ok_or_else(|| {
        errors::input(InputError::new(
            "model",
            format!("{model:?}"),
            format!("a built-in model: {}", solvers::builtin_names().join(", ")),
        ))
    })?;
    let doc = crate::scene::to_table(table, "")?;
    let problem = pipeline::load_table(&doc, Path::new(""), &[], &[]).map_err(errors::to_py)?;
    Ok((problem, def))
}

/// The error of a model's solve on the problem.
pub fn solve_error(problem: &Problem, model: &str, e: SolveError) -> PyErr {
    errors::to_py(Error::Solve { scene: problem.name.clone(), solver: model.to_string(), source: Box::new(e) })
}

/// Steady (fx/fn, fy/fn, mz [N·mm]) of `model` for each row (cx, cy, cs [1/mm]) of `creepages`.
#[pyfunction]
pub fn steady<'py>(
    py: Python<'py>,
    model: &str,
    creepages: PyReadonlyArray2<'py, f64>,
    table: &Bound<'py, PyDict>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let view = creepages.as_array();
    if view.ncols() != 3 {
        return Err(errors::input(InputError::new(
            "creepages",
            format!("an array of shape {:?}", view.shape()),
            "an (N, 3) array of (cx, cy, cs [1/mm])",
        )));
    }
    if let Some((k, v)) = view.iter().enumerate().find(|(_, v)| !v.is_finite()) {
        return Err(errors::input(InputError::new(format!("creepages[{}, {}]", k / 3, k % 3), v, "a finite number")));
    }
    let rows: Vec<[f64; 3]> = view.rows().into_iter().map(|r| [r[0], r[1], r[2]]).collect();
    let (problem, def) = model_problem(model, table)?;
    let out = py.detach(|| evaluate(&problem, def, &rows)).map_err(|e| solve_error(&problem, model, e))?;
    let array = Array2::from_shape_vec((rows.len(), 3), out).map_err(|e| errors::failure(e.to_string()))?;
    Ok(array.into_pyarray(py))
}

/// Rows per chunk of [`evaluate`]: a fixed number, whatever the thread count, so the result is
/// the same bit for bit with one thread or many and from run to run. A model whose steady solve
/// starts from its previous solution (the exact solver) gives within a chunk the CLI's sweep
/// over those rows bit for bit; at each chunk's first row it starts as the sweep's first point.
pub const CHUNK_ROWS: usize = 256;

/// The steady solves, one stepper per chunk of [`CHUNK_ROWS`] consecutive rows (the chunks run
/// in parallel), each loaded at the problem's first sample as the sample loop does.
fn evaluate(problem: &Problem, def: &ModelDef, rows: &[[f64; 3]]) -> Result<Vec<f64>, SolveError> {
    let mut out = vec![0.0; rows.len() * 3];
    let chunk = CHUNK_ROWS;
    let first = *problem.loading.first();
    out.par_chunks_mut(chunk * 3).zip(rows.par_chunks(chunk)).enumerate().try_for_each(|(k, (out, rows))| {
        let mut stepper = (def.build)(problem)?;
        stepper.load(&first)?;
        for (j, (o, c)) in out.chunks_mut(3).zip(rows).enumerate() {
            let step = k * chunk + j + 1;
            let s = Sample { step, cx: c[0], cy: c[1], cs: c[2], ..first };
            let r = stepper.steady(&s)?;
            if !(r.fx_over_fn.is_finite() && r.fy_over_fn.is_finite()) {
                return Err(SolveError::NonFinite { step });
            }
            o.copy_from_slice(&[r.fx_over_fn, r.fy_over_fn, r.mz_nmm]);
        }
        Ok(())
    })?;
    Ok(out)
}
