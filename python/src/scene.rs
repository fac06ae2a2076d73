//! A scene from Python: a path (a scene or study file), TOML text, or a dict of the scene's keys,
//! validated and resolved by the library's pipeline (the same checks and error text as the CLI).

use crate::errors;
use creepbench::pipeline;
use creepbench::problem::Problem;
use creepbench::scene::reader::parse_toml;
use creepbench::suite;
use creepbench::InputError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use std::path::{Path, PathBuf};

/// The scene's problems (one for a scene, one per point for a study file); `only` narrows their
/// solvers; `in_process` are the names of models run in this process that the scene may list.
/// `study` says which the caller asked for: a study file (`simulate_study`) or one scene.
pub fn problems(
    kind: &str,
    scene: &Bound<'_, PyAny>,
    only: &[String],
    in_process: &[String],
    study: bool,
) -> PyResult<Vec<Problem>> {
    if study && kind != "path" {
        return Err(errors::input(InputError::new(
            "scene",
            if kind == "toml" { "TOML text" } else { "a dict" },
            "a study file's path",
        )));
    }
    let table = match kind {
        "path" => {
            let path: PathBuf = scene.extract()?;
            let sources = suite::sources_of_file(&path).map_err(errors::to_py)?;
            let is_study = sources.iter().any(|s| s.study.is_some());
            if is_study != study {
                let allowed = if study {
                    "a study file (a [study] table): a scene file goes to simulate()"
                } else {
                    "a scene file, TOML text or a dict: a study file (a [study] table) goes to simulate_study()"
                };
                return Err(errors::input(InputError::new("scene", path.display().to_string(), allowed)));
            }
            return sources
                .iter()
                .map(|s| pipeline::load_source_with(s, only, in_process).map_err(errors::to_py))
                .collect();
        }
        "toml" => parse_toml(&scene.extract::<String>()?, "scene").map_err(errors::input)?,
        _ => to_table(scene.cast::<PyDict>()?, "")?,
    };
    Ok(vec![pipeline::load_table(&table, Path::new(""), only, in_process).map_err(errors::to_py)?])
}

/// A dict of TOML values as a TOML table; `at` is its dotted place, for errors.
pub fn to_table(d: &Bound<'_, PyDict>, at: &str) -> PyResult<toml::Table> {
    let mut table = toml::Table::new();
    for (k, v) in d.iter() {
        let key: String = k.extract().map_err(|_| {
            errors::input(InputError::new(
                place(at, "<key>"),
                k.repr().map_or_else(|_| "?".into(), |r| r.to_string()),
                "string keys",
            ))
        })?;
        let value = to_value(&v, &place(at, &key))?;
        table.insert(key, value);
    }
    Ok(table)
}

fn place(at: &str, key: &str) -> String {
    if at.is_empty() {
        key.to_string()
    } else {
        format!("{at}.{key}")
    }
}

/// One Python value as a TOML value (bool, int, float, str, list or tuple, dict).
fn to_value(v: &Bound<'_, PyAny>, at: &str) -> PyResult<toml::Value> {
    if v.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(v.extract()?));
    }
    if v.is_instance_of::<PyInt>() {
        if let Ok(i) = v.extract::<i64>() {
            return Ok(toml::Value::Integer(i));
        }
    }
    if v.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(v.extract()?));
    }
    if let Ok(s) = v.cast::<PyString>() {
        return Ok(toml::Value::String(s.extract()?));
    }
    if let Ok(d) = v.cast::<PyDict>() {
        return Ok(toml::Value::Table(to_table(d, at)?));
    }
    if v.is_instance_of::<PyList>() || v.is_instance_of::<PyTuple>() {
        let items = v.try_iter()?.enumerate().map(|(n, x)| to_value(&x?, &format!("{at}[{n}]")));
        return Ok(toml::Value::Array(items.collect::<PyResult<_>>()?));
    }
    // numpy scalars and other numbers
    if let Ok(f) = v.extract::<f64>() {
        return Ok(toml::Value::Float(f));
    }
    let repr = v.repr().map_or_else(|_| "?".into(), |r| r.to_string());
    Err(errors::input(InputError::new(at, repr, "a TOML value: bool, int, float, str, list, tuple or dict")))
}
