//! Reference data from outside the project (reference/README.md), read only. Each reference set
//! is one file implementing [`ReferenceSet`]: it loads its data and compares stored results with
//! it; [`References::sets`] is the registry the gate and the report iterate.

pub mod contact;
pub mod envelope;
pub mod table;
pub mod thesis;

use crate::comparison::finding::{Against, Finding};
use crate::comparison::rule::Rule;
use crate::error::{Error, InputError};
use crate::history::History;
use crate::suite::results::StoredScene;
use std::path::Path;

/// Default location of the reference data.
pub const DEFAULT_DIR: &str = "reference";

/// Every label the reference sets' findings carry (a set may use more than one: CONTACT's exact
/// theory and its FASTSIM): what a tolerance rule may name besides golden and previous.
pub const LABELS: [Against; 6] =
    [contact::EXACT, contact::FASTSIM, envelope::ENVELOPE, envelope::NONHERTZ, table::TABLE, thesis::AGAINST];

/// A set of reference results.
pub trait ReferenceSet: Send + Sync {
    /// Short label of the set (findings, the report).
    fn label(&self) -> &'static str;
    /// Every comparison of a stored scene with this set (none when it holds nothing for it),
    /// judged by `rules`.
    fn compare(&self, scene: &StoredScene, rules: &[Rule]) -> Vec<Finding>;
    /// The set's own history of a scene, if it has one (plots, error tables).
    fn history(&self, scene: &str) -> Option<&History>;
}

/// Every reference set the project holds.
#[derive(Debug, Clone, Default)]
pub struct References {
    pub contact: contact::ContactCases,
    pub envelope: envelope::EnvelopeCases,
    pub nonhertz: envelope::EnvelopeCases,
    /// CONTACT's own test table (3220 steady cases).
    pub table: envelope::EnvelopeCases,
    pub thesis: thesis::ThesisTables,
}

impl References {
    /// Load every set from `dir`.
    pub fn load(dir: &Path) -> Result<References, Error> {
        if !dir.is_dir() {
            let allowed = "a folder of reference data (CONTACT, thesis) with its MANIFEST.sha256";
            return Err(InputError::new("--reference", dir.display(), allowed).into());
        }
        // Every file against the reviewed checksums: a changed, missing or extra reference file
        // fails until its manifest is updated in a reviewed commit.
        crate::safety::manifest::verify(dir).map_err(|source| Error::Manifest { dir: dir.to_path_buf(), source })?;
        Ok(References {
            contact: contact::ContactCases::load(dir)?,
            envelope: envelope::EnvelopeCases::load(dir, "contact_envelope", envelope::ENVELOPE)?,
            nonhertz: envelope::EnvelopeCases::load(dir, "contact_nonhertz", envelope::NONHERTZ)?,
            table: table::load(dir)?,
            thesis: thesis::ThesisTables::load(dir)?,
        })
    }

    /// The registry: every set, in the order of the report. Adding a set: its file, a field and
    /// a line here.
    pub fn sets(&self) -> [&dyn ReferenceSet; 5] {
        [&self.contact, &self.envelope, &self.nonhertz, &self.table, &self.thesis]
    }

    /// The first history any set holds for a scene (drawn as markers in the plots).
    pub fn history(&self, scene: &str) -> Option<&History> {
        self.sets().into_iter().find_map(|s| s.history(scene))
    }
}

/// Read a reference file (bounded; typed error naming it).
fn read(path: &Path) -> Result<String, Error> {
    Ok(crate::safety::read::read_text(path, crate::safety::read::REFERENCE_LIMIT_BYTES, "reference file")?)
}
