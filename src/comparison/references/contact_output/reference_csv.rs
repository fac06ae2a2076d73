//! The totals of CONTACT's printed output as a reference CSV of this project (the columns of
//! reference/contact_envelope's histories, plus the printed extras): one row per module-3 case
//! with printed totals, and for each printed value its resolution, `<column>_rounding` = half a
//! unit of the last digit CONTACT printed (carried through fx/fn), so that a gate can state its
//! tolerance in printed units.

use super::printed::Printed;
use super::{CaseBody, CaseOutput, Friction, Frictional, Stepping, Totals};
use crate::error::InputError;

/// The columns, in order (the `_rounding` columns follow, for [`ROUNDED`]).
pub const COLUMNS: [&str; 23] = [
    "case",
    "step",
    "t_s",
    "dt_s",
    "cx",
    "cy",
    "cs",
    "fn_n",
    "mu",
    "fx_n",
    "fy_n",
    "mz_nmm",
    "fx_over_fn",
    "fy_over_fn",
    "fx_over_fstat_fn",
    "fy_over_fstat_fn",
    "n_adhesion",
    "n_slip",
    "approach_mm",
    "pn_max_mpa",
    "elastic_energy_nmm",
    "fric_power_nmm_per_s",
    "fric_work_nmm",
];

/// The columns of printed (rounded) values, each with a column `<column>_rounding` after
/// [`COLUMNS`].
pub const ROUNDED: [&str; 17] = [
    "cx",
    "cy",
    "cs",
    "fn_n",
    "mu",
    "fx_n",
    "fy_n",
    "mz_nmm",
    "fx_over_fn",
    "fy_over_fn",
    "fx_over_fstat_fn",
    "fy_over_fstat_fn",
    "approach_mm",
    "pn_max_mpa",
    "elastic_energy_nmm",
    "fric_power_nmm_per_s",
    "fric_work_nmm",
];

/// An inclusive range of case numbers (`--cases A-B`, or one case `A`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CaseRange {
    pub first: u32,
    pub last: u32,
}

impl std::str::FromStr for CaseRange {
    type Err = InputError;

    fn from_str(s: &str) -> Result<Self, InputError> {
        let bad = || InputError::new("--cases", s, "A-B (whole case numbers, A <= B) or one case number A");
        let (a, b) = s.split_once('-').unwrap_or((s, s));
        let (first, last): (u32, u32) = (a.trim().parse().map_err(|_| bad())?, b.trim().parse().map_err(|_| bad())?);
        (first <= last).then_some(CaseRange { first, last }).ok_or_else(bad)
    }
}

impl CaseRange {
    pub fn contains(&self, case: u32) -> bool {
        (self.first..=self.last).contains(&case)
    }
}

/// One row: a case's printed totals, mu carried from the last FSTAT printed before it.
struct Row<'a> {
    case: u32,
    t: &'a Totals,
    mu: Option<Printed>,
}

const NONE: Printed = Printed { value: f64::NAN, half_unit: f64::NAN };

impl Row<'_> {
    /// The rounded values in the order of [`ROUNDED`] (NaN where not printed).
    fn rounded(&self) -> [Printed; 17] {
        let t = self.t;
        let (power, work) = match t.frictional {
            Frictional::PowerNmmPerS(p) => (p, NONE),
            Frictional::WorkNmm(w) => (NONE, w),
        };
        [
            t.cx().unwrap_or(NONE),
            t.cy().unwrap_or(NONE),
            t.kinematics.map_or(NONE, |k| k.cphi_per_mm),
            t.fn_n,
            self.mu.unwrap_or(NONE),
            t.fx_n,
            t.fy_n,
            t.mz_nmm,
            t.fx_n.over(t.fn_n),
            t.fy_n.over(t.fn_n),
            t.fx_over_fstat_fn().unwrap_or(NONE),
            t.fy_over_fstat_fn().unwrap_or(NONE),
            t.approach_mm,
            t.pn_max_mpa,
            t.elastic_energy_nmm,
            power,
            work,
        ]
    }

    /// The cells in the order of [`header`].
    fn cells(&self) -> Vec<String> {
        let t = self.t;
        // CONTACT prints no time; the case's step is DT (shifts) or DQ / VELOC (rolling).
        let dt_s = match t.kinematics.map(|k| (k.stepping, k.veloc_mm_s)) {
            Some((Stepping::Shift { dt_s }, _)) => dt_s.value,
            Some((Stepping::Rolling { dq_mm, .. }, v)) => dq_mm.value / v.value,
            None => f64::NAN,
        };
        let counts = t.statistics.map_or([f64::NAN; 2], |s| [s.nadh as f64, s.nslip as f64]);
        let r = self.rounded();
        let case = self.case.to_string();
        let mut cells = vec![case.clone(), case, "0".into(), number(dt_s)];
        cells.extend(r[..12].iter().map(|p| number(p.value)));
        cells.extend(counts.map(number));
        cells.extend(r[12..].iter().map(|p| number(p.value)));
        cells.extend(r.iter().map(|p| number(p.half_unit)));
        cells
    }
}

/// A number as the CSV holds it: every digit of the f64 (shortest round trip), NaN for none.
fn number(v: f64) -> String {
    match v {
        v if v.is_nan() => "NaN".into(),
        0.0 => "0".into(), // -0 too (it equals 0): a printed 0.000 negated
        v if !(1e-4..1e15).contains(&v.abs()) => format!("{v:e}"),
        v => format!("{v}"),
    }
}

/// The header line: [`COLUMNS`], then `<c>_rounding` for each of [`ROUNDED`].
pub fn header() -> String {
    let rounding = ROUNDED.iter().map(|c| format!("{c}_rounding"));
    COLUMNS.iter().map(|c| c.to_string()).chain(rounding).collect::<Vec<_>>().join(",")
}

/// The reference CSV of the module-3 cases in `range` (all when None) that printed totals.
/// CONTACT keeps the friction until a case reads it again: `mu` is the last FSTAT printed by a
/// module-3 case at or before the row's (NaN after one that printed another law, or per-row
/// friction).
pub fn write(cases: &[CaseOutput], range: Option<CaseRange>) -> (String, usize) {
    let mut out = header();
    out.push('\n');
    let (mut mu, mut rows) = (None, 0);
    for c in cases {
        let CaseBody::Totals(t) = &c.body else { continue };
        mu = match t.friction {
            Friction::Coulomb { fstat, .. } => Some(fstat),
            Friction::Other => None,
            Friction::NotPrinted => mu,
        };
        if range.is_some_and(|r| !r.contains(c.case)) {
            continue;
        }
        out.push_str(&Row { case: c.case, t, mu }.cells().join(","));
        out.push('\n');
        rows += 1;
    }
    (out, rows)
}
