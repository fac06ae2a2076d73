//! `[geometry]`: a contact given per element (docs/scene-format.md). `kind = "profile"`:
//! `h = a1 x² + g(y)` with g linear between the rows of a CSV `y_mm,g_mm`; `kind = "field"`: h per
//! element from a CSV `ix,iy,h_mm` (1-based, ix along CONTACT's x, every element once).

use super::keys::{key, Absent, Allowed, Keys};
use super::reader::{Range, Section};
use crate::error::InputError;
use crate::physics::geometry::{GeometrySpec, Profile};
use std::path::Path;

/// `[geometry]`'s keys (`<!-- keys:geometry -->`).
pub const KEYS: Keys = Keys {
    id: "geometry",
    owner: file!(),
    keys: &[
        key("kind", "–", Allowed::Choice(&["profile", "field"], ""), Absent::Required, r#"how h is given"#),
        key(
            "a1_per_mm",
            "1/mm",
            Allowed::Number(Range::new(0.0, true, 1e3, true), ""),
            Absent::Text("required for `profile`"),
            r#"the curvature term along x: h = a1·x² + g(y): `a1_per_mm = 0.0008`"#,
        ),
        key(
            "profile",
            "–",
            Allowed::Text("a path to a CSV file (columns `y_mm`, `g_mm`), relative to the scene file"),
            Absent::Text("required for `profile`"),
            r#"the columns `y_mm,g_mm` (exactly these), at least two rows, y strictly increasing and covering every element centre; g is linear between rows: `profile = "flat_profile.csv"`"#,
        ),
        key(
            "field",
            "–",
            Allowed::Text("a path to a CSV file (columns `ix`, `iy`, `h_mm`), relative to the scene file"),
            Absent::Text("required for `field`"),
            r#"the columns `ix,iy,h_mm`: 1-based element indices (ix along CONTACT's x from x0) and h [mm], every element of the grid exactly once: `field = "h.csv"`"#,
        ),
    ],
};

/// Read the `[geometry]` table; `(mx, my)` is the grid the field must fill.
pub fn read(g: Section, dir: &Path, (mx, my): (usize, usize)) -> Result<GeometrySpec, InputError> {
    let mut g = g.declare(&KEYS);
    let spec = match g.pick("kind")? {
        "profile" => {
            let a1_per_mm = g.num("a1_per_mm")?;
            let field = g.field("profile");
            let file = g.text("profile")?;
            let (cols, lines, origin) = read_columns(&dir.join(file), &field, &["y_mm", "g_mm"])?;
            let (y_mm, g_mm) = (cols[0].clone(), cols[1].clone());
            if y_mm.len() < 2 {
                return Err(InputError::new(&origin, format!("{} rows", y_mm.len()), "at least two rows"));
            }
            if let Some(r) = (1..y_mm.len()).find(|&r| y_mm[r] <= y_mm[r - 1]) {
                return Err(InputError::new(
                    format!("{origin} line {}", lines[r]),
                    format!("y_mm = {} after {}", y_mm[r], y_mm[r - 1]),
                    "strictly increasing y_mm",
                ));
            }
            GeometrySpec::Profile { a1_per_mm, profile: Profile { y_mm, g_mm } }
        }
        _ => {
            let field = g.field("field");
            let file = g.text("field")?;
            let (cols, lines, origin) = read_columns(&dir.join(file), &field, &["ix", "iy", "h_mm"])?;
            let h_mm = per_element(&cols, &lines, &origin, (mx, my))?.remove(0);
            GeometrySpec::Field { h_mm, blend: None, pn_mpa: None }
        }
    };
    g.finish()?;
    Ok(spec)
}

/// The value columns (after `ix, iy`) of a per-element CSV placed in CONTACT's element order
/// (`iy`-major, 1-based, ix along CONTACT's x), every element of the `mx` x `my` grid exactly once.
pub(crate) fn per_element(
    cols: &[Vec<f64>],
    lines: &[usize],
    origin: &str,
    (mx, my): (usize, usize),
) -> Result<Vec<Vec<f64>>, InputError> {
    let mut out = vec![vec![f64::NAN; mx * my]; cols.len() - 2];
    let mut seen = vec![false; mx * my];
    for (r, (&ix, &iy)) in cols[0].iter().zip(&cols[1]).enumerate() {
        // The message's place, written only for a message (not per row).
        let line = || format!("{origin} line {}", lines[r]);
        let index = |v: f64, n: usize| (v.fract() == 0.0 && v >= 1.0 && v <= n as f64).then(|| v as usize - 1);
        let (Some(i), Some(j)) = (index(ix, mx), index(iy, my)) else {
            return Err(InputError::new(
                line(),
                format!("ix = {ix}, iy = {iy}"),
                format!("whole numbers 1 ≤ ix ≤ {mx}, 1 ≤ iy ≤ {my} (the grid's elements)"),
            ));
        };
        if std::mem::replace(&mut seen[j * mx + i], true) {
            return Err(InputError::new(line(), format!("ix = {ix}, iy = {iy}"), "every element once"));
        }
        for (o, c) in out.iter_mut().zip(&cols[2..]) {
            o[j * mx + i] = c[r];
        }
    }
    if let Some(k) = seen.iter().position(|v| !v) {
        return Err(InputError::new(
            origin,
            format!("{} of {} elements", cols[0].len(), mx * my),
            format!("every element of the {mx} x {my} grid (ix = {}, iy = {} is missing)", k % mx + 1, k / mx + 1),
        ));
    }
    Ok(out)
}

/// The columns `names` (exactly these, in this order) of a CSV of finite numbers, the line of
/// the file each row is on (for messages; empty lines are skipped, [`super::table::line_of`]) and
/// the origin messages name (`field (file)`).
pub(crate) type Columns = (Vec<Vec<f64>>, Vec<usize>, String);

/// [`Columns`] of the CSV at `path`, given as the scene's `field`.
pub(crate) fn read_columns(path: &Path, field: &str, names: &[&str]) -> Result<Columns, InputError> {
    read_columns_of(path, field, &[names.to_vec()]).map(|(c, _)| c)
}

/// [`Columns`] of the CSV at `path` whose header is one of `choices` (which one: its index).
pub(crate) fn read_columns_of(path: &Path, field: &str, choices: &[Vec<&str>]) -> Result<(Columns, usize), InputError> {
    let text = crate::safety::read::read_text(path, crate::safety::read::TABLE_LIMIT_BYTES, "geometry file")
        .map_err(|e| InputError::new(field, path.display(), format!("an existing, readable CSV file ({e})")))?;
    let origin = format!("{field} ({})", path.display());
    let mut rdr = csv::ReaderBuilder::new().trim(csv::Trim::All).from_reader(text.as_bytes());
    let header: Vec<String> = rdr
        .headers()
        .map_err(|e| InputError::new(&origin, "unreadable header", format!("a CSV header line ({e})")))?
        .iter()
        .map(str::to_string)
        .collect();
    let Some(choice) = choices.iter().position(|names| header == *names) else {
        let each: Vec<String> = choices.iter().map(|names| names.join(",")).collect();
        return Err(InputError::new(
            format!("{origin} header"),
            crate::error::name_excerpt(&header.join(",")),
            format!("the columns {}", each.join(" or ")),
        ));
    };
    let names = &choices[choice];
    let mut cols = vec![Vec::new(); names.len()];
    let mut lines = Vec::new();
    // Byte records (no UTF-8 check of the whole record) read into one record (not a copy per
    // row); the message's place written only for a message (not per row).
    let mut rec = csv::ByteRecord::new();
    for r in 0.. {
        let read = rdr.read_byte_record(&mut rec);
        let at = match &read {
            Ok(_) => rec.position(),
            Err(e) => e.position(),
        };
        let row = at.and_then(|p| super::table::line_at(&text, p)).unwrap_or(r + 2);
        let line = || format!("{origin} line {row}");
        if !read.map_err(|e| InputError::new(line(), "malformed", format!("{} numbers ({e})", names.len())))? {
            break;
        }
        if rec.len() != names.len() {
            return Err(InputError::new(line(), rec.len(), format!("{} fields", names.len())));
        }
        for (c, cell) in rec.iter().enumerate() {
            match std::str::from_utf8(cell).map(str::parse::<f64>) {
                Ok(Ok(v)) if v.is_finite() => cols[c].push(v),
                _ => {
                    return Err(InputError::new(
                        format!("{} column {}", line(), names[c]),
                        format!("{:?}", String::from_utf8_lossy(cell)),
                        "a finite number",
                    ))
                }
            }
        }
        lines.push(row);
    }
    if cols[0].is_empty() {
        return Err(InputError::new(&origin, "no rows", "at least one row of numbers"));
    }
    Ok(((cols, lines, origin), choice))
}
