//! The loading of a history's scene: `[creepage]` of a steady sweep (over the creepages or the
//! speed), or the table of a transient history (`<name>_table.csv`, rolling or shifts, at the
//! times `k DQ / VELOC`) with its `[init]`.

use super::history::{Run, Start};
use super::read_back::{probe, read_back, tempdir_for};
use super::rows::{chi_deg, courant_for, prescribed, speeds, step_lengths, sweep_axes, sweep_of, Sweep};
use super::{case3, floats, table, Draft, Source};
use crate::error::InputError;
use std::fmt::Write;
use toml::Value;

/// `[creepage]` of a sweep: over the speed where VELOC changes (the creepages held), else over
/// the creepages ([`sweep_of`]).
pub(super) fn sweep(src: &Source, draft: &mut Draft) {
    let (axis, forced) = sweep_axes(src.first);
    let mut cr = vec![("kind", Value::String("sweep".into()))];
    match speeds(src.cases, src.h) {
        Some(at) => {
            cr.extend([("over", Value::String("v_mm_s".into())), ("at", floats(&at))]);
            for (j, key) in axis.iter().enumerate() {
                if src.rows[0][j].to_bits() != 0 || forced[j] {
                    cr.push((key, Value::Float(src.rows[0][j])));
                }
            }
        }
        None => {
            let points: Vec<[f64; 3]> = src.rows.iter().map(|r| [r[0], r[1], r[2]]).collect();
            let Sweep { param: k, direction, constants, t } =
                sweep_of(&points).expect("histories are split where no sweep fits");
            cr.push(("at", floats(&t)));
            let over = direction.iter().filter(|&&d| d != 0.0).count() == 1;
            if over {
                cr.push(("over", Value::String(axis[k].into())));
            } else {
                cr.push(("direction", floats(&direction)));
            }
            // A prescribed force's constant is written even where 0 (the key prescribes it),
            // unless `over` names it.
            for (j, key) in axis.iter().enumerate() {
                if constants[j].to_bits() != 0 || (forced[j] && !(over && j == k)) {
                    cr.push((key, Value::Float(constants[j])));
                }
            }
        }
    }
    extra_slip(src, draft, &mut cr);
    draft.insert("creepage", table(cr));
}

/// E = 9: the extra rigid slip EXRHS as `[creepage] extra_slip` with its file `<name>_w.csv`
/// (columns ix, iy, wx, wy in CONTACT's element order, as `<name>_h.csv`).
fn extra_slip(src: &Source, draft: &mut Draft, cr: &mut Vec<(&str, Value)>) {
    let (Some(w), Some(potcon)) = (&src.first.state.exrhs, &src.first.state.potcon) else { return };
    let mx = potcon.mx_my().0;
    let mut csv = String::from("ix,iy,wx,wy\n");
    for (e, pair) in w.chunks_exact(2).enumerate() {
        let _ = writeln!(csv, "{},{},{:?},{:?}", e % mx + 1, e / mx + 1, pair[0], pair[1]);
    }
    let file_name = format!("{}_w.csv", src.name);
    cr.push(("extra_slip", Value::String(file_name.clone())));
    draft.files.push((file_name, csv));
}

/// `[creepage] kind = "table"` with its file, and `[init]` after a steady or shift start, of a
/// transient history (rolling or shifts).
pub(super) fn transient(src: &Source, draft: &mut Draft) -> Result<(), InputError> {
    let columns = Columns::of(src);
    let speed = speeds(src.cases, src.h);
    let courant = courants(src, draft)?;
    let chis = directions(src);
    let turns = src.h.run != Run::Shifts && chis.iter().any(|&c| c != chis[0]);
    if turns && courant.is_some() {
        return Err(InputError::new(
            src.place(),
            "CHI and DQ changing in one history",
            "one of the rolling direction (CHI) and the rolling step (DQ) changing per case",
        ));
    }
    let speed_column = if speed.is_some() { ",v_mm_s" } else { "" };
    let courant_column = if courant.is_some() { ",courant" } else { "" };
    let quad_columns = match (src.quads.is_some(), turns) {
        (true, _) => ",b1_per_mm,b2_per_mm,b3_per_mm,b4,b5,b6_mm",
        (false, true) => ",chi_deg",
        (false, false) => "",
    };
    let mut csv = format!("t_s,{}{speed_column}{courant_column}{quad_columns}\n", columns.header());
    match (&speed, &courant) {
        (None, None) => fixed_step_rows(&mut csv, src, &columns, turns.then_some(chis.as_slice())),
        _ if src.quads.is_some() => {
            return Err(InputError::new(
                src.place(),
                "VELOC or DQ and B(1..6) changing in one history",
                "one of the speed (VELOC) or step (DQ) and the undeformed distance (IBASE = 1) changing per case",
            ))
        }
        _ if columns.by_pen && columns.by_fn => {
            return Err(InputError::new(
                src.place(),
                "VELOC or DQ changing with N = 0 and N = 1 in one history",
                "one of the speed (VELOC) or step (DQ) changing per case and N changing per case",
            ))
        }
        (speed, courant) => varying_step_rows(&mut csv, src, &columns, (speed.as_deref(), courant.as_ref())),
    }
    let file_name = format!("{}_table.csv", src.name);
    let mut cr = vec![("kind", Value::String("table".into())), ("file", Value::String(file_name.clone()))];
    for (j, key) in [(1, "cy"), (2, "cs")] {
        if !columns.kept.contains(&j) && src.rows[0][j].to_bits() != 0 {
            cr.push((key, Value::Float(src.rows[0][j])));
        }
    }
    extra_slip(src, draft, &mut cr);
    draft.insert("creepage", table(cr));
    let init = match src.h.run {
        Run::Transient { start: Start::Steady } => Some("steady"),
        Run::Transient { start: Start::Shift } => Some("shift"),
        _ => None,
    };
    if let Some(kind) = init {
        draft.insert("init", table(vec![("kind", Value::String(kind.into()))]));
    }
    draft.files.push((file_name, csv));
    Ok(())
}

/// The table's value columns: which of a row's [cx or Fx/FN, cy or Fy/FN, cs, FN or PEN, μ] it
/// holds, their names, and what each case prescribes.
struct Columns {
    /// Indices into a row of the columns written.
    kept: Vec<usize>,
    names: [String; 5],
    /// Per case: whether it prescribes Fx, Fy ([`prescribed`]).
    forces: Vec<[bool; 2]>,
    /// Per case: whether it prescribes the approach (N = 0).
    by_approach: Vec<bool>,
    /// Whether some case prescribes the approach, some the load.
    by_pen: bool,
    by_fn: bool,
}

impl Columns {
    /// F per case: the force's column where a case prescribes it; creepages and forces in one
    /// history (F changing): both columns, each row's other cell empty. N = 0: PEN is the column
    /// pen_mm, always written (FN is the solver's); N = 0 and 1 in one history: both columns.
    fn of(src: &Source) -> Columns {
        let forces: Vec<[bool; 2]> = src.h.cases.iter().map(|&k| prescribed(case3(src.cases, k))).collect();
        let by_approach: Vec<bool> = src.h.cases.iter().map(|&k| case3(src.cases, k).digits.n == 0).collect();
        let (by_pen, by_fn) = (by_approach.iter().any(|&p| p), by_approach.iter().any(|&p| !p));
        let mut c = Columns { kept: Vec::new(), names: Default::default(), forces, by_approach, by_pen, by_fn };
        let rows = &src.rows;
        let varies = |j: usize| rows.iter().any(|r| r[j].to_bits() != rows[0][j].to_bits());
        c.kept = (0..5).filter(|&j| j == 0 || (j == 1 && c.any(1)) || (j == 3 && by_pen) || varies(j)).collect();
        let pair = |i: usize, given: &str, force: &str| match (c.any(i), c.mixed(i)) {
            (false, _) => given.to_string(),
            (true, false) => force.to_string(),
            (true, true) => format!("{given},{force}"),
        };
        let load = match (by_pen, by_fn) {
            (true, true) => "fn_n,pen_mm",
            (true, false) => "pen_mm",
            _ => "fn_n",
        };
        let names = [pair(0, "cx", "fx_over_fn"), pair(1, "cy", "fy_over_fn"), "cs".into(), load.into(), "mu".into()];
        c.names = names;
        c
    }

    /// Whether some case prescribes force `i` (0: x, 1: y).
    fn any(&self, i: usize) -> bool {
        self.forces.iter().any(|f| f[i])
    }

    /// Whether some cases prescribe force `i` and others its creepage.
    fn mixed(&self, i: usize) -> bool {
        self.any(i) && !self.forces.iter().all(|f| f[i])
    }

    /// The header's value columns.
    fn header(&self) -> String {
        self.kept.iter().map(|&j| self.names[j].as_str()).collect::<Vec<_>>().join(",")
    }

    /// Row n's cells: a pair's two cells (the given one first), one left empty.
    fn cells(&self, rows: &[[f64; 5]], n: usize) -> Vec<String> {
        let cell = |j: usize| {
            let (both, second) = match j {
                0 => (self.mixed(0), self.forces[n][0]),
                1 => (self.mixed(1), self.forces[n][1]),
                3 => (self.by_pen && self.by_fn, self.by_approach[n]),
                _ => (false, false),
            };
            match (both, second) {
                (true, true) => format!(",{:?}", rows[n][j]),
                (true, false) => format!("{:?},", rows[n][j]),
                _ => format!("{:?}", rows[n][j]),
            }
        };
        self.kept.iter().map(|&j| cell(j)).collect()
    }
}

/// Each case's Courant number and the grid's dx [mm], where the step (DQ) changes per case.
type Courants = (Vec<f64>, f64);

/// DQ changing within the history: each case's Courant number, `courant · dx` = DQ exactly, and
/// dx, the project's grid's (read back from a probe of the scene so far).
fn courants(src: &Source, draft: &Draft) -> Result<Option<Courants>, InputError> {
    let Some(dq) = step_lengths(src.cases, src.h) else {
        return Ok(None);
    };
    let dir = tempdir_for(&src.place())?;
    let dx_mm = read_back(dir.path(), &format!("{}.toml", src.name), &probe(&draft.doc), &draft.files)?.grid.dx_mm;
    Ok(Some((dq.iter().map(|&q| courant_for(q, dx_mm)).collect(), dx_mm)))
}

/// CHI per case [deg] (a shift start takes its rolling cases' direction).
fn directions(src: &Source) -> Vec<f64> {
    let h = src.h;
    h.cases
        .iter()
        .enumerate()
        .map(|(n, &k)| match (n, h.run) {
            (0, Run::Transient { start: Start::Shift }) => chi_deg(src.roll.state.chi_rad),
            _ => chi_deg(case3(src.cases, k).state.chi_rad),
        })
        .collect()
}

/// The rows at a fixed step, t = k DQ/VELOC (shifts: CONTACT's dummy time step of 1 s, user
/// guide, "Tangential quantities in case of a shift"), from t = 0 at a steady or shift start,
/// with B(1..6) where they change, else CHI where it changes (`chis`).
fn fixed_step_rows(csv: &mut String, src: &Source, columns: &Columns, chis: Option<&[f64]>) {
    let roll = &src.roll.state;
    let dt_s = if src.h.run == Run::Shifts { 1.0 } else { roll.dq_mm / roll.veloc_mm_s };
    let steady_start = src.h.run.has_start();
    for n in 0..src.rows.len() {
        let step = if steady_start { n } else { n + 1 };
        let mut values = columns.cells(&src.rows, n);
        if let Some(q) = &src.quads {
            values.extend(q[n].iter().map(|b| format!("{b:?}")));
        } else if let Some(chis) = chis {
            values.push(format!("{:?}", chis[n]));
        }
        let _ = writeln!(csv, "{:?},{}", step as f64 * dt_s, values.join(","));
    }
}

/// The rows where the speed (`speed`: VELOC per case) or the step (`courant`: the Courant number
/// per case and dx) changes: t_k = t_(k−1) + DQ_k / VELOC_k ([`speed_rows`]).
fn varying_step_rows(
    csv: &mut String,
    src: &Source,
    columns: &Columns,
    (speed, courant): (Option<&[f64]>, Option<&Courants>),
) {
    let roll = &src.roll.state;
    let steady_start = src.h.run.has_start();
    let mut values: Vec<Vec<String>> = (0..src.rows.len()).map(|n| columns.cells(&src.rows, n)).collect();
    let (mut t_s, mut own) = (Vec::with_capacity(src.rows.len()), Vec::with_capacity(src.rows.len()));
    let mut t = 0.0;
    for (n, row) in values.iter_mut().enumerate() {
        let v = speed.map_or(roll.veloc_mm_s, |v| v[n]);
        let dq = courant.map_or(roll.dq_mm, |(c, dx)| c[n] * dx);
        if !(steady_start && n == 0) {
            t += dq / v;
        }
        t_s.push(t);
        own.push(dq / v);
        if let Some(v) = speed {
            row.push(format!("{:?}", v[n]));
        }
        if let Some((c, _)) = courant {
            row.push(format!("{:?}", c[n]));
        }
    }
    speed_rows(csv, &values, &t_s, courant.is_some().then_some(own.as_slice()));
}

/// The rows of a history whose speed or step changes per case, at t_k = t_(k-1) + DQ_k / VELOC_k
/// (`t_s`; the steady or shift start at t = 0): each case's values held over a quarter of the
/// steps either side of t_k (from t = 0 for the first), so that the scene's step k, the fixed
/// point of (v, dq) = (V, DQ)(t_(k-1) + dq/v) (`problem::loading`), finds VELOC_k, DQ_k and t_k.
/// Where DQ changes (`own`: each case's DQ_k / VELOC_k) the hold after t_k is also shorter than a
/// quarter of case k's own step: a step k + 1 four times as long as step k would otherwise find
/// the false fixed point t_k + DQ_k / VELOC_k inside it.
fn speed_rows(csv: &mut String, values: &[Vec<String>], t: &[f64], own: Option<&[f64]>) {
    for (n, cells) in values.iter().enumerate() {
        let cells = cells.join(",");
        let gap_after = if n + 1 < t.len() { t[n + 1] - t[n] } else { t[n] - if n > 0 { t[n - 1] } else { 0.0 } };
        let gap_after = own.map_or(gap_after, |d| gap_after.min(d[n]));
        let lower = if n == 0 { 0.0 } else { t[n] - 0.25 * (t[n] - t[n - 1]) };
        let _ = writeln!(csv, "{lower:?},{cells}");
        let _ = writeln!(csv, "{:?},{cells}", t[n] + 0.25 * gap_after);
    }
}
