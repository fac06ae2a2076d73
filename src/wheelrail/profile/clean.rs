//! CONTACT's curation of profile points (user guide, "Curation of anomolous input data";
//! `m_profile.f90`: `filter_close_points`, `filter_double_kinks`, `delete_outside_boundbox`,
//! `profile_check_bowtie`, `segs_have_intersection`, `profile_find_kinks`): points too close
//! together are dropped, a zig-zag (two successive turns sharper than ZIGTHRS) is replaced by the
//! mean of its two points, a profile whose segments cross (a loop) is refused, and the kinks
//! (isolated turns sharper than KINKHIGH with no turn above KINKLOW within KINKWID) break the
//! spline into sections.

use super::canonical::Pt;
use super::error::ProfileError;
use std::f64::consts::PI;

/// CONTACT's smallest distance between successive points of a Miniprof or plain table and of
/// values passed directly (`point_dist_min`), in the file's units.
pub const POINT_DIST_MIN: f64 = 1e-4;

/// The number of points after which a kink is no longer recorded (CONTACT's `max_num_kinks`).
const MAX_KINKS: usize = 99;

/// Points closer than `dist_min` to the last point kept are dropped (CONTACT's
/// `filter_close_points`; none below 1e-12). Returns how many were dropped.
pub fn drop_close_points(pts: &mut Vec<Pt>, dist_min: f64) -> usize {
    if dist_min < 1e-12 || pts.is_empty() {
        return 0;
    }
    let before = pts.len();
    let mut kept: Vec<Pt> = Vec::with_capacity(before);
    kept.push(pts[0]);
    for p in &pts[1..] {
        let last = kept[kept.len() - 1];
        let dist2 = (last.y - p.y).powi(2) + (last.z - p.z).powi(2);
        if dist2 >= dist_min * dist_min {
            kept.push(*p);
        }
    }
    *pts = kept;
    before - pts.len()
}

/// An angle difference brought into [−π, π] as CONTACT's filters do.
fn wrap(mut d: f64) -> f64 {
    if d < -PI {
        d += 2.0 * PI;
    }
    if d > PI {
        d -= 2.0 * PI;
    }
    d
}

/// The inclination of each segment, atan2(dz, dy).
fn inclinations(pts: &[Pt]) -> Vec<f64> {
    pts.windows(2).map(|w| (w[1].z - w[0].z).atan2(w[1].y - w[0].y)).collect()
}

/// Zig-zags replaced by the mean of their two points (CONTACT's `filter_double_kinks`): where the
/// inclination turns by more than `zig_thrs_rad` both into and out of a segment. Returns how many
/// points were dropped. As CONTACT, a zig-zag at the second-last segment keeps the second-last
/// point besides the mean.
pub fn replace_zigzags(pts: &mut Vec<Pt>, zig_thrs_rad: f64) -> usize {
    let n = pts.len();
    if n <= 3 {
        return 0;
    }
    let nseg = n - 1;
    let alpha = inclinations(pts);
    // 1-based segment iseg joins points iseg and iseg+1; alpha[iseg-1] is its inclination.
    let a = |iseg: usize| alpha[iseg - 1];
    let p = |i: usize| pts[i - 1];
    let mut out = vec![p(1)];
    let mut iseg = 1;
    while iseg < nseg - 1 {
        iseg += 1;
        let d0 = wrap(a(iseg) - a(iseg - 1));
        let d1 = wrap(a(iseg + 1) - a(iseg));
        if d0.abs() > zig_thrs_rad && d1.abs() > zig_thrs_rad {
            let (q, r) = (p(iseg), p(iseg + 1));
            out.push(Pt::new((q.y + r.y) / 2.0, (q.z + r.z) / 2.0, q.line));
            iseg += 1;
        } else {
            out.push(p(iseg));
        }
    }
    out.push(p(n - 1));
    out.push(p(n));
    let dropped = n.saturating_sub(out.len());
    *pts = out;
    dropped
}

/// Points with y outside [y_min, y_max] dropped (SIMPACK's `bound.y.min`, `bound.y.max`, CONTACT's
/// `delete_outside_boundbox`; no bound when y_min ≥ y_max). Returns how many were dropped.
pub fn drop_outside_y(pts: &mut Vec<Pt>, y_min: f64, y_max: f64) -> usize {
    if y_min >= y_max {
        return 0;
    }
    let before = pts.len();
    pts.retain(|p| !(p.y < y_min || p.y > y_max));
    before - pts.len()
}

/// z clipped to [z_min, z_max] (SIMPACK's `bound.z.min`, `bound.z.max`; none when z_min ≥ z_max).
pub fn clip_z(pts: &mut [Pt], z_min: f64, z_max: f64) {
    if z_min < z_max {
        pts.iter_mut().for_each(|p| p.z = z_min.max(z_max.min(p.z)));
    }
}

/// CONTACT's margin for close encounters of two segments, mm.
const BOWTIE_TINY: f64 = 1e-9;

/// Whether segments a0–a1 and b0–b1 intersect, within `tiny` (CONTACT's
/// `segs_have_intersection`).
fn segments_intersect(a0: Pt, a1: Pt, b0: Pt, b1: Pt, tiny: f64) -> bool {
    if a0.y.max(a1.y) + tiny < b0.y.min(b1.y) || b0.y.max(b1.y) + tiny < a0.y.min(a1.y) {
        return false;
    }
    if a0.z.max(a1.z) + tiny < b0.z.min(b1.z) || b0.z.max(b1.z) + tiny < a0.z.min(a1.z) {
        return false;
    }
    let (mut ty, mut tz) = (a1.y - a0.y, a1.z - a0.z);
    let mut len = (ty * ty + tz * tz).sqrt();
    if len < 1e-20 {
        len = 1.0;
    }
    ty /= len;
    tz /= len;
    let (ny, nz) = (-tz, ty);
    let local = |p: Pt| (ty * (p.y - a0.y) + tz * (p.z - a0.z), ny * (p.y - a0.y) + nz * (p.z - a0.z));
    let ((t2a, n2a), (t2b, n2b)) = (local(b0), local(b1));
    if n2a.max(n2b) < -tiny || n2a.min(n2b) > tiny {
        return false;
    }
    if n2a.abs().max(n2b.abs()) < tiny {
        return true;
    }
    let ti = t2a - n2a * (t2b - t2a) / (n2b - n2a);
    !(ti < -tiny || ti > len + tiny)
}

/// A profile whose segments cross another one (a loop, CONTACT's `profile_check_bowtie`, error 323)
/// is refused, naming the first pair and the count.
pub fn check_no_loop(pts: &[Pt], file: &str) -> Result<(), ProfileError> {
    let nseg = pts.len().saturating_sub(1);
    let mut first: Option<(usize, usize)> = None;
    let mut count = 0usize;
    for i in 0..nseg.saturating_sub(1) {
        for j in i + 2..nseg {
            if segments_intersect(pts[i], pts[i + 1], pts[j], pts[j + 1], BOWTIE_TINY) {
                count += 1;
                first.get_or_insert((i, j));
            }
        }
    }
    match first {
        None => Ok(()),
        Some((i, j)) => {
            let seg = |k: usize| {
                let (a, b) = (pts[k], pts[k + 1]);
                let lines = if a.line > 0 { format!(" (lines {}–{})", a.line, b.line) } else { String::new() };
                format!("segment {}{lines} ({}, {})–({}, {})", k + 1, a.y, a.z, b.y, b.z)
            };
            Err(ProfileError::profile(
                file,
                "segments that cross each other (a loop)",
                format!("{} crosses {} ({count} crossing(s) in all)", seg(i), seg(j)),
                "a profile whose segments do not cross (CONTACT's error 323)",
            ))
        }
    }
}

/// CONTACT's kink detection settings (KINKHIGH, KINKLOW, KINKWID).
#[derive(Debug, Clone, Copy)]
pub struct KinkSettings {
    pub high_rad: f64,
    pub low_rad: f64,
    pub width_mm: f64,
}

/// The turn of the inclination at each interior point (0-based; 0 at the ends).
fn turns(pts: &[Pt]) -> Vec<f64> {
    let n = pts.len();
    let mut dalph = vec![0.0; n];
    for i in 1..n.saturating_sub(1) {
        let (dy0, dz0) = (pts[i].y - pts[i - 1].y, pts[i].z - pts[i - 1].z);
        let (dy1, dz1) = (pts[i + 1].y - pts[i].y, pts[i + 1].z - pts[i].z);
        dalph[i] = wrap(dz1.atan2(dy1) - dz0.atan2(dy0));
    }
    dalph
}

/// Whether no neighbour of 1-based point `ipnt` within `width` turns by more than `low` (the
/// neighbours walked outwards while closer than `width`, as CONTACT does).
fn isolated(pts: &[Pt], dalph: &[f64], ipnt: usize, s: &KinkSettings) -> bool {
    let n = pts.len();
    let dist =
        |a: usize, b: usize| ((pts[a - 1].y - pts[b - 1].y).powi(2) + (pts[a - 1].z - pts[b - 1].z).powi(2)).sqrt();
    let mut k = ipnt;
    let mut dst = 0.0;
    while k > 2 && dst < s.width_mm {
        k -= 1;
        dst = dist(ipnt, k);
        if dst < s.width_mm && dalph[k - 1].abs() > s.low_rad {
            return false;
        }
    }
    let mut k = ipnt;
    dst = 0.0;
    while k < n - 1 && dst < s.width_mm {
        k += 1;
        dst = dist(k, ipnt);
        if dst < s.width_mm && dalph[k - 1].abs() > s.low_rad {
            return false;
        }
    }
    true
}

/// The break points of the spline (0-based indices, the first and last point included): the
/// kinks, CONTACT's `profile_find_kinks`. A kink two points after the previous break gets a break
/// at the point between (no section of one segment beside another); past 97 breaks no more kinks
/// are recorded.
pub fn find_kinks(pts: &[Pt], s: &KinkSettings) -> Vec<usize> {
    let n = pts.len();
    let dalph = turns(pts);
    let mut breaks = vec![1usize];
    for ipnt in 2..n {
        if dalph[ipnt - 1].abs() <= s.high_rad || !isolated(pts, &dalph, ipnt, s) {
            continue;
        }
        if breaks.len() >= MAX_KINKS - 2 {
            continue;
        }
        if ipnt - breaks[breaks.len() - 1] == 2 {
            breaks.push(ipnt - 1);
        }
        breaks.push(ipnt);
    }
    if breaks.len() < MAX_KINKS {
        breaks.push(n);
    }
    breaks.into_iter().map(|b| b - 1).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(v: &[(f64, f64)]) -> Vec<Pt> {
        v.iter().map(|&(y, z)| Pt::new(y, z, 0)).collect()
    }

    #[test]
    fn close_points_are_dropped_against_the_last_kept() {
        let mut p = pts(&[(0.0, 0.0), (0.00005, 0.0), (0.00009, 0.0), (0.0002, 0.0), (1.0, 0.0)]);
        assert_eq!(drop_close_points(&mut p, POINT_DIST_MIN), 2);
        assert_eq!(p.iter().map(|p| p.y).collect::<Vec<_>>(), [0.0, 0.0002, 1.0]);
    }

    #[test]
    fn a_zigzag_is_replaced_by_the_mean_of_its_points() {
        // A straight line with points 3 and 4 swapped: two turns of 180°.
        let mut p = pts(&[(0.0, 0.0), (1.0, 0.0), (3.0, 0.0), (2.0, 0.0), (4.0, 0.0), (5.0, 0.0), (6.0, 0.0)]);
        assert_eq!(replace_zigzags(&mut p, 150f64.to_radians()), 1);
        assert_eq!(p.iter().map(|p| p.y).collect::<Vec<_>>(), [0.0, 1.0, 2.5, 4.0, 5.0, 6.0]);
    }

    #[test]
    fn a_loop_is_refused_naming_the_crossing_segments() {
        let p = pts(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, -1.0), (3.0, -1.0)]);
        let e = check_no_loop(&p, "loop.txt").unwrap_err().to_string();
        assert!(e.contains("segment 1") && e.contains("segment 3") && e.contains("323"), "{e}");
        check_no_loop(&pts(&[(0.0, 0.0), (1.0, 0.0), (2.0, 1.0), (3.0, 0.0)]), "ok.txt").unwrap();
    }

    #[test]
    fn an_isolated_corner_is_a_kink_and_a_rounded_one_is_not() {
        let s = KinkSettings { high_rad: 30f64.to_radians(), low_rad: 6f64.to_radians(), width_mm: 2.0 };
        // A V with 1 mm spacing: one turn of 90° at point 10 (0-based).
        let v: Vec<(f64, f64)> = (0..21).map(|i| (i as f64, (i as f64 - 10.0).abs())).collect();
        assert_eq!(find_kinks(&pts(&v), &s), [0, 10, 20]);
        // A circle sampled finely turns by little at every point: no kink.
        let c: Vec<(f64, f64)> =
            (0..50).map(|i| (i as f64 * 0.1).sin_cos()).map(|(a, b)| (10.0 * a, 10.0 * b)).collect();
        assert_eq!(find_kinks(&pts(&c), &s), [0, 49]);
    }
}
