//! Reference data from outside the project (reference/README.md): CONTACT's results for the
//! thesis scenes and the thesis's published figures. Read only; never written by the tool.

use crate::error::{Error, InputError};
use crate::history::{History, Row};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Default location of the reference data.
pub const DEFAULT_DIR: &str = "reference";

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

/// Table 4.2 of the thesis (CONTACT, μ = 1, 22×22): delay ratios.
#[derive(Debug, Clone, Copy)]
pub struct ThesisDelay {
    pub freq_hz: f64,
    pub delay_ms: f64,
    pub delay_ratio: f64,
}

/// The reference set: CONTACT cases and histories, thesis figures.
#[derive(Debug, Clone, Default)]
pub struct References {
    pub dir: PathBuf,
    pub cases: BTreeMap<String, ContactCase>,
    pub thesis_delays: Vec<ThesisDelay>,
    /// Thesis scalar figures by key (thesis_figures.csv).
    pub thesis_figures: BTreeMap<String, f64>,
}

fn read(path: &Path) -> Result<String, Error> {
    std::fs::read_to_string(path)
        .map_err(|e| InputError::new("reference", path.display(), format!("an existing reference file ({e})")).into())
}

impl References {
    /// Load reference/contact/cases.csv and the thesis tables.
    pub fn load(dir: &Path) -> Result<References, Error> {
        let mut refs = References { dir: dir.to_path_buf(), ..Default::default() };
        let cases = read(&dir.join("contact/cases.csv"))?;
        let mut rdr = csv::Reader::from_reader(cases.as_bytes());
        let head: Vec<String> =
            rdr.headers().map_err(|e| Error::other(e.to_string()))?.iter().map(String::from).collect();
        let col = |n: &str| head.iter().position(|h| h == n);
        for rec in rdr.records() {
            let rec = rec.map_err(|e| Error::other(format!("cases.csv: {e}")))?;
            let get = |n: &str| col(n).and_then(|i| rec.get(i)).unwrap_or("");
            let num = |n: &str| get(n).parse::<f64>().ok();
            let c = ContactCase {
                name: get("name").into(),
                kind: get("kind").into(),
                method: get("method").into(),
                mx: num("mx").unwrap_or(0.0) as usize,
                n_steps: num("n_steps").unwrap_or(0.0) as usize,
                contact_wall_s: num("contact_wall_s").unwrap_or(f64::NAN),
                loop_area: num("loop_area"),
                pn_max_mpa: num("pn_max_mpa").unwrap_or(f64::NAN),
                freq_hz: num("freq_hz"),
            };
            refs.cases.insert(c.name.clone(), c);
        }
        let t42 = read(&dir.join("thesis/table_4_2_delay.csv"))?;
        for line in t42.lines().skip(1).filter(|l| !l.trim().is_empty()) {
            let v: Vec<f64> = line.split(',').filter_map(|x| x.trim().parse().ok()).collect();
            if v.len() >= 4 {
                refs.thesis_delays.push(ThesisDelay { freq_hz: v[0], delay_ms: v[2], delay_ratio: v[3] });
            }
        }
        let figs = read(&dir.join("thesis/thesis_figures.csv"))?;
        for line in figs.lines().skip(1).filter(|l| !l.trim().is_empty()) {
            let parts: Vec<&str> = line.splitn(3, ',').collect();
            if let (Some(k), Some(v)) = (parts.first(), parts.get(1).and_then(|v| v.trim().parse().ok())) {
                refs.thesis_figures.insert(k.trim().to_string(), v);
            }
        }
        Ok(refs)
    }

    /// CONTACT's history for a case, as a [`History`] named "CONTACT" (steady sweeps renumbered
    /// from 1 like ours). `None` when there is no reference for that scene.
    pub fn contact_history(&self, case: &str) -> Result<Option<History>, Error> {
        let Some(c) = self.cases.get(case) else { return Ok(None) };
        let text = read(&self.dir.join(format!("contact/{case}.csv")))?;
        let mut rdr = csv::Reader::from_reader(text.as_bytes());
        let head: Vec<String> =
            rdr.headers().map_err(|e| Error::other(e.to_string()))?.iter().map(String::from).collect();
        let col =
            |n: &str| head.iter().position(|h| h == n).ok_or_else(|| Error::other(format!("{case}.csv lacks {n}")));
        let (cs, ct, cx, cy, fnn, fx, fy) =
            (col("step")?, col("t_s")?, col("cx")?, col("cy")?, col("fn_n")?, col("fx_over_fn")?, col("fy_over_fn")?);
        let mut h = History::new("CONTACT", &["n_adhesion", "n_slip"]);
        let (na, ns) = (col("n_adhesion")?, col("n_slip")?);
        for rec in rdr.records() {
            let rec = rec.map_err(|e| Error::other(format!("{case}.csv: {e}")))?;
            let n = |i: usize| {
                rec[i].parse::<f64>().map_err(|_| Error::other(format!("{case}.csv: bad number {:?}", &rec[i])))
            };
            let step = n(cs)? as usize + usize::from(c.kind == "steady");
            h.rows.push(Row {
                step,
                t_s: n(ct)?,
                cx: n(cx)?,
                cy: n(cy)?,
                cs: 0.0,
                fn_n: n(fnn)?,
                fx_over_fn: n(fx)?,
                fy_over_fn: n(fy)?,
                extra: vec![n(na)?, n(ns)?],
            });
        }
        Ok(Some(h))
    }
}
