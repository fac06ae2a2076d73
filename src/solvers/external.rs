//! External models: any executable that reads the resolved scene (scene.json) and writes a
//! history CSV in the `simulate` format. Protocol (README, "Bring your own model"):
//! the command is run in the scene's folder as `COMMAND... SCENE_JSON OUT_CSV`; it must exit 0
//! and leave OUT_CSV with the header `step,t_s,cx,cy,cs,fn_n,fx_over_fn,fy_over_fn[,...]` and
//! one row per step of the scene (the step column must match the scene's steps; a row for
//! step 0, the initial state, is dropped unless the scene starts from a steady state).
//! The model runs with stdin closed, a timeout and its process group killed when it ends; its
//! output is read with a size limit and must be finite, with the scene's loading columns.

use crate::error::Error;
use crate::history::{History, COLUMNS};
use crate::problem::{Problem, ResolvedScene, Sample};
use crate::safety::excerpt::{excerpt, one_line};
use crate::safety::read::{read_text, MODEL_OUTPUT_LIMIT_BYTES};
use crate::safety::{interrupt, process};
use crate::scene::ExternalSolver;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

/// A user-supplied model run as a child process.
pub struct External {
    spec: ExternalSolver,
}

impl External {
    pub fn new(spec: ExternalSolver) -> Self {
        External { spec }
    }

    /// The model's name in the scene.
    pub fn name(&self) -> &str {
        &self.spec.name
    }

    /// Run the model over the whole scene and read its validated history back.
    pub fn run(&self, problem: &Problem) -> Result<History, Error> {
        let fail =
            |m: String| Error::External { scene: problem.name.clone(), solver: self.spec.name.clone(), message: m };
        let dir =
            tempfile::Builder::new().prefix("creepbench-ext").tempdir().map_err(|e| fail(format!("temp dir: {e}")))?;
        // Removed by the interrupt handler if creepbench is stopped meanwhile, else just below.
        let cleanup = interrupt::register_folder(dir.path().to_path_buf());
        let result = run_in(&self.spec, problem, dir.path()).map_err(fail);
        drop(dir);
        drop(cleanup);
        result
    }
}

/// Run the model in the temporary folder `dir` and read its validated output.
fn run_in(spec: &ExternalSolver, problem: &Problem, dir: &Path) -> Result<History, String> {
    let scene_json = dir.join("scene.json");
    let out_csv = dir.join(format!("{}.csv", spec.name));
    let json = ResolvedScene::of(problem, &problem.solvers).to_json();
    std::fs::write(&scene_json, json).map_err(|e| format!("writing scene.json: {e}"))?;
    let mut program = std::path::PathBuf::from(&spec.command[0]);
    if program.components().count() > 1 && program.is_relative() {
        program = problem.scene_dir.join(program);
    }
    let mut command = Command::new(&program);
    command
        .args(&spec.command[1..])
        .arg(&scene_json)
        .arg(&out_csv)
        .current_dir(if problem.scene_dir.as_os_str().is_empty() { Path::new(".") } else { &problem.scene_dir });
    process::run(command, Duration::from_secs_f64(spec.timeout_s), MODEL_OUTPUT_LIMIT_BYTES)
        .map_err(|e| e.to_string())?;
    validate(read_output(&spec.name, &out_csv)?, problem, &out_csv)
}

/// Models copy the loading from scene.json: it must come back equal to this relative tolerance.
const LOADING_RTOL: f64 = 1e-9;
/// Longest message of the CSV parser quoted in an error.
const PARSE_MESSAGE_CHARS: usize = 300;

/// The model's output file: a regular file (not a link, FIFO or device), of bounded size, parsed.
fn read_output(model: &str, out_csv: &Path) -> Result<History, String> {
    match std::fs::symlink_metadata(out_csv) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            return Err(format!("the model wrote no output file {}", out_csv.display()));
        }
        Ok(m) if m.file_type().is_symlink() => {
            return Err(format!("output {} is a symbolic link, not a regular file", out_csv.display()));
        }
        _ => {}
    }
    let text = read_text(out_csv, MODEL_OUTPUT_LIMIT_BYTES, "model output").map_err(|e| e.to_string())?;
    History::from_csv(model, &text)
        .map_err(|e| format!("output {}: {}", out_csv.display(), one_line(&e.to_string(), PARSE_MESSAGE_CHARS)))
}

/// The history as the scene expects it: no duplicate or shadowing column, one row per step of
/// the scene, every value finite, and the loading columns equal to the scene's.
fn validate(mut h: History, problem: &Problem, out_csv: &Path) -> Result<History, String> {
    let file = out_csv.display();
    for (k, c) in h.extra_columns.iter().enumerate() {
        if COLUMNS.contains(&c.as_str()) {
            return Err(format!("output {file}: extra column {} repeats a leading column", excerpt(c)));
        }
        if h.extra_columns[..k].contains(c) {
            return Err(format!("output {file}: column {} appears twice", excerpt(c)));
        }
    }
    // Step 0 (the initial state) is part of the output only when the scene starts steady.
    if problem.loading.steady_start().is_none() {
        h.rows.retain(|r| r.step != 0);
    }
    let expected: Vec<&Sample> = problem.loading.rows().collect();
    let got: Vec<usize> = h.rows.iter().map(|r| r.step).collect();
    if !got.iter().copied().eq(expected.iter().map(|s| s.step)) {
        return Err(format!(
            "output {file} has {} rows ({}); the scene has {} steps ({})",
            got.len(),
            steps(got.first().copied(), got.last().copied()),
            expected.len(),
            steps(expected.first().map(|s| s.step), expected.last().map(|s| s.step))
        ));
    }
    for (r, s) in h.rows.iter_mut().zip(&expected) {
        // μ is the scene's: a model may leave the column out, or must copy it.
        let mu_given = if r.mu.is_nan() { s.mu } else { r.mu };
        r.mu = s.mu;
        let leading = [
            ("t_s", r.t_s),
            ("cx", r.cx),
            ("cy", r.cy),
            ("cs", r.cs),
            ("fn_n", r.fn_n),
            ("fx_over_fn", r.fx_over_fn),
            ("fy_over_fn", r.fy_over_fn),
        ];
        let extra = h.extra_columns.iter().map(String::as_str).zip(r.extra.iter().copied());
        if let Some((column, v)) = leading.into_iter().chain(extra).find(|(_, v)| !v.is_finite()) {
            return Err(format!(
                "output {file} step {} column {}: {} is not a finite number",
                r.step,
                excerpt(column),
                excerpt(&v.to_string())
            ));
        }
        let loading = [
            ("t_s", r.t_s, s.t_s),
            ("cx", r.cx, s.cx),
            ("cy", r.cy, s.cy),
            ("cs", r.cs, s.cs),
            ("fn_n", r.fn_n, s.fn_n),
            ("mu", mu_given, s.mu),
        ];
        if let Some((column, v, want)) =
            loading.into_iter().find(|&(_, v, want)| (v - want).abs() > LOADING_RTOL * v.abs().max(want.abs()))
        {
            return Err(format!(
                "output {file} step {} column {}: {} differs from the scene's {want} (the loading columns must be copied from scene.json)",
                r.step,
                excerpt(column),
                excerpt(&v.to_string())
            ));
        }
    }
    Ok(h)
}

/// A range of step numbers for a message: `steps 1..6`, `no steps`.
fn steps(first: Option<usize>, last: Option<usize>) -> String {
    match (first, last) {
        (Some(a), Some(b)) => format!("steps {a}..{b}"),
        _ => "no steps".into(),
    }
}
