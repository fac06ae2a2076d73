//! The `table` creepage kind: a CSV `t_s,cx[,cy,cs,fn_n,mu,v_mm_s]` read and validated row by row
//! (`fx_over_fn`, `fy_over_fn` in place of `cx`, `cy`: the total forces prescribed, CONTACT's F = 1, 2;
//! `pen_mm` in place of `fn_n`: the approach prescribed, CONTACT's N = 0).

use crate::error::InputError;
use std::path::Path;

/// Columns a creepage table may have; `t_s` and one of `cx`, `fx_over_fn` are required.
pub const COLUMNS: [&str; 18] = [
    "t_s",
    "courant",
    "cx",
    "cy",
    "cs",
    "fn_n",
    "mu",
    "v_mm_s",
    "fx_over_fn",
    "fy_over_fn",
    "pen_mm",
    "b1_per_mm",
    "b2_per_mm",
    "b3_per_mm",
    "b4",
    "b5",
    "b6_mm",
    "chi_deg",
];

/// The columns of a row's undeformed distance, CONTACT's IBASE = 1 B(1..6): all or none.
pub const H_COLUMNS: [&str; 6] = ["b1_per_mm", "b2_per_mm", "b3_per_mm", "b4", "b5", "b6_mm"];

/// The largest approach a table may prescribe [mm]: beyond any elastic contact of rail steel.
pub const PEN_MAX_MM: f64 = 10.0;

/// The table's longitudinal column: the creepage given, or the force prescribed, or per row one
/// of them (both columns, each row's other cell empty: CONTACT's F changing within a history).
#[derive(Debug, Clone, PartialEq)]
pub enum TableX {
    /// `cx`.
    Creepage(Vec<f64>),
    /// `fx_over_fn`.
    Force(Vec<f64>),
    /// `cx` and `fx_over_fn`, NaN where a row leaves the cell empty.
    PerRow { cx: Vec<f64>, fx_over_fn: Vec<f64> },
}

impl TableX {
    /// The column's values, whichever it is (per row: the creepage column, NaN where a force is
    /// prescribed).
    pub fn values(&self) -> &[f64] {
        match self {
            TableX::Creepage(v) | TableX::Force(v) | TableX::PerRow { cx: v, .. } => v,
        }
    }
}

/// Pairs of columns a row may choose between (both in the header: each row gives exactly one,
/// the other cell empty).
const PER_ROW: [(&str, &str, &str); 3] = [
    ("fn_n", "pen_mm", "fn_n (the normal force prescribed) and pen_mm (the approach prescribed)"),
    ("cx", "fx_over_fn", "cx (the creepage given) and fx_over_fn (the force prescribed)"),
    ("cy", "fy_over_fn", "cy (the creepage given) and fy_over_fn (the force prescribed)"),
];

/// The Courant number of a table row (as `[rolling] courant`).
const COURANT_LIMIT: super::reader::Range = super::reader::Range::new(0.0, false, 100.0, true);

/// Which of two per-row columns a row gives ([`CreepageTable::either_at`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Either {
    First(f64),
    Second(f64),
}

/// A validated table: strictly increasing times, finite values in range. In scene.json by its
/// rows ([`TableRows`]), read back through the same checks as its file.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(try_from = "TableRows", into = "TableRows")]
pub struct CreepageTable {
    pub t_s: Vec<f64>,
    /// One optional series per column after `t_s`: cx, or the prescribed Fx/FN in its place
    /// ([`TableX`]).
    pub cx: TableX,
    pub cy: Option<Vec<f64>>,
    /// The prescribed Fy/FN in place of `cy` (not both).
    pub fy_over_fn: Option<Vec<f64>>,
    pub cs: Option<Vec<f64>>,
    pub fn_n: Option<Vec<f64>>,
    /// The approach [mm] prescribed in place of FN (CONTACT N = 0, PEN): FN is then an outcome.
    /// With both columns each row gives one of `fn_n`, `pen_mm` (the other NaN): [`Self::normal_at`].
    pub pen_mm: Option<Vec<f64>>,
    /// The undeformed distance per row, `h = b1 x² + b2 xy + b3 y² + b4 x + b5 y + b6` in
    /// CONTACT's coordinates (its IBASE = 1 B(1..6), one case per row), columns [`H_COLUMNS`].
    pub h_coefficients: Option<[Vec<f64>; 6]>,
    pub mu: Option<Vec<f64>>,
    /// The rolling speed [mm/s]: step k lasts dq/v_k.
    pub v_mm_s: Option<Vec<f64>>,
    /// The Courant number per row: step k rolls dq_k = courant_k dx and lasts dq_k/v_k
    /// (CONTACT's DQ changing within a history).
    pub courant: Option<Vec<f64>>,
    /// The rolling direction CHI [deg] per row (CONTACT's CHI read anew in a case of a history):
    /// held, not interpolated ([`Self::held`]).
    pub chi_deg: Option<Vec<f64>>,
}

impl CreepageTable {
    /// Read `path`; errors name `field` (the scene key), the row and column.
    pub fn from_file(path: &Path, field: &str) -> Result<Self, InputError> {
        let text = crate::safety::read::read_text(path, crate::safety::read::TABLE_LIMIT_BYTES, "creepage table")
            .map_err(|e| InputError::new(field, path.display(), format!("an existing, readable CSV file ({e})")))?;
        Self::from_csv(&text, &format!("{field} ({})", path.display()))
    }

    /// Parse CSV text: the header's columns checked, then every row, then the times.
    pub fn from_csv(text: &str, origin: &str) -> Result<Self, InputError> {
        let mut rdr = csv::ReaderBuilder::new().trim(csv::Trim::All).from_reader(text.as_bytes());
        let header = read_header(&mut rdr, origin)?;
        check_columns(&header, origin)?;
        check_required(&header, origin)?;
        let h_given = h_columns_given(&header, origin)?;
        let (cols, lines) = read_rows(&mut rdr, text, &header, origin)?;
        let table = Self::from_columns(&header, &cols, h_given);
        check_times(&table.t_s, &lines, origin)?;
        Ok(table)
    }

    /// The table of the checked columns `cols` (`cols[i]` the values of `header[i]`); `h_given`:
    /// the header has the [`H_COLUMNS`].
    fn from_columns(header: &[String], cols: &[Vec<f64>], h_given: bool) -> Self {
        let col = |name: &str| header.iter().position(|h| h == name).map(|i| cols[i].clone());
        CreepageTable {
            cx: match (col("cx"), col("fx_over_fn")) {
                (Some(cx), Some(fx_over_fn)) => TableX::PerRow { cx, fx_over_fn },
                (None, Some(f)) => TableX::Force(f),
                (cx, None) => TableX::Creepage(cx.unwrap_or_default()),
            },
            cy: col("cy"),
            fy_over_fn: col("fy_over_fn"),
            cs: col("cs"),
            fn_n: col("fn_n"),
            pen_mm: col("pen_mm"),
            h_coefficients: h_given.then(|| H_COLUMNS.map(|c| col(c).unwrap_or_default())),
            mu: col("mu"),
            v_mm_s: col("v_mm_s"),
            courant: col("courant"),
            chi_deg: col("chi_deg"),
            t_s: col("t_s").unwrap_or_default(),
        }
    }

    /// Linear interpolation of `series` at time `t`, held at the first row before it and at the
    /// last row beyond it (a step just past a rounded last time takes the last row's values).
    pub fn interpolate(&self, series: &[f64], t: f64) -> f64 {
        let ts = &self.t_s;
        if t <= ts[0] {
            return series[0];
        }
        let k = ts.partition_point(|&x| x <= t);
        if k >= ts.len() {
            return series[ts.len() - 1];
        }
        let (t0, t1) = (ts[k - 1], ts[k]);
        series[k - 1] + (series[k] - series[k - 1]) * (t - t0) / (t1 - t0)
    }

    /// The normal input at time `t`: (FN, the approach if prescribed); `fn_default` where the
    /// table has no `fn_n`. Between two rows of one kind interpolated; between a row with FN and
    /// one with the approach, the row at `t` (exactly) or else the later row's.
    pub fn normal_at(&self, t: f64, fn_default: f64) -> (f64, Option<f64>) {
        match (&self.fn_n, &self.pen_mm) {
            (None, None) => (fn_default, None),
            (Some(f), None) => (self.interpolate(f, t), None),
            (None, Some(p)) => (fn_default, Some(self.interpolate(p, t))),
            (Some(f), Some(p)) => match self.either_at(f, p, t) {
                Either::First(f) => (f, None),
                Either::Second(p) => (fn_default, Some(p)),
            },
        }
    }

    /// One of two per-row columns `a`, `b` (NaN where a row leaves its cell empty) at time `t`:
    /// between two rows of one kind interpolated; between a row of each kind, the row at `t`
    /// (exactly) or else the later row's.
    pub fn either_at(&self, a: &[f64], b: &[f64], t: f64) -> Either {
        let ts = &self.t_s;
        let k = ts.partition_point(|&x| x <= t).min(ts.len() - 1);
        let (lo, hi) = (k.saturating_sub(1), k);
        if b[lo].is_nan() == b[hi].is_nan() {
            return if b[hi].is_nan() {
                Either::First(self.interpolate(a, t))
            } else {
                Either::Second(self.interpolate(b, t))
            };
        }
        let row = if ts[lo] == t { lo } else { hi };
        if b[row].is_nan() {
            Either::First(a[row])
        } else {
            Either::Second(b[row])
        }
    }

    /// The value of `series` at time `t` held from row to row: the row at `t` (exactly), else the
    /// later row (the first before the first row, the last beyond the last), as one CONTACT case
    /// per row gives it.
    pub fn held(&self, series: &[f64], t: f64) -> f64 {
        let ts = &self.t_s;
        let k = ts.partition_point(|&x| x <= t).min(ts.len() - 1);
        let lo = k.saturating_sub(1);
        series[if ts[lo] == t { lo } else { k }]
    }

    /// Last time in the table [s].
    pub fn end_s(&self) -> f64 {
        *self.t_s.last().unwrap_or(&0.0)
    }

    /// The table's columns as its file had them, in [`COLUMNS`]' order (NaN: an empty cell).
    pub fn columns(&self) -> Vec<(&'static str, &[f64])> {
        let (cx, fx) = match &self.cx {
            TableX::Creepage(cx) => (Some(cx), None),
            TableX::Force(fx) => (None, Some(fx)),
            TableX::PerRow { cx, fx_over_fn } => (Some(cx), Some(fx_over_fn)),
        };
        let h = |i: usize| self.h_coefficients.as_ref().map(|b| &b[i]);
        let given = [
            Some(&self.t_s),
            self.courant.as_ref(),
            cx,
            self.cy.as_ref(),
            self.cs.as_ref(),
            self.fn_n.as_ref(),
            self.mu.as_ref(),
            self.v_mm_s.as_ref(),
            fx,
            self.fy_over_fn.as_ref(),
            self.pen_mm.as_ref(),
            h(0),
            h(1),
            h(2),
            h(3),
            h(4),
            h(5),
            self.chi_deg.as_ref(),
        ];
        COLUMNS.iter().zip(given).filter_map(|(&name, v)| Some((name, v?.as_slice()))).collect()
    }
}

/// A creepage table in scene.json: its header's columns and its rows, `null` for an empty cell.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TableRows {
    pub columns: Vec<String>,
    pub rows: Vec<Vec<Option<f64>>>,
}

impl From<CreepageTable> for TableRows {
    fn from(t: CreepageTable) -> Self {
        let cols = t.columns();
        let cell = |v: f64| (!v.is_nan()).then_some(v);
        TableRows {
            columns: cols.iter().map(|(name, _)| name.to_string()).collect(),
            rows: (0..t.t_s.len()).map(|i| cols.iter().map(|(_, v)| cell(v[i])).collect()).collect(),
        }
    }
}

impl TryFrom<TableRows> for CreepageTable {
    type Error = InputError;

    /// The rows as the CSV they came from (each number in its shortest form, which reads back
    /// to the same value), read with every check of a table file.
    fn try_from(t: TableRows) -> Result<Self, InputError> {
        let mut text = t.columns.join(",");
        for row in &t.rows {
            text.push('\n');
            let cells: Vec<String> = row.iter().map(|c| c.map(|v| v.to_string()).unwrap_or_default()).collect();
            text.push_str(&cells.join(","));
        }
        text.push('\n');
        CreepageTable::from_csv(&text, "scene.json loading.creepage.table")
    }
}

/// The header line's column names.
fn read_header(rdr: &mut csv::Reader<&[u8]>, origin: &str) -> Result<Vec<String>, InputError> {
    Ok(rdr
        .headers()
        .map_err(|e| InputError::new(origin, "unreadable header", format!("a CSV header line ({e})")))?
        .iter()
        .map(str::to_string)
        .collect())
}

/// Whether the header has column `c`.
fn has(header: &[String], c: &str) -> bool {
    header.iter().any(|h| h == c)
}

/// Every header column one of [`COLUMNS`], none twice.
fn check_columns(header: &[String], origin: &str) -> Result<(), InputError> {
    for (n, h) in header.iter().enumerate() {
        if !COLUMNS.contains(&h.as_str()) || header[..n].contains(h) {
            return Err(InputError::new(
                format!("{origin} header column {}", n + 1),
                crate::error::name_excerpt(h),
                format!("distinct columns from {}", COLUMNS.join(", ")),
            ));
        }
    }
    Ok(())
}

/// The required columns in the header: `t_s`, and `cx` or `fx_over_fn`.
fn check_required(header: &[String], origin: &str) -> Result<(), InputError> {
    for (req, or) in [("t_s", "t_s"), ("cx", "fx_over_fn")] {
        if !has(header, req) && !has(header, or) {
            let what = if req == or { req.to_string() } else { format!("{req} or {or}") };
            return Err(InputError::new(
                format!("{origin} header"),
                format!("{} columns", header.len()),
                format!("must include column {what}"),
            ));
        }
    }
    Ok(())
}

/// Whether the header has the undeformed distance's columns [`H_COLUMNS`]: all six or none.
fn h_columns_given(header: &[String], origin: &str) -> Result<bool, InputError> {
    let h_given = H_COLUMNS.iter().filter(|c| has(header, c)).count();
    if h_given != 0 && h_given != H_COLUMNS.len() {
        return Err(InputError::new(
            format!("{origin} header"),
            format!("{h_given} of the columns {}", H_COLUMNS.join(", ")),
            "all six (the row's undeformed distance b1 x² + b2 xy + b3 y² + b4 x + b5 y + b6) or none",
        ));
    }
    Ok(h_given > 0)
}

/// The data rows' values, one series per header column: each row of the header's fields, one
/// of each per-row pair given ([`PER_ROW`]), every cell a number in its column's range; and the
/// line of the file each row is on (for messages).
fn read_rows(
    rdr: &mut csv::Reader<&[u8]>,
    text: &str,
    header: &[String],
    origin: &str,
) -> Result<(Vec<Vec<f64>>, Vec<usize>), InputError> {
    // Both fn_n and pen_mm (cx and fx_over_fn, cy and fy_over_fn): each row gives exactly one
    // of them, the other cell empty.
    let pairs: Vec<(&str, &str, &str)> =
        PER_ROW.iter().copied().filter(|(a, b, _)| has(header, a) && has(header, b)).collect();
    let per_row = |name: &str| pairs.iter().any(|(a, b, _)| *a == name || *b == name);
    let mut cols: Vec<Vec<f64>> = vec![Vec::new(); header.len()];
    let mut lines = Vec::new();
    for (r, rec) in rdr.records().enumerate() {
        let row = line_of(text, &rec).unwrap_or(r + 2);
        let rec = check_record(rec, header.len(), origin, row)?;
        check_pairs(&rec, header, &pairs, origin, row)?;
        for (c, cell) in rec.iter().enumerate() {
            cols[c].push(read_cell(cell, &header[c], per_row(&header[c]), origin, row)?);
        }
        lines.push(row);
    }
    Ok((cols, lines))
}

/// The 1-based line of `text` (the CSV read) a record starts on: the reader skips empty lines, so
/// a record's index is not its line, and the position it gives a record after empty lines is that
/// of the first of them (csv 1.4: its line and byte): the empty lines from there are counted too.
pub(super) fn line_of<R: Positioned>(text: &str, rec: &csv::Result<R>) -> Option<usize> {
    let position = match rec {
        Ok(rec) => rec.at(),
        Err(e) => e.position(),
    }?;
    line_at(text, position)
}

/// The 1-based line of `text` a record at `position` starts on ([`line_of`]).
pub(super) fn line_at(text: &str, position: &csv::Position) -> Option<usize> {
    let rest = text.as_bytes().get(usize::try_from(position.byte()).ok()?..)?;
    let empty_lines = rest.iter().take_while(|b| matches!(b, b'\r' | b'\n')).filter(|&&b| b == b'\n').count();
    Some(position.line() as usize + empty_lines)
}

/// A CSV record's position (string or byte record).
pub(super) trait Positioned {
    /// Where the record starts.
    fn at(&self) -> Option<&csv::Position>;
}

impl Positioned for csv::StringRecord {
    fn at(&self) -> Option<&csv::Position> {
        self.position()
    }
}

impl Positioned for csv::ByteRecord {
    fn at(&self) -> Option<&csv::Position> {
        self.position()
    }
}

/// The record of line `row`: readable CSV of `fields` fields (the header's).
fn check_record(
    rec: csv::Result<csv::StringRecord>,
    fields: usize,
    origin: &str,
    row: usize,
) -> Result<csv::StringRecord, InputError> {
    let rec = rec.map_err(|e| {
        InputError::new(format!("{origin} line {row}"), "malformed", format!("a CSV row of {fields} numbers ({e})"))
    })?;
    if rec.len() != fields {
        return Err(InputError::new(format!("{origin} line {row}"), rec.len(), format!("{fields} fields")));
    }
    Ok(rec)
}

/// Line `row` gives exactly one cell of each per-row pair of the header (`pairs`), the other empty.
fn check_pairs(
    rec: &csv::StringRecord,
    header: &[String],
    pairs: &[(&str, &str, &str)],
    origin: &str,
    row: usize,
) -> Result<(), InputError> {
    let empty = |c: &str| header.iter().position(|h| h == c).is_some_and(|i| rec[i].is_empty());
    for (a, b, what) in pairs {
        if empty(a) == empty(b) {
            return Err(InputError::new(
                format!("{origin} line {row} columns {a}, {b}"),
                if empty(a) { "both empty" } else { "both given" },
                format!("exactly one of {what} per row, the other cell empty"),
            ));
        }
    }
    Ok(())
}

/// The cell of column `name` on line `row`: NaN where it is empty in a per-row column, else a
/// number in the column's range ([`in_range`]).
fn read_cell(cell: &str, name: &str, per_row: bool, origin: &str, row: usize) -> Result<f64, InputError> {
    if cell.is_empty() && per_row {
        return Ok(f64::NAN);
    }
    let v: f64 = cell
        .parse()
        .map_err(|_| InputError::new(format!("{origin} line {row} column {name}"), format!("{cell:?}"), "a number"))?;
    if !in_range(name, v) {
        return Err(InputError::new(format!("{origin} line {row} column {name}"), v, allowed(name)));
    }
    Ok(v)
}

/// Whether `v` is in the range of column `name` (as [`allowed`] says it).
fn in_range(name: &str, v: f64) -> bool {
    match name {
        "t_s" => v.is_finite() && v >= 0.0,
        "cx" | "cy" => v.is_finite() && v.abs() <= 1.0,
        "fx_over_fn" | "fy_over_fn" => v.is_finite() && v.abs() < 1.0,
        "cs" => v.is_finite() && v.abs() <= 10.0,
        "v_mm_s" => super::SPEED_LIMIT.contains(v),
        "mu" => super::MU_LIMIT.contains(v),
        "courant" => COURANT_LIMIT.contains(v),
        "pen_mm" => (0.0..=PEN_MAX_MM).contains(&v),
        "chi_deg" => (0.0..360.0).contains(&v),
        c if H_COLUMNS.contains(&c) => v.is_finite(),
        _ => v.is_finite() && v > 0.0, // fn_n
    }
}

/// What column `name` allows, as an error says it ([`in_range`]).
fn allowed(name: &str) -> &'static str {
    match name {
        "t_s" => "a finite time >= 0",
        "cx" | "cy" => "a finite creepage in [-1, 1]",
        "fx_over_fn" | "fy_over_fn" => "a finite force ratio in (-1, 1) (below the row's mu)",
        "cs" => "a finite spin in [-10, 10] 1/mm",
        "v_mm_s" => "a rolling speed in (0, 1e6] mm/s",
        "mu" => "a coefficient of friction in (0, 1000] (as [contact] mu)",
        "courant" => "a Courant number in (0, 100] (the step's rolling distance dq = courant dx)",
        "pen_mm" => {
            "a finite approach in [0, 10] mm (0: where the undeformed distance given per element is negative somewhere)"
        }
        "chi_deg" => "a rolling direction in [0, 360) degrees",
        c if H_COLUMNS.contains(&c) => "a finite coefficient",
        _ => "a finite number > 0",
    }
}

/// The times `t_s`: at least one row, strictly increasing; `lines`: each row's line of the file.
fn check_times(t_s: &[f64], lines: &[usize], origin: &str) -> Result<(), InputError> {
    if t_s.is_empty() {
        return Err(InputError::new(origin, "no data rows", "at least one row"));
    }
    for w in 1..t_s.len() {
        if t_s[w] <= t_s[w - 1] {
            return Err(InputError::new(
                format!("{origin} line {} column t_s", lines[w]),
                t_s[w],
                format!("strictly increasing times (previous {})", t_s[w - 1]),
            ));
        }
    }
    Ok(())
}
