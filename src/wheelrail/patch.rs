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

/// Elements added around the interpenetration on every side.
const MARGIN_ELEMENTS: f64 = 2.0;

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
/// in plane coordinates.
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

/// The interpenetration-weighted reference point and contact angle of a region.
pub fn reference(region: &[LocusSample], rail: &PlacedRail) -> Option<PatchFrame> {
    let w: f64 = region.iter().map(|s| s.pen_mm).sum();
    if w <= 0.0 {
        return None;
    }
    let mean = |f: &dyn Fn(&LocusSample) -> f64| region.iter().map(|s| s.pen_mm * f(s)).sum::<f64>() / w;
    let (x, y) = (mean(&|s| s.x_mm), mean(&|s| s.y_mm));
    let delta_rad = mean(&|s| s.rail_slope.atan());
    Some(PatchFrame { origin: Point3::new(x, y, rail.z_mm(y)?), delta_rad })
}

/// The grid covering the region with [`MARGIN_ELEMENTS`] on each side: laterally the region's
/// extent in s, longitudinally each locus point's `x ± √(2 R pen)` (a circle of the wheel's radius
/// R cut at depth pen).
pub fn grid(region: &[LocusSample], frame: &PatchFrame, radius_mm: f64, dx_mm: f64, ds_mm: f64) -> PatchGrid {
    let e_s = frame.e_s();
    let s_of = |s: &LocusSample| (Point3::new(s.x_mm, s.y_mm, s.z_mm) - frame.origin).dot(&e_s);
    let (mut s_lo, mut s_hi, mut x_lo, mut x_hi) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in region {
        let half = (2.0 * radius_mm * p.pen_mm).sqrt();
        let x = p.x_mm - frame.origin.x;
        (x_lo, x_hi) = (x_lo.min(x - half), x_hi.max(x + half));
        (s_lo, s_hi) = (s_lo.min(s_of(p)), s_hi.max(s_of(p)));
    }
    let edges = |lo: f64, hi: f64, d: f64| {
        let (a, b) = ((lo / d).floor() - MARGIN_ELEMENTS, (hi / d).ceil() + MARGIN_ELEMENTS);
        (a * d, (b - a) as usize)
    };
    let (x0_mm, mx) = edges(x_lo, x_hi, dx_mm);
    let (s0_mm, ms) = edges(s_lo, s_hi, ds_mm);
    PatchGrid { mx, ms, dx_mm, ds_mm, x0_mm, s0_mm }
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
    let frame = reference(region, rail).ok_or(WheelRailError::NoContact)?;
    let grid = grid(region, &frame, wheel.nominal_radius_mm, dx_mm, ds_mm);
    let h_mm = undeformed_distance(&frame, &grid, wheel, rail);
    let pen_max_mm = region.iter().map(|s| s.pen_mm).fold(0.0, f64::max);
    Ok(PatchGeometry { frame, grid, h_mm, pen_max_mm })
}
