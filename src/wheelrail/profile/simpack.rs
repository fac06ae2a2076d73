//! SIMPACK rail (`.prr`) and wheel (`.prw`) profiles as CONTACT reads them (`m_profile.f90`
//! `read_simpack_profile`; user guide, "Supported formats"): a `header` section (`version`,
//! `type` 0 rail or 1 wheel), a `spline` section with the file's own processing options and a
//! `point` section of `y z [weight]` lines, in the file's length unit (`units.len.f` per metre).
//! CONTACT applies the file's options (minimum point distance, shift, bounds, mirroring,
//! inversion, unit) except its smoothing, then the input's MIRRORY, MIRRORZ and SCALEYZ; it does
//! not detect the direction of z for a SIMPACK file. `rotate` other than 0 is refused, as by
//! CONTACT.

use super::canonical::{self, Pt};
use super::clean;
use super::error::ProfileError;
use super::lines::{self, At, Entry};
use super::{Cleaning, ProfileKind, ProfileOptions};

/// SIMPACK's comment characters.
const COMMENT: &str = "!%";

/// The options of a file's `spline` section, with CONTACT's defaults.
#[derive(Debug, Clone, PartialEq)]
struct SplineSection {
    point_dist_min: f64,
    shift_y: f64,
    shift_z: f64,
    rotate: f64,
    bound_y: (f64, f64),
    bound_z: (f64, f64),
    mirror_y: i64,
    mirror_z: i64,
    /// `None`: not given (CONTACT detects it).
    inversion: Option<i64>,
    units_len_f: f64,
    units_ang_f: f64,
}

impl Default for SplineSection {
    fn default() -> Self {
        SplineSection {
            point_dist_min: 1e-4,
            shift_y: 0.0,
            shift_z: 0.0,
            rotate: 0.0,
            bound_y: (-1e9, 1e9),
            bound_z: (-1e9, 1e9),
            mirror_y: 0,
            mirror_z: 0,
            inversion: None,
            units_len_f: 1.0,
            units_ang_f: 1.0,
        }
    }
}

/// Where the reader is among the file's sections.
#[derive(Debug, Default)]
struct Nesting {
    header: bool,
    spline: bool,
    point: bool,
}

impl Nesting {
    /// Enter or leave a section (CONTACT's errors 101, 102).
    fn apply(&mut self, name: &str, at: At<'_>) -> Result<(), ProfileError> {
        let Nesting { header, spline, point } = *self;
        let (ok, state) = match name {
            "header.begin" => (!header && !spline && !point, (true, spline, point)),
            "header.end" => (header && !spline && !point, (false, spline, point)),
            "spline.begin" => (!spline && !header && !point, (header, true, point)),
            "spline.end" => (spline && !header && !point, (header, false, point)),
            "point.begin" => (!point && spline && !header, (header, spline, true)),
            "point.end" => (point && spline && !header, (header, spline, false)),
            _ => {
                return Err(at.structure(
                    format!("unknown section name {:?} (CONTACT's error 102)", crate::error::excerpt(name)),
                    "header.begin, header.end, spline.begin, spline.end, point.begin, point.end, key = value lines and, in the point section, lines of numbers",
                ))
            }
        };
        if !ok {
            return Err(at.structure(
                format!("{name} here (CONTACT's error 101: incorrect nesting of sections)"),
                "header.begin … header.end, then spline.begin with point.begin … point.end inside, then spline.end",
            ));
        }
        (self.header, self.spline, self.point) = state;
        Ok(())
    }
}

/// What the file holds.
#[derive(Debug, Default)]
struct Parsed {
    spline: SplineSection,
    points: Vec<Pt>,
}

/// A key of the header section (CONTACT: exactly one number; `type` must match the kind).
fn header_key(key: &str, value: &str, kind: ProfileKind, at: At<'_>) -> Result<(), ProfileError> {
    let numbers = lines::leading_numbers(value);
    if numbers.len() != 1 || !numbers[0].is_finite() {
        return Err(at.value(1, key, value, "one integer value (CONTACT's error 111)"));
    }
    if key == "type" {
        let t = numbers[0].round();
        let want = if kind == ProfileKind::Wheel { 1.0 } else { 0.0 };
        if t != want {
            let code = if kind == ProfileKind::Wheel { 113 } else { 112 };
            return Err(at.value(
                1,
                "type",
                value,
                &format!("{want} for a {} profile (CONTACT's error {code})", kind.name()),
            ));
        }
    }
    Ok(())
}

/// A key of the spline section (outside its point section); unknown keys are ignored, as by
/// CONTACT.
fn spline_key(sp: &mut SplineSection, key: &str, value: &str, at: At<'_>) -> Result<(), ProfileError> {
    let num = || lines::key_number(key, value, at);
    match key {
        // SIMPACK's own smoothing: CONTACT checks it is one number and disregards it.
        "approx.smooth" if lines::leading_numbers(value).len() != 1 => {
            return Err(at.value(1, key, value, "one number (CONTACT's error 131)"));
        }
        "point.dist.min" => sp.point_dist_min = num()?.max(1e-6),
        "shift.y" => sp.shift_y = num()?,
        "shift.z" => sp.shift_z = num()?,
        "rotate" => sp.rotate = num()?,
        "inversion" => sp.inversion = Some(num()?.round() as i64),
        "bound.y.min" => sp.bound_y.0 = num()?,
        "bound.y.max" => sp.bound_y.1 = num()?,
        "bound.z.min" => sp.bound_z.0 = num()?,
        "bound.z.max" => sp.bound_z.1 = num()?,
        "mirror.y" => sp.mirror_y = num()?.round() as i64,
        "mirror.z" => sp.mirror_z = num()?.round() as i64,
        "units.len.f" => sp.units_len_f = num()?,
        "units.ang.f" => sp.units_ang_f = num()?,
        _ => {}
    }
    Ok(())
}

/// A line of the point section: y, z and an optional weight.
fn point_line(code: &str, at: At<'_>) -> Result<Pt, ProfileError> {
    let v = lines::numbers(code, at, "a point (y z [weight])", 2)?;
    if v.len() > 3 {
        return Err(at.value(
            1,
            "a point (y z [weight])",
            code.trim(),
            "2 or 3 numbers: y, z and an optional weight (CONTACT skips a line of more)",
        ));
    }
    Ok(Pt::new(v[0], v[1], at.line))
}

/// The sections and points of the file, up to `spline.end` (CONTACT stops reading there).
fn parse(text: &str, file: &str, kind: ProfileKind) -> Result<Parsed, ProfileError> {
    let mut nest = Nesting::default();
    let mut parsed = Parsed::default();
    for line in lines::non_empty_lines(text, COMMENT) {
        let at = At { file, line: line.number };
        let code = lines::cut_comment_outside_quotes(line.text, COMMENT);
        match lines::entry(code) {
            Entry::Keyword(name) | Entry::KeyValue { key: name, value: "" } => nest.apply(name, at)?,
            Entry::KeyValue { key, value } if nest.header => header_key(key, value, kind, at)?,
            Entry::KeyValue { key, value } if nest.spline && !nest.point => {
                spline_key(&mut parsed.spline, key, value, at)?
            }
            Entry::KeyValue { .. } => {}
            Entry::Numbers if nest.spline && nest.point => parsed.points.push(point_line(code, at)?),
            Entry::Numbers => {}
        }
        if line.text.contains("spline.end") {
            return Ok(parsed);
        }
    }
    let section = if nest.point {
        "the point section"
    } else if nest.spline {
        "the spline section"
    } else if nest.header {
        "the header section"
    } else {
        "the file"
    };
    let at = At { file, line: text.lines().count().max(1) };
    Err(at.structure(format!("the file ends in {section} (CONTACT's error 100)"), "a file that ends with spline.end"))
}

/// The file's options applied in CONTACT's order (its modifications 1–10), then the input's.
fn process(
    parsed: Parsed,
    file: &str,
    kind: ProfileKind,
    opts: &ProfileOptions,
) -> Result<(Vec<Pt>, Cleaning), ProfileError> {
    let Parsed { spline: sp, mut points } = parsed;
    let mut cleaning = Cleaning { read: points.len(), ..Default::default() };
    if points.len() < 2 {
        return Err(ProfileError::profile(
            file,
            "the number of points",
            points.len(),
            "at least 2 points in the point section",
        ));
    }
    cleaning.too_close = clean::drop_close_points(&mut points, sp.point_dist_min);
    cleaning.zigzag = clean::replace_zigzags(&mut points, opts.zig_thrs_rad);
    points.iter_mut().for_each(|p| {
        p.y += sp.shift_y;
        p.z += sp.shift_z;
    });
    if (sp.rotate / sp.units_ang_f).abs() > 1e-6 {
        return Err(ProfileError::profile(
            file,
            "rotate",
            sp.rotate,
            "0: a profile rotation is not implemented (CONTACT's error 182)",
        ));
    }
    cleaning.outside_bounds = clean::drop_outside_y(&mut points, sp.bound_y.0, sp.bound_y.1);
    clean::clip_z(&mut points, sp.bound_z.0, sp.bound_z.1);
    if points.len() < 2 {
        return Err(ProfileError::profile(
            file,
            "the number of points inside bound.y.min, bound.y.max",
            points.len(),
            "at least 2 points",
        ));
    }
    if i64::from(opts.mirror_y) + sp.mirror_y == 1 {
        canonical::mirror_y(&mut points);
        cleaning.mirrored_y = true;
    }
    if i64::from(opts.mirror_z) + sp.mirror_z == 1 {
        canonical::mirror_z(&mut points);
        cleaning.mirrored_z = true;
    }
    if !(sp.units_len_f.is_finite() && sp.units_len_f > 0.0) {
        return Err(ProfileError::profile(
            file,
            "units.len.f",
            crate::error::number(sp.units_len_f),
            "a positive factor: the file's length unit per metre (1000 for mm)",
        ));
    }
    let factor_scale = opts.scale * 1000.0;
    points.iter_mut().for_each(|p| {
        p.y = factor_scale * p.y / sp.units_len_f;
        p.z = factor_scale * p.z / sp.units_len_f;
    });
    let invert = match sp.inversion {
        None => canonical::inversion_needed(&points, kind).0,
        Some(v) => v == 1,
    };
    if invert {
        canonical::invert(&mut points);
        cleaning.inverted = true;
    }
    canonical::check_overall_order(&points, kind, file)?;
    Ok((points, cleaning))
}

/// The canonical points of a SIMPACK file's text.
pub fn read(
    text: &str,
    file: &str,
    kind: ProfileKind,
    opts: &ProfileOptions,
) -> Result<(Vec<Pt>, Cleaning), ProfileError> {
    let parsed = parse(text, file, kind)?;
    process(parsed, file, kind, opts)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(points: &str, spline_keys: &str) -> String {
        format!(
            "header.begin\n  version = 1\n  type = 0\nheader.end\nspline.begin\n{spline_keys}  units.len.f = 1000.\n  point.begin\n{points}  point.end\nspline.end\n"
        )
    }

    fn crown() -> String {
        (0..=40)
            .map(|i| {
                let y = -20.0 + i as f64;
                format!("   {y} {}\n", y * y / 200.0)
            })
            .collect()
    }

    #[test]
    fn a_rail_file_is_read_with_its_options() {
        let (pts, c) =
            read(&file(&crown(), "  shift.z = 1.0\n"), "r.prr", ProfileKind::Rail, &ProfileOptions::default()).unwrap();
        assert_eq!(pts.len(), 41);
        assert_eq!((pts[0].y, pts[0].z, pts[0].line), (-20.0, 3.0, 9));
        assert_eq!(c.read, 41);
        let (mirrored, c) =
            read(&file(&crown(), "  mirror.y = 1\n"), "r.prr", ProfileKind::Rail, &ProfileOptions::default()).unwrap();
        // Mirrored, then put back in ascending order.
        assert!(c.mirrored_y && c.inverted);
        assert_eq!(mirrored[0].y, -20.0);
    }

    #[test]
    fn a_metre_file_is_scaled_by_its_unit_and_scale() {
        let keys = "  units.len.f = 1.\n";
        let text = file(&crown(), keys).replace("  units.len.f = 1000.\n", "");
        let opts = ProfileOptions { scale: 0.001, ..Default::default() };
        let (pts, _) = read(&text, "m.prr", ProfileKind::Rail, &opts).unwrap();
        assert_eq!(pts[0].y, -20.0);
    }

    #[test]
    fn structure_errors_name_the_line() {
        let text = "header.begin\n  type = 1\nheader.end\n";
        let e = read(text, "w.prr", ProfileKind::Rail, &ProfileOptions::default()).unwrap_err();
        assert!(matches!(&e, ProfileError::Value { line: 2, .. }) && e.to_string().contains("112"), "{e}");
        let e = read("spline.begin\npoint.begin\n1 2\n", "r.prr", ProfileKind::Rail, &ProfileOptions::default())
            .unwrap_err();
        assert!(e.to_string().contains("ends in the point section"), "{e}");
        let e = read("point.begin\n", "r.prr", ProfileKind::Rail, &ProfileOptions::default()).unwrap_err();
        assert!(matches!(&e, ProfileError::Structure { line: 1, .. }) && e.to_string().contains("101"), "{e}");
        let text = file("   1.0 abc\n", "");
        let e = read(&text, "r.prr", ProfileKind::Rail, &ProfileOptions::default()).unwrap_err();
        assert!(matches!(&e, ProfileError::Value { line: 8, column: 8, .. }), "{e}");
        let e = read(&file(&crown(), "  rotate = 0.1\n"), "r.prr", ProfileKind::Rail, &ProfileOptions::default())
            .unwrap_err();
        assert!(e.to_string().contains("182"), "{e}");
    }
}
