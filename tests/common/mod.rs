//! Shared helpers of the integration tests.
#![allow(dead_code)]

use creepbench::history::History;
use creepbench::problem::Problem;
use creepbench::scene::Scene;
use creepbench::solvers;
use std::path::{Path, PathBuf};

/// Repository root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The thesis's default contact (ch. 4.1) as a scene, with `creepage` and `extra` TOML appended.
pub fn scene_text(name: &str, solvers: &str, mu: f64, grid: usize, creepage: &str, extra: &str) -> String {
    format!(
        r#"name = "{name}"
solvers = {solvers}
[contact]
a_mm = 8.56
b_mm = 4.08
fn_n = 100000.0
mu = {mu}
[material]
g_mpa = 82000.0
poisson = 0.28
[grid]
mx = {grid}
my = {grid}
[creepage]
{creepage}
{extra}
"#
    )
}

pub fn problem(text: &str) -> Problem {
    let scene = Scene::from_toml(text, Path::new(".")).expect("valid scene");
    Problem::resolve(&scene).expect("resolvable scene")
}

pub fn run(problem: &Problem, solver: &str) -> History {
    let model = solvers::builtin(solver).expect("a built-in model");
    solvers::sample_loop::run(problem, model, &[], None).expect("solver run").history
}

pub fn f(h: &History) -> Vec<f64> {
    h.column("fx_over_fn").unwrap()
}

/// A CONTACT reference history column by name.
pub fn reference(case: &str, column: &str) -> Vec<f64> {
    let path = root().join("reference/contact").join(format!("{case}.csv"));
    let mut rdr = csv::Reader::from_path(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let idx = rdr.headers().unwrap().iter().position(|h| h == column).expect("column");
    rdr.records().map(|r| r.unwrap()[idx].parse::<f64>().unwrap()).collect()
}

pub fn max_abs_diff(a: &[f64], b: &[f64]) -> (f64, usize) {
    assert_eq!(a.len(), b.len(), "lengths differ");
    a.iter()
        .zip(b)
        .enumerate()
        .map(|(k, (x, y))| ((x - y).abs(), k))
        .fold((0.0, 0), |m, v| if v.0 > m.0 { v } else { m })
}
