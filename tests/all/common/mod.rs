//! Shared helpers of the integration tests.
#![allow(dead_code)]

use creepbench::history::History;
use creepbench::problem::Problem;
use creepbench::scene::Scene;
use creepbench::solvers;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

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
    creepbench::pipeline::resolve(&scene).expect("resolvable scene")
}

pub fn run(problem: &Problem, solver: &str) -> History {
    let model = solvers::builtin(solver).expect("a built-in model");
    creepbench::history::sample_loop::run(problem, model, &[], None).expect("solver run").history
}

pub fn f(h: &History) -> Vec<f64> {
    h.column("fx_over_fn").unwrap()
}

/// A CONTACT reference history column by name (`reference/contact`).
pub fn reference(case: &str, column: &str) -> Vec<f64> {
    reference_in("contact", case, column)
}

/// A reference history column by name from `reference/<folder>/<case>.csv`.
pub fn reference_in(folder: &str, case: &str, column: &str) -> Vec<f64> {
    let path = root().join("reference").join(folder).join(format!("{case}.csv"));
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

/// The exact solver's fields of the scene file `scene` (relative to the root) against CONTACT's
/// field file `field_csv`, element by element in the mirrored frame (element i ↔ CONTACT's
/// ix = mx − i): pressure and both traction components within `tol` of μ p_max, and the same
/// adhesion/slip division. Returns (elements compared, largest difference over μ p_max).
#[allow(dead_code)]
pub fn compare_fields_with_contact(scene: &str, field_csv: &str, tol: f64) -> (usize, f64) {
    use creepbench::solvers::contact::tangential::ElementState;
    let path = root().join(scene);
    let sc = creepbench::scene::Scene::from_file(&path).unwrap();
    let p = creepbench::pipeline::resolve(&sc).unwrap();
    let mut rdr = csv::Reader::from_path(root().join(field_csv)).unwrap();
    let rows: Vec<csv::StringRecord> = rdr.records().map(Result::unwrap).collect();
    let steps: Vec<usize> = rows.iter().map(|r| r[0].parse().unwrap()).collect();
    let (_, fields) =
        creepbench::history::sample_loop::run_with_fields(&p, &creepbench::solvers::contact::MODEL, &|s| {
            steps.contains(&s)
        })
        .unwrap();
    let g = &p.grid;
    let (mut n, mut worst) = (0, 0.0f64);
    for (r, step) in rows.iter().zip(&steps) {
        let num = |i: usize| r[i].parse::<f64>().unwrap();
        let (ix, iy) = (num(1) as usize, num(2) as usize);
        let fld = fields.iter().find(|f| f.step == *step).expect("the step was kept");
        let mu = p.loading.rows().find(|s| s.step == *step).unwrap().mu;
        let scale = mu * fld.pn_mpa.iter().fold(0.0f64, |m, &v| m.max(v));
        let k = g.index(g.mx - ix, iy - 1);
        for (ours, theirs, what) in
            [(fld.pn_mpa[k], num(5), "pn"), (fld.px_mpa[k], num(6), "px"), (fld.py_mpa[k], num(7), "py")]
        {
            let d = (ours - theirs).abs() / scale;
            assert!(d < tol, "{scene} step {step} ({ix}, {iy}) {what}: {ours} vs {theirs}");
            worst = worst.max(d);
        }
        let ours = match fld.state[k] {
            ElementState::Exterior => "E",
            ElementState::Adhesion => "A",
            ElementState::Slip => "S",
        };
        assert_eq!(ours, &r[8], "{scene} step {step} ({ix}, {iy}) state");
        n += 1;
    }
    (n, worst)
}

/// A fresh empty folder under the target's temporary directory (removed first if it exists).
#[allow(dead_code)]
pub fn tempdir(name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A scene of a shipped suite (`scenes/<suite>`) by name: a scene file or a study's point.
pub fn suite_scene(suite: &str, name: &str) -> creepbench::suite::SceneSource {
    creepbench::suite::find(&[root().join("scenes").join(suite)], name).unwrap()
}

/// That scene's TOML text.
pub fn suite_scene_text(suite: &str, name: &str) -> String {
    suite_scene(suite, name).text().unwrap()
}

/// That scene resolved.
pub fn suite_problem(suite: &str, name: &str, only: &[String]) -> Problem {
    creepbench::pipeline::load_source(&suite_scene(suite, name), only).unwrap()
}

/// That scene written as `dir/<name>.toml` (for the command-line tests).
pub fn suite_scene_file(suite: &str, name: &str, dir: &Path) -> PathBuf {
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, suite_scene_text(suite, name)).unwrap();
    path
}

/// The folder a failed external model's error message says is kept: it exists and holds the
/// model's stdout.txt and stderr.txt; returned: the folder, its file names (sorted), the two
/// texts. The folder is removed here.
pub fn take_kept_folder(message: &str) -> (PathBuf, Vec<String>, String, String) {
    let after = message.split("the model's folder is kept: ").nth(1).unwrap_or_else(|| panic!("no folder: {message}"));
    let folder = PathBuf::from(after.split(", with its stdout.txt").next().unwrap());
    let read = |f: &str| std::fs::read_to_string(folder.join(f)).unwrap_or_else(|e| panic!("{f} in {folder:?}: {e}"));
    let (stdout, stderr) = (read("stdout.txt"), read("stderr.txt"));
    let mut files: Vec<String> =
        std::fs::read_dir(&folder).unwrap().flatten().map(|e| e.file_name().to_string_lossy().into()).collect();
    files.sort();
    std::fs::remove_dir_all(&folder).unwrap();
    (folder, files, stdout, stderr)
}

/// `creepbench args` run in `dir` (writing to `dir/out`): its exit code and error output; where
/// it fails, nothing may have been written to `dir/out` (`what` names the case in that message).
pub fn run_in(dir: &Path, args: &[&str], what: &str) -> (Option<i32>, String) {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_creepbench")).current_dir(dir).args(args).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success() || !dir.join("out").exists(), "{what}: written after an error: {err}");
    (o.status.code(), err)
}

/// `creepbench ARGS` in a new folder `name` holding `s.toml` = `scene`: (exit code, stderr, folder).
pub fn run_scene(name: &str, scene: &str, args: &[&str]) -> (Option<i32>, String, PathBuf) {
    let dir = tempdir(name);
    std::fs::write(dir.join("s.toml"), scene).unwrap();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_creepbench")).current_dir(&dir).args(args).output().unwrap();
    (o.status.code(), String::from_utf8_lossy(&o.stderr).to_string(), dir)
}

/// Add `by` to the value at `line` (0 = the header) and `column` of a CSV file (a drift made by
/// hand for the gate's tests).
#[allow(dead_code)]
pub fn nudge_csv(csv: &Path, line: usize, column: usize, by: f64) {
    let text = std::fs::read_to_string(csv).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let mut cells: Vec<String> = lines[line].split(',').map(String::from).collect();
    cells[column] = format!("{}", cells[column].parse::<f64>().unwrap() + by);
    lines[line] = cells.join(",");
    std::fs::write(csv, lines.join("\n") + "\n").unwrap();
}

/// One run of the shipped wheel–rail suite, as `creepbench run --suite scenes/wheelrail` makes it
/// (results and report in `dir`), shared by the tests that gate it and that read its report: it
/// is the suite the tests would otherwise run twice.
pub struct WheelRailRun {
    pub dir: tempfile::TempDir,
    pub outcome: creepbench::commands::RunOutcome,
}

impl WheelRailRun {
    pub fn report_dir(&self) -> PathBuf {
        self.dir.path().join("rep")
    }
}

/// The shipped wheel–rail suite's run, made by the first test that asks for it.
pub fn wheelrail_suite_run() -> &'static WheelRailRun {
    static RUN: OnceLock<WheelRailRun> = OnceLock::new();
    RUN.get_or_init(|| {
        let dir = tempfile::tempdir().unwrap();
        let (results_dir, report_dir) = (dir.path().join("res"), dir.path().join("rep"));
        let outputs =
            creepbench::commands::RunOutputs { results_dir: &results_dir, report_dir: &report_dir, fits: None };
        let outcome = creepbench::commands::run_with(
            &[root().join("scenes/wheelrail")],
            &root().join("reference"),
            outputs,
            creepbench::commands::Runner::cli(None, false),
            &root().join("golden"),
        )
        .unwrap();
        WheelRailRun { dir, outcome }
    })
}

/// |ours − theirs| in half-units of CONTACT's last printed digit.
pub fn half_units(ours: f64, theirs: creepbench::comparison::references::contact_output::printed::Printed) -> f64 {
    (ours - theirs.value).abs() / theirs.half_unit
}
