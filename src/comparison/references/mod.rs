//! Reference data from outside the project (reference/README.md), read only. Each reference set
//! is one file implementing [`ReferenceSet`] (it loads its data and compares stored results with
//! it) and one entry of [`SETS`], the registry the gate, the tolerances and the report ask: its
//! labels with their catch-all rules, its loader and the report section that draws its cases.

pub mod contact;
pub mod contact_output;
pub mod contact_public;
pub mod contact_wheelrail;
pub mod envelope;
pub mod friction;
pub mod table;
pub mod thesis;
pub mod wheelrail_cases;

use crate::comparison::finding::{Against, Finding};
use crate::comparison::rule::{self, Rule};
use crate::error::{Error, InputError};
use crate::history::History;
use crate::suite::results::StoredScene;
use std::any::Any;
use std::path::Path;

/// Default location of the reference data.
pub const DEFAULT_DIR: &str = "reference";

/// A set of reference results.
pub trait ReferenceSet: Any + Send + Sync {
    /// Short label of the set (findings, the report).
    fn label(&self) -> &'static str;
    /// Every comparison of a stored scene with this set (none when it holds nothing for it),
    /// judged by `rules`.
    fn compare(&self, scene: &StoredScene, rules: &[Rule]) -> Vec<Finding>;
    /// The set's own history of a scene, if it has one (plots, error tables).
    fn history(&self, scene: &str) -> Option<&History>;
}

/// One entry of the registry: a reference set.
pub struct SetDef {
    /// The labels its findings carry (CONTACT's cases use two: the exact theory and its
    /// FASTSIM), each with the reason of its catch-all rule: what no rule of `tolerances.toml`
    /// covers is reported, with no tolerance ([`rule::catch_all`]).
    pub labels: &'static [(Against, &'static str)],
    /// The folder (or file) of the reference tree the set reads: a tree without it holds none of
    /// the set's data (a tree of one's own references, `--reference`, holds only what it has; the
    /// project's `reference/` lists every file in its manifest, so a removed one fails there).
    pub folder: &'static str,
    /// Read the set from the reference folder.
    pub load: fn(&Path) -> Result<Box<dyn ReferenceSet>, Error>,
    /// The id of the report section that draws its cases (`None`: the report's scene groups
    /// draw them, with the set's history as markers).
    pub section: Option<&'static str>,
}

/// The registry: every reference set, in the order of the gate and the report. Adding a set:
/// its file and a line here (and its gated rules in `tolerances.toml`, if it has any).
pub const SETS: [SetDef; 9] = [
    SetDef {
        labels: &[
            (contact::EXACT, "simplified models differ from the exact theory by design; the report shows by how much"),
            (contact::FASTSIM, "reported"),
        ],
        folder: "contact",
        load: |dir| Ok(Box::new(contact::ContactCases::load(dir)?)),
        section: None,
    },
    SetDef {
        labels: &[(
            envelope::ENVELOPE,
            "the fast models against the exact theory on the envelope: reported per case, not gated (issue 12)",
        )],
        folder: "contact_envelope",
        load: |dir| Ok(Box::new(envelope::EnvelopeCases::load(dir, "contact_envelope", envelope::ENVELOPE)?)),
        section: Some(ENVELOPE_SECTION),
    },
    SetDef {
        labels: &[(
            envelope::NONHERTZ,
            "the fast models on non-Hertzian contacts: reported per case, not gated (issue 13)",
        )],
        folder: "contact_nonhertz",
        load: |dir| Ok(Box::new(envelope::EnvelopeCases::load(dir, "contact_nonhertz", envelope::NONHERTZ)?)),
        section: Some(NONHERTZ_SECTION),
    },
    SetDef {
        labels: &[(
            table::TABLE,
            "the fast models against CONTACT on its test table: reported (the model ladder), not gated",
        )],
        folder: table::FILE,
        load: |dir| Ok(Box::new(table::load(dir)?)),
        section: None,
    },
    SetDef {
        labels: &[(
            thesis::AGAINST,
            "the thesis's figures were read off its plots and used another grid treatment; reported beside ours",
        )],
        folder: "thesis",
        load: |dir| Ok(Box::new(thesis::ThesisTables::load(dir)?)),
        section: None,
    },
    friction::SET,
    friction::VARIANTS_SET,
    SetDef {
        labels: &[(
            contact_public::AGAINST,
            "CONTACT's printed totals of its public cases: a quantity no rule names is reported",
        )],
        folder: contact_public::FOLDER,
        load: |dir| Ok(Box::new(contact_public::PublicCases::load(dir)?)),
        section: None,
    },
    SetDef {
        labels: &[(
            wheelrail_cases::AGAINST,
            "CONTACT's printed module-1 results: a quantity no rule names is reported",
        )],
        folder: wheelrail_cases::FOLDER,
        load: |dir| Ok(Box::new(wheelrail_cases::WheelRailCases::load(dir)?)),
        section: None,
    },
];

/// The id of the report section of CONTACT's envelope cases.
pub const ENVELOPE_SECTION: &str = "envelope";
/// The id of the report section of CONTACT's non-Hertzian cases.
pub const NONHERTZ_SECTION: &str = "nonhertz";

/// Every label the reference sets' findings carry: what a tolerance rule may name besides golden
/// and previous.
pub fn labels() -> impl Iterator<Item = Against> {
    SETS.iter().flat_map(|s| s.labels.iter().map(|(l, _)| *l))
}

/// Each label's last rule, in the registry's order: reported, no tolerance.
pub fn catch_alls() -> impl Iterator<Item = Rule> {
    SETS.iter().flat_map(|s| s.labels.iter().map(|(l, why)| rule::catch_all(*l, why)))
}

/// Every reference set the project holds, loaded, in the registry's order.
pub struct References {
    sets: Vec<(&'static SetDef, Box<dyn ReferenceSet>)>,
    /// The sets whose folder the tree does not have (loaded as holding nothing).
    absent: Vec<&'static SetDef>,
}

impl References {
    /// Load every set of the registry from `dir`.
    pub fn load(dir: &Path) -> Result<References, Error> {
        if !dir.is_dir() {
            let allowed = "a folder of reference data (CONTACT, thesis) with its MANIFEST.sha256";
            return Err(InputError::new("--reference", dir.display(), allowed).into());
        }
        // Every file against the reviewed checksums: a changed, missing or extra reference file
        // fails until its manifest is updated in a reviewed commit.
        crate::safety::manifest::verify(dir).map_err(|source| Error::Manifest { dir: dir.to_path_buf(), source })?;
        let (present, absent): (Vec<&SetDef>, Vec<&SetDef>) = SETS.iter().partition(|d| dir.join(d.folder).exists());
        let sets = present.into_iter().map(|def| Ok((def, (def.load)(dir)?))).collect::<Result<_, Error>>()?;
        Ok(References { sets, absent })
    }

    /// The folders of the sets this tree does not have, with the label of each set's findings:
    /// their comparisons are not made (the commands say so once).
    pub fn absent(&self) -> impl Iterator<Item = (&'static str, Against)> + '_ {
        self.absent.iter().filter_map(|d| d.labels.first().map(|(l, _)| (d.folder, *l)))
    }

    /// Every set, in the registry's order.
    pub fn sets(&self) -> impl Iterator<Item = &dyn ReferenceSet> {
        self.sets.iter().map(|(_, s)| s.as_ref())
    }

    /// The set whose first label is `label`, as its own type (`None`: no such set of that type).
    pub fn get<T: ReferenceSet>(&self, label: Against) -> Option<&T> {
        let (_, set) = self.sets.iter().find(|(def, _)| def.labels.first().is_some_and(|(l, _)| *l == label))?;
        (set.as_ref() as &dyn Any).downcast_ref::<T>()
    }

    /// The set whose first label is `label`, as its own type, to attach what a stage above
    /// computes for it (the importer's survey of CONTACT's public decks).
    pub fn get_mut<T: ReferenceSet>(&mut self, label: Against) -> Option<&mut T> {
        let (_, set) = self.sets.iter_mut().find(|(def, _)| def.labels.first().is_some_and(|(l, _)| *l == label))?;
        (set.as_mut() as &mut dyn Any).downcast_mut::<T>()
    }

    /// The set that the report section `id` draws, as its own type.
    pub fn of_section<T: ReferenceSet>(&self, id: &str) -> Option<&T> {
        let (_, set) = self.sets.iter().find(|(def, _)| def.section == Some(id))?;
        (set.as_ref() as &dyn Any).downcast_ref::<T>()
    }

    /// The report section that draws this scene, if a set with a section of its own holds it
    /// (its cases are drawn there, not in the report's scene groups).
    pub fn section_of(&self, scene: &str) -> Option<&'static str> {
        self.sets.iter().find_map(|(def, set)| def.section.filter(|_| set.history(scene).is_some()))
    }

    /// The first history any set holds for a scene (drawn as markers in the plots).
    pub fn history(&self, scene: &str) -> Option<&History> {
        self.sets().find_map(|s| s.history(scene))
    }
}

/// Read a reference file (bounded; typed error naming it).
fn read(path: &Path) -> Result<String, Error> {
    Ok(crate::safety::read::read_text(path, crate::safety::read::REFERENCE_LIMIT_BYTES, "reference file")?)
}

/// An error if `name` was given by an earlier row of the cases file `path` (`seen` collects
/// the names): a second row of one case would replace the first in silence.
fn first_row(seen: &mut std::collections::BTreeSet<String>, path: &Path, line: usize, name: &str) -> Result<(), Error> {
    if seen.insert(name.to_string()) {
        return Ok(());
    }
    Err(Error::Format {
        path: path.into(),
        source: crate::error::FormatError::Value {
            line,
            column: "name".into(),
            value: crate::error::excerpt(name),
            what: "a case name no earlier row gives",
        },
    })
}
