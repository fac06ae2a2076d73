//! `simulate_wheelrail`: a wheel–rail scene (profiles, track, wheelset cases) through the
//! library's wheel–rail pipeline, kept as the result folder's files the CLI writes
//! (`<model>.csv`, `<model>_patches.csv`; docs/wheelrail.md).

use crate::errors;
use creepbench::pipeline::wheelrail_scene::{self, SceneRun};
use creepbench::safety::lock;
use creepbench::scene::reader::parse_toml;
use creepbench::scene::wheelrail::WheelRailScene;
use creepbench::{commands, suite, Error};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::{Path, PathBuf};

/// One wheel–rail scene's results (`creepbench.WheelRailSimulation` wraps it).
#[pyclass(frozen, module = "creepbench._creepbench")]
pub struct WheelRailRun {
    run: SceneRun,
}

/// Run a wheel–rail scene (`kind` "path", "toml" or "table": the profile paths of TOML text or a
/// dict are taken from the current folder); `solvers` narrows its models as `simulate --solver`
/// does.
#[pyfunction]
#[pyo3(signature = (kind, scene, solvers))]
pub fn simulate_wheelrail(
    py: Python<'_>,
    kind: &str,
    scene: &Bound<'_, PyAny>,
    solvers: Vec<String>,
) -> PyResult<WheelRailRun> {
    let mut scene = match kind {
        "path" => WheelRailScene::from_file(&scene.extract::<PathBuf>()?).map_err(errors::input)?,
        "toml" => {
            let table = parse_toml(&scene.extract::<String>()?, "scene").map_err(errors::input)?;
            WheelRailScene::from_table(&table, Path::new("")).map_err(errors::input)?
        }
        _ => {
            let table = crate::scene::to_table(scene.cast::<PyDict>()?, "")?;
            WheelRailScene::from_table(&table, Path::new("")).map_err(errors::input)?
        }
    };
    commands::narrow(&mut scene, &solvers).map_err(errors::to_py)?;
    let run = py.detach(|| wheelrail_scene::run_scene(&scene)).map_err(errors::to_py)?;
    Ok(WheelRailRun { run })
}

#[pymethods]
impl WheelRailRun {
    /// The scene's name.
    #[getter]
    fn name(&self) -> &str {
        &self.run.name
    }

    /// The models in the order they ran.
    #[getter]
    fn solvers(&self) -> Vec<String> {
        self.run.models.clone()
    }

    /// The result folder's files as the CLI writes them: `(name, text)`.
    fn files(&self) -> Vec<(String, String)> {
        suite::wheelrail::files(&self.run)
            .into_iter()
            .map(|(name, bytes)| (name, String::from_utf8_lossy(&bytes).into_owned()))
            .collect()
    }

    /// Write the result folder `dir/<name>/` as `creepbench simulate --out dir` does.
    fn save(&self, py: Python<'_>, dir: PathBuf) -> PyResult<PathBuf> {
        py.detach(|| -> Result<PathBuf, Error> {
            let _lock = lock::lock_folder(&dir, lock::DEFAULT_LOCK_WAIT)?;
            suite::wheelrail::write(&dir, &self.run)
        })
        .map_err(errors::to_py)
    }
}
