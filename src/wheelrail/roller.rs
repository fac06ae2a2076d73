//! A wheel on a roller rig (CONTACT's C = 4, 5; user guide, "Module 1", the C digit): the rail
//! profile is the roller's, a surface of revolution about the roller's axis, parallel to the
//! track's y at NOMRAD_R below the profile's z = 0, turning at VPITCH_ROL. What differs from a
//! wheel on a track: the contact locus iterated on the roller (`m_wr_locatecp`,
//! `locus_iterate_roller`), the rail's curvature along x in the interpenetration's weight
//! (`locate_interpen_1d`), the reference's height on the roller at its x (`set_cpatch_reference`),
//! the roller's surface meshed for the undeformed distance (`wr_ud_planar`, `grid_revolve_profile`)
//! and its material's velocity in the creepages (`wr_creep_cref`).

use super::patch::{PatchFrame, PatchGrid};
use super::rail::PlacedRail;
use super::varrail::Loci;
use super::wheel::PlacedWheel;
use nalgebra::{Point3, Vector3};

/// The roller: NOMRAD_R [mm] (its axis that far below the profile's z = 0) and VPITCH_ROL [rad/s]
/// (its angular velocity about its axis, the track's y).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Roller {
    pub radius_mm: f64,
    pub vpitch_rad_s: f64,
}

/// The locus iteration's sweeps (`locus_iterate_roller`: `niter = 3`).
const LOCUS_SWEEPS: usize = 3;
/// The roller's height where its profile has no point or its circle no point at x [mm]
/// (CONTACT's 888: no contact there).
const OFF_ROLLER_MM: f64 = 888.0;

impl Roller {
    /// The effective radius of the wheel (radius `wheel_mm`) and the roller along x: the curvature
    /// of the gap, 1/R_w + 1/R_r, in the interpenetration's weight and chord (`curv_y`).
    pub fn gap_radius_mm(&self, wheel_mm: f64) -> f64 {
        1.0 / (1.0 / wheel_mm + 1.0 / self.radius_mm)
    }

    /// The height of the roller at track (x, z0) where its principal profile (x = 0) has height z0,
    /// the axis at `axis_z_mm`: z_c − √((z_c − z0)² − x²) (`set_cpatch_reference`).
    pub fn z_at_x(axis_z_mm: f64, z0_mm: f64, x_mm: f64) -> f64 {
        let r = axis_z_mm - z0_mm;
        axis_z_mm - (r * r - x_mm * x_mm).max(0.0).sqrt()
    }

    /// The roller's axis height in the track for the reference point and the creepages: the rail
    /// profile's origin z plus NOMRAD_R (`set_cpatch_reference`: `mtrk%z() + nom_radius`).
    pub fn axis_z_mm(&self, rail: &PlacedRail) -> f64 {
        rail.origin_mm[1] + self.radius_mm
    }

    /// The velocity of the roller's material at track point `p`, axis at (·, ·, `axis_z_mm`):
    /// ω × (p − C), ω = (0, VPITCH_ROL, 0) (`wr_creep_cref`, `m_rol%o = (0, 0, NOMRAD_R)`).
    pub fn material_velocity(&self, p: &Point3<f64>) -> Vector3<f64> {
        Vector3::new(0.0, self.vpitch_rad_s, 0.0).cross(&Vector3::new(p.x, p.y, p.z - self.radius_mm))
    }

    /// The roller's angular velocity (track coordinates).
    pub fn angular_velocity(&self) -> Vector3<f64> {
        Vector3::new(0.0, self.vpitch_rad_s, 0.0)
    }
}

/// CONTACT's contact locus of `wheel` on the roller (`locus_iterate_roller`): from x = 0 at every
/// wheel profile point, three sweeps of: the locus points in the track; the roller's radius
/// below each, r = R_r − z_r(y) (the placed profile's height, the axis at z = R_r in the track),
/// its height R_r − √(r² − x²) and slope dz/dx = x / r; the wheel's x where its circle's slope
/// along the track is the roller's, linearised in x with the roller's nominal curvature, clamped
/// to ±R_w/2. The wheel's locus is its last x (z from the x before), the roller's the points of
/// the last sweep; each CONTACT's spline. `None` for a wheel without profile points.
pub fn loci(roller: &Roller, rail: &PlacedRail, wheel: &PlacedWheel) -> Option<Loci> {
    let nodes = wheel.curve.locus_nodes()?;
    if nodes.len() < 2 {
        return None;
    }
    let (rw, rr) = (wheel.nominal_radius_mm, roller.radius_mm);
    let r = wheel.rotation.matrix();
    let mut x: Vec<f64> = vec![0.0; nodes.len()];
    let mut z_lc: Vec<f64> = nodes.iter().map(|n| n.z_mm).collect();
    let at = |x: f64, y_w: f64, z: f64| wheel.to_track(Vector3::new(x, wheel.y_offset_mm + y_w, rw + z));
    let mut rail_pts = vec![Point3::origin(); nodes.len()];
    for _ in 0..LOCUS_SWEEPS {
        for (i, n) in nodes.iter().enumerate() {
            let q = at(x[i], n.y_mm, z_lc[i]);
            let rho = rail.z_mm(q.y).map(|z| rr - z);
            let z_r = match rho {
                Some(rho) if rho * rho - q.x * q.x > 0.0 => rr - (rho * rho - q.x * q.x).sqrt(),
                _ => OFF_ROLLER_MM,
            };
            rail_pts[i] = Point3::new(q.x, q.y, z_r);
            let dz_dx = rho.map_or(0.0, |rho| q.x / rho);
            let ry = rw + n.z_mm;
            z_lc[i] = if ry * ry - x[i] * x[i] > 0.0 { (ry * ry - x[i] * x[i]).sqrt() - rw } else { -999.0 };
            let rnom_z = rw + z_lc[i];
            let a_y = ry * n.dz_dy;
            let denom = x[i] * r[(2, 0)] - a_y * r[(2, 1)] + rnom_z * r[(2, 2)];
            let x_new =
                (-denom * dz_dx + denom * x[i] / rr + a_y * r[(0, 1)] - rnom_z * r[(0, 2)]) / (r[(0, 0)] + denom / rr);
            x[i] = x_new.clamp(-0.5 * rw, 0.5 * rw);
        }
    }
    let wheel_pts: Vec<Point3<f64>> = nodes.iter().enumerate().map(|(i, n)| at(x[i], n.y_mm, z_lc[i])).collect();
    let s_wheel: Vec<f64> = nodes.iter().map(|n| n.s_mm).collect();
    Some(Loci::through(s_wheel, &wheel_pts, &rail_pts))
}

/// The roller's n (distance along the plane's normal from the plane) at every element centre, on
/// CONTACT's mesh of it (`wr_ud_planar` with `grid_revolve_profile`, `interp_cartz2unif`): the
/// rail profile's points (rail coordinates) revolved about the axis R_r below the profile's z = 0
/// into slices at track x = x_ref + i DX, placed in the track and taken to the patch's plane. The
/// slices lie on the grid's columns (the plane's x is the track's less x_ref), where CONTACT's
/// bilinear interpolation in a cell is linear in s between the slice's two nodes: each element's n
/// is that, in the first segment of its column's slice that holds its s; `None` where none does
/// (CONTACT's h there is the surfaces' own: measured with its `.mat` output on `test-rollers2`
/// case 6, every one of the 3721 elements to its 6 printed digits).
pub fn rail_n_mm(roller: &Roller, rail: &PlacedRail, frame: &PatchFrame, grid: &PatchGrid) -> Option<Vec<Option<f64>>> {
    let points = rail.curve.points_mm()?;
    let (e_s, n) = (frame.e_s(), frame.n());
    let (sin, cos) = rail.angle_rad.sin_cos();
    let rr = roller.radius_mm;
    let mut out = vec![None; grid.len()];
    for i in 0..grid.mx {
        let x = frame.origin.x + grid.centre(i, 0).0;
        // The slice's nodes (s, n) in the profile's order.
        let nodes: Vec<[f64; 2]> = points
            .iter()
            .filter_map(|&[y_r, z_r]| {
                let rho = (z_r - rr).abs();
                (rho * rho - x * x > 0.0).then(|| {
                    let z = rr - (rho * rho - x * x).sqrt();
                    let p = Point3::new(
                        x,
                        rail.origin_mm[0] + cos * y_r - sin * z,
                        rail.origin_mm[1] + sin * y_r + cos * z,
                    );
                    let d = p - frame.origin;
                    [d.dot(&e_s), d.dot(&n)]
                })
            })
            .collect();
        for j in 0..grid.ms {
            let s = grid.centre(i, j).1;
            let segment = nodes.windows(2).find(|w| (w[0][0].min(w[1][0])..=w[0][0].max(w[1][0])).contains(&s));
            out[j * grid.mx + i] = segment.map(|w| {
                let t = if w[1][0] == w[0][0] { 0.0 } else { (s - w[0][0]) / (w[1][0] - w[0][0]) };
                w[0][1] + t * (w[1][1] - w[0][1])
            });
        }
    }
    Some(out)
}
