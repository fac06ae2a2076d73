//! The profiles' paths an imported wheel–rail scene writes: relative to the scene file's folder,
//! pointing at the files the deck names where they lie (docs/scene-format.md, "A wheel–rail
//! scene": a profile is a path relative to the scene). CONTACT reads a profile name relative to the
//! deck's folder (`m_varprof.f90`, `make_absolute_path`); the import copies no profile.

use crate::safety::relative::relative;
use std::path::PathBuf;

/// How the deck's profile names become the scene's paths.
#[derive(Debug, Clone, PartialEq)]
pub enum ProfilePaths {
    /// As the deck names them (for a scene written beside the deck, or a deck without a folder):
    /// `\` read as `/`, nothing checked.
    AsNamed,
    /// From the folder the scenes are written to (`out`, existing or not) to the file the deck
    /// names in its folder (`deck`), which must exist.
    Relative { deck: PathBuf, out: PathBuf },
}

impl ProfilePaths {
    /// The file the deck names `name`, where the deck's folder is known.
    pub fn deck_file(&self, name: &str) -> Option<PathBuf> {
        match self {
            ProfilePaths::AsNamed => None,
            ProfilePaths::Relative { deck, .. } => Some(deck.join(name.replace('\\', "/"))),
        }
    }

    /// The path the scene writes for the profile the deck names `name`, or why there is none.
    pub fn of(&self, name: &str) -> Result<String, String> {
        let named = name.replace('\\', "/");
        let ProfilePaths::Relative { deck, out } = self else {
            return Ok(named);
        };
        let file = deck.join(&named);
        if !file.is_file() {
            return Err(format!("the profile '{name}' is not a file beside the deck ({})", file.display()));
        }
        let rel = relative(out, &file).map_err(|e| e.to_string())?;
        rel.to_str().map(str::to_string).ok_or_else(|| format!("the profile path {} is not UTF-8", rel.display()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_profile_is_found_from_a_folder_not_yet_made() {
        let dir = tempfile::tempdir().unwrap();
        let deck = dir.path().join("deck");
        std::fs::create_dir_all(deck.join("profiles")).unwrap();
        std::fs::write(deck.join("profiles/r.prr"), "x").unwrap();
        let paths = ProfilePaths::Relative { deck: deck.clone(), out: dir.path().join("out/new") };
        assert_eq!(paths.of("profiles\\r.prr").unwrap(), "../../deck/profiles/r.prr");
        assert!(paths.of("profiles/none.prr").unwrap_err().contains("is not a file beside the deck"));
        assert_eq!(ProfilePaths::AsNamed.of("profiles\\r.prr").unwrap(), "profiles/r.prr");
    }
}
