//! CONTACT's public examples and test bank (reference/contact_public/, issue 32 item 4): a scene
//! imported from one of its decks (`[origin]` in scene.json) is compared with the totals CONTACT
//! printed in the deck's `.ref_out`, read by [`super::contact_output`] (signs converted there).
//! Row k of a history is case `first + k` of the deck when its step-0 row (a steady or shift
//! start) is a case; otherwise step s ≥ 1 is case `first + s − 1`. Under prescribed forces
//! CONTACT prints the force prescribed and the creepage (shift) it solved for: the creepages found
//! are compared with the latter (`cx_in_rounding`, `cy_in_rounding`) and the forces reached with
//! the former; with the approach prescribed (N = 0) the FN found with the printed FN
//! (`fn_in_rounding`). A creepage or shift solved for that CONTACT prints at its noise level (zero
//! by symmetry) is measured against the noise floor instead (`cx_at_noise_floor`,
//! `cy_at_noise_floor`, [`natural_scale`]), and a net force printed with digits finer than CONTACT's
//! iteration tolerance near zero against that floor (`fx_over_fn_at_noise_floor`, [`FX_NOISE`]). Each
//! difference is measured in
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
use std::path::{Path, PathBuf};

/// CONTACT's printed totals of its public cases.
pub const AGAINST: Against = Against::Reference("CONTACT public");

/// The folder of the decks and their printed output, under the reference folder.
pub const FOLDER: &str = "contact_public";

/// The quantities compared, each in half-units of the printed rounding.
pub const FX: &str = "fx_over_fn_in_rounding";
pub const FY: &str = "fy_over_fn_in_rounding";
pub const MZ_Q: &str = "mz_in_rounding";
/// The creepage (shift [mm]) solved for under a prescribed force, against CONTACT's CREEP X
/// (SHIFT X) and Y.
pub const CX: &str = "cx_in_rounding";
pub const CY: &str = "cy_in_rounding";
/// The largest surface temperature of both bodies on the contact [°C] (H = 1, 3), against
/// CONTACT's MAX(T1,T2): the larger of the history's [`TEMP1`] and [`TEMP2`].
pub const TEMP_Q: &str = "temperature_max_in_rounding";
/// The exact solver's columns of each body's largest surface temperature on the contact.
pub const TEMP1: &str = "temp1_max_c";
pub const TEMP2: &str = "temp2_max_c";
/// FN where the approach is prescribed (N = 0: the solver finds FN), against CONTACT's FN.
pub const FN_Q: &str = "fn_in_rounding";
/// The creepage or shift solved for where CONTACT prints it at its noise level (a value zero by
/// symmetry, e.g. SHIFT Y = −3.407e-12 mm under FY = 0, the residual of its force iteration):
/// measured in half-units of the noise floor [`NOISE_FRACTION`] × [`natural_scale`] instead of
/// the printed digits, which print noise no solver reproduces.
pub const CX_NOISE: &str = "cx_at_noise_floor";
pub const CY_NOISE: &str = "cy_at_noise_floor";
/// The noise floor of a solved creepage or shift as a fraction of its natural scale (the rule
/// in `tolerances.toml` says why this number).
pub const NOISE_FRACTION: f64 = 1e-6;
/// A net force that CONTACT prints near zero with digits finer than its own iteration tolerance
/// (its EPS of the tangential tractions, 1e-6 in the public decks: a net force is known to about
/// EPS μ FN; CONTACT itself prints |F| < 0.5 EPS μ FN as 0, `filt_sml`): fx/fn and fy/fn printed
/// other than 0, below [`NEAR_ZERO`] floors, are measured in half-units of the floor
/// [`NOISE_FRACTION`] × μ (a net traction of a grid's asymmetry, examples/spence35.inp cases 2-11:
/// FX/FSTAT/FN = −9.713E-05 to −7.827E-07).
pub const FX_NOISE: &str = "fx_over_fn_at_noise_floor";
pub const FY_NOISE: &str = "fy_over_fn_at_noise_floor";
/// How many floors from zero a printed net force counts as near zero (1e-4 μ FN: a hundred
/// times CONTACT's tolerance, where its four printed digits are at least 20 times finer).
pub const NEAR_ZERO: f64 = 100.0;

/// The natural scale of a creepage or shift solved for: μ FN/(G ā) [mm] for a shift (Mindlin's
/// shift at full slip is 3 μ FN (2 − ν)/(16 G a), Johnson 1985 §7.1) and μ FN/(G ā²) for a
/// creepage (Kalker's ξ at which G ā² C11 ξ reaches μ FN), ā = √(a b) the nominal ellipse's
/// mean semi-axis, μ and FN the row's.
pub fn natural_scale(a_mm: f64, b_mm: f64, g_mpa: f64, mu: f64, fn_n: f64, shift: bool) -> f64 {
    let mean_mm = (a_mm * b_mm).sqrt();
    let per_length = mu * fn_n / (g_mpa * mean_mm);
    if shift {
        per_length
    } else {
        per_length / mean_mm
    }
}

/// `printed` as the gate compares it: at the noise floor where CONTACT prints it below that floor
/// with finer digits (then `noise` names the quantity), else as printed.
fn at_noise_floor(
    printed: Printed,
    scale: f64,
    quantity: &'static str,
    noise: &'static str,
) -> (&'static str, Printed) {
    let floor = NOISE_FRACTION * scale;
    if printed.value.abs() < floor && printed.half_unit < 0.5 * floor {
        (noise, Printed { value: printed.value, half_unit: 0.5 * floor })
    } else {
        (quantity, printed)
    }
}

/// A printed fx/fn or fy/fn as the gate compares it: at the floor where it is near zero (within
/// [`NEAR_ZERO`] floors, not 0) and printed with digits finer than the floor (then `noise` names
/// the quantity), else as printed.
fn force_at_floor(
    printed: Printed,
    floor: f64,
    quantity: &'static str,
    noise: &'static str,
) -> (&'static str, Printed) {
    let near_zero = printed.value != 0.0 && printed.value.abs() < NEAR_ZERO * floor;
    if floor.is_finite() && near_zero && printed.half_unit < 0.5 * floor {
        (noise, Printed { value: printed.value, half_unit: 0.5 * floor })
    } else {
        (quantity, printed)
    }
}

/// Every deck's printed cases, by the deck's file name (`cattaneo.inp`).
#[derive(Debug, Clone, Default)]
pub struct PublicCases {
    pub decks: BTreeMap<String, Vec<contact_output::CaseOutput>>,
    /// Each deck's input file (beside its `.ref_out`).
    pub inputs: BTreeMap<String, PathBuf>,
    /// What the importer says of each deck's cases ([`PublicCases::attach_survey`]; empty until
    /// the caller attaches it: the import stage sits above this one).
    pub survey: BTreeMap<String, Survey>,
}

/// The importer's verdict on one deck's cases.
#[derive(Debug, Clone, PartialEq)]
pub enum Survey {
    /// Every case by number: its module and the features that keep it out.
    Cases(BTreeMap<usize, CaseSurvey>),
    /// The deck could not be read as a whole (the importer's message).
    Unread(String),
}

/// The importer's verdict on one case.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseSurvey {
    /// CONTACT's module: 1 wheel–rail contact from profiles, 3 a contact given by hand.
    pub module: u8,
    /// The features that keep the case out (empty: supported).
    pub refused: Vec<String>,
}

/// One comparison of a row with its printed case: the quantity and the difference in
/// half-units of the printed rounding.
#[derive(Debug, Clone, PartialEq)]
pub struct RowDiff {
    pub step: usize,
    pub case: usize,
    pub quantity: &'static str,
    pub ours: f64,
    pub printed: Printed,
}

impl RowDiff {
    /// |ours − printed| in half-units of the printed rounding.
    pub fn half_units(&self) -> f64 {
        (self.ours - self.printed.value).abs() / self.printed.half_unit
    }
}

impl PublicCases {
    /// Read every `.ref_out` under `dir/contact_public` (recursively), keyed by its deck's name.
    pub fn load(dir: &Path) -> Result<PublicCases, Error> {
        let mut files = Vec::new();
        collect_files(&dir.join(FOLDER), &mut files)?;
        let mut out = PublicCases::default();
        for path in files {
            let Some(stem) = path.file_stem().and_then(|s| s.to_str()) else { continue };
            let deck = format!("{stem}.inp");
            out.decks.insert(deck.clone(), contact_output::read(&path)?);
            out.inputs.insert(deck.clone(), path.with_extension("inp"));
        }
        Ok(out)
    }

    /// Attach the importer's verdict on every deck (`survey` of its input file).
    pub fn attach_survey(&mut self, survey: impl Fn(&Path) -> Survey) {
        self.survey = self.inputs.iter().map(|(deck, inp)| (deck.clone(), survey(inp))).collect();
    }

    /// Every comparison of a stored history with the printed cases of its origin: one row per
    /// case of the origin's range, compared where CONTACT printed the case (a deck may print only
    /// some, its O digit 0 for the others: `perfc_test/carter2d_100` prints 2 of its 1000). `Err`
    /// with why where the rows are not one case each or no case of the range is printed.
    pub fn row_diffs(&self, scene: &StoredScene, h: &History) -> Result<Vec<RowDiff>, String> {
        let Some(origin) = &scene.scene.origin else { return Ok(Vec::new()) };
        let [first, last] = origin.cases;
        let cases: Vec<Option<&Totals>> = (first..=last).map(|c| self.totals(&origin.file, c)).collect();
        // A transient history after a steady case starts from it: its step 0 is case `first`
        // (the importer writes one row per case, so it holds one row more than its steps ≥ 1).
        let stepped = h.rows.iter().filter(|r| r.sample.step >= 1).count();
        let steady_start = cases.len() == stepped + 1 && h.rows.first().is_some_and(|r| r.sample.step == 0);
        let rows: Vec<_> = h.rows.iter().filter(|r| steady_start || r.sample.step >= 1).collect();
        if cases.len() != rows.len() || cases.iter().all(Option::is_none) {
            let printed = cases.iter().flatten().count();
            return Err(format!(
                "{} rows, cases {first} to {last} of {} ({printed} printed): not one case per row, or none printed",
                rows.len(),
                origin.file
            ));
        }
        let mz: Option<BTreeMap<usize, f64>> =
            h.column(MZ).map(|v| h.rows.iter().map(|r| r.sample.step).zip(v).collect());
        let temperature: Option<BTreeMap<usize, f64>> = h.column(TEMP1).zip(h.column(TEMP2)).map(|(one, two)| {
            let max = one.iter().zip(&two).map(|(a, b)| a.max(*b));
            h.rows.iter().map(|r| r.sample.step).zip(max).collect()
        });
        // The steps whose FN the solver found for a prescribed approach (scene.json's loading).
        let loading = scene.scene.loading_rows().map_err(|e| format!("scene.json's loading: {e}"))?;
        let by_approach: Vec<usize> = loading.iter().filter(|s| s.pen_mm.is_some()).map(|s| s.step).collect();
        let mut out = Vec::new();
        for (k, (r, t)) in rows.iter().zip(&cases).enumerate() {
            let Some(t) = t else { continue };
            let (step, case) = (r.sample.step, first + k);
            let d = |(quantity, printed), ours| RowDiff { step, case, quantity, ours, printed };
            let (sc, mu) = (&scene.scene, r.sample.mu);
            let floor = NOISE_FRACTION * mu;
            out.push(d(force_at_floor(printed_ratio(t, t.x, t.fx_n, mu), floor, FX, FX_NOISE), r.fx_over_fn));
            out.push(d(force_at_floor(printed_ratio(t, t.y, t.fy_n, mu), floor, FY, FY_NOISE), r.fy_over_fn));
            if by_approach.contains(&step) {
                out.push(d((FN_Q, t.fn_n), r.sample.fn_n));
            }
            for (quantity, noise, ours, printed) in [(CX, CX_NOISE, r.sample.cx, t.x), (CY, CY_NOISE, r.sample.cy, t.y)]
            {
                let (c, shift) = match printed {
                    Tangential::SolvedCreepage(c) => (c, false),
                    Tangential::SolvedShiftMm(c) => (c, true),
                    _ => continue,
                };
                let scale = natural_scale(sc.a_mm, sc.b_mm, sc.g_mpa, mu, r.sample.fn_n, shift);
                out.push(d(at_noise_floor(c, scale, quantity, noise), ours));
            }
            if let Some(m) = mz.as_ref().and_then(|m| m.get(&step)) {
                out.push(d((MZ_Q, t.mz_nmm), *m));
            }
            if let (Some(ours), Some(printed)) = (temperature.as_ref().and_then(|m| m.get(&step)), t.temperature_max_c)
            {
                out.push(d((TEMP_Q, printed), *ours));
            }
        }
        Ok(out)
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
pub(super) fn collect_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) -> Result<(), Error> {
    let io = |e: std::io::Error| Error::Io { path: dir.to_path_buf(), source: e };
    let mut entries: Vec<_> =
        std::fs::read_dir(dir).map_err(io)?.map(|e| e.map(|e| e.path())).collect::<Result<_, _>>().map_err(io)?;
    entries.sort();
    for p in entries {
        if p.is_dir() {
            collect_files(&p, out)?;
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
fn finding(ctx: &Ctx, d: &RowDiff) -> Finding {
    let (p, case) = (d.printed, d.case);
    let note = if [FX_NOISE, FY_NOISE].contains(&d.quantity) {
        format!(
            "case {case}: ours {:.9e}, printed {:e} finer than CONTACT's iteration tolerance: compared within the floor {:e} ({NOISE_FRACTION:e} of its scale)",
            d.ours,
            p.value,
            2.0 * p.half_unit
        )
    } else if [CX_NOISE, CY_NOISE].contains(&d.quantity) {
        format!(
            "case {case}: ours {:.9e}, printed {:e} at CONTACT's noise level: compared within the noise floor {:e} ({NOISE_FRACTION:e} of its natural scale)",
            d.ours,
            p.value,
            2.0 * p.half_unit
        )
    } else {
        format!("case {case}: ours {:.9e}, printed {:e} ± {:e}", d.ours, p.value, p.half_unit)
    };
    ctx.finding(d.quantity, Some(d.step), (d.ours - p.value) / p.half_unit, 0.0, &note)
}

impl ReferenceSet for PublicCases {
    fn label(&self) -> &'static str {
        "CONTACT public"
    }

    fn compare(&self, ours: &StoredScene, rules: &[Rule]) -> Vec<Finding> {
        let mut out = Vec::new();
        for (solver, h) in &ours.histories {
            let ctx = Ctx { scene: &ours.name, solver, against: AGAINST, rules };
            match self.row_diffs(ours, h) {
                Ok(diffs) => {
                    for q in [FX, FY, MZ_Q, FX_NOISE, FY_NOISE, CX, CY, CX_NOISE, CY_NOISE, FN_Q, TEMP_Q] {
                        let fs = diffs.iter().filter(|d| d.quantity == q).map(|d| finding(&ctx, d));
                        out.extend(fs.max_by(|a, b| a.severity().total_cmp(&b.severity())));
                    }
                }
                Err(why) => out.push(ctx.unmatched(FX, why)),
            }
        }
        out
    }

    fn history(&self, _scene: &str) -> Option<&History> {
        None
    }
}
