//! Step 4 of the pipeline: a solver's output, one row per time step (or sweep point), in the
//! `<solver>.csv` format of interface.md.

use crate::problem::Sample;

/// The fixed leading columns of `<solver>.csv` (interface.md); extra columns follow.
pub const COLUMNS: [&str; 8] = ["step", "t_s", "cx", "cy", "cs", "fn_n", "fx_over_fn", "fy_over_fn"];

/// One row: the loading and the traction coefficients, plus solver-specific extra values.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    pub step: usize,
    pub t_s: f64,
    pub cx: f64,
    pub cy: f64,
    pub cs: f64,
    pub fn_n: f64,
    /// Tx / FN (thesis Eq. 2.30–2.31, 3.12), positive for positive cx.
    pub fx_over_fn: f64,
    pub fy_over_fn: f64,
    /// Values of the history's extra columns, in order.
    pub extra: Vec<f64>,
}

impl Row {
    /// A row for `sample` with traction coefficients (fx, fy) and extra values.
    pub fn new(sample: &Sample, fx_over_fn: f64, fy_over_fn: f64, extra: Vec<f64>) -> Self {
        Row {
            step: sample.step,
            t_s: sample.t_s,
            cx: sample.cx,
            cy: sample.cy,
            cs: sample.cs,
            fn_n: sample.fn_n,
            fx_over_fn,
            fy_over_fn,
            extra,
        }
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
                "step" => r.step as f64,
                "t_s" => r.t_s,
                "cx" => r.cx,
                "cy" => r.cy,
                "cs" => r.cs,
                "fn_n" => r.fn_n,
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
        let mut out = COLUMNS.join(",");
        for c in &self.extra_columns {
            out.push(',');
            out.push_str(c);
        }
        out.push('\n');
        for r in &self.rows {
            out.push_str(&format!(
                "{},{},{},{},{},{},{},{}",
                r.step, r.t_s, r.cx, r.cy, r.cs, r.fn_n, r.fx_over_fn, r.fy_over_fn
            ));
            for v in &r.extra {
                out.push(',');
                out.push_str(&format!("{v}"));
            }
            out.push('\n');
        }
        out
    }

    /// Parse a history CSV (ours, a golden file, or an external model's output).
    pub fn from_csv(solver: &str, text: &str) -> Result<History, String> {
        let mut rdr = csv::ReaderBuilder::new().trim(csv::Trim::All).from_reader(text.as_bytes());
        let header: Vec<String> =
            rdr.headers().map_err(|e| format!("header: {e}"))?.iter().map(str::to_string).collect();
        if header.len() < COLUMNS.len() || header[..COLUMNS.len()] != COLUMNS {
            return Err(format!("header must start with {} (got {})", COLUMNS.join(","), header.join(",")));
        }
        let mut h =
            History { solver: solver.into(), extra_columns: header[COLUMNS.len()..].to_vec(), rows: Vec::new() };
        for (n, rec) in rdr.records().enumerate() {
            let line = n + 2;
            let rec = rec.map_err(|e| format!("line {line}: {e}"))?;
            if rec.len() != header.len() {
                return Err(format!("line {line}: {} fields, header has {}", rec.len(), header.len()));
            }
            let num = |c: usize| -> Result<f64, String> {
                let v: f64 = rec[c]
                    .parse()
                    .map_err(|_| format!("line {line} column {}: {:?} is not a number", header[c], &rec[c]))?;
                Ok(v)
            };
            let step = rec[0]
                .parse::<usize>()
                .map_err(|_| format!("line {line} column step: {:?} is not a step index", &rec[0]))?;
            let extra = (COLUMNS.len()..header.len()).map(num).collect::<Result<Vec<_>, _>>()?;
            h.rows.push(Row {
                step,
                t_s: num(1)?,
                cx: num(2)?,
                cy: num(3)?,
                cs: num(4)?,
                fn_n: num(5)?,
                fx_over_fn: num(6)?,
                fy_over_fn: num(7)?,
                extra,
            });
        }
        Ok(h)
    }
}
