//! Error types and the exit-status contract (docs/scene-format.md): 2 for invalid input, 1 otherwise.
//! The foundation of the stack (README, "The code"): this module imports no stage above it, so a
//! stage's own failure (a model's, an external model's) reaches [`Error`] boxed as a
//! [`StageError`], its typed enum living with its owner.

use std::fmt;
use std::path::PathBuf;

/// Invalid user input: names the field, the value given and what is allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("`{field}` = {value}: allowed: {allowed}")]
pub struct InputError {
    /// Dotted path of the field, e.g. `contact.fn_n` (prefixed by the file where known).
    pub field: String,
    /// The value as given (or a description of it).
    pub value: String,
    /// What is allowed.
    pub allowed: String,
}

impl InputError {
    /// An input error; a number longer than [`PLAIN_DIGITS_MAX`] is shown as [`number`] shows it
    /// (with an exponent), and the value is cut to a short
    /// excerpt (a message never echoes a whole input).
    pub fn new(field: impl Into<String>, value: impl fmt::Display, allowed: impl Into<String>) -> Self {
        let text = value.to_string();
        let shown = match text.parse::<f64>() {
            // Only a number whose plain form a message would cut; any other value as given.
            Ok(v) if v.is_finite() && text.len() > PLAIN_DIGITS_MAX => number(v),
            _ => text,
        };
        Self { field: field.into(), value: excerpt(&shown), allowed: allowed.into() }
    }
}

/// A column name as given, only if it looks like one (letters, digits, `_`, up to 40
/// characters): a file that is no table (say /etc/passwd given as one) is never quoted.
pub fn name_excerpt(v: &str) -> String {
    let name_like = !v.is_empty() && v.len() <= 40 && v.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_');
    if name_like {
        format!("{v:?}")
    } else {
        format!("a field that is not a column name ({} bytes)", v.len())
    }
}

/// A short, single-line excerpt of a value for messages (never a whole file).
pub fn excerpt(v: &str) -> String {
    let one_line: String = v.chars().map(|c| if c.is_control() { '?' } else { c }).collect();
    if one_line.chars().count() <= 60 {
        one_line
    } else {
        format!("{}… ({} bytes)", one_line.chars().take(60).collect::<String>(), v.len())
    }
}

/// Longest plain decimal a message shows; a longer one (1e300 has 301 digits, which [`excerpt`]
/// would cut) is written with an exponent.
const PLAIN_DIGITS_MAX: usize = 24;

/// A number as a message shows it: plain (`0.25`, `inf`), or with an exponent where the plain form
/// is longer than [`PLAIN_DIGITS_MAX`] (`1e300`).
pub fn number(v: f64) -> String {
    let plain = format!("{v}");
    if plain.len() > PLAIN_DIGITS_MAX {
        format!("{v:e}")
    } else {
        plain
    }
}

/// A difference or a tolerance as every message shows it: four significant digits with an
/// exponent (`1.000e-3`), so |diff| and allowed read alike in the console, the summary, JUnit and
/// the drift lines.
pub fn deviation(v: f64) -> String {
    format!("{v:.3e}")
}

/// A data file that does not have the expected form (a history, metrics, a reference table).
#[derive(Debug, thiserror::Error)]
pub enum FormatError {
    #[error("header must start with {expected} (got {got})")]
    Header { expected: String, got: String },
    #[error("lacks column {column}")]
    MissingColumn { column: String },
    #[error("line {line}: {fields} fields, the header has {expected}")]
    FieldCount { line: usize, fields: usize, expected: usize },
    #[error("line {line} column {column}: {value:?} is not {what}")]
    Value { line: usize, column: String, value: String, what: &'static str },
    #[error("line {line}: {source}")]
    Csv { line: usize, source: csv::Error },
    #[error(transparent)]
    Json(#[from] serde_json::Error),
    /// scene.json's declared loading that does not sample (`loading`, edited or damaged).
    #[error("its loading does not sample: {0}")]
    Loading(#[source] InputError),
}

/// A failure typed by the stage above this module that owns it (`solvers::SolveError`,
/// `history::external::ExternalError`), boxed so that the foundation does not import the stages.
pub type StageError = Box<dyn std::error::Error + Send + Sync + 'static>;

/// Why `creepbench fit` failed.
#[derive(Debug, thiserror::Error)]
pub enum FitError {
    #[error("the optimiser failed: {0}")]
    Optimiser(argmin::core::Error),
    #[error("writing its record (JSON): {0}")]
    Record(#[from] serde_json::Error),
    #[error("writing its parameters (TOML): {0}")]
    Toml(#[from] toml::ser::Error),
}

/// Every failure of the tool.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// Bad input (exit status 2).
    #[error("invalid input: {0}")]
    Input(#[from] InputError),
    /// A built-in model could not produce a trustworthy result (exit status 1).
    #[error("solver `{solver}` failed on scene `{scene}`: {source}")]
    Solve { scene: String, solver: String, source: StageError },
    /// An external model failed or wrote unusable output (exit status 1).
    #[error("external model `{solver}` failed on scene `{scene}`: {source}")]
    External { scene: String, solver: String, source: StageError },
    /// Gated comparisons drifted (exit status 1).
    #[error("{count} gated comparison(s) drifted")]
    Drift { count: usize },
    /// A file could not be read or written.
    #[error("{}: {source}", path.display())]
    Io { path: PathBuf, source: std::io::Error },
    /// A data file has not the expected form.
    #[error("{}: {source}", path.display())]
    Format { path: PathBuf, source: FormatError },
    /// A file refused by the bounded reader (not a regular file, too large, not text).
    #[error(transparent)]
    Read(#[from] crate::safety::read::ReadError),
    /// A result folder that could not be written safely.
    #[error(transparent)]
    Folder(#[from] crate::safety::folder::FolderError),
    /// A write into a protected folder (golden/ outside `bless`): exit status 2.
    #[error(transparent)]
    Guard(#[from] crate::safety::guard::GuardError),
    /// A result folder in use by another run.
    #[error(transparent)]
    Lock(#[from] crate::safety::lock::LockError),
    /// Reference data that do not match their reviewed checksums.
    #[error("{}: {source} (a reviewed change of reference data updates the manifest: `creepbench manifest {}`)", dir.display(), dir.display())]
    Manifest { dir: PathBuf, source: crate::safety::manifest::ManifestError },
    /// Another program's file that its reader does not accept (`creepbench import`; exit status 2).
    #[error("{}: {source}", path.display())]
    Import { path: PathBuf, source: StageError },
    /// The optimiser of `creepbench fit` failed (exit status 1).
    #[error("fit `{fit}`: {source}")]
    Fit { fit: String, source: FitError },
}

impl Error {
    /// Process exit status for this error (docs/scene-format.md).
    pub fn exit_code(&self) -> i32 {
        match self {
            Error::Input(_) | Error::Guard(_) | Error::Import { .. } => 2,
            _ => 1,
        }
    }

    /// An I/O error on `path`.
    pub fn io(path: impl Into<PathBuf>) -> impl FnOnce(std::io::Error) -> Error {
        let path = path.into();
        move |source| Error::Io { path, source }
    }

    /// A format error in `path`.
    pub fn format(path: impl Into<PathBuf>) -> impl FnOnce(FormatError) -> Error {
        let path = path.into();
        move |source| Error::Format { path, source }
    }
}

pub type Result<T, E = Error> = std::result::Result<T, E>;
