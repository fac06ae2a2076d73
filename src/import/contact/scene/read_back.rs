//! Every scene is read back with the project's own scene reader in a temporary folder before
//! anything is written, and must give every case's creepages, load and friction bit for bit.

use super::table;
use crate::error::InputError;
use crate::problem::Problem;
use std::path::Path;
use toml::{Table, Value};

/// A temporary folder to read a scene back in.
pub(super) fn tempdir_for(place: &str) -> Result<tempfile::TempDir, InputError> {
    tempfile::tempdir()
        .map_err(|e| InputError::new(place, "a temporary folder", format!("a writable temporary folder: {e}")))
}

/// The scene with a one-step loading at zero creepage in place of its own (no `[init]`): read
/// back only for its grid.
pub(super) fn probe(doc: &Table) -> Table {
    let mut probe = doc.clone();
    probe.remove("init");
    probe.remove("normal");
    let step = vec![("kind", Value::String("step".into())), ("c", Value::Float(0.0)), ("steps", Value::Integer(1))];
    probe.insert("creepage".into(), table(step));
    probe
}

/// Write the scene and its files into `dir`, read the scene back with the project's reader and
/// resolve it.
pub(super) fn read_back(
    dir: &Path,
    scene_file: &str,
    doc: &Table,
    files: &[(String, String)],
) -> Result<Problem, InputError> {
    let io =
        |e: std::io::Error| InputError::new(dir.display().to_string(), "a temporary folder", format!("writable: {e}"));
    let text = toml::to_string(doc)
        .map_err(|e| InputError::new(scene_file, "a scene", format!("a scene TOML can hold: {e}")))?;
    std::fs::write(dir.join(scene_file), text).map_err(io)?;
    for (name, contents) in files {
        std::fs::write(dir.join(name), contents).map_err(io)?;
    }
    let scene = crate::scene::Scene::from_file(&dir.join(scene_file))?;
    crate::pipeline::resolve(&scene)
}

/// Every row of the resolved scene equals its case: cx, cy, cs, FN (or PEN) and μ bit for bit,
/// and B(1..6) where they change per case.
pub(super) fn check_rows(
    problem: &Problem,
    rows: &[[f64; 5]],
    quads: Option<&[[f64; 6]]>,
    numbers: &[usize],
) -> Result<(), InputError> {
    let got: Vec<[f64; 5]> = problem
        .loading
        .rows()
        .map(|s| [s.fx_target.unwrap_or(s.cx), s.fy_target.unwrap_or(s.cy), s.cs, s.pen_mm.unwrap_or(s.fn_n), s.mu])
        .collect();
    let got_quads: Vec<Option<[f64; 6]>> = problem.loading.rows().map(|s| s.h_coefficients).collect();
    for (n, (g, q)) in
        got_quads.iter().zip(quads.map(|q| q.iter().map(Some).collect::<Vec<_>>()).unwrap_or_default()).enumerate()
    {
        if g.map(|g| g.map(f64::to_bits)) != q.map(|q| q.map(f64::to_bits)) {
            return Err(InputError::new(
                format!("scene {}, case {}", problem.name, numbers[n]),
                format!("{g:?}"),
                format!("the case's B(1..6) = {q:?} exactly"),
            ));
        }
    }
    if got.len() != rows.len() {
        return Err(InputError::new(
            format!("scene {}", problem.name),
            format!("{} rows", got.len()),
            format!("one row per case ({} cases)", rows.len()),
        ));
    }
    for ((g, r), n) in got.iter().zip(rows).zip(numbers) {
        if g.iter().zip(r).any(|(a, b)| a.to_bits() != b.to_bits()) {
            return Err(InputError::new(
                format!("scene {}, case {n}", problem.name),
                format!("{g:?}"),
                format!("the case's [cx, cy, cs, FN, mu] = {r:?} exactly"),
            ));
        }
    }
    Ok(())
}
