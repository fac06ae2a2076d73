//! The library's errors as the package's Python exceptions (defined once, in
//! `creepbench/errors.py`): invalid input as `SceneError` (a `ValueError` carrying `field`,
//! `value` and `allowed`), anything else as `RunError`, both `CreepbenchError`s, with the
//! library's message unchanged.

use creepbench::{Error, InputError};
use pyo3::prelude::*;

/// An instance of the package's exception class `class` made with `args`.
fn raise<'py, A: pyo3::call::PyCallArgs<'py>>(py: Python<'py>, class: &str, args: A) -> PyErr {
    let made = py.import("creepbench.errors").and_then(|m| m.getattr(class)).and_then(|c| c.call1(args));
    match made {
        Ok(instance) => PyErr::from_value(instance),
        Err(importing) => importing,
    }
}

/// A `SceneError` for an input error, its message the CLI's.
pub fn input(e: InputError) -> PyErr {
    let message = Error::Input(e.clone()).to_string();
    Python::attach(|py| raise(py, "SceneError", (message, e.field, e.value, e.allowed)))
}

/// A `RunError` with this message.
pub fn failure(message: impl Into<String>) -> PyErr {
    let message: String = message.into();
    Python::attach(|py| raise(py, "RunError", (message,)))
}

/// The Python exception of a library error; an in-process model's own exception is its cause.
pub fn to_py(e: Error) -> PyErr {
    match e {
        Error::Input(i) => input(i),
        Error::External { scene, solver, source } => match source.downcast::<PyErr>() {
            Ok(cause) => Python::attach(|py| {
                let err = failure(format!(
                    "in-process model `{solver}` failed on scene `{scene}`: {cause} (<in-process {solver}>)"
                ));
                err.set_cause(py, Some(*cause));
                err
            }),
            Err(source) => failure(Error::External { scene, solver, source }.to_string()),
        },
        other => failure(other.to_string()),
    }
}
