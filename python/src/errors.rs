//! The library's errors as Python exceptions: invalid input as `SceneError` (a `ValueError`
//! carrying `field`, `value` and `allowed`), anything else as `CreepbenchError`, with the
//! library's message unchanged.

use creepbench::{Error, InputError};
use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

create_exception!(creepbench, SceneError, PyValueError, "Invalid input: `field`, `value` and `allowed` name it.");
create_exception!(creepbench, CreepbenchError, PyRuntimeError, "A model, the gate or a file failed.");

/// A `SceneError` for an input error, its message the CLI's.
pub fn input(e: InputError) -> PyErr {
    let message = Error::Input(e.clone()).to_string();
    Python::attach(|py| {
        let err = SceneError::new_err(message);
        let value = err.value(py);
        let set = [("field", &e.field), ("value", &e.value), ("allowed", &e.allowed)]
            .into_iter()
            .try_for_each(|(k, v)| value.setattr(k, v));
        match set {
            Ok(()) => err,
            Err(setting) => setting,
        }
    })
}

/// The Python exception of a library error.
pub fn to_py(e: Error) -> PyErr {
    match e {
        Error::Input(i) => input(i),
        other => CreepbenchError::new_err(other.to_string()),
    }
}
