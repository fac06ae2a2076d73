//! An out-of-round wheel (CONTACT's wheel slices file `.slcw`, a wheel whose profile varies around
//! its circumference: a wheel flat; user guide, "Module 1", "Wheel slices-file"): the surface
//! r(θ, y_w) = NOMRAD + z(θ, y_w) of [`Slices`] at material angle θ, the wheel pitched by PITCH so
//! that θ = −PITCH lies at its lowest point (`compute_oor_whl`: `convert_cyl2cart`, x = r sin θ,
//! z = r cos θ, then `cartgrid_pitch`), and CONTACT's mesh of it around the contact
//! (`compute_oor_whl`: θ = −PITCH ± 0.2 rad in slices about 4 DX apart).

use super::mesh_interp::{interpolate, Mesh, Scheme, Uniform};
use super::patch::{PatchFrame, PatchGrid};
use super::profile::slices::Slices;
use super::wheel::PlacedWheel;
use nalgebra::{Point3, Vector3};
use std::f64::consts::PI;

/// The half-width of the mesh around the lowest point [rad] (`compute_oor_whl`).
const MESH_HALF_ANGLE_RAD: f64 = 0.2;
/// The mesh's slices are this many DX apart at the nominal radius (`compute_oor_whl`).
const MESH_STEP_OVER_DX: f64 = 4.0;

/// A wheel slices file with the wheelset's pitch angle.
#[derive(Debug, Clone, Copy)]
pub struct WheelSlices<'a> {
    pub slices: &'a Slices,
    /// PITCH [rad]: the material angle θ = −PITCH lies at the wheel's lowest point.
    pub pitch_rad: f64,
}

/// θ mapped to [−π, π) (CONTACT's `wrap_around`).
pub fn wrap_around(theta_rad: f64) -> f64 {
    (theta_rad + PI).rem_euclid(2.0 * PI) - PI
}

impl WheelSlices<'_> {
    /// The material angle θ at angle φ from the lowest point (positive forward, along +x):
    /// θ = φ − PITCH, wrapped.
    pub fn theta_rad(&self, phi_rad: f64) -> f64 {
        wrap_around(phi_rad - self.pitch_rad)
    }

    /// The profile's z [mm] at angle φ from the lowest point and profile position y_w (the
    /// surface's radius there is NOMRAD + z); `None` where the surface does not reach y_w.
    pub fn z_mm(&self, phi_rad: f64, y_w_mm: f64) -> Option<f64> {
        self.slices.surface_z_at(self.theta_rad(phi_rad), y_w_mm)
    }
}

/// The mesh's lateral parameters: the m samples' sites (CONTACT's `nknotv − 6` values from
/// `tvj(4)` to `tvj(nknotv − 3)`, its not-a-knot spline's knots reinserted: the sites).
fn lateral_parameters(slices: &Slices) -> Vec<f64> {
    (0..slices.samples()).map(|k| k as f64).collect()
}

/// The number of angles of the mesh of a wheel of nominal radius `radius_mm` for elements of
/// `dx_mm` (`compute_oor_whl`: round(0.4 R / (4 DX) + 2), odd).
pub fn mesh_angles(radius_mm: f64, dx_mm: f64) -> usize {
    let n = (2.0 * MESH_HALF_ANGLE_RAD * radius_mm / (MESH_STEP_OVER_DX * dx_mm) + 2.0).round() as usize;
    n + usize::from(n.is_multiple_of(2))
}

/// CONTACT's mesh of the out-of-round wheel (`compute_oor_whl`) for elements of `dx_mm`, in the
/// wheel's frame from its centre: angles θ = −PITCH − 0.2 + k dθ (fastest; nslc =
/// round(0.4 R / (4 DX) + 2), odd), then the lateral parameters; the number of angles and the nodes.
pub fn mesh_local(oor: &WheelSlices, wheel: &PlacedWheel, dx_mm: f64) -> (usize, Vec<Vector3<f64>>) {
    let radius = wheel.nominal_radius_mm;
    let span = 2.0 * MESH_HALF_ANGLE_RAD;
    let n = mesh_angles(radius, dx_mm);
    let d_theta = span / (n as f64 - 1.0).max(1.0);
    let theta_min = -oor.pitch_rad - MESH_HALF_ANGLE_RAD;
    let v = lateral_parameters(oor.slices);
    let columns: Vec<(f64, Vec<(f64, f64)>)> = (0..n)
        .map(|k| {
            let theta = theta_min + k as f64 * d_theta;
            (theta + oor.pitch_rad, oor.slices.surface_at(wrap_around(theta), &v))
        })
        .collect();
    let mut nodes = Vec::with_capacity(n * v.len());
    for j in 0..v.len() {
        for (phi, points) in &columns {
            let (y, z) = points[j];
            let rho = radius + z;
            let (s, c) = phi.sin_cos();
            nodes.push(Vector3::new(rho * s, wheel.y_offset_mm + y, rho * c));
        }
    }
    (n, nodes)
}

/// The wheel's n (distance along the plane's normal from the plane) at every element centre of
/// `grid`, interpolated bicubically in CONTACT's mesh of the out-of-round wheel around the patch
/// (`wr_ud_planar` with a variable wheel profile): the grid's x edges and the region's lateral
/// ends `y_mm` (the rail's z there along the plane at the grid's s edges) in the wheel's frame,
/// widened by 2 DX along x; angles θ from −PITCH + atan(x / r_min) at both ends in slices about
/// DX apart (round((θ₁ − θ₀) R / DX) + 2, odd), the lateral parameter v uniform over the
/// samples' sites; `None` off the mesh.
pub fn wheel_n_mm(
    oor: &WheelSlices,
    wheel: &PlacedWheel,
    frame: &PatchFrame,
    grid: &PatchGrid,
    y_mm: [f64; 2],
) -> Vec<Option<f64>> {
    let radius = wheel.nominal_radius_mm;
    let (sin_d, _) = frame.delta_rad.sin_cos();
    let x_edges = [grid.x0_mm, grid.x0_mm + grid.mx as f64 * grid.dx_mm].map(|x| frame.origin.x + x);
    let s_edges = [grid.s0_mm, grid.s0_mm + grid.ms as f64 * grid.ds_mm];
    let z_at = s_edges.map(|s| frame.origin.z + s * sin_d);
    let corners =
        [(0, 0), (0, 1), (1, 0), (1, 1)].map(|(i, j)| wheel.to_wheel(&Point3::new(x_edges[i], y_mm[j], z_at[j])));
    let x_min = corners.iter().map(|q| q.x).fold(f64::MAX, f64::min) - 2.0 * grid.dx_mm;
    let x_max = corners.iter().map(|q| q.x).fold(f64::MIN, f64::max) + 2.0 * grid.dx_mm;
    // q.z from the centre is NOMRAD plus the profile's z: r_min = NOMRAD + z_min.
    let r_min = corners.iter().map(|q| q.z).fold(f64::MAX, f64::min) - grid.ds_mm * sin_d.abs();
    let (th0, th1) = (-oor.pitch_rad + (x_min / r_min).atan(), -oor.pitch_rad + (x_max / r_min).atan());
    let mut n_u = ((th1 - th0) * radius / grid.dx_mm).round() as usize + 2;
    if n_u.is_multiple_of(2) {
        n_u += 1;
    }
    let d_th = (th1 - th0) / (n_u as f64 - 1.0).max(1.0);
    let v = lateral_parameters(oor.slices);
    let (e_s, n) = (frame.e_s(), frame.n());
    let columns: Vec<(f64, Vec<(f64, f64)>)> = (0..n_u)
        .map(|k| {
            let theta = th0 + k as f64 * d_th;
            (theta + oor.pitch_rad, oor.slices.surface_at(wrap_around(theta), &v))
        })
        .collect();
    let mut nodes = Vec::with_capacity(n_u * v.len());
    for j in 0..v.len() {
        for (phi, points) in &columns {
            let (y, dr) = points[j];
            let rho = radius + dr;
            let p = wheel.to_track(Vector3::new(rho * phi.sin(), wheel.y_offset_mm + y, rho * phi.cos()));
            let d = p - frame.origin;
            nodes.push([d.x, d.dot(&e_s), d.dot(&n)]);
        }
    }
    let out = Uniform {
        x0: grid.x0_mm + 0.5 * grid.dx_mm,
        dx: grid.dx_mm,
        nx: grid.mx,
        y0: grid.s0_mm + 0.5 * grid.ds_mm,
        dy: grid.ds_mm,
        ny: grid.ms,
    };
    interpolate(Mesh { nodes: &nodes, n_u }, &out, Scheme::Bicubic)
}
