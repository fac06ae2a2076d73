//! Step 4 of the pipeline: a solver's output, one row per time step (or sweep point), in the
//! `<solver>.csv` format of docs/scene-format.md; made by the [`sample_loop`] from a built-in model's
//! steps, or read from an [`external`] model's output.

pub mod abscissa;
pub mod external;
pub mod sample_loop;
pub mod stress;

use crate::error::{excerpt, FormatError};
use crate::problem::Sample;

/// The fixed leading columns of `<solver>.csv` (docs/scene-format.md); extra columns follow.
pub const COLUMNS: [&str; 8] = ["step", "t_s", "cx", "cy", "cs", "fn_n", "fx_over_fn", "fy_over_fn"];

/// The friction coefficient of the row: written by creepbench right after [`COLUMNS`]
/// (optional in an external model's output, which gets the scene's).
pub const MU: &str = "mu";

/// The column of each solve's termination code, written after the extra columns of a model whose
/// solves iterate ([`crate::solvers::Termination::code`]).
pub const TERMINATION: &str = "termination";

/// The spin-moment column [N·mm] every built-in model writes last (optional for external
/// models): the references' sign convention, [`crate::physics::moment`].
pub const MZ: &str = "mz_nmm";

/// The loading a history row keeps: the CSV's columns and the row's speed, a [`Sample`] without
/// what only the models read (prescribed forces and approach, undeformed distance, CHI, Courant
/// number), so that a long history holds 72 bytes a row for its loading rather than 208.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RowSample {
    pub step: usize,
    pub t_s: f64,
    pub cx: f64,
    pub cy: f64,
    /// Spin creepage [1/mm].
    pub cs: f64,
    pub fn_n: f64,
    pub mu: f64,
    /// The rolling speed [mm/s] where it differs per row; `None`: `[rolling] v_mm_s`.
    pub v_mm_s: Option<f64>,
}

impl RowSample {
    /// The rolling speed of this row [mm/s]: its own, else `rolling`'s.
    pub fn speed_mm_s(&self, rolling_v_mm_s: f64) -> f64 {
        self.v_mm_s.unwrap_or(rolling_v_mm_s)
    }
}

impl From<&Sample> for RowSample {
    fn from(s: &Sample) -> Self {
        let Sample { step, t_s, cx, cy, cs, fn_n, mu, v_mm_s, .. } = *s;
        RowSample { step, t_s, cx, cy, cs, fn_n, mu, v_mm_s }
    }
}

impl From<Sample> for RowSample {
    fn from(s: Sample) -> Self {
        RowSample::from(&s)
    }
}

/// One row: the loading and the traction coefficients, plus solver-specific extra values.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The loading of this row (step, time, creepages, load, friction); `mu` is NaN where a
    /// source does not give it.
    pub sample: RowSample,
    /// Tx / FN (thesis Eq. 2.30–2.31, 3.12), positive for positive cx.
    pub fx_over_fn: f64,
    pub fy_over_fn: f64,
    /// Values of the history's extra columns, in order.
    pub extra: Vec<f64>,
}

impl Row {
    /// A row for `sample` with traction coefficients (fx, fy) and extra values.
    pub fn new(sample: &Sample, fx_over_fn: f64, fy_over_fn: f64, extra: Vec<f64>) -> Self {
        Row { sample: sample.into(), fx_over_fn, fy_over_fn, extra }
    }
}

/// A solver's history.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct History {
    pub solver: String,
    /// Names of the extra columns after [`COLUMNS`].
    pub extra_columns: Vec<String>,
    pub rows: Vec<Row>,
}

impl History {
    pub fn new(solver: &str, extra_columns: &[&str]) -> Self {
        History {
            solver: solver.into(),
            extra_columns: extra_columns.iter().map(|s| s.to_string()).collect(),
            rows: Vec::new(),
        }
    }

    /// Time series of one column, by name (leading or extra).
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let lead = |r: &Row| -> Option<f64> {
            Some(match name {
                "step" => r.sample.step as f64,
                "t_s" => r.sample.t_s,
                "cx" => r.sample.cx,
                "cy" => r.sample.cy,
                "cs" => r.sample.cs,
                "fn_n" => r.sample.fn_n,
                "mu" => r.sample.mu,
                "fx_over_fn" => r.fx_over_fn,
                "fy_over_fn" => r.fy_over_fn,
                _ => return None,
            })
        };
        if let Some(k) = self.extra_columns.iter().position(|c| c == name) {
            return Some(self.rows.iter().map(|r| r.extra[k]).collect());
        }
        self.rows.iter().map(lead).collect()
    }

    /// CSV text: header, then one line per row. Numbers use Rust's shortest round-trip form,
    /// so the text is bit-identical for bit-identical results.
    pub fn to_csv(&self) -> String {
        let mut out = Vec::new();
        self.write_csv(&mut out).expect("writing into memory does not fail");
        String::from_utf8(out).expect("the CSV is ASCII")
    }

    /// The CSV text of [`History::to_csv`], written row by row into `out`.
    pub fn write_csv(&self, out: &mut dyn std::io::Write) -> std::io::Result<()> {
        write!(out, "{},{MU}", COLUMNS.join(","))?;
        for c in &self.extra_columns {
            write!(out, ",{c}")?;
        }
        out.write_all(b"\n")?;
        for r in &self.rows {
            let s = &r.sample;
            write!(
                out,
                "{},{},{},{},{},{},{},{},{}",
                s.step, s.t_s, s.cx, s.cy, s.cs, s.fn_n, r.fx_over_fn, r.fy_over_fn, s.mu
            )?;
            for v in &r.extra {
                write!(out, ",{v}")?;
            }
            out.write_all(b"\n")?;
        }
        Ok(())
    }

    /// Parse a history CSV (ours, a golden file, or an external model's output).
    pub fn from_csv(solver: &str, text: &str) -> Result<History, FormatError> {
        let mut rdr = csv::ReaderBuilder::new().trim(csv::Trim::All).from_reader(text.as_bytes());
        let header: Vec<String> =
            rdr.headers().map_err(|e| FormatError::Csv { line: 1, source: e })?.iter().map(str::to_string).collect();
        if header.len() < COLUMNS.len() || header[..COLUMNS.len()] != COLUMNS {
            let got = header.iter().map(|h| crate::error::name_excerpt(h)).collect::<Vec<_>>().join(", ");
            return Err(FormatError::Header { expected: COLUMNS.join(","), got: excerpt(&got) });
        }
        let has_mu = header.get(COLUMNS.len()).is_some_and(|c| c == MU);
        let first_extra = COLUMNS.len() + usize::from(has_mu);
        let mut h = History { solver: solver.into(), extra_columns: header[first_extra..].to_vec(), rows: Vec::new() };
        for (n, rec) in rdr.records().enumerate() {
            let line = n + 2;
            let rec = rec.map_err(|e| FormatError::Csv { line, source: e })?;
            if rec.len() != header.len() {
                return Err(FormatError::FieldCount { line, fields: rec.len(), expected: header.len() });
            }
            let bad =
                |c: usize, what| FormatError::Value { line, column: header[c].clone(), value: excerpt(&rec[c]), what };
            let num = |c: usize| rec[c].parse::<f64>().map_err(|_| bad(c, "a number"));
            let step = rec[0].parse::<usize>().map_err(|_| bad(0, "a step index"))?;
            let extra = (first_extra..header.len()).map(num).collect::<Result<Vec<_>, _>>()?;
            h.rows.push(Row {
                sample: Sample::given(
                    step,
                    num(1)?,
                    num(2)?,
                    num(3)?,
                    num(4)?,
                    num(5)?,
                    if has_mu { num(COLUMNS.len())? } else { f64::NAN },
                )
                .into(),
                fx_over_fn: num(6)?,
                fy_over_fn: num(7)?,
                extra,
            });
        }
        Ok(h)
    }
}
