//! `loading`: the loading of every row of a resolved scene (scene.json's text), sampled from its
//! declared loading by the library's one sampling (`ResolvedScene::loading_rows`), with the
//! columns of an external model's `loading.csv` (`problem::loading::loading_columns`).

use crate::errors;
use crate::simulate::Columns;
use creepbench::problem::loading::loading_columns;
use creepbench::problem::ResolvedScene;
use numpy::IntoPyArray;
use pyo3::prelude::*;

/// The column names and one float64 array per column (NaN where a row leaves an optional column out).
#[pyfunction]
pub fn loading<'py>(py: Python<'py>, scene_json: &str) -> PyResult<Columns<'py>> {
    let scene = ResolvedScene::from_json(scene_json).map_err(|e| {
        errors::input(creepbench::InputError::new("scene", format!("not a scene.json ({e})"), "a resolved scene"))
    })?;
    let rows = scene.loading_rows().map_err(errors::input)?;
    let columns = loading_columns(&rows);
    let names = columns.iter().map(|c| c.name.to_string()).collect();
    let values = columns
        .iter()
        .map(|c| rows.iter().map(|s| (c.value)(s).unwrap_or(f64::NAN)).collect::<Vec<_>>().into_pyarray(py))
        .collect();
    Ok((names, values))
}
