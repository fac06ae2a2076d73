//! `check`: the library's gate over suites (`commands::gate`), its findings as Python dicts.

use crate::{errors, model};
use creepbench::commands::{self, GateFiles, RunOutputs, Runner};
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

/// Run the suites and gate them as `creepbench check` does (`models`: Python callables run
/// in-process where a scene lists them); the findings and the loosened rules.
#[pyfunction]
#[pyo3(signature = (suites, reference, golden, against, tolerances, strict, models))]
#[allow(clippy::too_many_arguments)]
pub fn check(
    py: Python<'_>,
    suites: Vec<PathBuf>,
    reference: PathBuf,
    golden: PathBuf,
    against: Option<PathBuf>,
    tolerances: Vec<PathBuf>,
    strict: bool,
    models: Vec<(String, Py<PyAny>)>,
) -> PyResult<(Vec<PyFinding>, Vec<String>)> {
    let files = GateFiles { tolerances, strict, ..GateFiles::default() };
    let gate = py
        .detach(|| {
            model::with_in_process(&models, |in_process| {
                let runner = Runner { in_process, ..Runner::default() };
                commands::gate(
                    &suites,
                    &reference,
                    commands::Baseline { golden: &golden, against: against.as_deref() },
                    runner,
                    &files,
                )
            })
        })
        .map_err(errors::to_py)?;
    Ok((gate.findings.iter().map(PyFinding::of).collect(), gate.loosened.iter().map(|l| l.to_string()).collect()))
}

/// What `run` gives back: the result folder, validation.md, the report's findings, the loosened
/// rules and the oscillating histories.
type RunGiven = (PathBuf, PathBuf, Vec<PyFinding>, Vec<String>, Vec<String>);

/// Run the suites as `creepbench run` does (`models` as in [`check`]): the result folders in
/// `results`, the report in `report` (the fit files of `fits` run too when given).
#[pyfunction]
#[pyo3(signature = (suites, reference, golden, results, report, fits, models))]
#[allow(clippy::too_many_arguments)]
pub fn run(
    py: Python<'_>,
    suites: Vec<PathBuf>,
    reference: PathBuf,
    golden: PathBuf,
    results: PathBuf,
    report: PathBuf,
    fits: Option<PathBuf>,
    models: Vec<(String, Py<PyAny>)>,
) -> PyResult<RunGiven> {
    let outputs = RunOutputs { results_dir: &results, report_dir: &report, fits: fits.as_deref() };
    let outcome = py
        .detach(|| {
            model::with_in_process(&models, |in_process| {
                let runner = Runner { in_process, ..Runner::default() };
                commands::run_with(&suites, &reference, outputs, runner, &golden)
            })
        })
        .map_err(errors::to_py)?;
    let md = outcome.report.expect("a run of every scene (no shard) writes its report");
    Ok((
        outcome.results_dir,
        md,
        outcome.findings.iter().map(PyFinding::of).collect(),
        outcome.loosened.iter().map(|l| l.to_string()).collect(),
        outcome.oscillating,
    ))
}
