//! `creepbench import contact FILE.inp` (issue 32): CONTACT's module-3 input → scenes of this
//! project, one per history, each remembering its deck and cases (`[origin]`); its module-1 input
//! (issue 44) → wheel–rail scenes, one per run of cases that share all but the wheelset's position
//! and velocity ([`scene::wheelrail`]). The deck is read whole ([`deck`]), every case is assessed
//! against the feature tables ([`features`], and for module 1 what the wheel–rail scene can say),
//! the cases are grouped and written as scenes ([`scene`]), and every scene is read back with the
//! project's own reader before anything is written.

pub mod deck;
pub mod features;
pub mod lexer;
pub mod scene;
pub mod wheelrail_deck;

use crate::error::InputError;
use std::path::Path;

/// Largest input file read (a deck of the test bank is ~30 kB; element-wise geometries more).
pub const DECK_LIMIT_BYTES: u64 = 64 << 20;

/// A deck that cannot be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DeckError {
    #[error("{file}:{line}:{column}: {what}: {value:?} is not allowed: {allowed}")]
    Value { file: String, line: usize, column: usize, what: String, value: String, allowed: String },
    #[error("{file}:{line}: the file ends where {what} is expected")]
    EndOfFile { file: String, line: usize, what: String },
    #[error("{file}, case {case}, control word {word}: {digit} = {value} is not allowed: {allowed}")]
    Digit { file: String, case: usize, word: String, digit: String, value: i64, allowed: String },
}

impl From<DeckError> for InputError {
    fn from(e: DeckError) -> InputError {
        match e {
            DeckError::Value { file, line, column, what, value, allowed } => {
                InputError::new(format!("{file}:{line}:{column} ({what})"), format!("{value:?}"), allowed)
            }
            DeckError::EndOfFile { file, line, what } => InputError::new(
                format!("{file}:{line}"),
                "the end of the file",
                format!("{what} (the deck is cut short)"),
            ),
            DeckError::Digit { file, case, word, digit, value, allowed } => {
                InputError::new(format!("{file}, case {case}, control word {word}, digit {digit}"), value, allowed)
            }
        }
    }
}

/// What became of one case of a deck.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseStatus {
    /// The case number, counted from 1 over the deck as CONTACT counts.
    pub case: usize,
    /// The line its control words (or its MODULE line) start at.
    pub line: usize,
    /// The module (1 or 3).
    pub module: u8,
    /// The scene the case became part of (`None`: refused).
    pub scene: Option<String>,
    /// Why the case is not imported (empty when it is).
    pub refused: Vec<String>,
    /// Accepted features the scene does not carry (S, G, T = 0, …).
    pub notes: Vec<String>,
}

impl CaseStatus {
    pub fn supported(&self) -> bool {
        self.refused.is_empty()
    }
}

/// Read a deck file's text and the name its scenes remember.
fn read(path: &Path) -> Result<(String, String), InputError> {
    let file = path.file_name().map(|n| n.to_string_lossy().to_string()).unwrap_or_else(|| path.display().to_string());
    let text = crate::safety::read::read_text(path, DECK_LIMIT_BYTES, "CONTACT input file").map_err(|e| {
        InputError::new(path.display().to_string(), "unreadable", format!("a readable CONTACT input file: {e}"))
    })?;
    Ok((file, text))
}

/// Every case of the deck at `path` with its status: the scene it becomes part of, or why not
/// (for the report's table of CONTACT's public examples).
pub fn survey(path: &Path) -> Result<Vec<CaseStatus>, InputError> {
    import(path).map(|i| i.statuses)
}

/// The scenes of the deck at `path` (built and read back with the project's reader in a
/// temporary folder; nothing is written) and the status of every case; wheel–rail scenes as
/// written beside the deck (their profile paths relative to the deck's folder).
pub fn import(path: &Path) -> Result<scene::Imported, InputError> {
    import_into(path, path.parent().unwrap_or(Path::new("")))
}

/// [`import`] for scenes to be written into the folder `out`: a wheel–rail scene's profile paths
/// lead from `out` to the files the deck names in its folder (which must exist).
pub fn import_into(path: &Path, out: &Path) -> Result<scene::Imported, InputError> {
    let (file, text) = read(path)?;
    let stem = path.file_stem().map(|s| s.to_string_lossy().to_string()).unwrap_or_default();
    let deck = path.parent().unwrap_or(Path::new("")).to_path_buf();
    let paths = scene::wheelrail::ProfilePaths::Relative { deck, out: out.to_path_buf() };
    scene::import_text_with(&file, &stem, &text, &paths)
}
