//! CONTACT's canonical form of a profile (user guide, "Inputs regarding wheel and rail profiles",
//! "Form as needed by CONTACT"; `m_profile.f90`: `check_z_pos_down`, `check_inversion`,
//! `invert_points`, `check_overall_order`): lengths in mm, y towards the field side, z pointing
//! down (into the rail, out of the wheel), rail points ordered with y ascending and wheel points
//! with y descending, so that walking along the points the material is on the right.

use super::error::ProfileError;
use super::ProfileKind;
use std::f64::consts::PI;

/// One profile point as read, with the line of the file it came from (0: not from a file).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pt {
    pub y: f64,
    pub z: f64,
    pub line: usize,
}

impl Pt {
    pub fn new(y: f64, z: f64, line: usize) -> Pt {
        Pt { y, z, line }
    }
}

/// MIRRORY applied: y → −y.
pub fn mirror_y(pts: &mut [Pt]) {
    pts.iter_mut().for_each(|p| p.y = -p.y);
}

/// MIRRORZ applied: z → −z.
pub fn mirror_z(pts: &mut [Pt]) {
    pts.iter_mut().for_each(|p| p.z = -p.z);
}

/// Every coordinate multiplied by `factor` (SCALE, a unit conversion).
pub fn scale(pts: &mut [Pt], factor: f64) {
    pts.iter_mut().for_each(|p| {
        p.y *= factor;
        p.z *= factor;
    });
}

/// The 1-based index of the first smallest (`pick_min`) or largest z, as CONTACT's `idmin`,
/// `idmax`.
fn first_extreme_z(pts: &[Pt], pick_min: bool) -> usize {
    let mut best = 0;
    for (k, p) in pts.iter().enumerate() {
        let better = if pick_min { p.z < pts[best].z } else { p.z > pts[best].z };
        if better {
            best = k;
        }
    }
    best + 1
}

/// Fortran's `nint`: the nearest integer, halves away from zero.
fn nint(v: f64) -> i64 {
    v.round() as i64
}

/// Whether z must be mirrored to point down (MIRRORZ = 0, CONTACT's `check_z_pos_down`): a
/// wheel's lowest point (smallest z) lies at a side, within the first or last 5 % of the points;
/// a rail's z falls from the sides towards the middle. The thresholds are CONTACT's (its
/// single-precision constants included).
pub fn z_mirror_needed(pts: &[Pt], kind: ProfileKind) -> bool {
    match kind {
        ProfileKind::Wheel => wheel_z_mirror_needed(pts),
        ProfileKind::Rail => rail_z_mirror_needed(pts),
    }
}

/// A Fortran default-real constant, as it compares with a double.
fn single(v: f32) -> f64 {
    f64::from(v)
}

fn wheel_z_mirror_needed(pts: &[Pt]) -> bool {
    let n = pts.len();
    let (izmin, izmax) = (first_extreme_z(pts, true), first_extreme_z(pts, false));
    let frac_min = izmin as f64 / n as f64;
    let frac_max = izmax as f64 / n as f64;
    let at_side = |f: f64| f < single(0.05) || f > single(0.95);
    if at_side(frac_min) {
        false
    } else if at_side(frac_max) {
        true
    } else {
        // A hollow worn wheel? Mirror when the profile lies below the straight line between its
        // extremes, halfway between them.
        let ixm = nint(n as f64 * (frac_min + frac_max) / 2.0).clamp(1, n as i64) as usize;
        let z_straight = (pts[izmin - 1].z + pts[izmax - 1].z) / 2.0;
        pts[ixm - 1].z > z_straight
    }
}

/// The sign of the first change of z beyond 0.1 % of its range, walking from point `from` (1-based)
/// inwards by `step` while the index stays on the far side of `limit`; 0 where there is none.
fn first_change(pts: &[Pt], from: usize, step: i64, limit: i64, dz_tot: f64) -> i32 {
    let z0 = pts[from - 1].z;
    let mut i = from as i64;
    loop {
        let inside = if step > 0 { i < limit } else { i > limit };
        if !inside {
            return 0;
        }
        i += step;
        let dz = pts[(i - 1) as usize].z - z0;
        if dz.abs() > 0.001 * dz_tot {
            return if dz > 0.0 { 1 } else { -1 };
        }
    }
}

fn rail_z_mirror_needed(pts: &[Pt]) -> bool {
    let n = pts.len();
    let (izmin, izmax) = (first_extreme_z(pts, true), first_extreme_z(pts, false));
    let frac_min = izmin as f64 / n as f64;
    let dz_tot = (pts[izmax - 1].z - pts[izmin - 1].z).max(1e-5);
    let start = first_change(pts, 1, 1, nint(0.1 * n as f64), dz_tot);
    let end = first_change(pts, n, -1, nint(0.9 * n as f64), dz_tot);
    let mut mirror = if start == end || end == 0 {
        start
    } else if start == 0 {
        end
    } else {
        -1
    };
    if mirror == 0 {
        // Fallback: mirror if the smallest z lies in the first or last 10 % of the points.
        mirror = if frac_min < single(0.1) || frac_min > single(0.9) { 1 } else { -1 };
    }
    mirror == 1
}

/// An angle difference brought into (−π, π] as CONTACT's `check_inversion` does.
fn wrap_half_open(mut d: f64) -> f64 {
    if d <= -PI {
        d += 2.0 * PI;
    }
    if d > PI {
        d -= 2.0 * PI;
    }
    d
}

/// Whether the points run the wrong way at the top of the rail (its smallest z) or the bottom of
/// the wheel (its largest z, typically the flange), CONTACT's `check_inversion` (the coordinates
/// are finite: its negated comparisons are plain ones here). Returns the
/// 1-based indices of the points it looked at with the answer.
pub fn inversion_needed(pts: &[Pt], kind: ProfileKind) -> (bool, [usize; 3]) {
    let n = pts.len();
    let y = |i: usize| pts[i - 1].y;
    let z = |i: usize| pts[i - 1].z;
    match kind {
        ProfileKind::Rail => {
            let izmin = first_extreme_z(pts, true);
            let (i1, i2) = if izmin >= n { (izmin - 1, izmin) } else { (izmin, izmin + 1) };
            (y(i2) < y(i1), [i1, i2, i2])
        }
        ProfileKind::Wheel => {
            let i = first_extreme_z(pts, false);
            let around = [i.saturating_sub(1).max(1), i, (i + 1).min(n)];
            if i <= 1 {
                return (y(i + 1) >= y(i), around);
            }
            if i >= n {
                return (y(i) >= y(i - 1), around);
            }
            let (dy1, dy2) = (y(i) - y(i - 1), y(i + 1) - y(i));
            if dy1 * dy2 > 0.0 {
                return (dy1 >= 0.0, around);
            }
            // A sharp corner, '<' or '>': the profile must turn to the right.
            let (dz1, dz2) = (z(i) - z(i - 1), z(i + 1) - z(i));
            let dalph = wrap_half_open(dz2.atan2(dy2) - dz1.atan2(dy1));
            (dalph < 0.0, around)
        }
    }
}

/// The points in reverse order (CONTACT's `invert_points`).
pub fn invert(pts: &mut [Pt]) {
    pts.reverse();
}

/// The direction the points must run, for messages.
fn direction(kind: ProfileKind) -> &'static str {
    match kind {
        ProfileKind::Rail => "a rail profile's y ascending from the track centre to the field side",
        ProfileKind::Wheel => "a wheel profile's y descending from the field side to the flange",
    }
}

/// A point as messages show it.
fn shown(i: usize, p: &Pt) -> String {
    let line = if p.line > 0 { format!(" (line {})", p.line) } else { String::new() };
    format!("point {i}{line} y = {} mm, z = {} mm", p.y, p.z)
}

/// The first point before the last in the right order (CONTACT's `check_overall_order`, errors
/// 211 and 212).
pub fn check_overall_order(pts: &[Pt], kind: ProfileKind, file: &str) -> Result<(), ProfileError> {
    let (first, last) = (pts[0], pts[pts.len() - 1]);
    let wrong = match kind {
        ProfileKind::Wheel => first.y <= last.y,
        ProfileKind::Rail => first.y >= last.y,
    };
    if wrong {
        let code = if kind == ProfileKind::Wheel { 211 } else { 212 };
        return Err(ProfileError::profile(
            file,
            "the first and last points",
            format!("{}; {}", shown(1, &first), shown(pts.len(), &last)),
            format!("{} (CONTACT's error {code}; MIRRORY mirrors y)", direction(kind)),
        ));
    }
    Ok(())
}

/// The order at the top of the rail or the bottom of the wheel, as the finished profile must have
/// it (CONTACT's `check_inversion` reporting errors 221 and 222): a profile that folds back there.
pub fn check_inversion(pts: &[Pt], kind: ProfileKind, file: &str) -> Result<(), ProfileError> {
    let (wrong, around) = inversion_needed(pts, kind);
    if wrong {
        let code = if kind == ProfileKind::Wheel { 221 } else { 222 };
        let (what, place) = match kind {
            ProfileKind::Rail => ("the points at the top of the rail (its smallest z)", "at the top"),
            ProfileKind::Wheel => ("the points at the bottom of the wheel (its largest z)", "at the bottom"),
        };
        let mut idx = around.to_vec();
        idx.dedup();
        let value = idx.iter().map(|&i| shown(i, &pts[i - 1])).collect::<Vec<_>>().join("; ");
        return Err(ProfileError::profile(
            file,
            what,
            value,
            format!("{} {place}: the profile folds back there (CONTACT's error {code})", direction(kind)),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(v: &[(f64, f64)]) -> Vec<Pt> {
        v.iter().map(|&(y, z)| Pt::new(y, z, 0)).collect()
    }

    /// A rail crown: z down, smallest at the middle.
    fn crown(n: usize) -> Vec<Pt> {
        pts(&(0..n)
            .map(|i| {
                let y = -30.0 + 60.0 * i as f64 / (n - 1) as f64;
                (y, y * y / 100.0)
            })
            .collect::<Vec<_>>())
    }

    #[test]
    fn a_rail_with_z_down_is_kept_and_one_with_z_up_is_mirrored() {
        let mut p = crown(41);
        assert!(!z_mirror_needed(&p, ProfileKind::Rail));
        mirror_z(&mut p);
        assert!(z_mirror_needed(&p, ProfileKind::Rail));
    }

    #[test]
    fn a_wheel_whose_lowest_point_is_at_a_side_is_kept() {
        // Wheel, z down: the outer face rising to the smallest z at the field side (first point),
        // the tread at z = 0, the flange (largest z) near the end.
        let z = |i: usize| match i {
            0..5 => -2.0 * (5 - i) as f64,
            5..36 => 0.0,
            _ => 15.0 * (PI * (i - 35) as f64 / 15.0).sin(),
        };
        let mut p = pts(&(0..51).map(|i| (70.0 - 2.0 * i as f64, z(i))).collect::<Vec<_>>());
        assert!(!z_mirror_needed(&p, ProfileKind::Wheel));
        mirror_z(&mut p);
        assert!(z_mirror_needed(&p, ProfileKind::Wheel));
        mirror_z(&mut p);
        assert!(!inversion_needed(&p, ProfileKind::Wheel).0);
    }

    #[test]
    fn a_reversed_rail_is_inverted_and_the_overall_order_checked() {
        let mut p = crown(21);
        p.reverse();
        assert!(inversion_needed(&p, ProfileKind::Rail).0);
        let e = check_overall_order(&p, ProfileKind::Rail, "r.prr").unwrap_err();
        assert!(e.to_string().contains("212"), "{e}");
        invert(&mut p);
        assert!(!inversion_needed(&p, ProfileKind::Rail).0);
        check_overall_order(&p, ProfileKind::Rail, "r.prr").unwrap();
        check_inversion(&p, ProfileKind::Rail, "r.prr").unwrap();
    }
}
