//! CONTACT's results for the thesis scenes (reference/contact: cases.csv and one history per
//! case; Vollebregt & Kalker's program, its README gives the inputs): the exact theory, and its
//! FASTSIM with the parabolic bound for `steady_fastsim_g22`.

use super::{read, ReferenceSet};
use crate::comparison::delay;
use crate::comparison::finding::{Against, Ctx, Finding};
use crate::comparison::rule::Rule;
use crate::error::{Error, FormatError};
use crate::history::{History, Row};
use crate::metrics;
use crate::problem::Sample;
use crate::suite::results::StoredScene;
use std::collections::BTreeMap;
use std::path::Path;

/// CONTACT's exact theory.
pub const EXACT: Against = Against::Reference("CONTACT");
/// CONTACT's FASTSIM with the parabolic bound.
pub const FASTSIM: Against = Against::Reference("CONTACT FASTSIM");

/// The columns of cases.csv this reader uses (every one required).
const CASE_COLUMNS: [&str; 9] =
    ["name", "kind", "method", "mx", "n_steps", "contact_wall_s", "loop_area", "pn_max_mpa", "freq_hz"];

/// One row of reference/contact/cases.csv.
#[derive(Debug, Clone, Default)]
pub struct ContactCase {
    pub name: String,
    pub kind: String,
    pub method: String,
    pub mx: usize,
    pub n_steps: usize,
    /// Wall time of the whole CONTACT run [s].
    pub contact_wall_s: f64,
    /// Signed ∮ f dcx over the last full period (negative: f lags cx).
    pub loop_area: Option<f64>,
    pub pn_max_mpa: f64,
    pub freq_hz: Option<f64>,
}

/// Every CONTACT case with its history.
#[derive(Debug, Clone, Default)]
pub struct ContactCases {
    pub cases: BTreeMap<String, ContactCase>,
    /// Histories named "CONTACT", steady sweeps renumbered from 1 like ours.
    pub histories: BTreeMap<String, History>,
}

impl ContactCases {
    /// Load reference/contact/cases.csv and every case's history.
    pub fn load(dir: &Path) -> Result<ContactCases, Error> {
        let path = dir.join("contact/cases.csv");
        let text = read(&path)?;
        let mut rdr = csv::Reader::from_reader(text.as_bytes());
        let bad = |e: csv::Error| Error::Format { path: path.clone(), source: FormatError::Csv { line: 0, source: e } };
        let head: Vec<String> = rdr.headers().map_err(bad)?.iter().map(String::from).collect();
        // Every column read is required (a missing one is an error naming the file and it); a
        // value may be empty only where the case has none (loop area, frequency: not a sine).
        let col = |n: &str| {
            let missing =
                || Error::Format { path: path.clone(), source: FormatError::MissingColumn { column: n.into() } };
            head.iter().position(|h| h == n).ok_or_else(missing)
        };
        let [name, kind, method, mx, n_steps, wall, loop_area, pn_max, freq] = CASE_COLUMNS.map(col);
        let [name, kind, method, mx, n_steps, wall, loop_area, pn_max, freq] =
            [name?, kind?, method?, mx?, n_steps?, wall?, loop_area?, pn_max?, freq?];
        let mut out = ContactCases::default();
        let mut seen = std::collections::BTreeSet::new();
        for (line, rec) in rdr.records().enumerate() {
            let line = line + 2;
            let rec =
                rec.map_err(|e| Error::Format { path: path.clone(), source: FormatError::Csv { line, source: e } })?;
            let get = |i: usize| rec.get(i).unwrap_or("");
            super::first_row(&mut seen, &path, line, get(name))?;
            let not_a_number = |i: usize| {
                let (column, value) = (head[i].clone(), crate::error::excerpt(get(i)));
                Error::Format {
                    path: path.clone(),
                    source: FormatError::Value { line, column, value, what: "a number" },
                }
            };
            let opt = |i: usize| match get(i).trim() {
                "" => Ok(None),
                v => v.parse::<f64>().map(Some).map_err(|_| not_a_number(i)),
            };
            let num = |i: usize| opt(i)?.ok_or_else(|| not_a_number(i));
            let c = ContactCase {
                name: get(name).into(),
                kind: get(kind).into(),
                method: get(method).into(),
                mx: num(mx)? as usize,
                n_steps: num(n_steps)? as usize,
                contact_wall_s: num(wall)?,
                loop_area: opt(loop_area)?,
                pn_max_mpa: num(pn_max)?,
                freq_hz: opt(freq)?,
            };
            let h = read_history(&dir.join(format!("contact/{}.csv", c.name)), usize::from(c.kind == "steady"), &[])?;
            out.histories.insert(c.name.clone(), h);
            out.cases.insert(c.name.clone(), c);
        }
        Ok(out)
    }

    /// CONTACT's history of a scene.
    pub fn history(&self, scene: &str) -> Option<&History> {
        self.histories.get(scene)
    }
}

/// A CONTACT history CSV (the reference READMEs' format) as a [`History`] named "CONTACT": steps
/// shifted by `step_offset` (the thesis sweeps number from 0, ours from 1), `cs`, `mu` and the
/// row's rolling speed `v_mm_s` read where the file has them, and the extra columns `n_adhesion, n_slip` plus `extra`.
pub fn read_history(path: &Path, step_offset: usize, extra: &[&str]) -> Result<History, Error> {
    let text = read(path)?;
    let fail = Error::format(path);
    let mut rdr = csv::Reader::from_reader(text.as_bytes());
    let head: Vec<String> = match rdr.headers() {
        Ok(h) => h.iter().map(String::from).collect(),
        Err(e) => return Err(fail(FormatError::Csv { line: 1, source: e })),
    };
    let find = |n: &str| head.iter().position(|h| h == n);
    let col = |n: &str| find(n).ok_or_else(|| FormatError::MissingColumn { column: n.to_string() });
    let lead = ["step", "t_s", "cx", "cy", "fn_n", "fx_over_fn", "fy_over_fn", "n_adhesion", "n_slip"];
    let cols = lead.iter().chain(extra).map(|n| col(n)).collect::<Result<Vec<usize>, FormatError>>();
    let cols = match cols {
        Ok(c) => c,
        Err(e) => return Err(fail(e)),
    };
    let (cs_col, mu_col, v_col) = (find("cs"), find("mu"), find("v_mm_s"));
    let mut extra_names = vec!["n_adhesion", "n_slip"];
    extra_names.extend_from_slice(extra);
    let mut h = History::new("CONTACT", &extra_names);
    for (line, rec) in rdr.records().enumerate() {
        let line = line + 2;
        let row = rec.map_err(|e| FormatError::Csv { line, source: e }).and_then(|rec| {
            let n = |i: usize| {
                rec[i].parse::<f64>().map_err(|_| FormatError::Value {
                    line,
                    column: head[i].clone(),
                    value: crate::error::excerpt(&rec[i]),
                    what: "a number",
                })
            };
            let opt = |c: Option<usize>, default: f64| c.map_or(Ok(default), n);
            // A step is a whole number >= 0, increasing row by row: whatever a manifest says, a
            // repeated, negative or fractional step is garbage, not a reference.
            let step = n(cols[0])?;
            let previous = h.rows.last().map(|r: &Row| r.sample.step);
            let whole = step >= 0.0 && step.fract() == 0.0 && step < 1e15;
            let step = step as usize + step_offset;
            if !whole || previous.is_some_and(|p| step <= p) {
                return Err(FormatError::Value {
                    line,
                    column: head[cols[0]].clone(),
                    value: crate::error::excerpt(&rec[cols[0]]),
                    what: "a whole step index >= 0, greater than the previous row's",
                });
            }
            let sample = Sample::given(
                step,
                n(cols[1])?,
                n(cols[2])?,
                n(cols[3])?,
                opt(cs_col, 0.0)?,
                n(cols[4])?,
                opt(mu_col, f64::NAN)?,
            );
            Ok(Row {
                sample: Sample { v_mm_s: v_col.map(n).transpose()?, ..sample }.into(),
                fx_over_fn: n(cols[5])?,
                fy_over_fn: n(cols[6])?,
                extra: cols[7..].iter().map(|&c| n(c)).collect::<Result<Vec<f64>, FormatError>>()?,
            })
        });
        match row {
            Ok(r) => h.rows.push(r),
            Err(e) => return Err(Error::Format { path: path.to_path_buf(), source: e }),
        }
    }
    if h.rows.is_empty() {
        let source = FormatError::Value {
            line: 2,
            column: "step".into(),
            value: "no rows".into(),
            what: "at least one history row",
        };
        return Err(Error::Format { path: path.to_path_buf(), source });
    }
    Ok(h)
}

impl ReferenceSet for ContactCases {
    fn label(&self) -> &'static str {
        "CONTACT"
    }

    fn compare(&self, ours: &StoredScene, rules: &[Rule]) -> Vec<Finding> {
        let mut out = Vec::new();
        let (Some(case), Some(contact)) = (self.cases.get(&ours.name), self.histories.get(&ours.name)) else {
            return out;
        };
        let against = if case.method == "fastsim_parabolic" { FASTSIM } else { EXACT };
        let period = ours.scene.period_s();
        let t = contact.column("t_s").unwrap_or_default();
        let f = contact.column("fx_over_fn").unwrap_or_default();
        let contact_delay = period.and_then(|p| delay::of_history(contact, p));
        // Where f reaches μ near the creepage peak the delay is ill-defined (flat top); μ per
        // step from the scene's own loading (a table may vary it).
        // (The loading samples: checked when the folder was read, `suite::results::read_scene`.)
        let rows = ours.scene.loading_rows().unwrap_or_default();
        let mu_at: BTreeMap<usize, f64> = rows.iter().map(|s| (s.step, s.mu)).collect();
        let flat = contact
            .rows
            .iter()
            .filter_map(|r| Some(r.fx_over_fn.abs() / mu_at.get(&r.sample.step)?))
            .fold(0.0, f64::max);
        let saturated = flat >= delay::SATURATION;
        for (solver, h) in &ours.histories {
            let ctx = Ctx { scene: &ours.name, solver, against, rules };
            out.extend(ctx.column(h, contact, "fx_over_fn", false));
            let metric = |name: &str| ours.metric(solver, name);
            if let (Some(ours_d), Some(ref_d)) = (metric(crate::metrics::delay_ratio::NAME), contact_delay) {
                let mut fd = ctx.finding(
                    crate::metrics::delay_ratio::NAME,
                    None,
                    ours_d,
                    ref_d,
                    "CONTACT's delay from its history, same definition",
                );
                if saturated {
                    fd.gated = false;
                    fd.note = format!("f reaches {:.0} % of mu: the maximum is a flat top and the delay ill-defined (reference README); reported only", 100.0 * flat);
                }
                out.push(fd);
            }
            if let (Some(ours_a), Some(ref_a)) = (metric(crate::metrics::loop_area::NAME), case.loop_area) {
                out.push(ctx.finding(
                    crate::metrics::loop_area::NAME,
                    None,
                    ours_a,
                    ref_a.abs(),
                    "cases.csv loop_area (absolute value)",
                ));
            }
            if let (Some(v), Some(rv)) = (metric(crate::metrics::steady_value::NAME), f.last()) {
                if case.kind != "steady" {
                    out.push(ctx.finding(crate::metrics::steady_value::NAME, None, v, *rv, ""));
                }
            }
            if let (Some(v), Some(rv)) = (metric(crate::metrics::settling_time::NAME), metrics::settling_time(&t, &f)) {
                out.push(ctx.finding(crate::metrics::settling_time::NAME, None, v, rv, ""));
            }
        }
        out
    }

    fn history(&self, scene: &str) -> Option<&History> {
        ContactCases::history(self, scene)
    }
}
