//! The curved reference surface of a conformal patch (CONTACT's D = 4, `m_wr_locatecp`
//! `compute_curved_potcon`; user guide, "Conformal contact"): rail points at the rail profile's
//! arc length DS apart around the patch's reference, each paired with the wheel's point at the
//! opposite arc length from the wheel's reference, revolved to the reference's track x; the curve
//! is their midpoint, its normal the mean of the two outward normals. The rows kept are those
//! whose midpoint lies in the region's lateral range with a mean normal longer than 0.9, and two
//! beyond on each side.

use super::patch::{Candidate, PatchFrame};
use super::rail::PlacedRail;
use super::wheel::PlacedWheel;
use nalgebra::Vector3;

/// How far the rail's arc-length range reaches beyond the region's, relative (CONTACT's `fac_sc`).
const WIDEN: f64 = 0.2;
/// Rows added beyond the widened range on each side before the rows are chosen.
const EXTRA_ROWS: i64 = 3;
/// Rows kept beyond the chosen ones on each side.
const KEPT_BEYOND: usize = 2;
/// The shortest mean normal of a chosen row: the surfaces turn less than 2 acos(0.9) ≈ 52° apart.
const MIN_NORMAL: f64 = 0.9;
/// Fixed-point passes on the wheel points' x in the wheel (CONTACT's three).
const X_PASSES: usize = 3;

/// The curved reference: one point per grid row, rows DS apart in the rail's arc length.
#[derive(Debug, Clone, PartialEq)]
pub struct CurvedReference {
    /// The first row's index in the lattice of the reference's rail arc length (row j at arc
    /// length (first + j) DS from the reference, CONTACT's `sc`).
    pub first_row: i64,
    /// Each row's point: the rail's and the wheel's midpoint in track coordinates (y, z) [mm].
    pub point_mm: Vec<[f64; 2]>,
    /// Each row's normal: the mean of the rail's and the wheel's outward unit normals (track
    /// x, y, z; the rail's outward: up), not normalised.
    pub normal: Vec<[f64; 3]>,
}

impl CurvedReference {
    /// The number of rows.
    pub fn rows(&self) -> usize {
        self.point_mm.len()
    }

    /// Row j's unit normal in the track's y–z plane (the x part dropped, as CONTACT's rotations
    /// about x take it).
    pub fn normal_yz(&self, j: usize) -> [f64; 2] {
        let [_, ny, nz] = self.normal[j];
        let l = ny.hypot(nz);
        [ny / l, nz / l]
    }

    /// Row j's surface inclination atan2(n_y, −n_z) [rad] (CONTACT's `curv_incln`, printed as A).
    pub fn inclination_rad(&self, j: usize) -> f64 {
        let [_, ny, nz] = self.normal[j];
        ny.atan2(-nz)
    }

    /// Row j's point's lateral place in the patch's tangent plane, sp [mm] (CONTACT's
    /// `curved_sc_to_planar_sp`).
    pub fn sp_mm(&self, frame: &PatchFrame, j: usize) -> f64 {
        let [y, z] = self.point_mm[j];
        let e = frame.e_s();
        (y - frame.origin.y) * e.y + (z - frame.origin.z) * e.z
    }
}

/// The wheel profile's point at its spline parameter `s_w_mm`, revolved to the wheel's x `x_w`
/// (its frame, from the axle), in track coordinates, with the profile's outward unit normal
/// turned by the wheel's rotation (CONTACT's `grid_revolve_profile`, `spline_get_nvec_at_s`).
fn wheel_point(wheel: &PlacedWheel, s_w_mm: f64, x_w: f64) -> Option<(nalgebra::Point3<f64>, Vector3<f64>)> {
    let p = wheel.curve.spline_point(s_w_mm)?;
    let rho = wheel.nominal_radius_mm + p.z_mm;
    let z = (rho * rho - x_w * x_w).max(0.0).sqrt();
    let point = wheel.to_track(Vector3::new(x_w, wheel.y_offset_mm + p.y_mm, z));
    let [ty, tz] = p.tangent();
    Some((point, wheel.rotation * Vector3::new(0.0, tz, -ty)))
}

/// The curved reference of candidate `c` with frame `frame`, rows `ds_mm` apart in the rail's arc
/// length: from the reference in steady rolling, from the profile's arc-length origin on the
/// super-grid of shifts (`super_grid`; `compute_curved_potcon` with `sr_pot` = 0); `None` where a
/// profile has no spline (a closed form) or the rows leave a profile.
pub fn curved_reference(
    c: &Candidate,
    frame: &PatchFrame,
    (rail, wheel): (&PlacedRail, &PlacedWheel),
    ds_mm: f64,
    super_grid: bool,
) -> Option<CurvedReference> {
    let sr_ref = rail.s_mm(frame.origin.y)?;
    let sr_pot = if super_grid { 0.0 } else { sr_ref };
    let sr_sta = rail.s_mm(c.y_mm[0])?.min(sr_ref);
    let sr_end = rail.s_mm(c.y_mm[1])?.max(sr_ref);
    let sc_sta = sr_sta + WIDEN * (sr_sta - sr_ref) - sr_pot;
    let sc_end = sr_end + WIDEN * (sr_end - sr_ref) - sr_pot;
    let (k0, k1) = ((sc_sta / ds_mm).round() as i64 - EXTRA_ROWS, (sc_end / ds_mm).round() as i64 + EXTRA_ROWS);
    // Each row's rail arc length from the reference.
    let sc: Vec<f64> = (k0..=k1).map(|k| sr_pot + k as f64 * ds_mm - sr_ref).collect();
    let rail_rows: Vec<([f64; 2], [f64; 2])> = sc.iter().map(|s| rail.point_at_s(sr_ref + s)).collect::<Option<_>>()?;
    // The wheel: the reference's place in its frame, the arc length there, the opposite way.
    let q = wheel.to_wheel(&frame.origin);
    let sw_ref = wheel.curve.s_at_y(q.y - wheel.y_offset_mm)?;
    let mut x_w = vec![q.x; sc.len()];
    let mut wheel_rows = Vec::new();
    for pass in 0..X_PASSES {
        if pass > 0 {
            for (x, (p, _)) in x_w.iter_mut().zip(&wheel_rows) {
                let p: &nalgebra::Point3<f64> = p;
                *x += frame.origin.x - p.x;
            }
        }
        wheel_rows = sc.iter().zip(&x_w).map(|(s, &x)| wheel_point(wheel, sw_ref - s, x)).collect::<Option<_>>()?;
    }
    let mid = |k: usize| {
        let ((r, nr), (w, nw)) = (&rail_rows[k], &wheel_rows[k]);
        let point = [0.5 * (r[0] + w.y), 0.5 * (r[1] + w.z)];
        (point, [-0.5 * nw.x, 0.5 * (nr[0] - nw.y), 0.5 * (nr[1] - nw.z)])
    };
    // The row nearest the reference (the first of two equally near), and the rows chosen.
    let k_ref = (0..sc.len()).fold(0, |b, k| if sc[k].abs() < sc[b].abs() { k } else { b });
    let (mut lo, mut hi) = (k_ref.saturating_sub(1), k_ref + 1);
    for k in 0..sc.len() {
        let ([y, _], [nx, ny, nz]) = mid(k);
        if y >= c.y_mm[0] && y <= c.y_mm[1] && (nx * nx + ny * ny + nz * nz).sqrt() > MIN_NORMAL {
            (lo, hi) = (lo.min(k), hi.max(k));
        }
    }
    let (lo, hi) = (lo.saturating_sub(KEPT_BEYOND), (hi + KEPT_BEYOND).min(sc.len() - 1));
    let (point_mm, normal) = (lo..=hi).map(mid).unzip();
    Some(CurvedReference { first_row: k0 + lo as i64, point_mm, normal })
}

impl CurvedReference {
    /// The reference over rows `first_row ..= first_row + rows − 1` of its lattice, a superset of
    /// its own (CONTACT's `extend_curv_ref`, a grid widened to the contact of the time before):
    /// the points extended linearly from the two end rows, the normals constant.
    pub fn extended(&self, first_row: i64, rows: usize) -> CurvedReference {
        let (n, before) = (self.rows(), self.first_row - first_row);
        debug_assert!(n >= 2 && before >= 0 && rows as i64 >= before + n as i64, "a superset of the rows");
        let step = |a: usize, b: usize| {
            let (p, q) = (self.point_mm[a], self.point_mm[b]);
            [p[0] - q[0], p[1] - q[1]]
        };
        let (down, up) = (step(0, 1), step(n - 1, n - 2));
        let row = |j: usize| {
            let k = j as i64 - before;
            let (edge, d, m) = if k < 0 {
                (0, down, -k)
            } else if k >= n as i64 {
                (n - 1, up, k - n as i64 + 1)
            } else {
                (k as usize, [0.0; 2], 0)
            };
            let p = self.point_mm[edge];
            ([p[0] + m as f64 * d[0], p[1] + m as f64 * d[1]], self.normal[edge])
        };
        let (point_mm, normal) = (0..rows).map(row).unzip();
        CurvedReference { first_row, point_mm, normal }
    }
}
