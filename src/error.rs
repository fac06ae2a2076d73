//! Error types and the exit-status contract (interface.md): 2 for invalid input, 1 otherwise.

use std::fmt;

/// Invalid user input: names the field, the value given and what is allowed.
#[derive(Debug, Clone, PartialEq)]
pub struct InputError {
    /// Dotted path of the field, e.g. `contact.fn_n` (prefixed by the file where known).
    pub field: String,
    /// The value as given (or a description of it).
    pub value: String,
    /// What is allowed.
    pub allowed: String,
}

impl InputError {
    pub fn new(field: impl Into<String>, value: impl fmt::Display, allowed: impl Into<String>) -> Self {
        Self { field: field.into(), value: value.to_string(), allowed: allowed.into() }
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}` = {}: allowed: {}", self.field, self.value, self.allowed)
    }
}

impl std::error::Error for InputError {}

/// Every failure of the tool.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// Bad input (exit status 2).
    #[error("invalid input: {0}")]
    Input(#[from] InputError),
    /// A solver could not produce a trustworthy result (exit status 1).
    #[error("solver `{solver}` failed on scene `{scene}`: {message}")]
    Solve { scene: String, solver: String, message: String },
    /// A gated comparison drifted (exit status 1).
    #[error("{0}")]
    Drift(String),
    /// Anything else: I/O, formats (exit status 1).
    #[error("{0}")]
    Other(String),
}

impl Error {
    /// Process exit status for this error (interface.md).
    pub fn exit_code(&self) -> i32 {
        match self {
            Error::Input(_) => 2,
            _ => 1,
        }
    }

    pub fn other(msg: impl fmt::Display) -> Self {
        Error::Other(msg.to_string())
    }
}

impl From<std::io::Error> for Error {
    fn from(e: std::io::Error) -> Self {
        Error::Other(format!("I/O: {e}"))
    }
}

pub type Result<T, E = Error> = std::result::Result<T, E>;
