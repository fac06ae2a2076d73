//! CONTACT's public examples and test bank (reference/contact_public/, issue 32 item 4): a scene
//! imported from one of its decks (`[origin]` in scene.json) is compared with the totals CONTACT
//! printed in the deck's `.ref_out`, read by [`super::contact_output`] (signs converted there).
//! Step s ≥ 1 of a history is case `first + s − 1` of the deck. Each difference is measured in
//! half-units of the printed value's last digit (its rounding bound, [`Printed::half_unit`]), so
//! that one rule per quantity holds for every case: `tolerances.toml` states k per quantity.

use super::contact_output::printed::Printed;
use super::contact_output::{self, CaseBody, Tangential, Totals};
use super::ReferenceSet;
use crate::comparison::finding::{Against, Ctx, Finding};
use crate::comparison::rule::Rule;
use crate::error::Error;
use crate::history::{History, MZ};
use crate::suite::results::StoredScene;
use std::collections::BTreeMap;
use std::path::Path;

/// CONTACT's printed totals of its public cases.
pub const AGAINST: Against = Against::Reference("CONTACT public");

/// The folder of the decks and their printed output, under the reference folder.
pub const FOLDER: &str = "contact_public";

/// The quantities compared, each in half-units of the printed rounding.
pub const FX: &str = "fx_over_fn_in_rounding";
pub const FY: &str = "fy_over_fn_in_rounding";
pub const MZ_Q: &str = "mz_in_rounding";

/// Every deck's printed cases, by the deck's file name (`cattaneo.inp`).
#[derive(Debug, Clone, Default)]
pub struct PublicCases {
    pub decks: BTreeMap<String, Vec<contact_output::CaseOutput>>,
}

impl PublicCases {
    /// Read every `.ref_out` under `dir/contact_public` (recursively), keyed by its deck's name.
    pub fn load(dir: &Path) -> Result<PublicCases, Error> {
        let mut files = Vec::new();
        collect(&dir.join(FOLDER), &mut files)?;
        let mut decks = BTreeMap::new();
        for path in files {
            let Some(stem) = path.file_stem().and_then(|s| s.to_str()) else { continue };
            decks.insert(format!("{stem}.inp"), contact_output::read(&path)?);
        }
        Ok(PublicCases { decks })
    }

    /// The printed totals of case `case` of `deck`.
    pub fn totals(&self, deck: &str, case: usize) -> Option<&Totals> {
        let c = self.decks.get(deck)?.iter().find(|c| c.case as usize == case)?;
        match &c.body {
            CaseBody::Totals(t) => Some(t),
            _ => None,
        }
    }
}

/// Every `.ref_out` under `dir`, sorted.
fn collect(dir: &Path, out: &mut Vec<std::path::PathBuf>) -> Result<(), Error> {
    let io = |e: std::io::Error| Error::Io { path: dir.to_path_buf(), source: e };
    let mut entries: Vec<_> =
        std::fs::read_dir(dir).map_err(io)?.map(|e| e.map(|e| e.path())).collect::<Result<_, _>>().map_err(io)?;
    entries.sort();
    for p in entries {
        if p.is_dir() {
            collect(&p, out)?;
        } else if p.extension().is_some_and(|e| e == "ref_out") {
            out.push(p);
        }
    }
    Ok(())
}

/// f/FN as printed: the second line's F/FSTAT/FN times the row's μ (more digits than FX/FN),
/// F/FN where printed so, else FX over FN with both roundings.
fn printed_ratio(t: &Totals, tangential: Tangential, force: Printed, mu: f64) -> Printed {
    match tangential {
        Tangential::ForceOverFstatFn(p) if mu.is_finite() => p.times(mu),
        Tangential::ForceOverFn(p) => p,
        _ => force.over(t.fn_n),
    }
}

/// One finding: the difference in half-units of the printed rounding (theirs = 0), the values
/// in the note.
fn finding(ctx: &Ctx, quantity: &str, step: usize, case: usize, ours: f64, theirs: Printed) -> Finding {
    let note = format!("case {case}: ours {ours:.9e}, printed {:e} ± {:e}", theirs.value, theirs.half_unit);
    ctx.finding(quantity, Some(step), (ours - theirs.value) / theirs.half_unit, 0.0, &note)
}

/// The worst of several findings of one quantity.
fn worst(fs: impl Iterator<Item = Finding>) -> Option<Finding> {
    fs.max_by(|a, b| a.severity().total_cmp(&b.severity()))
}

impl ReferenceSet for PublicCases {
    fn label(&self) -> &'static str {
        "CONTACT public"
    }

    fn compare(&self, ours: &StoredScene, rules: &[Rule]) -> Vec<Finding> {
        let Some(origin) = &ours.scene.origin else { return Vec::new() };
        let [first, last] = origin.cases;
        let mut out = Vec::new();
        for (solver, h) in &ours.histories {
            let ctx = Ctx { scene: &ours.name, solver, against: AGAINST, rules };
            let rows: Vec<_> = h.rows.iter().filter(|r| r.sample.step >= 1).collect();
            let cases: Option<Vec<&Totals>> = (first..=last).map(|c| self.totals(&origin.file, c)).collect();
            let Some(cases) = cases.filter(|c| c.len() == rows.len()) else {
                let why = format!(
                    "{} rows of steps ≥ 1, cases {first} to {last} of {}: not one printed case per row",
                    rows.len(),
                    origin.file
                );
                out.push(ctx.unmatched(FX, why));
                continue;
            };
            let pairs = || rows.iter().zip(&cases).enumerate().map(|(k, (r, t))| (r.sample.step, first + k, *r, *t));
            out.extend(worst(pairs().map(|(s, c, r, t)| {
                finding(&ctx, FX, s, c, r.fx_over_fn, printed_ratio(t, t.x, t.fx_n, r.sample.mu))
            })));
            out.extend(worst(pairs().map(|(s, c, r, t)| {
                finding(&ctx, FY, s, c, r.fy_over_fn, printed_ratio(t, t.y, t.fy_n, r.sample.mu))
            })));
            if let Some(mz) = h.column(MZ) {
                let mz: BTreeMap<usize, f64> = h.rows.iter().map(|r| r.sample.step).zip(mz).collect();
                out.extend(worst(pairs().map(|(s, c, _, t)| finding(&ctx, MZ_Q, s, c, mz[&s], t.mz_nmm))));
            }
        }
        out
    }

    fn history(&self, _scene: &str) -> Option<&History> {
        None
    }
}
