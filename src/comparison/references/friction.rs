//! CONTACT's cases with friction falling with the slip velocity (reference/contact_friction:
//! cases.csv, one history per case; its README gives the laws, the memory and the inputs). The
//! exact solver's fx/fn, fy/fn and mz/(FN a) are compared at every step with CONTACT's published
//! values (gated to 2e-4) and fx/fn, fy/fn with the tightly converged `*_tight` columns (gated to
//! 1e-5), on the cases whose `gate` is `yes`; the others are compared and reported with the
//! reason of their note (issue 33).

use super::contact::read_history;
use super::envelope::EnvelopeCases;
use super::{read, ReferenceSet};
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

/// The three comparisons, each a case set of its own label.
pub struct FrictionCases {
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
    /// Load `dir/contact_friction/cases.csv` and every case's history.
    pub fn load(dir: &Path) -> Result<FrictionCases, Error> {
        let folder = dir.join(FOLDER);
        let path = folder.join("cases.csv");
        let empty = |against| EnvelopeCases { against: Some(against), ..EnvelopeCases::default() };
        let mut out = FrictionCases {
            published: empty(FRICTION),
            tight: empty(FRICTION_TIGHT),
            ungated: empty(FRICTION_UNGATED),
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
        for rec in rdr.records() {
            let rec = rec.map_err(bad)?;
            let field = |c: usize| rec.get(c).unwrap_or("").to_string();
            let (name, note) = (field(name_col), field(note_col));
            let case = folder.join(format!("{name}.csv"));
            let history = read_history(&case, 0, &[MZ])?;
            let set = if field(gate_col) == "yes" {
                out.tight.histories.insert(name.clone(), tight_history(&case)?);
                &mut out.published
            } else {
                &mut out.ungated
            };
            set.histories.insert(name.clone(), history);
            set.notes.insert(name, note);
        }
        Ok(out)
    }
}

impl ReferenceSet for FrictionCases {
    fn label(&self) -> &'static str {
        "CONTACT friction"
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
