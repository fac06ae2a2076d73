//! `check`: the library's gate over suites (`commands::gate`), its findings as Python dicts.

use crate::errors;
use creepbench::commands::{self, GateFiles};
use creepbench::comparison::compare::Finding;
use creepbench::comparison::console;
use pyo3::prelude::*;
use std::path::PathBuf;

/// One comparison's worst point, as a dict (`creepbench.Finding` reads it).
#[derive(IntoPyObject)]
pub struct PyFinding {
    scene: String,
    solver: String,
    against: String,
    quantity: String,
    step: Option<usize>,
    ours: f64,
    theirs: f64,
    diff: f64,
    allowed: f64,
    gated: bool,
    passed: bool,
    /// |diff| / allowed as `check` prints it.
    ratio: String,
    note: String,
}

impl PyFinding {
    pub fn of(f: &Finding) -> Self {
        PyFinding {
            scene: f.scene.clone(),
            solver: f.solver.clone(),
            against: f.against.label().to_string(),
            quantity: f.quantity.clone(),
            step: f.step,
            ours: f.ours,
            theirs: f.theirs,
            diff: f.diff,
            allowed: f.allowed,
            gated: f.gated,
            passed: f.passed(),
            ratio: console::ratio(f),
            note: f.note.clone(),
        }
    }
}

/// Run the suites and gate them as `creepbench check` does; the findings and the loosened rules.
#[pyfunction]
#[pyo3(signature = (suites, reference, golden, against, tolerances, strict))]
pub fn check(
    py: Python<'_>,
    suites: Vec<PathBuf>,
    reference: PathBuf,
    golden: PathBuf,
    against: Option<PathBuf>,
    tolerances: Vec<PathBuf>,
    strict: bool,
) -> PyResult<(Vec<PyFinding>, Vec<String>)> {
    let files = GateFiles { tolerances, strict, ..GateFiles::default() };
    let gate = py
        .detach(|| commands::gate(&suites, &reference, &golden, against.as_deref(), None, false, &files))
        .map_err(errors::to_py)?;
    Ok((gate.findings.iter().map(PyFinding::of).collect(), gate.loosened.iter().map(|l| l.to_string()).collect()))
}
