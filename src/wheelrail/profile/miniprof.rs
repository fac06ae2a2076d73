//! Miniprof rail (`.ban`) and wheel (`.whl`) profiles, and plain two-column tables (any other
//! extension), as CONTACT reads them (`m_profile.f90` `read_miniprof_profile`, which CONTACT uses
//! for plain tables too; user guide, "Supported formats"): header lines `Key=Value` (or old-style
//! plain lines) up to the first blank line, then one point a line, `X Y` in mm (Miniprof's X is
//! CONTACT's y, its Y is CONTACT's z, pointing up: MIRRORZ = 0 lets CONTACT detect that), the
//! columns as `ColumnDef` names them. Comments start with `!`, `"`, `%` or `#`; items are
//! separated by blanks, tabs or commas. A plain table may start with its data at once.
//!
//! CONTACT skips a data line with too few numbers (with a message); such a line is an error here.
//! Items after the columns that are not numbers (a note) are ignored, as by CONTACT.

use super::canonical::{self, Pt};
use super::clean;
use super::error::ProfileError;
use super::lines::{self, At, Entry};
use super::{Cleaning, ProfileKind, ProfileOptions};

/// Miniprof's comment characters (also those of plain tables).
const COMMENT: &str = "!\"%#";

/// CONTACT's default column definition (`X,Y,*`: X, Y and anything after).
const DEFAULT_COLUMNS: &str = "X,Y,*";

/// The columns of the data lines.
#[derive(Debug, Clone, PartialEq)]
struct Columns {
    def: String,
    count: usize,
    /// 0-based columns of X (CONTACT's y) and Y (CONTACT's z).
    x: usize,
    y: usize,
}

impl Default for Columns {
    fn default() -> Self {
        Columns { def: DEFAULT_COLUMNS.into(), count: 2, x: 0, y: 1 }
    }
}

/// `ColumnDef=X,Y,…`: one letter every other character (CONTACT's reading).
fn column_def(value: &str, at: At<'_>) -> Result<Columns, ProfileError> {
    let def = value.trim().to_string();
    let chars: Vec<char> = def.chars().collect();
    let count = chars.len().div_ceil(2);
    let mut cols = Columns { def: def.clone(), count, x: 0, y: 1 };
    for k in 0..count {
        match chars[2 * k] {
            'X' => cols.x = k,
            'Y' => cols.y = k,
            _ => {}
        }
    }
    if count > 20 || cols.x >= count || cols.y >= count {
        return Err(at.value(1, "ColumnDef", value, "at most 20 columns naming X and Y (e.g. X,Y or X,Y,A,C)"));
    }
    Ok(cols)
}

/// What the header gives: the columns and the offsets.
#[derive(Debug, Default)]
struct Header {
    columns: Columns,
    x_offset: f64,
    y_offset: f64,
    old_style: bool,
}

/// A `Key=Value` header line (case sensitive, as in CONTACT; the keys that change nothing are
/// ignored).
fn header_key(h: &mut Header, key: &str, value: &str, at: At<'_>) -> Result<(), ProfileError> {
    match key {
        "ColumnDef" => h.columns = column_def(value, at)?,
        "Xoffset" | "XOffset" => h.x_offset = lines::key_number(key, value, at)?,
        "Yoffset" | "YOffset" => h.y_offset = lines::key_number(key, value, at)?,
        _ => {}
    }
    Ok(())
}

/// One data line: the point at columns X and Y.
fn data_line(code: &str, cols: &Columns, at: At<'_>) -> Result<Pt, ProfileError> {
    let v = lines::numbers(code, at, &format!("a point (columns {})", cols.def), cols.count)?;
    Ok(Pt::new(v[cols.x], v[cols.y], at.line))
}

/// The first data line after a header without a blank line: with the default columns CONTACT
/// takes its count of numbers for the columns (at most 6); with a `ColumnDef` it skips the line
/// if it has more numbers (refused here).
fn first_data_line(code: &str, cols: &mut Columns, at: At<'_>) -> Result<(), ProfileError> {
    let n = lines::numbers(code, at, "a point", 1)?.len();
    if cols.def == DEFAULT_COLUMNS {
        cols.count = cols.count.max(n.min(6));
    } else if n > cols.count {
        return Err(at.value(
            1,
            "a point",
            code.trim(),
            &format!("{} numbers, the columns {} (CONTACT skips such a line)", cols.count, cols.def),
        ));
    }
    Ok(())
}

/// The header and the points of the file.
fn parse(text: &str, file: &str) -> Result<(Header, Vec<Pt>), ProfileError> {
    let mut h = Header::default();
    let mut in_headers = true;
    let mut points = Vec::new();
    for line in lines::non_empty_lines(text, COMMENT) {
        let at = At { file, line: line.number };
        let mut first_data = false;
        if line.blank_before >= 1 {
            in_headers = false;
        }
        if in_headers {
            match lines::entry(lines::cut_comment_outside_quotes(line.text, COMMENT)) {
                Entry::KeyValue { value: "", .. } | Entry::Keyword(_) => h.old_style = true,
                Entry::KeyValue { key, value } => header_key(&mut h, key, value, at)?,
                // Data without the blank line before it (a plain table): the data start here;
                // after old-style header lines CONTACT ignores such a line.
                Entry::Numbers if h.old_style => {}
                Entry::Numbers => {
                    in_headers = false;
                    first_data = true;
                }
            }
        }
        if !in_headers {
            let code = lines::cut_comment(line.text, COMMENT);
            if first_data {
                first_data_line(code, &mut h.columns, at)?;
            }
            points.push(data_line(code, &h.columns, at)?);
        }
    }
    Ok((h, points))
}

/// The canonical points of a Miniprof file or plain table: CONTACT's modifications in its order
/// (close points, zig-zags, offsets, MIRRORY, MIRRORZ or its detection, SCALEYZ, the order).
pub fn read(
    text: &str,
    file: &str,
    kind: ProfileKind,
    opts: &ProfileOptions,
) -> Result<(Vec<Pt>, Cleaning), ProfileError> {
    let (h, mut points) = parse(text, file)?;
    let mut cleaning = Cleaning { read: points.len(), ..Default::default() };
    if points.len() < 2 {
        return Err(ProfileError::profile(
            file,
            "the number of points",
            points.len(),
            "at least 2 points (CONTACT's error 190)",
        ));
    }
    cleaning.too_close = clean::drop_close_points(&mut points, clean::POINT_DIST_MIN);
    cleaning.zigzag = clean::replace_zigzags(&mut points, opts.zig_thrs_rad);
    if points.len() < 2 {
        return Err(ProfileError::profile(
            file,
            "the number of points 1e-4 apart",
            points.len(),
            "at least 2 points (CONTACT's error 190)",
        ));
    }
    points.iter_mut().for_each(|p| {
        p.y += h.x_offset;
        p.z += h.y_offset;
    });
    if opts.mirror_y >= 1 {
        canonical::mirror_y(&mut points);
        cleaning.mirrored_y = true;
    }
    let mirror_z = match opts.mirror_z {
        0 => canonical::z_mirror_needed(&points, kind),
        m => m == 1,
    };
    if mirror_z {
        canonical::mirror_z(&mut points);
        cleaning.mirrored_z = true;
    }
    canonical::scale(&mut points, opts.scale);
    if canonical::inversion_needed(&points, kind).0 {
        canonical::invert(&mut points);
        cleaning.inverted = true;
    }
    canonical::check_overall_order(&points, kind, file)?;
    Ok((points, cleaning))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_plain_table_with_comments_and_commas_is_read() {
        let text = "% y, z\n# rail\n-10, 1.0\n0\t0.0\n10 1.0 % end\n";
        let (h, pts) = parse(text, "t.txt").unwrap();
        assert_eq!(h.columns.count, 2);
        assert_eq!(
            pts.iter().map(|p| (p.y, p.z, p.line)).collect::<Vec<_>>(),
            [(-10.0, 1.0, 3), (0.0, 0.0, 4), (10.0, 1.0, 5)]
        );
    }

    #[test]
    fn a_miniprof_header_ends_at_the_blank_line_and_names_the_columns() {
        let text = "Filename=x.ban\nColumnDef=Y,X\nXOffset=1.5\n\n1.0 2.0\n\" 5.0 6.0\n3.0 4.0\n";
        let (h, pts) = parse(text, "x.ban").unwrap();
        assert_eq!((h.columns.x, h.columns.y, h.x_offset), (1, 0, 1.5));
        assert_eq!(pts.iter().map(|p| (p.y, p.z)).collect::<Vec<_>>(), [(2.0, 1.0), (4.0, 3.0)]);
    }

    #[test]
    fn a_data_line_that_is_not_numbers_or_too_short_is_refused() {
        let e = parse("1 2\n3 x\n", "t.txt").unwrap_err();
        assert!(matches!(&e, ProfileError::Value { line: 2, column: 3, .. }), "{e}");
        let e = parse("1 2\n3\n", "t.txt").unwrap_err();
        assert!(
            matches!(&e, ProfileError::Value { line: 2, column: 2, .. }) && e.to_string().contains("2 numbers"),
            "{e}"
        );
        let e = read("% nothing\n", "t.txt", ProfileKind::Rail, &ProfileOptions::default()).unwrap_err();
        assert!(e.to_string().contains("190"), "{e}");
    }

    #[test]
    fn a_miniprof_rail_with_z_up_is_mirrored_in_z() {
        // Miniprof's Y up: the crown is the largest Y.
        let text: String = (0..=40)
            .map(|i| {
                let y = -20.0 + i as f64;
                format!("{y} {}\n", 10.0 - y * y / 100.0)
            })
            .collect();
        let (pts, c) = read(&text, "r.txt", ProfileKind::Rail, &ProfileOptions::default()).unwrap();
        assert!(c.mirrored_z && !c.inverted);
        assert_eq!(pts[20].z, -10.0);
    }
}
