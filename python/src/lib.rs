//! creepbench's Python bindings (PyO3): the library's pipeline, gate and models behind a
//! Python module. Each function here converts Python values, calls the library and converts back;
//! nothing is computed twice (docs/python.md).

mod errors;
mod gate;
mod loading;
mod model;
mod scene;
mod simulate;
mod steady;
mod stepper;
mod wheelrail;

use pyo3::prelude::*;

/// The compiled half of the `creepbench` package (the Python half wraps it: `creepbench/__init__.py`).
#[pymodule]
fn _creepbench(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(simulate::simulate, m)?)?;
    m.add_function(wrap_pyfunction!(gate::check, m)?)?;
    m.add_function(wrap_pyfunction!(gate::run, m)?)?;
    m.add("STEADY_CHUNK_ROWS", steady::CHUNK_ROWS)?;
    m.add_function(wrap_pyfunction!(steady::steady, m)?)?;
    m.add_function(wrap_pyfunction!(steady::model_names, m)?)?;
    m.add_function(wrap_pyfunction!(loading::loading, m)?)?;
    m.add_class::<simulate::Simulation>()?;
    m.add_class::<stepper::Stepper>()?;
    m.add_function(wrap_pyfunction!(wheelrail::simulate_wheelrail, m)?)?;
    m.add_class::<wheelrail::WheelRailRun>()?;
    Ok(())
}
