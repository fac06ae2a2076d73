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

/// The Python exception of a library error; an in-process model's own exception is its cause.
pub fn to_py(e: Error) -> PyErr {
    match e {
        Error::Input(i) => input(i),
        Error::External { scene, solver, source } => match source.downcast::<PyErr>() {
            Ok(cause) => Python::attach(|py| {
                let err = CreepbenchError::new_err(format!(
                    "in-process model `{solver}` failed on scene `{scene}`: {cause} (<in-process {solver}>)"
                ));
                err.set_cause(py, Some(*cause));
                err
            }),
            Err(source) => CreepbenchError::new_err(Error::External { scene, solver, source }.to_string()),
        },
        other => CreepbenchError::new_err(other.to_string()),
    }
}
