//! A contact patch from an interpenetration region (user guide, "Identification of contact
//! patches" and "Potential contact area and discretisation"; planar contact, D = 2): its reference
//! point and contact angle weighted by the interpenetration, its tangent plane, the potential
//! contact grid (DX × DS, edges on multiples of the element size from the reference point) and
//! the undeformed distance along the plane's normal between the exact surfaces.

use super::rail::PlacedRail;
use super::search::LocusSample;
use super::wheel::PlacedWheel;
use super::WheelRailError;
use nalgebra::{Point3, Vector3};

/// Elements added on every side of the interpenetration's extent (CONTACT's guard band).
const GUARD_ELEMENTS: i64 = 1;

/// The contact's local frame: origin on the rail, x along the track, s in the tangent plane
/// (the rail's lateral direction turned by δ), n into the rail.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchFrame {
    pub origin: Point3<f64>,
    /// δ: rotation about x from the track's z axis to n [rad].
    pub delta_rad: f64,
}

impl PatchFrame {
    pub fn e_s(&self) -> Vector3<f64> {
        Vector3::new(0.0, self.delta_rad.cos(), self.delta_rad.sin())
    }
    pub fn n(&self) -> Vector3<f64> {
        Vector3::new(0.0, -self.delta_rad.sin(), self.delta_rad.cos())
    }
    /// The track point at plane coordinates (x, s).
    pub fn at(&self, x_mm: f64, s_mm: f64) -> Point3<f64> {
        self.origin + Vector3::x() * x_mm + self.e_s() * s_mm
    }
}

/// The potential contact: `mx × ms` elements of `dx × ds` over `[x0, x0 + mx dx] × [s0, s0 + ms ds]`
/// in plane coordinates, element centres on whole multiples of dx and ds from the reference.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchGrid {
    pub mx: usize,
    pub ms: usize,
    pub dx_mm: f64,
    pub ds_mm: f64,
    pub x0_mm: f64,
    pub s0_mm: f64,
}

impl PatchGrid {
    /// Centre of element (i, j) in plane coordinates.
    pub fn centre(&self, i: usize, j: usize) -> (f64, f64) {
        (self.x0_mm + self.dx_mm * (i as f64 + 0.5), self.s0_mm + self.ds_mm * (j as f64 + 0.5))
    }
    pub fn len(&self) -> usize {
        self.mx * self.ms
    }
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// One patch's geometry: its frame, grid and undeformed distance (CONTACT's element order:
/// `j mx + i`, i along x).
#[derive(Debug, Clone, PartialEq)]
pub struct PatchGeometry {
    pub frame: PatchFrame,
    pub grid: PatchGrid,
    pub h_mm: Vec<f64>,
    /// The deepest interpenetration of the region [mm].
    pub pen_max_mm: f64,
}

/// The weight of a mesh point: `∫ (pen − a x²)² dx` over the chord where the wheel, a circle
/// of curvature 2a = 1/R_nom along x, reaches below the rail (CONTACT's squared-gap weight,
/// `compute_wgt_center_1d`).
fn weight(pen_mm: f64, a_per_mm: f64) -> f64 {
    let t0 = (pen_mm / a_per_mm).sqrt();
    (2.0 * pen_mm * pen_mm * t0 - 4.0 / 3.0 * pen_mm * a_per_mm * t0.powi(3) + 0.4 * a_per_mm * a_per_mm * t0.powi(5))
        .max(1e-10)
}

/// The interpenetration-weighted reference point and contact angle of a region (CONTACT's
/// "interpenetration centre of gravity", and the rail's height at its y).
pub fn reference(region: &[LocusSample], rail: &PlacedRail, radius_mm: f64) -> Option<PatchFrame> {
    let a = 0.5 / radius_mm;
    let inside = || region.iter().filter(|s| s.pen_mm >= 0.0);
    let w: f64 = inside().map(|s| weight(s.pen_mm, a)).sum();
    if w <= 0.0 {
        return None;
    }
    let mean = |f: &dyn Fn(&LocusSample) -> f64| inside().map(|s| weight(s.pen_mm, a) * f(s)).sum::<f64>() / w;
    let (x, y) = (mean(&|s| s.x_mm), mean(&|s| s.y_mm));
    let delta_rad = mean(&|s| s.rail_angle_rad);
    Some(PatchFrame { origin: Point3::new(x, y, rail.z_mm(y)?), delta_rad })
}

/// Where the gap crosses zero between mesh points k and k + step (linear), or point k's y.
fn crossing(region: &[LocusSample], k: usize, next: usize) -> f64 {
    let (a, b) = (&region[k], &region[next]);
    let d = b.pen_mm - a.pen_mm;
    if a.pen_mm * b.pen_mm <= -1e-12 && d.abs() >= 1e-9 {
        a.y_mm - a.pen_mm * (b.y_mm - a.y_mm) / d
    } else {
        a.y_mm
    }
}

/// Arc length [mm] along the rail from track y0 to y1 (signed; Simpson's rule on √(1 + z'²)).
fn arc_length(rail: &PlacedRail, y0: f64, y1: f64) -> f64 {
    const N: usize = 200;
    let h = (y1 - y0) / N as f64;
    let f = |y: f64| (1.0 + rail.dz_dy(y).unwrap_or(0.0).powi(2)).sqrt();
    let inner: f64 = (1..N).map(|k| if k % 2 == 1 { 4.0 } else { 2.0 } * f(y0 + h * k as f64)).sum();
    h / 3.0 * (f(y0) + inner + f(y1))
}

/// Element indices `[lo, hi]` covering `[from, to]` with centres on multiples of `d`, one guard
/// element beyond (CONTACT's `set_planar_potcon`).
fn indices(from: f64, to: f64, d: f64) -> (i64, i64) {
    ((from / d).floor() as i64 - GUARD_ELEMENTS, (to / d).ceil() as i64 + GUARD_ELEMENTS)
}

/// The potential contact: longitudinally each interpenetrating mesh point's `x ± √(pen/a)` (the
/// chord of a circle of curvature 2a = 1/R_nom), laterally the rail's arc length from the
/// reference to the region's zero crossings; rounded out to whole elements plus a guard element.
pub fn grid(
    region: &[LocusSample],
    frame: &PatchFrame,
    rail: &PlacedRail,
    radius_mm: f64,
    dx_mm: f64,
    ds_mm: f64,
) -> PatchGrid {
    let a = 0.5 / radius_mm;
    let (mut x_lo, mut x_hi) = (f64::MAX, f64::MIN);
    for p in region.iter().filter(|s| s.pen_mm >= 0.0) {
        let half = (p.pen_mm / a).sqrt();
        (x_lo, x_hi) = (x_lo.min(p.x_mm - half), x_hi.max(p.x_mm + half));
    }
    let last = region.len() - 1;
    let (y_sta, y_end) = (crossing(region, 0, 1.min(last)), crossing(region, last, last.saturating_sub(1)));
    let s_of = |y: f64| arc_length(rail, frame.origin.y, y);
    let (s_a, s_b) = (s_of(y_sta), s_of(y_end));
    let (ix_l, ix_h) = indices(x_lo - frame.origin.x, x_hi - frame.origin.x, dx_mm);
    let (is_l, is_h) = indices(s_a.min(s_b), s_a.max(s_b), ds_mm);
    PatchGrid {
        mx: (ix_h - ix_l + 1) as usize,
        ms: (is_h - is_l + 1) as usize,
        dx_mm,
        ds_mm,
        x0_mm: (ix_l as f64 - 0.5) * dx_mm,
        s0_mm: (is_l as f64 - 0.5) * ds_mm,
    }
}

/// Gap [mm] used where a normal line misses one of the surfaces (off the profiles' ends): far
/// outside any contact.
const MISSED_MM: f64 = 10.0;

/// The undeformed distance at every element: along n, from the wheel's surface to the rail's.
pub fn undeformed_distance(frame: &PatchFrame, grid: &PatchGrid, wheel: &PlacedWheel, rail: &PlacedRail) -> Vec<f64> {
    let n = frame.n();
    let mut h = Vec::with_capacity(grid.len());
    for j in 0..grid.ms {
        for i in 0..grid.mx {
            let (x, s) = grid.centre(i, j);
            let p = frame.at(x, s);
            let t_r = rail.along([p.y, p.z], [n.y, n.z]);
            let t_w = wheel.along(&p, &n);
            h.push(match (t_r, t_w) {
                (Some(r), Some(w)) => r - w,
                _ => MISSED_MM,
            });
        }
    }
    h
}

/// The patch of one region.
pub fn build(
    region: &[LocusSample],
    wheel: &PlacedWheel,
    rail: &PlacedRail,
    dx_mm: f64,
    ds_mm: f64,
) -> Result<PatchGeometry, WheelRailError> {
    let frame = reference(region, rail, wheel.nominal_radius_mm).ok_or(WheelRailError::NoContact)?;
    let grid = grid(region, &frame, rail, wheel.nominal_radius_mm, dx_mm, ds_mm);
    let h_mm = undeformed_distance(&frame, &grid, wheel, rail);
    let pen_max_mm = region.iter().map(|s| s.pen_mm).fold(0.0, f64::max);
    Ok(PatchGeometry { frame, grid, h_mm, pen_max_mm })
}
