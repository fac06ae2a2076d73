//! `[cases]` of a wheel–rail scene (docs/scene-format.md, "`[cases]`"): a table file of cases,
//! one per row, and/or a study of cases — the values every case shares, and axes whose columns
//! vary, crossed as a study's axes (`scene::study`: the first outermost, the keys of one axis
//! together), each column's values a list or `{ from, to, step }`.
//!
//! ```toml
//! [cases]
//! vertical = "force"
//! fz_n = 10000.0
//! vs_mm_s = 2000.0           # vpitch_rad_s: −vs_mm_s / nominal_radius_mm unless given
//!
//! [[cases.axis]]
//! name = "shift"
//! y_mm = { from = 0.0, to = 10.0, step = 0.5 }
//! yaw_rad = { from = 0.0, to = 0.024, step = 0.0012 }
//! ```

use super::keys::{bound, key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use super::wheelrail::{
    case_columns, case_columns_with_pitch, case_columns_with_positions, CaseRow, LongitudinalSpec, MotionSpec, MuBy,
    MuVariation, VerticalSpec,
};
use crate::error::InputError;
use std::path::Path;

/// A length of the cases [mm] (shared with the profiles' and `[wheelrail]`'s positions).
pub(super) const LENGTH: Range = Range::new(-1e5, true, 1e5, true);
/// An angle of the cases [rad].
pub(super) const ANGLE: Range = Range::new(-1.5, true, 1.5, true);
/// The pitch angle [rad] (CONTACT allows the wheel's θ in [−1.5π, 1.5π]).
const PITCH: Range = Range::new(-4.8, true, 4.8, true);
const SPEED: Range = Range::new(-1e7, true, 1e7, true);
const FORCE: Range = Range::new(-1e8, true, 1e8, true);
/// The most cases of a scene (its table and its axes together).
pub const MAX_CASES: usize = 100_000;

/// The row of [`KEYS`] and [`AXIS_KEYS`] that stands for the columns' keys (a name with a space:
/// a family of keys, each declared in [`COLUMNS`]).
const A_COLUMN: &str = "a column's name";

/// `[cases]`'s keys (`<!-- keys:cases -->`).
pub const KEYS: Keys = Keys {
    id: "cases",
    owner: file!(),
    keys: &[
        key(
            "vertical",
            "–",
            Allowed::Choice(&["force", "position"], ""),
            Absent::Choice("force"),
            r#"what fixes the wheelset's height: the vertical force on the rail, column `fz_n` (CONTACT's N = 1; the height is found), or the height itself, column `z_mm` (N = 0): `vertical = "position"`"#,
        ),
        key(
            "longitudinal",
            "–",
            Allowed::Choice(&["velocity", "force"], "`\"force\"` only with `vertical = \"force\"`"),
            Absent::Choice("velocity"),
            r#"what fixes the wheelset's pitch: its velocity, column `vpitch_rad_s` (CONTACT's F = 0), or the total longitudinal force on the rail in wheelset coordinates, column `fx_ws_n` in its place (F = 1: VPITCH is found so that the exact theory's FX(WS) is `fx_ws_n`, with FZ prescribed; [wheelrail.md](wheelrail.md#the-longitudinal-force-prescribed)): `longitudinal = "force"`"#,
        ),
        key(
            "file",
            "–",
            Allowed::Text("a CSV path relative to the scene file (its columns below), or `[[cases.axis]]` tables"),
            Absent::Text("required without `axis`"),
            r#"the cases, one per row (1 to 1e5 rows): `file = "cases.csv"`"#,
        ),
        key(
            "axis",
            "–",
            Allowed::Text("one or more `[[cases.axis]]` tables"),
            Absent::Text("none"),
            r#"the axes of a study of cases, crossed, the first outermost (as a study's `[[study.axis]]`); at most 1e5 cases with the table's"#,
        ),
        key(
            A_COLUMN,
            "the column's",
            Allowed::Text("the column's (below); `fz_n`, `z_mm`, `roll_rad`, `yaw_rad`, `vs_mm_s`, `vy_mm_s`, `vz_mm_s`, `vroll_rad_s`, `vyaw_rad_s`, `vpitch_rad_s` or `fx_ws_n`, as the table has it"),
            Absent::Text("`fz_n` (or `z_mm`), `vs_mm_s` and `fx_ws_n` required; `vpitch_rad_s` −`vs_mm_s` / `nominal_radius_mm` (rolling at the nominal radius); the others 0"),
            r#"only with `axis`: the value every case of the study shares, for a column no axis varies (one an axis varies is refused here): `fz_n = 10000.0`"#,
        ),
    ],
};

/// `[[cases.axis]]`'s keys (`<!-- keys:cases_axis -->`, with [`STEP_KEYS`]).
pub const AXIS_KEYS: Keys = Keys {
    id: "cases_axis",
    owner: file!(),
    keys: &[
        key(
            "name",
            "–",
            Allowed::Text("a name of `a-z`, `0-9`, `_`, distinct among the axes"),
            Absent::Required,
            r#"the axis's name (in messages): `name = "shift"`"#,
        ),
        key(
            "a column's name (not `contact_case`)",
            "the column's",
            Allowed::Text("a non-empty list of the column's values, or `{ from, to, step }`"),
            Absent::Text("at least one"),
            r#"the column's values on this axis; every column of one axis has as many values, and they vary together; a column is on one axis at most: `y_mm = [0.0, 5.0, 10.0]`"#,
        ),
    ],
};

/// The keys of a column's `{ from, to, step }` on an axis (shown with [`AXIS_KEYS`]).
pub const STEP_KEYS: Keys = Keys {
    id: "cases_axis",
    owner: file!(),
    keys: &[
        key(
            "from",
            "the column's",
            Allowed::Text("the column's range"),
            Absent::Required,
            r#"the first value of a `{ from, to, step }`: `y_mm = { from = 0.0, to = 10.0, step = 0.5 }`"#,
        ),
        key(
            "to",
            "the column's",
            Allowed::Text("the column's range, ≥ `from`"),
            Absent::Required,
            r#"the last value: from, from + step, … up to `to` (within a millionth of a step; `to` itself when (to − from)/step is whole)"#,
        ),
        key(
            "step",
            "the column's",
            Allowed::Number(Range::new(0.0, false, 2e7, true), ""),
            Absent::Required,
            r#"the step between values"#,
        ),
    ],
};

/// The columns of the cases table (`<!-- columns:cases_columns -->`: column, unit, allowed,
/// meaning), exactly those of [`case_columns`] in its order: a table's values, and the values
/// `[cases]` and its axes give, are checked by these declarations.
pub const COLUMNS: Keys = Keys {
    id: "cases_columns",
    owner: file!(),
    keys: &[
        key(
            "contact_case",
            "–",
            Allowed::Whole(0, 1_000_000_000, ""),
            Absent::Required,
            "the case's number (CONTACT's case number for an imported deck)",
        ),
        key(
            "s_mm",
            "mm",
            Allowed::Number(LENGTH, r#"only with `motion = "shift"` or `"shift_sequence"`, or in steady rolling (`motion = "rolling"`) on a rail slices file (`[rail] profile` a `.slcs` file); not with `[wheelrail] s_mm` or `mu_by = "track_s"`"#),
            Absent::Text("an optional column: without it each position is `[wheelrail] s_mm` or follows from the shifts (`vs_mm_s`)"),
            r#"the wheelset's position along the track S_WS of each case, as CONTACT reads it per case; in a shift the anchor of the material-fixed grid (element centres at track x = −`s_mm` + i `dx_mm`), independent of the shift (`testbank/examples_trans/m1_catt_shift`: a shift of 4 mm from rest at 0, then shifts of 0.2 mm at 0.2, 0.4, …); in steady rolling on a rail slices file where the wheelset stands on the rail: the rail's cross-section at `s_mm` and its surface around it (`testbank/examples_s+c/mbench_intrup`: the UK crossing at S_WS = 110 … 130 mm); a table that has it gives it second, after `contact_case`"#,
        ),
        key("y_mm", "mm", Allowed::Number(LENGTH, ""), Absent::Required, "the wheelset's lateral displacement Y_WS"),
        key(
            "fz_n",
            "N",
            Allowed::Number(Range::new(0.0, false, 1e8, true), ""),
            Absent::Required,
            r#"with `vertical = "force"`: the vertical force FZ on the rail"#,
        ),
        key(
            "z_mm",
            "mm",
            Allowed::Number(LENGTH, ""),
            Absent::Required,
            r#"with `vertical = "position"`: the wheelset's height Z_WS (z downwards)"#,
        ),
        key("roll_rad", "rad", Allowed::Number(ANGLE, ""), Absent::Required, "the wheelset's roll angle ROLL"),
        key("yaw_rad", "rad", Allowed::Number(ANGLE, ""), Absent::Required, "the wheelset's yaw angle YAW"),
        key(
            "vs_mm_s",
            "mm/s",
            Allowed::Number(SPEED, "not 0 on a track, 0 on a roller rig (`[rail] roller_radius_mm`)"),
            Absent::Required,
            r#"the forward speed VS_WS (the creepages are over it; on a roller rig the roller turns instead, `[rail] roller_vpitch_rad_s`); in a shift (`motion = "shift"` or `"shift_sequence"`) this and the other velocity columns are the step's shifts in mm and rad; in a sequence of shifts each case's position along the track is the one before plus this shift (× 1 s), unless the table has the column `s_mm`"#,
        ),
        key("vy_mm_s", "mm/s", Allowed::Number(SPEED, ""), Absent::Required, "the lateral velocity VY_WS"),
        key("vz_mm_s", "mm/s", Allowed::Number(SPEED, ""), Absent::Required, "the vertical velocity VZ_WS"),
        key("vroll_rad_s", "rad/s", Allowed::Number(SPEED, ""), Absent::Required, "the roll rate VROLL"),
        key("vyaw_rad_s", "rad/s", Allowed::Number(SPEED, ""), Absent::Required, "the yaw rate VYAW"),
        key(
            "vpitch_rad_s",
            "rad/s",
            Allowed::Number(SPEED, ""),
            Absent::Required,
            r#"with `longitudinal = "velocity"`: the pitch rate VPITCH (about −VS/NOMRAD in rolling)"#,
        ),
        key(
            "fx_ws_n",
            "N",
            Allowed::Number(
                FORCE,
                "\\|`fx_ws_n`\\| below μ·`fz_n` (μ the largest of `mu_values` with `mu_by`); not with `frictionless`",
            ),
            Absent::Required,
            r#"with `longitudinal = "force"`, in place of `vpitch_rad_s`: FX_WS, the total force on the rail along the wheelset's x (CONTACT's sign: negative when braking the wheel moving along +x); VPITCH is found (its search starts at −VS/NOMRAD) and written in `<model>.csv`; a force the contact cannot carry at the case's position (the wheel slides) stops the run with exit 2"#,
        ),
        key(
            "pitch_rad",
            "rad",
            Allowed::Number(PITCH, ""),
            Absent::Text("an optional column: without it every case's pitch is 0"),
            r#"the wheelset's pitch angle PITCH: the material angle θ = −`pitch_rad` of an out-of-round wheel (`[wheel] profile` a `.slcw` wheel slices file) lies at its lowest point; a round wheel is the same at every pitch; a table that has it gives it last (`examples/wheelflat`: −25° to −50° turn the flat under the contact)"#,
        ),
    ],
};

/// A column's declaration ([`COLUMNS`]; every column of [`case_columns`] has one, a test checks).
fn declared(name: &str) -> Allowed {
    COLUMNS.get(name).map_or(Allowed::Text("a column of the cases table"), |k| k.allowed)
}

/// The values a column allows: its declared range (a whole number's as a range of numbers).
fn range(name: &str) -> Range {
    match declared(name) {
        Allowed::Number(range, _) => range,
        Allowed::Whole(min, max, _) => Range::new(min as f64, true, max as f64, true),
        _ => Range::new(0.0, false, 0.0, false),
    }
}

/// `[cases]`: `vertical`, `longitudinal`, and the cases of the table `file` followed by those of
/// the axes (numbered on from the table's largest `contact_case`, from 1 without a table); at
/// least one of the two. `nominal_radius_mm` gives the default pitch rate of the axes' cases.
pub(super) fn read(
    top: &mut Section,
    dir: &Path,
    nominal_radius_mm: f64,
) -> Result<(VerticalSpec, LongitudinalSpec, Vec<CaseRow>), InputError> {
    let mut c = top.table("cases")?.declare(&KEYS).declare(&COLUMNS);
    let vertical = match c.pick_or_default("vertical")? {
        "force" => VerticalSpec::Force,
        _ => VerticalSpec::Position,
    };
    let longitudinal = match c.pick_or_default("longitudinal")? {
        "force" if vertical == VerticalSpec::Position => {
            return Err(InputError::new(
                c.field("longitudinal"),
                "\"force\" with vertical = \"position\"",
                format!(
                    "{} (CONTACT's F = 1 requires N = 1)",
                    KEYS.get("longitudinal").map_or(String::new(), |k| k.allowed.message())
                ),
            ))
        }
        "force" => LongitudinalSpec::Force,
        _ => LongitudinalSpec::Velocity,
    };
    let spec = (vertical, longitudinal);
    let mut cases = match c.has("file") || !c.has("axis") {
        true => from_file(&mut c, dir, spec)?,
        false => Vec::new(),
    };
    let axes = c.opt_tables("axis")?;
    refuse_other_columns(&mut c, spec, axes.is_some())?;
    if let Some(axes) = axes {
        let first = cases.iter().map(|r| r.contact_case + 1).max().unwrap_or(1);
        let swept = sweep(&mut c, axes, spec, nominal_radius_mm, first)?;
        if cases.len() + swept.len() > MAX_CASES {
            return Err(InputError::new(
                c.field("axis"),
                format!("{} cases with the table's", cases.len() + swept.len()),
                format!("at most {} cases", bound(MAX_CASES as f64)),
            ));
        }
        cases.extend(swept);
    }
    c.finish()?;
    Ok((vertical, longitudinal, cases))
}

/// Refuses in `[cases]` a column's key that gives no value there: `contact_case` (the cases are
/// numbered), any column without axes (there is no study of cases to share it), and a column
/// the table does not have (`z_mm` with `vertical = "force"`, …).
fn refuse_other_columns(c: &mut Section, spec: Spec, axes: bool) -> Result<(), InputError> {
    let columns = case_columns(spec.0, spec.1);
    c.refuse(
        "contact_case",
        "no value in [cases]: the cases are numbered (the table's, then the axes' on from its largest)",
    )?;
    for k in COLUMNS.keys.iter().skip(1) {
        if !axes {
            c.refuse(k.key, "no value without [[cases.axis]] (a value every case of a study of cases shares)")?;
        } else if !columns.contains(&k.key) {
            let why = format!("a column of the cases table as [cases] sets it: {}", columns[1..].join(", "));
            c.refuse(k.key, &why)?;
        }
    }
    Ok(())
}

/// With FX_WS prescribed: friction (not `frictionless`) and every case's |FX_WS| below
/// `mu_max`·FZ, the most Coulomb friction carries (a larger force has no pitch velocity).
pub fn check_longitudinal(
    longitudinal: LongitudinalSpec,
    frictionless: bool,
    mu_max: f64,
    cases: &[CaseRow],
) -> Result<(), InputError> {
    if longitudinal != LongitudinalSpec::Force {
        return Ok(());
    }
    if frictionless {
        return Err(InputError::new(
            "wheelrail.frictionless",
            true,
            "false with [cases] longitudinal = \"force\" (FX_WS is carried by friction)",
        ));
    }
    for r in cases {
        let (fx, fz) = (r.velocity[5], r.vertical);
        if fx.abs() >= mu_max * fz {
            return Err(InputError::new(
                format!("cases, contact_case {}: fx_ws_n", r.contact_case),
                fx,
                format!(
                    "|fx_ws_n| below mu·fz_n = {mu_max} × {fz} = {} N (beyond it no pitch velocity gives the force: the wheel slides)",
                    mu_max * fz
                ),
            ));
        }
    }
    Ok(())
}

/// The table's column `s_mm` (each case's S_WS) only in a shift (`motion = "shift"` or
/// `"shift_sequence"`) or in steady rolling on a rail slices file (`varying_rail`: S_WS places
/// the wheelset on the rail), without `[wheelrail] s_mm` (`given_s`; one place gives the
/// position) and without μ along the track (whose position is `[wheelrail] s_mm`).
pub fn check_positions(
    cases: &[CaseRow],
    motion: MotionSpec,
    (given_s, varying_rail): (bool, bool),
    mu_variation: Option<&MuVariation>,
) -> Result<(), InputError> {
    if cases.iter().all(|r| r.s_mm.is_none()) {
        return Ok(());
    }
    let why = if !(matches!(motion, MotionSpec::Shift { .. }) || (motion == MotionSpec::Rolling && varying_rail)) {
        "motion = \"shift\" or \"shift_sequence\" (the position anchors a shift's material-fixed grid), or steady rolling (motion = \"rolling\") on a rail slices file ([rail] profile a .slcs file: the position places the wheelset on the rail)"
    } else if given_s {
        "no [wheelrail] s_mm beside it (one place gives the positions)"
    } else if mu_variation.is_some_and(|v| matches!(v.by, MuBy::TrackS { .. })) {
        "no mu_by = \"track_s\" beside it (μ is taken at [wheelrail] s_mm)"
    } else {
        return Ok(());
    };
    Err(InputError::new("cases.file column s_mm", "given", format!("the column s_mm only with {why}")))
}

/// The cases of the table `file`, one per row; its columns [`case_columns`], or with the shift's
/// positions `s_mm` second ([`case_columns_with_positions`]).
fn from_file(c: &mut Section, dir: &Path, spec: Spec) -> Result<Vec<CaseRow>, InputError> {
    let field = c.field("file");
    let file = c.text("file")?;
    let choices = [
        case_columns(spec.0, spec.1),
        case_columns_with_positions(spec.0, spec.1),
        case_columns_with_pitch(spec.0, spec.1),
    ];
    let ((mut cols, lines, origin), choice) = super::geometry::read_columns_of(&dir.join(file), &field, &choices)?;
    let n = cols[0].len();
    if n == 0 || n > MAX_CASES {
        return Err(InputError::new(&origin, format!("{n} rows"), format!("1 to {} cases", bound(MAX_CASES as f64))));
    }
    let positions = (choice == 1).then(|| cols.remove(1));
    let pitches = (choice == 2).then(|| cols.pop().unwrap_or_default());
    let pitch = |r: usize, line: &str| -> Result<f64, InputError> {
        let Some(p) = &pitches else { return Ok(0.0) };
        match PITCH.contains(p[r]) {
            true => Ok(p[r]),
            false => Err(InputError::new(format!("{line} column pitch_rad"), p[r], declared("pitch_rad").message())),
        }
    };
    let values = |r: usize| -> Vec<f64> { cols.iter().map(|col| col[r]).collect() };
    let position = |r: usize, line: &str| -> Result<Option<f64>, InputError> {
        let Some(p) = &positions else { return Ok(None) };
        match LENGTH.contains(p[r]) {
            true => Ok(Some(p[r])),
            false => Err(InputError::new(format!("{line} column s_mm"), p[r], declared("s_mm").message())),
        }
    };
    (0..n)
        .map(|r| {
            let line = format!("{origin} line {}", lines[r]);
            Ok(CaseRow { s_mm: position(r, &line)?, pitch_rad: pitch(r, &line)?, ..row(&values(r), &line, spec)? })
        })
        .collect()
}

/// The vertical and longitudinal problems, which fix the table's columns.
pub(super) type Spec = (VerticalSpec, LongitudinalSpec);

/// One axis: its name and its columns (index in [`case_columns`]) with their values.
struct Axis {
    name: String,
    columns: Vec<(usize, Vec<f64>)>,
}

/// The cases of `[[cases.axis]]`: the axes crossed (the first outermost), every other column
/// fixed by `[cases]` itself, numbered from `first`.
fn sweep(
    c: &mut Section,
    tables: Vec<Section>,
    spec: Spec,
    nominal_radius_mm: f64,
    first: u64,
) -> Result<Vec<CaseRow>, InputError> {
    let columns = case_columns(spec.0, spec.1);
    let mut axes: Vec<Axis> = Vec::new();
    for t in tables {
        let a = axis(t, &columns)?;
        if let Some(b) = axes.iter().find(|b| b.name == a.name) {
            return Err(InputError::new(c.field("axis"), format!("{:?} twice", b.name), "distinct axis names"));
        }
        for (k, _) in &a.columns {
            if let Some(b) = axes.iter().find(|b| b.columns.iter().any(|(j, _)| j == k)) {
                return Err(InputError::new(
                    c.field("axis"),
                    format!("{} on the axes {:?} and {:?}", columns[*k], b.name, a.name),
                    "each column on one axis at most (columns that vary together share an axis)",
                ));
            }
        }
        axes.push(a);
    }
    let fixed = fixed(c, &columns, &axes)?;
    let total = axes.iter().try_fold(1usize, |n, a| n.checked_mul(a.columns[0].1.len())).unwrap_or(usize::MAX);
    if total > MAX_CASES {
        return Err(InputError::new(
            c.field("axis"),
            format!("{total} cases"),
            format!("at most {} cases", bound(MAX_CASES as f64)),
        ));
    }
    let mut out = Vec::with_capacity(total);
    for n in 0..total {
        let mut values = fixed.clone();
        values[0] = first as f64 + n as f64;
        let mut rest = n;
        for a in axes.iter().rev() {
            let len = a.columns[0].1.len();
            for (k, v) in &a.columns {
                values[*k] = v[rest % len];
            }
            rest /= len;
        }
        let last = values.len() - 1;
        if values[last].is_nan() {
            // Rolling at the nominal radius: −VS / NOMRAD (CONTACT's VPITCH of a free wheel).
            values[last] = -values[5] / nominal_radius_mm;
        }
        out.push(row(&values, &format!("{} (case {})", c.field("axis"), first as usize + n), spec)?);
    }
    Ok(out)
}

/// One `[[cases.axis]]`: `name` and one or more columns, each a list of values or
/// `{ from, to, step }`, all of one length.
fn axis(t: Section, columns: &[&str]) -> Result<Axis, InputError> {
    let mut t = t.declare(&AXIS_KEYS).declare(&COLUMNS);
    let name = t.text("name")?.to_string();
    if name.is_empty() || !name.bytes().all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_') {
        let allowed = AXIS_KEYS.get("name").map_or(String::new(), |k| k.allowed.message());
        return Err(InputError::new(t.field("name"), format!("{name:?}"), allowed));
    }
    let varied: Vec<&str> = columns[1..].to_vec();
    if let Some(k) = t.keys().into_iter().find(|k| k != "name" && !varied.contains(&k.as_str())) {
        return Err(InputError::new(
            t.field(&k),
            t.raw().get(&k).map_or_else(String::new, ToString::to_string),
            format!("name, or columns of the cases table that vary: {}", varied.join(", ")),
        ));
    }
    let mut out = Vec::new();
    for (k, column) in columns.iter().enumerate().skip(1) {
        if !t.has(column) {
            continue;
        }
        let values = values(&mut t, column, range(column))?;
        if let Some((j, v)) = out.first().map(|(j, v): &(usize, Vec<f64>)| (*j, v.len())) {
            if values.len() != v {
                return Err(InputError::new(
                    t.field(column),
                    format!("{} values", values.len()),
                    format!("{v} values, as {} of the same axis (its columns vary together)", columns[j]),
                ));
            }
        }
        out.push((k, values));
    }
    if out.is_empty() {
        return Err(InputError::new(
            t.field("name"),
            format!("{name:?} varies nothing"),
            format!("at least one column of {}", varied.join(", ")),
        ));
    }
    t.finish()?;
    Ok(Axis { name, columns: out })
}

/// A column's values on an axis: a list, or `{ from, to, step }` (from, from + step, … up to
/// `to` within a millionth of a step), each within the column's range.
fn values(t: &mut Section, column: &str, range: Range) -> Result<Vec<f64>, InputError> {
    match t.raw().get(column) {
        Some(toml::Value::Table(_)) => {}
        Some(toml::Value::Array(_)) => return Ok(t.opt_f64_list(column, range, MAX_CASES)?.unwrap_or_default()),
        other => {
            let shown = other.map_or_else(String::new, ToString::to_string);
            return Err(InputError::new(
                t.field(column),
                shown,
                format!("a list of numbers or {{ from, to, step }}, each {}", range.describe()),
            ));
        }
    }
    let mut s = t.table(column)?.declare(&STEP_KEYS);
    let from = s.f64("from", range)?;
    let to = s.f64("to", range)?;
    let step = s.num("step")?;
    s.finish()?;
    if to < from {
        return Err(InputError::new(t.field(column) + ".to", to, format!("at least from = {}", bound(from))));
    }
    let count = ((to - from) / step + 1e-6).floor() + 1.0;
    if count > MAX_CASES as f64 {
        return Err(InputError::new(
            t.field(column) + ".step",
            step,
            format!("a step giving at most {} values from {} to {}", bound(MAX_CASES as f64), bound(from), bound(to)),
        ));
    }
    Ok((0..count as usize).map(|k| from + k as f64 * step).collect())
}

/// The values every case of the axes shares (`[cases]`'s keys named after the columns): given,
/// or their defaults (0; `vpitch_rad_s` NaN, filled in per case); `fz_n` or `z_mm`, `vs_mm_s`
/// and `fx_ws_n` are required unless on an axis. A column both fixed and on an axis is refused.
fn fixed(c: &mut Section, columns: &[&str], axes: &[Axis]) -> Result<Vec<f64>, InputError> {
    let mut out = vec![0.0; columns.len()];
    for (k, column) in columns.iter().enumerate().skip(1) {
        if let Some(a) = axes.iter().find(|a| a.columns.iter().any(|(j, _)| *j == k)) {
            c.refuse(column, &format!("no fixed value: the axis {:?} varies it", a.name))?;
            out[k] = f64::NAN;
            continue;
        }
        out[k] = match (c.opt_num(column)?, *column) {
            (Some(v), _) => v,
            (None, "fz_n" | "z_mm" | "vs_mm_s" | "fx_ws_n") => {
                return Err(InputError::new(
                    c.field(column),
                    "missing",
                    format!("required with [[cases.axis]] unless an axis varies it: {}", declared(column).message()),
                ))
            }
            (None, "vpitch_rad_s") => f64::NAN,
            (None, _) => 0.0,
        };
    }
    Ok(out)
}

/// One case from its values in the order of [`case_columns`], checked (`line` names it).
pub(super) fn row(v: &[f64], line: &str, spec: Spec) -> Result<CaseRow, InputError> {
    let columns = case_columns(spec.0, spec.1);
    let check = |c: usize| match range(columns[c]).contains(v[c]) {
        true => Ok(v[c]),
        false => Err(InputError::new(format!("{line} column {}", columns[c]), v[c], declared(columns[c]).message())),
    };
    let case = check(0)?;
    if case.fract() != 0.0 {
        return Err(InputError::new(format!("{line} column contact_case"), case, "a whole number"));
    }
    let mut velocity = [0.0; 6];
    for (k, x) in velocity.iter_mut().enumerate() {
        *x = check(5 + k)?;
    }
    Ok(CaseRow {
        contact_case: case as u64,
        y_mm: check(1)?,
        vertical: check(2)?,
        roll_rad: check(3)?,
        yaw_rad: check(4)?,
        velocity,
        s_mm: None,
        pitch_rad: 0.0,
    })
}

#[cfg(test)]
mod tests {
    use crate::scene::wheelrail::WheelRailScene;
    use std::path::Path;

    /// A wheel–rail scene whose `[cases]` table is `cases` (the profiles are not read here).
    fn scene(cases: &str) -> Result<WheelRailScene, String> {
        let text = format!(
            "name = \"s\"\n[wheelrail]\nside = \"left\"\nmu = 0.3\ndx_mm = 0.5\nds_mm = 0.5\n\
             [rail]\nprofile = \"r.prr\"\ngauge_height_mm = 14.0\ngauge_width_mm = 1435.0\n\
             [wheel]\nprofile = \"w.prw\"\nflange_back_distance_mm = 1360.0\nflange_back_position_mm = -70.0\n\
             nominal_radius_mm = 460.0\n[material]\ng_mpa = 82000.0\npoisson = 0.28\n{cases}"
        );
        WheelRailScene::from_toml(&text, Path::new(".")).map_err(|e| e.to_string())
    }

    #[test]
    fn one_axis_of_shift_and_yaw_together_expands_to_21_cases() {
        let s = scene(
            "[cases]\nfz_n = 10000.0\nvs_mm_s = 2000.0\n[[cases.axis]]\nname = \"shift\"\n\
             y_mm = { from = 0.0, to = 10.0, step = 0.5 }\nyaw_rad = { from = 0.0, to = 0.024, step = 0.0012 }\n",
        )
        .unwrap();
        assert_eq!(s.cases.len(), 21);
        for (k, c) in s.cases.iter().enumerate() {
            assert_eq!(c.contact_case, k as u64 + 1);
            assert_eq!(c.y_mm, 0.5 * k as f64);
            assert_eq!(c.yaw_rad, 0.0012 * k as f64);
            assert_eq!((c.vertical, c.roll_rad), (10000.0, 0.0));
            assert_eq!(c.velocity, [2000.0, 0.0, 0.0, 0.0, 0.0, -2000.0 / 460.0]);
        }
        assert_eq!(s.cases[20].y_mm, 10.0);
        // The patch maps default to the first, middle and last case.
        assert!(s.report.patch_cases.is_empty());
        assert_eq!(s.patch_cases(), [1, 11, 21]);
        assert!(!s.report.in_section());
    }

    #[test]
    fn two_axes_cross_the_first_outermost() {
        let s = scene(
            "[cases]\nvertical = \"position\"\nz_mm = -0.1\nvs_mm_s = 1000.0\nvpitch_rad_s = -2.0\n\
             [[cases.axis]]\nname = \"y\"\ny_mm = [0.0, 5.0]\n[[cases.axis]]\nname = \"yaw\"\nyaw_rad = [0.0, 0.01, 0.02]\n\
             [report]\ngroup = \"wheelrail\"\npatch_cases = [2, 6]\n",
        )
        .unwrap();
        let got: Vec<(u64, f64, f64)> = s.cases.iter().map(|c| (c.contact_case, c.y_mm, c.yaw_rad)).collect();
        let want = [(1, 0.0, 0.0), (2, 0.0, 0.01), (3, 0.0, 0.02), (4, 5.0, 0.0), (5, 5.0, 0.01), (6, 5.0, 0.02)];
        assert_eq!(got, want);
        assert!(s.cases.iter().all(|c| c.vertical == -0.1 && c.velocity[5] == -2.0));
        assert!(s.report.in_section());
        assert_eq!(s.patch_cases(), [2, 6]);
    }

    #[test]
    fn fx_ws_prescribed_takes_the_last_column_and_bad_forces_are_refused() {
        let axis = "[[cases.axis]]\nname = \"y\"\ny_mm = [0.0, 2.0]\n";
        let head = "[cases]\nlongitudinal = \"force\"\nfz_n = 10000.0\nvs_mm_s = 2000.0\n";
        let s = scene(&format!("{head}fx_ws_n = -2000.0\n{axis}")).unwrap();
        assert_eq!(s.longitudinal, crate::scene::wheelrail::LongitudinalSpec::Force);
        assert!(s.cases.iter().all(|c| c.velocity[5] == -2000.0), "{:?}", s.cases);
        let s = scene(&format!("[cases]\nfz_n = 1.0\nvs_mm_s = 1.0\n{axis}")).unwrap();
        assert_eq!(s.longitudinal, crate::scene::wheelrail::LongitudinalSpec::Velocity);
        for (body, field, allowed) in [
            (format!("{head}{axis}"), "cases.fx_ws_n", "required"),
            (format!("{head}fx_ws_n = 3000.0\n{axis}"), "contact_case 1: fx_ws_n", "below mu·fz_n = 0.3 × 10000"),
            (format!("{head}vpitch_rad_s = -4.0\nfx_ws_n = 1.0\n{axis}"), "cases.vpitch_rad_s", "vpitch_rad_s"),
            (
                format!("[cases]\nvertical = \"position\"\nlongitudinal = \"force\"\nz_mm = 0.1\nvs_mm_s = 1.0\nfx_ws_n = 1.0\n{axis}"),
                "cases.longitudinal",
                "CONTACT's F = 1 requires N = 1",
            ),
        ] {
            let err = scene(&body).unwrap_err();
            assert!(err.contains(field) && err.contains(allowed), "{body:?}: {err}");
        }
        // FX_WS is carried by friction: not with a frictionless scene.
        let err = scene(&format!("{head}fx_ws_n = 1.0\n{axis}[report]\ngroup = \"other\"\n"))
            .and_then(|_| {
                let mut doc: toml::Table = toml::from_str(&format!(
                    "name = \"s\"\n[wheelrail]\nside = \"left\"\nmu = 0.3\ndx_mm = 0.5\nds_mm = 0.5\nfrictionless = true\n\
                     [rail]\nprofile = \"r.prr\"\ngauge_height_mm = 14.0\ngauge_width_mm = 1435.0\n\
                     [wheel]\nprofile = \"w.prw\"\nflange_back_distance_mm = 1360.0\nflange_back_position_mm = -70.0\n\
                     nominal_radius_mm = 460.0\n[material]\ng_mpa = 82000.0\npoisson = 0.28\n{head}fx_ws_n = 1.0\n{axis}"
                ))
                .unwrap();
                doc.remove("report");
                WheelRailScene::from_table(&doc, Path::new(".")).map_err(|e| e.to_string())
            })
            .unwrap_err();
        assert!(err.contains("wheelrail.frictionless") && err.contains("carried by friction"), "{err}");
    }

    #[test]
    fn bad_axes_are_refused_naming_the_field_the_value_and_what_is_allowed() {
        let head = "[cases]\nfz_n = 10000.0\nvs_mm_s = 2000.0\n[[cases.axis]]\nname = \"a\"\n";
        for (body, field, allowed) in [
            ("y_mn = [0.0, 1.0]\n", "cases.axis[0].y_mn", "columns of the cases table that vary: y_mm, fz_n"),
            ("contact_case = [1, 2]\n", "cases.axis[0].contact_case", "y_mm, fz_n, roll_rad"),
            ("y_mm = [0.0, 1.0]\nyaw_rad = [0.0]\n", "cases.axis[0].yaw_rad", "2 values, as y_mm"),
            ("y_mm = { from = 2.0, to = 1.0, step = 0.5 }\n", "cases.axis[0].y_mm.to", "at least from = 2"),
            ("y_mm = { from = 0.0, to = 1.0, step = 0.0 }\n", "cases.axis[0].y_mm.step", "(0, "),
            ("y_mm = { from = 0.0, to = 1.0 }\n", "cases.axis[0].y_mm.step", "required"),
            ("y_mm = \"wide\"\n", "cases.axis[0].y_mm", "a list of numbers or { from, to, step }"),
            ("yaw_rad = [0.0, 2.0]\n", "cases.axis[0].yaw_rad[1]", "[-1.5, 1.5]"),
            ("fz_n = [1.0]\n", "cases.fz_n", "the axis \"a\" varies it"),
            ("", "cases.axis[0].name", "at least one column"),
        ] {
            let err = scene(&format!("{head}{body}")).unwrap_err();
            assert!(err.contains(field) && err.contains(allowed), "{body:?}: {err}");
        }
        let err = scene("[cases]\nfz_n = 1.0\n[[cases.axis]]\nname = \"a\"\ny_mm = [0.0]\n").unwrap_err();
        assert!(err.contains("cases.vs_mm_s") && err.contains("required"), "{err}");
        let two = "[[cases.axis]]\nname = \"a\"\ny_mm = [0.0]\n[[cases.axis]]\nname = \"a\"\nyaw_rad = [0.0]\n";
        let err = scene(&format!("[cases]\nfz_n = 1.0\nvs_mm_s = 1.0\n{two}")).unwrap_err();
        assert!(err.contains("\"a\" twice") && err.contains("distinct axis names"), "{err}");
        let err = scene(&format!("{head}y_mm = [0.0]\n[report]\npatch_cases = [7]\n")).unwrap_err();
        assert!(err.contains("report.patch_cases[0]") && err.contains("a contact_case of the scene's cases"), "{err}");
        let err = scene(&format!("{head}y_mm = [0.0]\n[report]\ngroup = \"steady\"\n")).unwrap_err();
        assert!(err.contains("report.group") && err.contains("wheelrail"), "{err}");
    }

    /// The positions per case (column `s_mm`, second): read into each row and taken as a shift's
    /// positions, or in steady rolling on a rail slices file as each case's S_WS; refused in
    /// steady rolling on a profile, beside `[wheelrail] s_mm`, out of range.
    #[test]
    fn a_shifts_positions_column_gives_each_cases_position_and_is_refused_elsewhere() {
        let dir = tempfile::tempdir().unwrap();
        let head = "contact_case,s_mm,y_mm,z_mm,roll_rad,yaw_rad,vs_mm_s,vy_mm_s,vz_mm_s,vroll_rad_s,vyaw_rad_s,vpitch_rad_s\n";
        let rows =
            "1,0.0,0.0,-0.2,0.0,0.0,4.0,0.0,0.0,0.0,0.0,-0.04\n2,0.2,0.0,-0.2,0.0,0.0,0.2,0.0,0.0,0.0,0.0,-0.002\n";
        std::fs::write(dir.path().join("c.csv"), format!("{head}{rows}")).unwrap();
        std::fs::write(dir.path().join("bad.csv"), format!("{head}1,2e5,0.0,-0.2,0.0,0.0,4.0,0.0,0.0,0.0,0.0,-0.04\n"))
            .unwrap();
        let scene_on = |wheelrail: &str, file: &str, rail: &str| {
            let text = format!(
                "name = \"s\"\nsolvers = [\"contact\"]\n[wheelrail]\nside = \"right\"\nmu = 0.4\ndx_mm = 0.2\nds_mm = 0.2\n{wheelrail}\
                 [rail]\nprofile = \"{rail}\"\ny_mm = 0.0\nz_mm = 0.0\n\
                 [wheel]\nprofile = \"w.prw\"\nflange_back_distance_mm = 0.0\nflange_back_position_mm = 0.0\n\
                 nominal_radius_mm = 100.0\n[material]\ng_mpa = 200.0\npoisson = 0.28\n\
                 [cases]\nvertical = \"position\"\nfile = \"{file}\"\n"
            );
            WheelRailScene::from_toml(&text, dir.path()).map_err(|e| e.to_string())
        };
        let scene = |wheelrail: &str, file: &str| scene_on(wheelrail, file, "r.prr");
        let s = scene("motion = \"shift_sequence\"\n", "c.csv").unwrap();
        assert_eq!(s.cases.iter().map(|r| r.s_mm).collect::<Vec<_>>(), [Some(0.0), Some(0.2)]);
        assert_eq!(s.cases[1].velocity, [0.2, 0.0, 0.0, 0.0, 0.0, -0.002]);
        assert_eq!(s.shift_positions_mm(), Some(vec![0.0, 0.2]), "not 0 then 4 (the first shift's)");
        // Steady rolling on a rail slices file: each case's S_WS, where the wheelset stands on the
        // rail (`mbench_intrup`), drawn against it in a crossing's figure.
        let s = scene_on("[report]\ngroup = \"crossing\"\n", "c.csv", "x.slcs").unwrap();
        assert_eq!((s.motion, s.shift_positions_mm()), (crate::scene::wheelrail::MotionSpec::Rolling, None));
        assert_eq!(s.case_positions_mm(), Some(vec![0.0, 0.2]));
        assert_eq!(s.report.figures, crate::scene::wheelrail::WheelRailFigures::Crossing);
        for (wheelrail, file, field, allowed) in [
            ("", "c.csv", "cases.file column s_mm", "motion = \"shift\" or \"shift_sequence\""),
            ("", "c.csv", "cases.file column s_mm", "or steady rolling (motion = \"rolling\") on a rail slices file"),
            ("motion = \"shift\"\ns_mm = 1.0\n", "c.csv", "cases.file column s_mm", "no [wheelrail] s_mm"),
            ("motion = \"shift\"\n", "bad.csv", "line 2 column s_mm", "[-1e5, 1e5]"),
        ] {
            let err = scene(wheelrail, file).unwrap_err();
            assert!(err.contains(field) && err.contains(allowed), "{wheelrail:?} {file}: {err}");
        }
        let err = scene_on("s_mm = 1.0\n", "c.csv", "x.slcs").unwrap_err();
        assert!(err.contains("cases.file column s_mm") && err.contains("no [wheelrail] s_mm"), "{err}");
        // A wheel flat's figure is drawn against the distance an out-of-round wheel rolled.
        let err = scene_on("[report]\ngroup = \"wheel_flat\"\n", "c.csv", "x.slcs").unwrap_err();
        assert!(err.contains("report.group") && err.contains("only on a wheel slices file"), "{err}");
    }

    /// The declared columns are exactly those of the eight tables [`case_columns`] and
    /// [`case_columns_with_positions`] give (the reader checks each column by its declaration; the
    /// docs' columns table is generated from it).
    #[test]
    fn the_declared_columns_are_the_tables_columns_in_their_order() {
        use crate::scene::wheelrail::{
            case_columns, case_columns_with_pitch, case_columns_with_positions, LongitudinalSpec as L,
            VerticalSpec as V,
        };
        let declared: Vec<&str> = super::COLUMNS.keys.iter().map(|k| k.key).collect();
        let mut seen = std::collections::BTreeSet::new();
        for (v, l) in
            [(V::Force, L::Velocity), (V::Force, L::Force), (V::Position, L::Velocity), (V::Position, L::Force)]
        {
            for cols in [case_columns(v, l), case_columns_with_positions(v, l), case_columns_with_pitch(v, l)] {
                let at: Vec<usize> =
                    cols.iter().map(|c| declared.iter().position(|d| d == c).expect("declared")).collect();
                assert!(at.windows(2).all(|w| w[0] < w[1]), "{cols:?} in the declared order");
                seen.extend(cols);
            }
        }
        assert_eq!(seen.len(), declared.len(), "every declared column is one of a table: {seen:?}");
    }
}
