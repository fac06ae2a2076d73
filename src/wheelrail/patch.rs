//! A contact patch from an interpenetration region (user guide, "Identification of contact
//! patches" and "Potential contact area and discretisation"; planar contact, D = 2): its reference
//! point and contact angle weighted by the interpenetration, its tangent plane, the potential
//! contact grid (DX × DS, edges on multiples of the element size from the reference point) and
//! the undeformed distance along the plane's normal between the surfaces (the wheel's exact or
//! CONTACT's mesh of it).

use super::conformal_grid::ConformalPatch;
use super::conformal_reference;
use super::oorwheel;
use super::profile::Profile;
use super::rail::PlacedRail;
use super::roller::{self, Roller};
use super::search::LocusSample;
use super::varrail::RailSlices;
use super::wheel::PlacedWheel;
use super::wheel_mesh::{self, WheelSurface};
use super::{conformal_grid, shift, Motion, WheelRailError};
use crate::physics::halfspace::blend::Blend;
use crate::scene::wheelrail::Approach;
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
/// in plane coordinates, element centres on whole multiples of dx and ds from the anchor: the
/// reference in steady rolling, CONTACT's material-fixed super-grid origin in a shift.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchGrid {
    pub mx: usize,
    pub ms: usize,
    pub dx_mm: f64,
    pub ds_mm: f64,
    pub x0_mm: f64,
    pub s0_mm: f64,
    /// The anchor (x, s) in plane coordinates [mm] (CONTACT's `mpot`; (0, 0): the reference).
    pub anchor_mm: [f64; 2],
    /// The indices (i, j) of the grid's first element in the anchor's lattice (element centres at
    /// the anchor plus (i dx, j ds)): in a shift, CONTACT's super-grid indices, the same material
    /// point from case to case.
    pub first_index: [i64; 2],
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
    /// The sub-patches of regions combined between D_COMB and D_SEP, their cross-influence
    /// attenuated in the normal problem (CONTACT's blending approach); `None` for one region.
    pub blend: Option<Blend>,
    /// The interpenetration's extent in track coordinates (what a continued shift connects by).
    pub extent: Extent,
    /// The rail profile's arc length at the reference (CONTACT's `sr_ref`; `None` for a closed-form
    /// rail): where a steady grid lies on the super-grid when transient rolling follows it.
    pub rail_s_mm: Option<f64>,
    /// The conformal approach's curved reference (CONTACT's D = 4), one point per grid row: the
    /// grid's s is then its arc length; `None` in planar contact.
    pub curved: Option<ConformalPatch>,
    /// The surfaces the rigid slip is taken on, element by element (CONTACT's D = 3 and 4:
    /// `wr_rigslip_wrsurf`); `None` where the creepages are the reference's (D = 2).
    pub surfaces: Option<Surfaces>,
}

/// The rail's and the wheel's surfaces at each element: their distance along the patch's normal
/// n from the plane [mm] (CONTACT's element order, its `rail_srfc`, `whl_srfc`; `None` off a
/// surface).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Surfaces {
    pub rail_n_mm: Vec<Option<f64>>,
    pub wheel_n_mm: Vec<Option<f64>>,
}

impl Surfaces {
    pub(super) fn with_capacity(n: usize) -> Self {
        Surfaces { rail_n_mm: Vec::with_capacity(n), wheel_n_mm: Vec::with_capacity(n) }
    }

    pub(super) fn push(&mut self, rail_mm: Option<f64>, wheel_mm: Option<f64>) {
        self.rail_n_mm.push(rail_mm);
        self.wheel_n_mm.push(wheel_mm);
    }

    /// The undeformed distance at element `k` along n, the rail's less the wheel's (scaled by
    /// `factor`); [`MISSED_MM`] off either surface.
    pub fn gap_mm(&self, k: usize, factor: f64) -> f64 {
        match (self.rail_n_mm[k], self.wheel_n_mm[k]) {
            (Some(r), Some(w)) => (r - w) * factor,
            _ => MISSED_MM,
        }
    }

    /// The undeformed distance at every element ([`Surfaces::gap_mm`]).
    pub fn gaps_mm(&self) -> Vec<f64> {
        (0..self.rail_n_mm.len()).map(|k| self.gap_mm(k, 1.0)).collect()
    }
}

/// The weight of a mesh point: `∫ (pen − a x²)² dx` over the chord where the wheel, a circle
/// of curvature 2a = 1/R_nom along x, reaches below the rail (CONTACT's squared-gap weight,
/// `compute_wgt_center_1d`).
fn weight(pen_mm: f64, a_per_mm: f64) -> f64 {
    let t0 = (pen_mm / a_per_mm).sqrt();
    (2.0 * pen_mm * pen_mm * t0 - 4.0 / 3.0 * pen_mm * a_per_mm * t0.powi(3) + 0.4 * a_per_mm * a_per_mm * t0.powi(5))
        .max(1e-10)
}

/// A region's extent and weighted centre (CONTACT's `t_cpatch` before its grid): the chord's
/// x range, the y range to the gap's zero crossings with the rail's z there, the
/// interpenetration-weighted x, y and rail inclination, and the total weight.
#[derive(Debug, Clone, PartialEq)]
pub struct Candidate {
    pub x_mm: [f64; 2],
    pub y_mm: [f64; 2],
    pub z_mm: [f64; 2],
    pub wgt_x_mm: f64,
    pub wgt_y_mm: f64,
    pub wgt_angle_rad: f64,
    pub total_weight: f64,
    /// The deepest interpenetration [mm].
    pub pen_max_mm: f64,
    /// The extents of the sub-patches merged in between D_COMB and D_SEP (the first its own
    /// extent at that pass); empty until then.
    pub parts: Vec<Extent>,
}

/// An extent in track coordinates: x, y and the rail's z at the y ends [mm].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extent {
    pub x_mm: [f64; 2],
    pub y_mm: [f64; 2],
    pub z_mm: [f64; 2],
}

impl Candidate {
    fn extent(&self) -> Extent {
        Extent { x_mm: self.x_mm, y_mm: self.y_mm, z_mm: self.z_mm }
    }
}

/// The candidate patch of a region (CONTACT's `locate_interpen_1d` with `compute_wgt_center_1d`
/// and `compute_contact_length_1d`); `None` where nothing interpenetrates.
pub fn candidate(region: &[LocusSample], radius_mm: f64) -> Option<Candidate> {
    let a = 0.5 / radius_mm;
    let inside = || region.iter().filter(|s| s.pen_mm >= 0.0);
    let total_weight: f64 = inside().map(|s| weight(s.pen_mm, a)).sum();
    if total_weight <= 0.0 {
        return None;
    }
    let mean =
        |f: &dyn Fn(&LocusSample) -> f64| inside().map(|s| weight(s.pen_mm, a) * f(s)).sum::<f64>() / total_weight;
    let (mut x_lo, mut x_hi) = (f64::MAX, f64::MIN);
    for p in inside() {
        let half = (p.pen_mm / a).sqrt();
        (x_lo, x_hi) = (x_lo.min(p.x_mm - half), x_hi.max(p.x_mm + half));
    }
    let last = region.len() - 1;
    let (start, end) = (crossing(region, 0, 1.min(last)), crossing(region, last, last.saturating_sub(1)));
    Some(Candidate {
        x_mm: [x_lo, x_hi],
        y_mm: [start[0], end[0]],
        z_mm: [start[1], end[1]],
        wgt_x_mm: mean(&|s| s.x_mm),
        wgt_y_mm: mean(&|s| s.y_mm),
        wgt_angle_rad: mean(&|s| s.rail_angle_rad),
        total_weight,
        pen_max_mm: inside().map(|s| s.pen_mm).fold(0.0, f64::max),
        parts: Vec::new(),
    })
}

/// CONTACT's distance between two candidates' extents (`cpatch_distance`): the gaps between their
/// x ranges and between their y ranges, with the z step across the y gap.
pub fn distance_mm(a: &Candidate, b: &Candidate) -> f64 {
    extent_distance_mm(&a.extent(), &b.extent())
}

/// [`distance_mm`] between two extents.
fn extent_distance_mm(a: &Extent, b: &Extent) -> f64 {
    let gap = |lo0: f64, hi0: f64, lo1: f64, hi1: f64| (lo0 - hi1).max(lo1 - hi0).max(0.0);
    let dx = gap(a.x_mm[0], a.x_mm[1], b.x_mm[0], b.x_mm[1]);
    let (dy, dz) = if a.y_mm[0] > b.y_mm[1] {
        (a.y_mm[0] - b.y_mm[1], a.z_mm[0] - b.z_mm[1])
    } else if b.y_mm[0] > a.y_mm[1] {
        (b.y_mm[0] - a.y_mm[1], b.z_mm[0] - a.z_mm[1])
    } else {
        (0.0, 0.0)
    };
    (dx * dx + dy * dy + dz * dz).sqrt()
}

/// The thresholds of patch combination (A_SEP, D_SEP, D_COMB, D_TURN).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Separation {
    pub angle_rad: f64,
    pub distance_mm: f64,
    pub combine_mm: f64,
    /// Separate patches closer than D_TURN have their reference angles turned towards their
    /// weighted mean (CONTACT's default 2 D_SEP − D_COMB).
    pub turn_mm: f64,
}

/// `b` merged into `a`: the union of the extents, the weights' combined centre and angle.
fn merge(a: &mut Candidate, b: &Candidate) {
    let w = a.total_weight + b.total_weight;
    let mix = |u: f64, v: f64| (u * a.total_weight + v * b.total_weight) / w;
    a.wgt_x_mm = mix(a.wgt_x_mm, b.wgt_x_mm);
    a.wgt_y_mm = mix(a.wgt_y_mm, b.wgt_y_mm);
    a.wgt_angle_rad = mix(a.wgt_angle_rad, b.wgt_angle_rad);
    a.total_weight = w;
    a.x_mm = [a.x_mm[0].min(b.x_mm[0]), a.x_mm[1].max(b.x_mm[1])];
    if b.y_mm[0] < a.y_mm[0] {
        (a.y_mm[0], a.z_mm[0]) = (b.y_mm[0], b.z_mm[0]);
    }
    if b.y_mm[1] > a.y_mm[1] {
        (a.y_mm[1], a.z_mm[1]) = (b.y_mm[1], b.z_mm[1]);
    }
    a.pen_max_mm = a.pen_max_mm.max(b.pen_max_mm);
}

/// CONTACT's `sort_cpatches_yvalue`, `combine_cpatches` and `turn_cpatch_refangle`: candidates
/// from the field side to the track centre (y descending on the right side); a first pass merges
/// those within D_COMB, a second those within D_SEP keeping each merged region's extent as a
/// sub-patch (blended: [`sub_patch_factors`]), never two whose angles differ by more than A_SEP;
/// then neighbours between D_SEP and D_TURN apart have their angles turned ([`turn_angles`]).
pub fn combine(mut c: Vec<Candidate>, sep: &Separation) -> Vec<Candidate> {
    c.sort_by(|a, b| b.wgt_y_mm.total_cmp(&a.wgt_y_mm));
    for (pass, limit) in [sep.combine_mm, sep.distance_mm].into_iter().enumerate() {
        let mut i = 0;
        // CONTACT starts the sub-patches of every patch but the last in the second pass.
        while i + 1 < c.len() {
            if pass == 1 {
                c[i].parts = vec![c[i].extent()];
            }
            let mut j = i + 1;
            while j < c.len() {
                let close = (c[i].wgt_angle_rad - c[j].wgt_angle_rad).abs() <= sep.angle_rad
                    && distance_mm(&c[i], &c[j]) <= limit;
                if close {
                    let b = c.remove(j);
                    merge(&mut c[i], &b);
                    if pass == 1 {
                        c[i].parts.push(b.extent());
                    }
                } else {
                    j += 1;
                }
            }
            i += 1;
        }
    }
    turn_angles(&mut c, sep);
    c
}

/// CONTACT's `turn_cpatch_refangle`: for each pair of neighbours (in the order of [`combine`])
/// whose y–z gap d lies in [D_SEP, D_TURN] and whose angles differ by at most A_SEP, both angles
/// move by `(D_TURN − d) / (D_TURN − D_SEP)` of the way to their weighted mean (from the angles
/// before any turning).
fn turn_angles(c: &mut [Candidate], sep: &Separation) {
    if sep.turn_mm <= sep.distance_mm + 1e-12 {
        return;
    }
    let before: Vec<(f64, f64)> = c.iter().map(|p| (p.wgt_angle_rad, p.total_weight)).collect();
    for i in 0..c.len().saturating_sub(1) {
        let (a, b) = (&c[i], &c[i + 1]);
        let d = (a.y_mm[0] - b.y_mm[1]).hypot(a.z_mm[0] - b.z_mm[1]);
        let ((a0, w0), (a1, w1)) = (before[i], before[i + 1]);
        if (a0 - a1).abs() > sep.angle_rad || d < sep.distance_mm || d > sep.turn_mm {
            continue;
        }
        let mean = (a0 * w0 + a1 * w1) / (w0 + w1);
        let f = (sep.turn_mm - d) / (sep.turn_mm - sep.distance_mm);
        c[i].wgt_angle_rad += f * (mean - a0);
        c[i + 1].wgt_angle_rad += f * (mean - a1);
    }
}

/// The blending factors between a patch's sub-patches (CONTACT's `f_sep2`):
/// `((D_SEP − d) / (D_SEP − D_COMB))^0.8` for sub-patches d apart (0 beyond D_SEP), 1 on the
/// diagonal; row-major.
pub fn sub_patch_factors(parts: &[Extent], sep: &Separation) -> Vec<f64> {
    let n = parts.len();
    let mut f = vec![1.0; n * n];
    for i in 0..n {
        for j in i + 1..n {
            let d = extent_distance_mm(&parts[i], &parts[j]);
            let v = ((sep.distance_mm - d).max(0.0) / (sep.distance_mm - sep.combine_mm)).powf(0.8);
            (f[i * n + j], f[j * n + i]) = (v, v);
        }
    }
    f
}

/// The sub-patch of every element (CONTACT's `eldiv_cpatches` on the rectangles of
/// `m_wr_solvecp`): each sub-patch's x range and its y range in plane coordinates
/// ((y − y_ref) / cos δ), widened by 0.4 D_COMB, rounded to the nearest element centres; a later
/// sub-patch takes elements an earlier one holds; 0 outside all.
pub fn sub_patch_of_elements(parts: &[Extent], frame: &PatchFrame, grid: &PatchGrid, sep: &Separation) -> Vec<u16> {
    let cos = frame.delta_rad.cos();
    let lateral = |e: &Extent| [(e.y_mm[0] - frame.origin.y) / cos, (e.y_mm[1] - frame.origin.y) / cos];
    elements_of_parts(parts, frame, grid, sep, lateral)
}

/// The sub-patch of every element of a conformal patch (CONTACT's `m_wr_solvecp` with
/// `compute_sc_for_yz`): as [`sub_patch_of_elements`], each sub-patch's lateral range the rows
/// whose reference points lie nearest (in y, z) to its ends, the first of equals.
pub fn curved_sub_patch_of_elements(
    parts: &[Extent],
    frame: &PatchFrame,
    grid: &PatchGrid,
    reference: &super::conformal_reference::CurvedReference,
    sep: &Separation,
) -> Vec<u16> {
    let nearest_row = |y: f64, z: f64| {
        let d2 = |j: usize| (y - reference.point_mm[j][0]).powi(2) + (z - reference.point_mm[j][1]).powi(2);
        (0..reference.rows()).fold(0, |best, j| if d2(j) < d2(best) { j } else { best })
    };
    let row_s = |y: f64, z: f64| grid.centre(0, nearest_row(y, z)).1;
    let lateral = |e: &Extent| [row_s(e.y_mm[0], e.z_mm[0]), row_s(e.y_mm[1], e.z_mm[1])];
    elements_of_parts(parts, frame, grid, sep, lateral)
}

/// The sub-patch of every element from each sub-patch's x range and its `lateral` range on the
/// grid [mm], both widened by 0.4 D_COMB and rounded to the nearest element centres; a later
/// sub-patch takes elements an earlier one holds; 0 outside all.
fn elements_of_parts(
    parts: &[Extent],
    frame: &PatchFrame,
    grid: &PatchGrid,
    sep: &Separation,
    lateral: impl Fn(&Extent) -> [f64; 2],
) -> Vec<u16> {
    let widen = 0.4 * sep.combine_mm;
    let mut part = vec![0u16; grid.len()];
    let (xc0, sc0) = grid.centre(0, 0);
    let index = |v: f64, c0: f64, size: f64, n: usize| ((v - c0) / size).round().clamp(-1.0, n as f64) as i64;
    for (p, e) in parts.iter().enumerate() {
        let x = [e.x_mm[0] - frame.origin.x - widen, e.x_mm[1] - frame.origin.x + widen];
        let [s0, s1] = lateral(e);
        let s = [s0 - widen, s1 + widen];
        let (i0, i1) = (index(x[0], xc0, grid.dx_mm, grid.mx).max(0), index(x[1], xc0, grid.dx_mm, grid.mx));
        let (j0, j1) = (index(s[0], sc0, grid.ds_mm, grid.ms).max(0), index(s[1], sc0, grid.ds_mm, grid.ms));
        for j in j0..=j1.min(grid.ms as i64 - 1) {
            for i in i0..=i1.min(grid.mx as i64 - 1) {
                part[j as usize * grid.mx + i as usize] = p as u16 + 1;
            }
        }
    }
    part
}

/// The reference frame of a candidate: its weighted x and y on the rail, its weighted angle.
pub fn frame(c: &Candidate, rail: &PlacedRail) -> Option<PatchFrame> {
    Some(PatchFrame { origin: Point3::new(c.wgt_x_mm, c.wgt_y_mm, rail.z_mm(c.wgt_y_mm)?), delta_rad: c.wgt_angle_rad })
}

/// Where the gap crosses zero between mesh points k and `next`: y and the rail's z, each linear
/// between the two points (CONTACT's `locate_interpen_1d`, step 5.i), or point k's.
fn crossing(region: &[LocusSample], k: usize, next: usize) -> [f64; 2] {
    let (a, b) = (&region[k], &region[next]);
    let d = b.pen_mm - a.pen_mm;
    if a.pen_mm * b.pen_mm <= -1e-12 && d.abs() >= 1e-9 {
        let t = -a.pen_mm / d;
        [a.y_mm + t * (b.y_mm - a.y_mm), a.z_rail_mm + t * (b.z_rail_mm - a.z_rail_mm)]
    } else {
        [a.y_mm, a.z_rail_mm]
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

/// The potential contact of a candidate: its x range, and laterally the rail's arc length from the
/// reference to its y range's ends, rounded out to whole elements plus a guard element. In a
/// shift the same on CONTACT's super-grid (`set_planar_potcon` with `mpot`): x from track
/// x = −S_WS, s the rail profile's own arc length (its spline parameter), the reference at
/// (−S_WS − x_ref, −s_ref) from the anchor.
pub fn grid(
    c: &Candidate,
    frame: &PatchFrame,
    rail: &PlacedRail,
    (dx_mm, ds_mm): (f64, f64),
    motion: Motion,
) -> Result<PatchGrid, WheelRailError> {
    let ([xa, xb], [sa, sb], anchor_mm) = match motion {
        Motion::Rolling => {
            // The rail spline's parameter from the reference (CONTACT's sr − sr_pot), else the
            // arc length of the closed form.
            let spline = |y: f64| Some(rail.s_mm(y)? - rail.s_mm(frame.origin.y)?);
            let s_of = |y: f64| spline(y).unwrap_or_else(|| arc_length(rail, frame.origin.y, y));
            let x = [c.x_mm[0] - frame.origin.x, c.x_mm[1] - frame.origin.x];
            (x, [s_of(c.y_mm[0]), s_of(c.y_mm[1])], [0.0, 0.0])
        }
        Motion::Shift { .. } | Motion::Transient { .. } => {
            let s_ws_mm = motion.super_grid_s_mm().unwrap_or(0.0);
            let s_of = |y: f64| rail.s_mm(y).ok_or(WheelRailError::NoRailArcLength);
            let s_ref = s_of(frame.origin.y)?;
            let x = [c.x_mm[0] + s_ws_mm, c.x_mm[1] + s_ws_mm];
            (x, [s_of(c.y_mm[0])?, s_of(c.y_mm[1])?], [-s_ws_mm - frame.origin.x, -s_ref])
        }
    };
    let (ix_l, ix_h) = indices(xa, xb, dx_mm);
    let (is_l, is_h) = indices(sa.min(sb), sa.max(sb), ds_mm);
    Ok(PatchGrid {
        mx: (ix_h - ix_l + 1) as usize,
        ms: (is_h - is_l + 1) as usize,
        dx_mm,
        ds_mm,
        x0_mm: anchor_mm[0] + (ix_l as f64 - 0.5) * dx_mm,
        s0_mm: anchor_mm[1] + (is_l as f64 - 0.5) * ds_mm,
        anchor_mm,
        first_index: [ix_l, is_l],
    })
}

/// Gap [mm] used where a normal line misses one of the surfaces (off the profiles' ends): far
/// outside any contact.
pub(super) const MISSED_MM: f64 = 10.0;

/// How far beyond the grid's lateral range a column's cross-section is kept [mm]
/// ([`grid_rail_y_range`]).
const COLUMN_MARGIN_MM: f64 = 5.0;

/// The wheel's n at every element where it is CONTACT's mesh: of an out-of-round wheel always
/// (around the region's lateral ends `y_mm`), of a round one with [`WheelSurface::ContactMesh`].
fn meshed_wheel(
    frame: &PatchFrame,
    grid: &PatchGrid,
    wheel: &PlacedWheel,
    surface: WheelSurface,
    y_mm: [f64; 2],
) -> Option<Vec<Option<f64>>> {
    match &wheel.oor {
        Some(oor) => Some(oorwheel::wheel_n_mm(oor, wheel, frame, grid, y_mm)),
        None => (surface == WheelSurface::ContactMesh).then(|| {
            let rows: Vec<f64> = (0..grid.ms).map(|j| grid.centre(0, j).1).collect();
            wheel_mesh::wheel_n_mm(frame, grid, wheel, &rows)
        }),
    }
}

/// The surfaces at every element along n (the undeformed distance their difference,
/// [`Surfaces::gap_mm`]). The wheel's surface is the exact one or CONTACT's mesh of it (`meshed`,
/// [`meshed_wheel`]).
pub fn undeformed_distance(
    frame: &PatchFrame,
    grid: &PatchGrid,
    wheel: &PlacedWheel,
    rail: &PlacedRail,
    meshed: Option<Vec<Option<f64>>>,
) -> Surfaces {
    let n = frame.n();
    let mut h = Surfaces::with_capacity(grid.len());
    for j in 0..grid.ms {
        // The plane's point (x, s) lies at the same track (y, z) for every x: the rail (a prism
        // along x) is met at the same distance along n by the whole row.
        let (x0, s0) = grid.centre(0, j);
        let row = frame.at(x0, s0);
        let t_r = rail.along([row.y, row.z], [n.y, n.z]).or_else(|| rail_n_past_end(frame, rail, s0));
        for i in 0..grid.mx {
            let t_w = match &meshed {
                Some(m) => m[j * grid.mx + i],
                None => {
                    let (x, s) = grid.centre(i, j);
                    wheel.along(&frame.at(x, s), &n)
                }
            };
            h.push(t_r, t_w);
        }
    }
    h
}

/// The rail's n at plane coordinate `s_mm` past one of its profile's ends: the end's own n (CONTACT's
/// `spline_get_loc_xz_at_y` evaluates the rail turned into the patch's plane, and `spline_eval`
/// holds it constant beyond the spline's first and last points); `None` where `s_mm` lies past
/// neither end.
fn rail_n_past_end(frame: &PatchFrame, rail: &PlacedRail, s_mm: f64) -> Option<f64> {
    let (e_s, n) = (frame.e_s(), frame.n());
    let local = |[y, z]: [f64; 2], axis: Vector3<f64>| (y - frame.origin.y) * axis.y + (z - frame.origin.z) * axis.z;
    rail.ends_mm()?.into_iter().find_map(|(end, inside)| {
        let s_end = local(end, e_s);
        ((s_mm - s_end) * (local(inside, e_s) - s_end) < 0.0).then(|| local(end, n))
    })
}

/// Each grid column's cross-section of a variable rail, at track x = x_ref + x_i
/// (`varprof_get_loc_z_at_xy`: u = S_WS + x, held to the first and last slice), cut to the
/// samples near the grid's lateral range ([`RailSlices::section_near_x`]).
fn column_sections(
    v: &RailSlices,
    frame: &PatchFrame,
    grid: &PatchGrid,
    rail: &PlacedRail,
) -> Result<Vec<Profile>, WheelRailError> {
    let y_r = grid_rail_y_range(frame, grid, rail);
    (0..grid.mx)
        .map(|i| v.section_near_x(frame.origin.x + grid.centre(i, 0).0, y_r).ok_or(WheelRailError::NoContact))
        .collect()
}

/// The rail profile's lateral range [mm] under the grid's corners, widened by
/// [`COLUMN_MARGIN_MM`] for the lines along n that meet the rail beside them.
fn grid_rail_y_range(frame: &PatchFrame, grid: &PatchGrid, rail: &PlacedRail) -> [f64; 2] {
    let (s, c) = rail.angle_rad.sin_cos();
    let [oy, oz] = rail.origin_mm;
    let corners = [(0, 0), (grid.mx - 1, 0), (0, grid.ms - 1), (grid.mx - 1, grid.ms - 1)];
    let (lo, hi) = corners.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &(i, j)| {
        let (x, s_mm) = grid.centre(i, j);
        let p = frame.at(x, s_mm);
        let y_r = c * (p.y - oy) + s * (p.z - oz);
        (lo.min(y_r), hi.max(y_r))
    });
    [lo - COLUMN_MARGIN_MM, hi + COLUMN_MARGIN_MM]
}

/// [`undeformed_distance`] on a variable rail: the rail met along n in each column's own
/// cross-section (`columns[i]`, placed).
fn undeformed_distance_varying(
    frame: &PatchFrame,
    grid: &PatchGrid,
    wheel: &PlacedWheel,
    columns: &[PlacedRail],
    meshed: Option<Vec<Option<f64>>>,
) -> Surfaces {
    let n = frame.n();
    let mut h = Surfaces::with_capacity(grid.len());
    for j in 0..grid.ms {
        for (i, rail) in columns.iter().enumerate() {
            let (x, s) = grid.centre(i, j);
            let p = frame.at(x, s);
            let t_r = rail.along([p.y, p.z], [n.y, n.z]);
            let t_w = match &meshed {
                Some(m) => m[j * grid.mx + i],
                None => wheel.along(&p, &n),
            };
            h.push(t_r, t_w);
        }
    }
    h
}

/// [`undeformed_distance`] on a roller: the roller's n at each element (its mesh,
/// [`roller::rail_n_mm`]) less the wheel's; off the roller's mesh nothing touches.
fn roller_distance(
    frame: &PatchFrame,
    grid: &PatchGrid,
    wheel: &PlacedWheel,
    on_roller: &[Option<f64>],
    meshed: Option<Vec<Option<f64>>>,
) -> Surfaces {
    let n = frame.n();
    let mut h = Surfaces::with_capacity(grid.len());
    for j in 0..grid.ms {
        for i in 0..grid.mx {
            let e = j * grid.mx + i;
            let t_w = match &meshed {
                Some(m) => m[e],
                None => {
                    let (x, s) = grid.centre(i, j);
                    wheel.along(&frame.at(x, s), &n)
                }
            };
            h.push(on_roller[e], t_w);
        }
    }
    h
}

/// Where a widened grid reaches beyond the patch's own extent, no wheel surface: CONTACT meshes the
/// wheel over the region's x and y ranges and two elements beyond (`wr_ud_planar`: `xmin` …
/// `ymax`, the wheel's z −999 off the mesh), so an element whose point in the tangent plane lies
/// further out does not touch (another patch's interpenetration there is that patch's). Row j lies
/// at `row_s(j)` in the tangent plane (its own s; a conformal patch's row at its sp).
fn beyond_the_wheel_surface(
    c: &Candidate,
    frame: &PatchFrame,
    grid: &PatchGrid,
    row_s: impl Fn(usize) -> f64,
    h_mm: &mut [f64],
) {
    let (mx, my) = (2.0 * grid.dx_mm, 2.0 * grid.ds_mm);
    for j in 0..grid.ms {
        for i in 0..grid.mx {
            let p = frame.at(grid.centre(i, j).0, row_s(j));
            let off = p.x < c.x_mm[0] - mx || p.x > c.x_mm[1] + mx || p.y < c.y_mm[0] - my || p.y > c.y_mm[1] + my;
            if off {
                h_mm[j * grid.mx + i] = MISSED_MM;
            }
        }
    }
}

/// The patch of one candidate; in a shift that continues a sequence its grid widened to the
/// contact of the time before of the old patches it connects to ([`shift::widened`]); with the
/// conformal approach on its curved reference ([`conformal_grid`]).
pub fn build(
    c: &Candidate,
    wheel: &PlacedWheel,
    rail: &PlacedRail,
    size_mm: (f64, f64),
    sep: &Separation,
    (surface, motion, previous, approach): (WheelSurface, Motion, Option<&shift::Previous>, Approach),
    (slices, roller): (Option<&RailSlices>, Option<&Roller>),
) -> Result<PatchGeometry, WheelRailError> {
    // A variable rail: the cross-section at the reference's x (CONTACT's `complete_patches`).
    let section = match slices {
        Some(v) => Some(v.section_at_x(c.wgt_x_mm).ok_or(WheelRailError::NoContact)?),
        None => None,
    };
    let here = section.as_ref().map(|p| PlacedRail { curve: p, origin_mm: rail.origin_mm, angle_rad: rail.angle_rad });
    let rail = here.as_ref().unwrap_or(rail);
    let mut frame = frame(c, rail).ok_or(WheelRailError::NoContact)?;
    if let Some(r) = roller {
        // The reference on the roller at its x (`set_cpatch_reference`).
        frame.origin.z = Roller::z_at_x(r.axis_z_mm(rail), frame.origin.z, frame.origin.x);
    }
    let mut grid = grid(c, &frame, rail, size_mm, motion)?;
    if approach == Approach::Conformal {
        return build_conformal(c, frame, grid, (wheel, rail), (surface, motion, previous), sep);
    }
    let mut widened = false;
    if let (Some(_), Some(previous)) = (motion.super_grid_s_mm(), previous) {
        if let Some(old) = shift::inherited_by(c.extent(), previous) {
            widened = true;
            grid = shift::widened(&grid, &old, previous.iterated);
        }
    }
    let meshed = meshed_wheel(&frame, &grid, wheel, surface, c.y_mm);
    let surfaces = match (slices, roller) {
        (_, Some(r)) => {
            let on_roller = roller::rail_n_mm(r, rail, &frame, &grid).ok_or(WheelRailError::NoContact)?;
            roller_distance(&frame, &grid, wheel, &on_roller, meshed)
        }
        (Some(v), None) => {
            let columns = column_sections(v, &frame, &grid, rail)?;
            let placed: Vec<PlacedRail> = columns
                .iter()
                .map(|p| PlacedRail { curve: p, origin_mm: rail.origin_mm, angle_rad: rail.angle_rad })
                .collect();
            undeformed_distance_varying(&frame, &grid, wheel, &placed, meshed)
        }
        (None, None) => undeformed_distance(&frame, &grid, wheel, rail, meshed),
    };
    let mut h_mm = surfaces.gaps_mm();
    if widened {
        beyond_the_wheel_surface(c, &frame, &grid, |j| grid.centre(0, j).1, &mut h_mm);
    }
    let blend = (c.parts.len() > 1).then(|| {
        let part = sub_patch_of_elements(&c.parts, &frame, &grid, sep);
        // Outside every sub-patch nothing touches (CONTACT's planform, IPLAN = 4).
        for (h, p) in h_mm.iter_mut().zip(&part) {
            if *p == 0 {
                *h = MISSED_MM;
            }
        }
        Blend { part, factor: sub_patch_factors(&c.parts, sep), n: c.parts.len() }
    });
    let rail_s_mm = rail.s_mm(frame.origin.y);
    Ok(PatchGeometry {
        frame,
        grid,
        h_mm,
        pen_max_mm: c.pen_max_mm,
        blend,
        extent: c.extent(),
        rail_s_mm,
        curved: None,
        surfaces: (approach == Approach::PlanarSurfaceSlip).then_some(surfaces),
    })
}

/// The conformal patch of candidate `c` (CONTACT's D = 4): its curved reference, the grid on it
/// and the undeformed distance ([`conformal_grid`]); in a shift or transient step that continues
/// a sequence the grid widened to the contact of the time before and the reference extended to it
/// (`merge_prev_potcon`, `extend_curv_ref`); regions combined between D_COMB and D_SEP apart its
/// sub-patches on the curved rows ([`curved_sub_patch_of_elements`], blended as planar ones).
fn build_conformal(
    c: &Candidate,
    frame: PatchFrame,
    planar: PatchGrid,
    (wheel, rail): (&PlacedWheel, &PlacedRail),
    (surface, motion, previous): (WheelSurface, Motion, Option<&shift::Previous>),
    sep: &Separation,
) -> Result<PatchGeometry, WheelRailError> {
    let super_grid = motion.super_grid_s_mm().is_some();
    let mut reference = conformal_reference::curved_reference(c, &frame, (rail, wheel), planar.ds_mm, super_grid)
        .ok_or(WheelRailError::NoCurvedReference)?;
    let mut grid = conformal_grid::grid(&planar, &reference);
    let inherited =
        previous.filter(|_| super_grid).and_then(|p| shift::inherited_by(c.extent(), p).map(|old| (old, p.iterated)));
    let widened = inherited.is_some();
    if let Some((old, iterated)) = inherited {
        grid = shift::widened(&grid, &old, iterated);
        reference = reference.extended(grid.first_index[1], grid.ms);
    }
    let (patch, surfaces) = conformal_grid::surfaces(&frame, &grid, reference, (wheel, rail), surface);
    let mut h_mm = conformal_grid::undeformed_distance(&frame, &grid, &patch, &surfaces);
    if widened {
        beyond_the_wheel_surface(c, &frame, &grid, |j| patch.sp_mm[j], &mut h_mm);
    }
    let blend = (c.parts.len() > 1).then(|| {
        let part = curved_sub_patch_of_elements(&c.parts, &frame, &grid, &patch.reference, sep);
        // Outside every sub-patch nothing touches (CONTACT's planform, IPLAN = 4).
        for (h, p) in h_mm.iter_mut().zip(&part) {
            if *p == 0 {
                *h = MISSED_MM;
            }
        }
        Blend { part, factor: sub_patch_factors(&c.parts, sep), n: c.parts.len() }
    });
    let rail_s_mm = rail.s_mm(frame.origin.y);
    Ok(PatchGeometry {
        frame,
        grid,
        h_mm,
        pen_max_mm: c.pen_max_mm,
        blend,
        extent: c.extent(),
        rail_s_mm,
        curved: Some(patch),
        surfaces: Some(surfaces),
    })
}

#[cfg(test)]
#[path = "patch_tests.rs"]
mod tests;
