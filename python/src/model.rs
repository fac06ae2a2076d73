//! A Python callable as a model run in this process (`simulate(..., models={name: f})`): it is
//! called with the resolved scene (scene.json's text, as an external model reads it) and gives the
//! history's columns; the library parses them as an external model's CSV and validates them the
//! same way (`history::external::validate_in_process`), then compares them as any model's.

use creepbench::history::external::ExternalError;
use creepbench::history::History;
use creepbench::pipeline::InProcess;
use creepbench::problem::{Problem, ResolvedScene};
use creepbench::Error;
use numpy::PyReadonlyArray1;
use pyo3::prelude::*;
use std::fmt::Write;
use std::path::PathBuf;

/// Python callables `(name, callable)` as the library's in-process models, given to `f`.
pub fn with_in_process<R>(models: &[(String, Py<PyAny>)], f: impl FnOnce(&[InProcess]) -> R) -> R {
    let calls: Vec<_> = models.iter().map(|(name, c)| (name.as_str(), move |p: &Problem| call(c, name, p))).collect();
    let in_process: Vec<InProcess> =
        calls.iter().map(|(n, c)| (*n, c as &(dyn Fn(&Problem) -> Result<History, Error> + Sync))).collect();
    f(&in_process)
}

/// Call the model `name` (the Python wrapper's adapter around the user's callable, which returns
/// `(column names, one float64 array per column)`) on the problem.
pub fn call(callable: &Py<PyAny>, name: &str, problem: &Problem) -> Result<History, Error> {
    let json = ResolvedScene::of(problem, &problem.solvers).to_json();
    let failed = |source: Box<dyn std::error::Error + Send + Sync>| Error::External {
        scene: problem.name.clone(),
        solver: name.to_string(),
        source,
    };
    let text = Python::attach(|py| -> PyResult<String> {
        let out = callable.call1(py, (json,))?;
        let (columns, values): (Vec<String>, Vec<PyReadonlyArray1<f64>>) = out.extract(py)?;
        let values: Vec<_> = values.iter().map(|v| v.as_array()).collect();
        Ok(csv_text(&columns, &values))
    })
    .map_err(|e| failed(Box::new(e)))?;
    History::from_csv(name, &text).map_err(|format| {
        failed(Box::new(ExternalError::Unparsable { out: PathBuf::from(format!("<in-process {name}>")), format }))
    })
}

/// The columns as the CSV an external model writes: the step column as an integer where it is
/// one, every other value in Rust's shortest round-trip form (so the parse gives the same f64).
fn csv_text(columns: &[String], values: &[numpy::ndarray::ArrayView1<f64>]) -> String {
    let mut out = columns.join(",");
    out.push('\n');
    let rows = values.iter().map(|v| v.len()).max().unwrap_or(0);
    for r in 0..rows {
        for (c, v) in values.iter().enumerate() {
            if c > 0 {
                out.push(',');
            }
            match v.get(r) {
                Some(&x) if c == 0 && x >= 0.0 && x.fract() == 0.0 && x < 1e15 => write!(out, "{}", x as u64),
                Some(x) => write!(out, "{x}"),
                None => Ok(()),
            }
            .expect("writing to a String");
        }
        out.push('\n');
    }
    out
}
