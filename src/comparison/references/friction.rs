//! CONTACT's cases with friction falling with the slip velocity: two sets of one format,
//! reference/contact_friction (CONTACT's shared folder, issue 33) and
//! reference/contact_friction_variants (25 variants run for this project): cases.csv, one history
//! per case; each folder's README gives the laws, the memory and the inputs. One loader reads
//! either with its own labels ([`Labels`]). The exact solver's fx/fn, fy/fn and mz/(FN a) are
//! compared at every step with CONTACT's published values (gated to 2e-4) and fx/fn, fy/fn with
//! the tightly converged `*_tight` columns (gated to 1e-5), by each case's `gate`: `yes` both;
//! `tight` the tight columns only (CONTACT's own iteration error exceeds what the published
//! values are gated to), its published values reported; `no` none, reported with the reason of
//! its note.

use super::contact::read_history;
use super::envelope::EnvelopeCases;
use super::{read, ReferenceSet, SetDef};
use crate::comparison::finding::{Against, Finding};
use crate::comparison::rule::Rule;
use crate::error::{Error, FormatError};
use crate::history::{History, MZ};
use crate::suite::results::StoredScene;
use std::path::Path;

/// CONTACT's published values on the gated cases.
pub const FRICTION: Against = Against::Reference("CONTACT friction");
/// The tightly converged fixed point (`fx_over_fn_tight`, `fy_over_fn_tight`) on the gated cases.
pub const FRICTION_TIGHT: Against = Against::Reference("CONTACT friction tight");
/// CONTACT's published values on the cases its README does not gate.
pub const FRICTION_UNGATED: Against = Against::Reference("CONTACT friction, not gated");

/// The set's folder inside the reference folder.
pub const FOLDER: &str = "contact_friction";
/// The labels of `contact_friction`.
pub const LABELS: Labels = Labels { published: FRICTION, tight: FRICTION_TIGHT, ungated: FRICTION_UNGATED };

/// The registry's entry of `contact_friction` (`SETS`): its labels with the catch-all reasons of
/// the comparisons no rule of `tolerances.toml` covers, and its loader.
pub const SET: SetDef = SetDef {
    labels: &[
        (FRICTION, "the fast models against the exact theory with falling friction: reported"),
        (FRICTION_TIGHT, "the fast models against the tightly converged exact theory: reported"),
        (FRICTION_UNGATED, "cases CONTACT's README does not gate (cases.csv gate = no, its note says why: two steady solutions, or the memoryless falling branch oscillating in time): reported"),
    ],
    folder: FOLDER,
    load: |dir| Ok(Box::new(FrictionCases::load(dir, FOLDER, LABELS)?)),
    section: None,
};

/// The variants' published values on the cases whose gate is `yes`.
pub const VARIANTS: Against = Against::Reference("CONTACT friction variants");
/// The variants' tightly converged fixed point on the cases whose gate is `yes` or `tight`.
pub const VARIANTS_TIGHT: Against = Against::Reference("CONTACT friction variants tight");
/// The variants' published values on the cases whose gate is `tight` or `no`.
pub const VARIANTS_UNGATED: Against = Against::Reference("CONTACT friction variants, not gated");

/// The variants' folder inside the reference folder.
pub const VARIANTS_FOLDER: &str = "contact_friction_variants";
/// The labels of `contact_friction_variants`.
pub const VARIANTS_LABELS: Labels = Labels { published: VARIANTS, tight: VARIANTS_TIGHT, ungated: VARIANTS_UNGATED };

/// The registry's entry of the variants (`SETS`): their labels with the catch-all reasons of the
/// comparisons no rule of `tolerances.toml` covers, and their loader.
pub const VARIANTS_SET: SetDef = SetDef {
    labels: &[
        (VARIANTS, "the fast models against the exact theory on the falling-friction variants: reported"),
        (VARIANTS_TIGHT, "the fast models against the variants' tightly converged exact theory: reported"),
        (VARIANTS_UNGATED, "the variants' published values that cases.csv does not gate (gate = tight: CONTACT's own iteration error exceeds 2e-4 there, the tight values are gated; gate = no: two steady solutions; each note says why): reported"),
    ],
    folder: VARIANTS_FOLDER,
    load: |dir| Ok(Box::new(FrictionCases::load(dir, VARIANTS_FOLDER, VARIANTS_LABELS)?)),
    section: None,
};

/// The labels a falling-friction set's findings carry, one per comparison.
#[derive(Debug, Clone, Copy)]
pub struct Labels {
    /// CONTACT's published values on the cases whose gate is `yes`.
    pub published: Against,
    /// The `*_tight` columns on the cases whose gate is `yes` or `tight`.
    pub tight: Against,
    /// CONTACT's published values on the cases whose gate is `tight` or `no` (reported).
    pub ungated: Against,
}

/// The three comparisons, each a case set of its own label.
pub struct FrictionCases {
    label: &'static str,
    published: EnvelopeCases,
    tight: EnvelopeCases,
    ungated: EnvelopeCases,
}

/// A case's history with its `*_tight` columns as fx/fn, fy/fn (and no moment).
fn tight_history(path: &Path) -> Result<History, Error> {
    let mut h = read_history(path, 0, &["fx_over_fn_tight", "fy_over_fn_tight"])?;
    for row in &mut h.rows {
        (row.fx_over_fn, row.fy_over_fn) = (row.extra[2], row.extra[3]);
    }
    Ok(h)
}

impl FrictionCases {
    /// Load `dir/<folder>/cases.csv` and every case's history, its findings carrying `labels`.
    pub fn load(dir: &Path, folder: &str, labels: Labels) -> Result<FrictionCases, Error> {
        let folder = dir.join(folder);
        let path = folder.join("cases.csv");
        let empty = |against| EnvelopeCases { against: Some(against), ..EnvelopeCases::default() };
        let mut out = FrictionCases {
            label: labels.published.label(),
            published: empty(labels.published),
            tight: empty(labels.tight),
            ungated: empty(labels.ungated),
        };
        let text = read(&path)?;
        let mut rdr = csv::Reader::from_reader(text.as_bytes());
        let bad = |e: csv::Error| Error::Format { path: path.clone(), source: FormatError::Csv { line: 0, source: e } };
        let head: Vec<String> = rdr.headers().map_err(bad)?.iter().map(String::from).collect();
        let column = |name: &str| {
            head.iter().position(|h| h == name).ok_or_else(|| Error::Format {
                path: path.clone(),
                source: FormatError::MissingColumn { column: name.into() },
            })
        };
        let (name_col, gate_col, note_col) = (column("name")?, column("gate")?, column("note")?);
        let mut seen = std::collections::BTreeSet::new();
        for (line, rec) in rdr.records().enumerate() {
            let rec = rec.map_err(bad)?;
            let field = |c: usize| rec.get(c).unwrap_or("").to_string();
            let (name, note, gate) = (field(name_col), field(note_col), field(gate_col));
            super::first_row(&mut seen, &path, line + 2, &name)?;
            let case = folder.join(format!("{name}.csv"));
            let history = read_history(&case, 0, &[MZ])?;
            // yes: published and tight gated; tight: the tight columns gated, the published values
            // reported (CONTACT's own iteration error there exceeds their tolerance); no: reported.
            if gate == "yes" || gate == "tight" {
                out.tight.histories.insert(name.clone(), tight_history(&case)?);
            }
            let set = match gate.as_str() {
                "yes" => &mut out.published,
                "tight" | "no" => &mut out.ungated,
                _ => {
                    return Err(Error::Format {
                        path: path.clone(),
                        source: FormatError::Value {
                            line: line + 2,
                            column: "gate".into(),
                            value: crate::error::excerpt(&gate),
                            what: "yes, tight or no",
                        },
                    })
                }
            };
            set.histories.insert(name.clone(), history);
            set.notes.insert(name, note);
        }
        Ok(out)
    }
}

impl ReferenceSet for FrictionCases {
    fn label(&self) -> &'static str {
        self.label
    }

    fn compare(&self, ours: &StoredScene, rules: &[Rule]) -> Vec<Finding> {
        let mut out = self.published.compare(ours, rules);
        out.extend(self.tight.compare(ours, rules));
        out.extend(self.ungated.compare(ours, rules));
        out
    }

    fn history(&self, scene: &str) -> Option<&History> {
        self.published.history(scene).or_else(|| self.ungated.history(scene))
    }
}
