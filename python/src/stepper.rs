//! `Stepper`: one built-in model stepped from Python (a multibody loop drives the UBA, the
//! relaxation model or the exact solver one time step at a time), through the library's
//! `solvers::Stepper` as the sample loop drives it: a reload when FN or μ changes.

use crate::errors;
use crate::steady::{model_problem, solve_error};
use creepbench::problem::{Problem, Sample};
use creepbench::solvers;
use creepbench::InputError;
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// A model with its own state (`creepbench.Stepper` wraps it).
#[pyclass(unsendable, module = "creepbench._creepbench")]
pub struct Stepper {
    // Declared before `problem`, so dropped before it: it borrows `problem`.
    stepper: Box<dyn solvers::Stepper + 'static>,
    problem: Box<Problem>,
    model: String,
    /// (FN, μ) of the last load, none before the first solve.
    loaded: Option<(f64, f64)>,
    steps: usize,
}

#[pymethods]
impl Stepper {
    #[new]
    fn new(model: &str, table: &Bound<'_, PyDict>) -> PyResult<Self> {
        let (problem, def) = model_problem(model, table)?;
        let problem = Box::new(problem);
        // SAFETY: the stepper borrows the boxed problem, whose heap address stays put while the
        // box lives; the box is never moved out of or changed, and it is dropped after the stepper
        // (field order), so the borrow never outlives it.
        let borrowed: &'static Problem = unsafe { &*(problem.as_ref() as *const Problem) };
        let stepper = (def.build)(borrowed).map_err(|e| solve_error(&problem, model, e))?;
        Ok(Stepper { stepper, problem, model: model.to_string(), loaded: None, steps: 0 })
    }

    /// The model's name.
    #[getter]
    fn model(&self) -> &str {
        &self.model
    }

    /// The time step [s] (courant dx / v of the scene's rolling).
    #[getter]
    fn dt_s(&self) -> f64 {
        self.problem.rolling.dt_s
    }

    /// Time steps taken so far.
    #[getter]
    fn steps(&self) -> usize {
        self.steps
    }

    /// One time step to creepages (cx, cy, cs [1/mm]) at load fn_n [N] and friction mu:
    /// (fx/fn, fy/fn, mz [N·mm]).
    fn step(&mut self, cx: f64, cy: f64, cs: f64, fn_n: f64, mu: f64) -> PyResult<(f64, f64, f64)> {
        let s = self.sample(self.steps + 1, cx, cy, cs, fn_n, mu)?;
        let r = self.stepper.transient(&s).map_err(|e| solve_error(&self.problem, &self.model, e))?;
        self.steps += 1;
        Ok((r.fx_over_fn, r.fy_over_fn, r.mz_nmm))
    }

    /// Steady rolling at these creepages, load and friction (the state becomes the steady one):
    /// (fx/fn, fy/fn, mz [N·mm]).
    fn steady(&mut self, cx: f64, cy: f64, cs: f64, fn_n: f64, mu: f64) -> PyResult<(f64, f64, f64)> {
        let s = self.sample(self.steps, cx, cy, cs, fn_n, mu)?;
        let r = self.stepper.steady(&s).map_err(|e| solve_error(&self.problem, &self.model, e))?;
        Ok((r.fx_over_fn, r.fy_over_fn, r.mz_nmm))
    }

    /// The traction field of the last solve, if the model has one: `{"pn_mpa", "px_mpa",
    /// "py_mpa"}` as (my, mx) arrays.
    fn field<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(v) = self.stepper.field() else { return Ok(None) };
        let d = PyDict::new(py);
        for (key, values) in [("pn_mpa", v.pressure_mpa), ("px_mpa", v.tx_mpa), ("py_mpa", v.ty_mpa)] {
            let a = Array2::from_shape_vec((v.grid.my, v.grid.mx), values.to_vec())
                .map_err(|e| errors::failure(e.to_string()))?;
            d.set_item(key, a.into_pyarray(py) as Bound<'py, PyArray2<f64>>)?;
        }
        Ok(Some(d))
    }
}

impl Stepper {
    /// The sample of step `step`, after loading the contact when FN or μ changed.
    fn sample(&mut self, step: usize, cx: f64, cy: f64, cs: f64, fn_n: f64, mu: f64) -> PyResult<Sample> {
        for (field, v, ok, allowed) in [
            ("cx", cx, cx.is_finite(), "a finite number"),
            ("cy", cy, cy.is_finite(), "a finite number"),
            ("cs", cs, cs.is_finite(), "a finite number [1/mm]"),
            ("fn_n", fn_n, fn_n.is_finite() && fn_n > 0.0, "a finite load > 0 [N]"),
            ("mu", mu, mu.is_finite() && mu > 0.0, "a finite friction coefficient > 0"),
        ] {
            if !ok {
                return Err(errors::input(InputError::new(field, v, allowed)));
            }
        }
        let s = Sample::given(step, step as f64 * self.problem.rolling.dt_s, cx, cy, cs, fn_n, mu);
        if self.loaded != Some((fn_n, mu)) {
            self.stepper.load(&s).map_err(|e| solve_error(&self.problem, &self.model, e))?;
            self.loaded = Some((fn_n, mu));
        }
        Ok(s)
    }
}
