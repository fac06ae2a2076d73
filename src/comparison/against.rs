//! What a result is compared against: a baseline result set or a reference set.

/// What results are compared against.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Against {
    /// golden/: this project's blessed results.
    Golden,
    /// Another result set (`check --against DIR`): drift between two model versions.
    Previous,
    /// A reference set from outside the project, by its label (`references`).
    Reference(&'static str),
    /// The scene file a merged result was run from: what the result owes it (`owed`). No rule
    /// file names it, so its failures cannot be loosened.
    SceneFile,
}

impl Against {
    pub fn label(self) -> &'static str {
        match self {
            Against::Golden => "golden",
            Against::Previous => "previous",
            Against::Reference(label) => label,
            Against::SceneFile => "scene file",
        }
    }

    /// Whether this is a comparison with CONTACT (exact theory or its FASTSIM).
    pub fn is_contact(self) -> bool {
        matches!(self, Against::Reference(l) if l.starts_with("CONTACT"))
    }
}
