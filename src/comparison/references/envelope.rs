//! CONTACT's case sets beyond the thesis family, one folder each (cases.csv, one history per case;
//! its README gives the inputs): `contact_envelope` (lateral creepage, spin and combined
//! creepage, friction and load that change in time, other Courant numbers and grids) and
//! `contact_nonhertz` (non-Hertzian contacts from lateral profiles). Every model's fx/fn, fy/fn
//! and spin moment are compared at every step; the exact solver is gated (issues 12, 13: 1e-5),
//! the others reported.

use super::contact::read_history;
use super::{read, ReferenceSet};
use crate::comparison::finding::{Against, Ctx, Finding};
use crate::comparison::rule::Rule;
use crate::error::{Error, FormatError};
use crate::history::{History, MZ};
use crate::suite::results::StoredScene;
use std::collections::BTreeMap;
use std::path::Path;

/// CONTACT's exact theory on the envelope cases.
pub const ENVELOPE: Against = Against::Reference("CONTACT envelope");
/// CONTACT's exact theory on the non-Hertzian cases.
pub const NONHERTZ: Against = Against::Reference("CONTACT non-Hertzian");

/// The spin moment made dimensionless, `mz / (FN a)` (a: the nominal semi-axis along x), so that
/// one tolerance fits every case; the quantity name of its findings.
pub const MZ_OVER_FN_A: &str = "mz_over_fn_a";

/// Every case's history of one CONTACT case set, by case name.
#[derive(Debug, Clone, Default)]
pub struct EnvelopeCases {
    /// Its comparisons' label ([`ENVELOPE`], [`NONHERTZ`]).
    pub against: Option<Against>,
    pub histories: BTreeMap<String, History>,
    /// The cases' notes (cases.csv `note`), for the report.
    pub notes: BTreeMap<String, String>,
    /// The element fields of the cases that ship a `<case>_field.csv`, per step (patch maps).
    pub fields: BTreeMap<String, Vec<(usize, Vec<FieldCell>)>>,
}

/// One element of a CONTACT field file: centre in CONTACT's coordinates, pressure, state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldCell {
    pub x_mm: f64,
    pub y_mm: f64,
    pub pn_mpa: f64,
    /// CONTACT's element state: 'E' exterior, 'A' adhesion, 'S' slip.
    pub state: char,
}

/// A field file `step,ix,iy,x_mm,y_mm,pn_mpa,px_mpa,py_mpa,state`, grouped by step.
fn read_field(path: &Path) -> Result<Vec<(usize, Vec<FieldCell>)>, Error> {
    let text = read(path)?;
    let bad = |line: usize, e: csv::Error| Error::Format {
        path: path.to_path_buf(),
        source: FormatError::Csv { line, source: e },
    };
    let mut rdr = csv::Reader::from_reader(text.as_bytes());
    let mut out: Vec<(usize, Vec<FieldCell>)> = Vec::new();
    for (n, rec) in rdr.deserialize::<(usize, usize, usize, f64, f64, f64, f64, f64, char)>().enumerate() {
        let (step, _, _, x_mm, y_mm, pn_mpa, _, _, state) = rec.map_err(|e| bad(n + 2, e))?;
        let cell = FieldCell { x_mm, y_mm, pn_mpa, state };
        match out.last_mut() {
            Some((k, cells)) if *k == step => cells.push(cell),
            _ => out.push((step, vec![cell])),
        }
    }
    Ok(out)
}

impl EnvelopeCases {
    /// Load `dir/folder/cases.csv` and every case's history (with `mz_nmm`), compared as `against`.
    pub fn load(dir: &Path, folder: &str, against: Against) -> Result<EnvelopeCases, Error> {
        let path = dir.join(folder).join("cases.csv");
        let text = read(&path)?;
        let mut rdr = csv::Reader::from_reader(text.as_bytes());
        let bad = |e: csv::Error| Error::Format { path: path.clone(), source: FormatError::Csv { line: 0, source: e } };
        let head: Vec<String> = rdr.headers().map_err(bad)?.iter().map(String::from).collect();
        let (Some(name_col), Some(note_col)) =
            (head.iter().position(|h| h == "name"), head.iter().position(|h| h == "note"))
        else {
            let column = if head.iter().any(|h| h == "name") { "note" } else { "name" };
            return Err(Error::Format { path, source: FormatError::MissingColumn { column: column.into() } });
        };
        let mut out = EnvelopeCases { against: Some(against), ..EnvelopeCases::default() };
        let mut seen = std::collections::BTreeSet::new();
        for (line, rec) in rdr.records().enumerate() {
            let rec = rec.map_err(bad)?;
            let (name, note) = (rec.get(name_col).unwrap_or(""), rec.get(note_col).unwrap_or(""));
            super::first_row(&mut seen, &path, line + 2, name)?;
            let h = read_history(&dir.join(folder).join(format!("{name}.csv")), 0, &[MZ])?;
            out.histories.insert(name.to_string(), h);
            let field = dir.join(folder).join(format!("{name}_field.csv"));
            if field.is_file() {
                out.fields.insert(name.to_string(), read_field(&field)?);
            }
            out.notes.insert(name.to_string(), note.to_string());
        }
        Ok(out)
    }
}

/// `mz / (FN a)` per step of a history that has the moment column.
fn mz_over_fn_a(h: &History, a_mm: f64) -> Option<Vec<f64>> {
    let mz = h.column(MZ)?;
    Some(h.rows.iter().zip(mz).map(|(r, m)| m / (r.sample.fn_n * a_mm)).collect())
}

impl ReferenceSet for EnvelopeCases {
    fn label(&self) -> &'static str {
        match self.against {
            Some(Against::Reference(label)) => label,
            _ => "CONTACT case set (not loaded)",
        }
    }

    fn compare(&self, ours: &StoredScene, rules: &[Rule]) -> Vec<Finding> {
        let mut out = Vec::new();
        let Some(contact) = self.histories.get(&ours.name) else {
            return out;
        };
        let a_mm = ours.scene.a_mm;
        let theirs_mz: BTreeMap<usize, f64> = match mz_over_fn_a(contact, a_mm) {
            Some(v) => contact.rows.iter().map(|r| r.sample.step).zip(v).collect(),
            None => BTreeMap::new(),
        };
        for (solver, h) in &ours.histories {
            let ctx = Ctx { scene: &ours.name, solver, against: self.against.unwrap_or(ENVELOPE), rules };
            out.extend(ctx.column(h, contact, "fx_over_fn", true));
            out.extend(ctx.column(h, contact, "fy_over_fn", true));
            match mz_over_fn_a(h, a_mm) {
                Some(m) => {
                    let worst = h
                        .rows
                        .iter()
                        .zip(m)
                        .filter_map(|(r, v)| {
                            Some(ctx.finding(
                                MZ_OVER_FN_A,
                                Some(r.sample.step),
                                v,
                                *theirs_mz.get(&r.sample.step)?,
                                "mz / (FN a)",
                            ))
                        })
                        .max_by(|a, b| a.severity().total_cmp(&b.severity()));
                    out.extend(worst);
                }
                None => out.push(ctx.unmatched(MZ_OVER_FN_A, format!("{solver} wrote no {MZ} column"))),
            }
        }
        out
    }

    fn history(&self, scene: &str) -> Option<&History> {
        self.histories.get(scene)
    }
}
