//! External models: any executable that reads the resolved scene (scene.json) and its loading
//! per row (`loading.csv` beside it) and writes a history CSV in the `simulate` format. Protocol
//! (docs/models.md, "Bring your own model"):
//! the command is run in the scene's folder as `COMMAND... SCENE_JSON OUT_CSV`; it must exit 0
//! and leave OUT_CSV with the header `step,t_s,cx,cy,cs,fn_n,fx_over_fn,fy_over_fn[,...]` and
//! one row per step of the scene (the step column must match the scene's steps; a row for
//! step 0, the initial state, is dropped unless the scene starts from a steady state).
//! The model runs with stdin closed, a timeout and its process group killed when it ends; its
//! output is read with a size limit and must be finite, with the scene's loading columns.
//! When it fails, its folder is kept with its printed output (`stdout.txt`, `stderr.txt`) and
//! named in the error; when it succeeds, the folder is removed and what it printed goes to the
//! scene's result folder as `<model>.stdout.txt` / `<model>.stderr.txt`.

use super::{History, COLUMNS};
use crate::error::{Error, FormatError};
use crate::problem::loading::write_loading_csv;
use crate::problem::{Problem, ResolvedScene, Sample};
use crate::safety::excerpt::{excerpt, one_line};
use crate::safety::interrupt;
use crate::safety::process::{self, Output, ProcessError};
use crate::safety::read::{read_text, ReadError, MODEL_OUTPUT_LIMIT_BYTES};
use crate::scene::ExternalSolver;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

/// Why an external model gave no usable history (the messages name the output file).
#[derive(Debug, thiserror::Error)]
pub enum ExternalError {
    #[error("temp dir: {0}")]
    TempDir(#[source] std::io::Error),
    #[error("{source} (the model's folder is kept: {}, with its stdout.txt and stderr.txt)", .folder.display())]
    Kept { folder: PathBuf, source: Box<ExternalError> },
    #[error("{source} (keeping the model's folder {} failed: {io})", .folder.display())]
    NotKept { folder: PathBuf, source: Box<ExternalError>, io: std::io::Error },
    #[error("writing scene.json: {0}")]
    SceneJson(#[source] std::io::Error),
    #[error("writing {LOADING_CSV}: {0}")]
    LoadingCsv(#[source] std::io::Error),
    #[error(transparent)]
    Process(#[from] ProcessError),
    #[error("the model wrote no output file {}", .0.display())]
    NoOutput(PathBuf),
    #[error("output {} is a symbolic link, not a regular file", .0.display())]
    SymbolicLink(PathBuf),
    #[error(transparent)]
    Read(#[from] ReadError),
    #[error("output {}: {}", .out.display(), one_line(&.format.to_string(), PARSE_MESSAGE_CHARS))]
    Unparsable { out: PathBuf, format: FormatError },
    #[error("output {}: extra column {} repeats a leading column", .out.display(), excerpt(.column))]
    RepeatsLeading { out: PathBuf, column: String },
    #[error("output {}: column {} appears twice", .out.display(), excerpt(.column))]
    Twice { out: PathBuf, column: String },
    #[error("output {} has {got} rows ({}); the scene has {expected} steps ({})", .out.display(), steps(*.got_steps), steps(*.expected_steps))]
    Rows { out: PathBuf, got: usize, got_steps: StepRange, expected: usize, expected_steps: StepRange },
    #[error("output {} step {step} column {}: {} is not a finite number", .out.display(), excerpt(.column), excerpt(&.value.to_string()))]
    NotFinite { out: PathBuf, step: usize, column: String, value: f64 },
    #[error("output {} step {step} column {}: {} differs from the scene's {want} (the loading columns must be copied from {LOADING_CSV})", .out.display(), excerpt(.column), excerpt(&.value.to_string()))]
    Loading { out: PathBuf, step: usize, column: &'static str, value: f64, want: f64 },
}

/// The first and last step of some rows (none when there are no rows).
pub type StepRange = Option<(usize, usize)>;

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

    /// Run the model over the whole scene and read its validated history back, with what it
    /// printed; on failure its folder is kept (see the module's documentation).
    pub fn run(&self, problem: &Problem) -> Result<Ran, Error> {
        let fail = |e: ExternalError| Error::External {
            scene: problem.name.clone(),
            solver: self.spec.name.clone(),
            source: Box::new(e),
        };
        let dir =
            tempfile::Builder::new().prefix("creepbench-ext").tempdir().map_err(|e| fail(ExternalError::TempDir(e)))?;
        // Removed by the interrupt handler if creepbench is stopped meanwhile, else just below
        // (on success) or kept (on failure).
        let cleanup = interrupt::register_folder(dir.path().to_path_buf());
        let mut output = Output::default();
        let result = run_in(&self.spec, problem, dir.path(), &mut output);
        let result = match result {
            Ok(history) => {
                drop(dir);
                Ok(Ran { logs: logs(&self.spec.name, &output), history })
            }
            Err(e) => Err(keep(dir.keep(), e, &output)),
        };
        drop(cleanup);
        result.map_err(fail)
    }
}

/// A successful run: the history and the files of what the model printed.
#[derive(Debug)]
pub struct Ran {
    pub history: History,
    /// `(file name, text)`: `<model>.stdout.txt` and `<model>.stderr.txt`, those not empty.
    pub logs: Vec<(String, String)>,
}

/// The log files of a successful run of `model`: each stream that printed something.
fn logs(model: &str, output: &Output) -> Vec<(String, String)> {
    [("stdout", &output.stdout), ("stderr", &output.stderr)]
        .into_iter()
        .map(|(stream, captured)| (format!("{model}.{stream}.txt"), captured.log_text()))
        .filter(|(_, text)| !text.is_empty())
        .collect()
}

/// The error of a failed run, after writing what the model printed (the tail kept by the
/// process runner, or the output carried by the error) into its folder, which is kept.
fn keep(folder: PathBuf, e: ExternalError, output: &Output) -> ExternalError {
    let printed = match &e {
        ExternalError::Process(p) => p.output().unwrap_or(output),
        _ => output,
    };
    let written = [("stdout.txt", &printed.stdout), ("stderr.txt", &printed.stderr)]
        .into_iter()
        .try_for_each(|(file, captured)| std::fs::write(folder.join(file), captured.log_text()));
    match written {
        Ok(()) => ExternalError::Kept { folder, source: Box::new(e) },
        Err(io) => ExternalError::NotKept { folder, source: Box::new(e), io },
    }
}

/// The file beside the model's scene.json that holds the loading of every row (the initial
/// state at step 0 first, when the scene has one), as [`write_loading_csv`] writes it.
pub const LOADING_CSV: &str = "loading.csv";

/// The model's scene.json, written into its (buffered) file as it is produced.
fn write_scene_json(scene: &ResolvedScene, path: &Path) -> std::io::Result<()> {
    write_buffered(path, &|out| scene.write_json(out))
}

/// `write` into the new file `path`, buffered.
fn write_buffered(path: &Path, write: &dyn Fn(&mut dyn Write) -> std::io::Result<()>) -> std::io::Result<()> {
    let mut out = std::io::BufWriter::new(std::fs::File::create(path)?);
    write(&mut out)?;
    out.flush()
}

/// The model's loading.csv: the problem's loading, every row it sampled.
fn write_loading(problem: &Problem, path: &Path) -> std::io::Result<()> {
    let rows: Vec<Sample> = problem.loading.initial.iter().chain(&problem.loading.samples).copied().collect();
    write_buffered(path, &|out| write_loading_csv(&rows, out))
}

/// Run the model in the temporary folder `dir` and read its validated output; what it printed
/// is left in `output`.
fn run_in(spec: &ExternalSolver, problem: &Problem, dir: &Path, output: &mut Output) -> Result<History, ExternalError> {
    let scene_json = dir.join("scene.json");
    let out_csv = dir.join(format!("{}.csv", spec.name));
    write_scene_json(&ResolvedScene::of(problem, &problem.solvers), &scene_json).map_err(ExternalError::SceneJson)?;
    write_loading(problem, &dir.join(LOADING_CSV)).map_err(ExternalError::LoadingCsv)?;
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
    *output = process::run(command, Duration::from_secs_f64(spec.timeout_s), MODEL_OUTPUT_LIMIT_BYTES)?;
    validate(read_output(&spec.name, &out_csv)?, problem, &out_csv)
}

/// The history of a model run in this process (a Python callable), validated as an external
/// model's output; errors name the model as `<in-process NAME>` in place of its output file.
pub fn validate_in_process(h: History, problem: &Problem) -> Result<History, Error> {
    let out = PathBuf::from(format!("<in-process {}>", h.solver));
    let solver = h.solver.clone();
    validate(h, problem, &out).map_err(|e| Error::External { scene: problem.name.clone(), solver, source: Box::new(e) })
}

/// Models copy the loading from loading.csv: it must come back equal to this relative tolerance.
const LOADING_RTOL: f64 = 1e-9;
/// Longest message of the CSV parser quoted in an error.
const PARSE_MESSAGE_CHARS: usize = 300;

/// The model's output file: a regular file (not a link, FIFO or device), of bounded size, parsed.
fn read_output(model: &str, out_csv: &Path) -> Result<History, ExternalError> {
    match std::fs::symlink_metadata(out_csv) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Err(ExternalError::NoOutput(out_csv.into())),
        Ok(m) if m.file_type().is_symlink() => return Err(ExternalError::SymbolicLink(out_csv.into())),
        _ => {}
    }
    let text = read_text(out_csv, MODEL_OUTPUT_LIMIT_BYTES, "model output")?;
    History::from_csv(model, &text).map_err(|format| ExternalError::Unparsable { out: out_csv.into(), format })
}

/// The history as the scene expects it: no duplicate or shadowing column, one row per step of
/// the scene, every value finite, and the loading columns equal to the scene's.
fn validate(mut h: History, problem: &Problem, out_csv: &Path) -> Result<History, ExternalError> {
    let out = || out_csv.to_path_buf();
    for (k, c) in h.extra_columns.iter().enumerate() {
        if COLUMNS.contains(&c.as_str()) {
            return Err(ExternalError::RepeatsLeading { out: out(), column: c.clone() });
        }
        if h.extra_columns[..k].contains(c) {
            return Err(ExternalError::Twice { out: out(), column: c.clone() });
        }
    }
    // Step 0 (the initial state) is part of the output only when the scene starts steady or from a shift.
    if problem.loading.start().is_none() {
        h.rows.retain(|r| r.sample.step != 0);
    }
    let expected: Vec<&Sample> = problem.loading.rows().collect();
    let got: Vec<usize> = h.rows.iter().map(|r| r.sample.step).collect();
    if !got.iter().copied().eq(expected.iter().map(|s| s.step)) {
        return Err(ExternalError::Rows {
            out: out(),
            got: got.len(),
            got_steps: got.first().copied().zip(got.last().copied()),
            expected: expected.len(),
            expected_steps: expected.first().map(|s| s.step).zip(expected.last().map(|s| s.step)),
        });
    }
    for (r, s) in h.rows.iter_mut().zip(&expected) {
        // μ is the scene's: a model may leave the column out, or must copy it.
        let mu_given = if r.sample.mu.is_nan() { s.mu } else { r.sample.mu };
        r.sample.mu = s.mu;
        let leading = [
            ("t_s", r.sample.t_s),
            ("cx", r.sample.cx),
            ("cy", r.sample.cy),
            ("cs", r.sample.cs),
            ("fn_n", r.sample.fn_n),
            ("fx_over_fn", r.fx_over_fn),
            ("fy_over_fn", r.fy_over_fn),
        ];
        let extra = h.extra_columns.iter().map(String::as_str).zip(r.extra.iter().copied());
        if let Some((column, v)) = leading.into_iter().chain(extra).find(|(_, v)| !v.is_finite()) {
            return Err(ExternalError::NotFinite {
                out: out(),
                step: r.sample.step,
                column: column.to_string(),
                value: v,
            });
        }
        let loading = [
            ("t_s", r.sample.t_s, s.t_s),
            ("cx", r.sample.cx, s.cx),
            ("cy", r.sample.cy, s.cy),
            ("cs", r.sample.cs, s.cs),
            ("fn_n", r.sample.fn_n, s.fn_n),
            ("mu", mu_given, s.mu),
        ];
        if let Some((column, v, want)) =
            loading.into_iter().find(|&(_, v, want)| (v - want).abs() > LOADING_RTOL * v.abs().max(want.abs()))
        {
            return Err(ExternalError::Loading { out: out(), step: r.sample.step, column, value: v, want });
        }
    }
    Ok(h)
}

/// A range of step numbers for a message: `steps 1..6`, `no steps`.
fn steps(range: StepRange) -> String {
    match range {
        Some((a, b)) => format!("steps {a}..{b}"),
        None => "no steps".into(),
    }
}
