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

use super::reader::{Range, Section};
use super::wheelrail::{case_columns, CaseRow, LongitudinalSpec, VerticalSpec};
use crate::error::InputError;
use std::path::Path;

pub(super) const LENGTH: Range = Range::new(-1e5, true, 1e5, true);
pub(super) const ANGLE: Range = Range::new(-1.5, true, 1.5, true);
const SPEED: Range = Range::new(-1e7, true, 1e7, true);
const CASE_NUMBER: Range = Range::new(0.0, true, 1e9, true);
/// The most cases of a scene (its table and its axes together).
pub const MAX_CASES: usize = 100_000;

/// The allowed values of a column of the cases table.
fn range(column: &str) -> Range {
    match column {
        "contact_case" => CASE_NUMBER,
        "fz_n" => Range::new(0.0, false, 1e8, true),
        "y_mm" | "z_mm" => LENGTH,
        "roll_rad" | "yaw_rad" => ANGLE,
        "fx_ws_n" => Range::new(-1e8, true, 1e8, true),
        _ => SPEED,
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
    let mut c = top.table("cases")?;
    let vertical = match c.opt_choice("vertical", &["force", "position"])?.unwrap_or("force") {
        "force" => VerticalSpec::Force,
        _ => VerticalSpec::Position,
    };
    let longitudinal = match c.opt_choice("longitudinal", &["velocity", "force"])?.unwrap_or("velocity") {
        "force" if vertical == VerticalSpec::Position => {
            return Err(InputError::new(
                c.field("longitudinal"),
                "\"force\" with vertical = \"position\"",
                "\"velocity\", or \"force\" with vertical = \"force\" (CONTACT's F = 1 requires N = 1)",
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
    if let Some(axes) = c.opt_tables("axis")? {
        let first = cases.iter().map(|r| r.contact_case + 1).max().unwrap_or(1);
        let swept = sweep(&mut c, axes, spec, nominal_radius_mm, first)?;
        if cases.len() + swept.len() > MAX_CASES {
            return Err(InputError::new(
                c.field("axis"),
                format!("{} cases with the table's", cases.len() + swept.len()),
                format!("at most {MAX_CASES} cases"),
            ));
        }
        cases.extend(swept);
    }
    c.finish()?;
    Ok((vertical, longitudinal, cases))
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

/// The cases of the table `file`, one per row.
fn from_file(c: &mut Section, dir: &Path, spec: Spec) -> Result<Vec<CaseRow>, InputError> {
    let field = c.field("file");
    let file = c.str(
        "file",
        "a CSV path relative to the scene file (columns in docs/scene-format.md), or [[cases.axis]] tables",
    )?;
    let (cols, lines, origin) = super::geometry::read_columns(&dir.join(file), &field, &case_columns(spec.0, spec.1))?;
    let n = cols[0].len();
    if n == 0 || n > MAX_CASES {
        return Err(InputError::new(&origin, format!("{n} rows"), format!("1 to {MAX_CASES} cases")));
    }
    let values = |r: usize| -> Vec<f64> { cols.iter().map(|col| col[r]).collect() };
    (0..n).map(|r| row(&values(r), &format!("{origin} line {}", lines[r]), spec)).collect()
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
        return Err(InputError::new(c.field("axis"), format!("{total} cases"), format!("at most {MAX_CASES} cases")));
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
fn axis(mut t: Section, columns: &[&str]) -> Result<Axis, InputError> {
    let name = t.str("name", "an axis name of a-z, 0-9, _")?.to_string();
    if name.is_empty() || !name.bytes().all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_') {
        return Err(InputError::new(t.field("name"), format!("{name:?}"), "an axis name of a-z, 0-9, _"));
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
    let mut s = t.table(column)?;
    let from = s.f64("from", range)?;
    let to = s.f64("to", range)?;
    let step = s.f64("step", Range::new(0.0, false, 2e7, true))?;
    s.finish()?;
    if to < from {
        return Err(InputError::new(t.field(column) + ".to", to, format!("at least from = {from}")));
    }
    let count = ((to - from) / step + 1e-6).floor() + 1.0;
    if count > MAX_CASES as f64 {
        return Err(InputError::new(
            t.field(column) + ".step",
            step,
            format!("a step giving at most {MAX_CASES} values from {from} to {to}"),
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
        out[k] = match (c.opt_f64(column, range(column))?, *column) {
            (Some(v), _) => v,
            (None, "fz_n" | "z_mm" | "vs_mm_s" | "fx_ws_n") => {
                return Err(InputError::new(
                    c.field(column),
                    "missing",
                    format!("required with [[cases.axis]] unless an axis varies it: {}", range(column).describe()),
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
    let check = |c: usize| {
        let r = range(columns[c]);
        if r.contains(v[c]) {
            Ok(v[c])
        } else {
            Err(InputError::new(format!("{line} column {}", columns[c]), v[c], r.describe()))
        }
    };
    let case = check(0)?;
    if case.fract() != 0.0 {
        return Err(InputError::new(format!("{line} column contact_case"), case, "a whole number"));
    }
    let mut velocity = [0.0; 6];
    for (k, x) in velocity.iter_mut().enumerate() {
        *x = check(5 + k)?;
    }
    if velocity[0] == 0.0 {
        return Err(InputError::new(
            format!("{line} column vs_mm_s"),
            0,
            "a rolling speed other than 0 (the creepages are over it)",
        ));
    }
    Ok(CaseRow {
        contact_case: case as u64,
        y_mm: check(1)?,
        vertical: check(2)?,
        roll_rad: check(3)?,
        yaw_rad: check(4)?,
        velocity,
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
        assert!(!s.report.in_section);
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
        assert!(s.report.in_section);
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
}
