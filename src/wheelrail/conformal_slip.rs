//! The rigid slip of a conformal patch on the actual surfaces (CONTACT's D = 4, `m_wr_rigslip`
//! `wr_rigslip_wrsurf` with `project_midplane` and `extract_creepages`): the rail's and the
//! wheel's material velocities at each element's points of the two surfaces, less the rolling
//! speed along the track, turned into the row's frame of the curved reference (a roll by the
//! row's normal, `gf3_cart2curv`), their longitudinal parts taken along the mid-plane of the two
//! velocities; their difference over the speed is the rigid slip per element. Its least-squares
//! creepages over the interpenetration (CKSI, CETA, CPHI, the spin about the point dq/6 ahead of
//! each element's centre as the solver takes it) are the patch's; the rest is an extra rigid slip
//! per element (module 3's E = 9).

use super::conformal_grid::ConformalPatch;
use super::creepage::{Creepages, RailMotion};
use super::patch::PatchGeometry;
use super::wheel::{PlacedWheel, Velocity};
use nalgebra::Vector3;

/// CONTACT's offset of the spin term, as a fraction of dq (FACPHI in rolling; none in shifts).
const FACPHI: f64 = 1.0 / 6.0;

/// A conformal patch's creepages and the rest of its rigid slip.
#[derive(Debug, Clone, PartialEq)]
pub struct ConformalSlip {
    pub creepages: Creepages,
    /// The extra rigid slip per element (wx, wy) [-]: CONTACT's element order, its x and the
    /// row's lateral direction.
    pub extra: (Vec<f64>, Vec<f64>),
}

/// The velocity `v` (track) in row j's frame: (along x, along the row's tangent, along its inward
/// normal); the row's tangent is the plane's e_s turned by the angle between the normals.
fn in_row(g: &PatchGeometry, c: &ConformalPatch, j: usize, v: Vector3<f64>) -> [f64; 3] {
    let (e_s, n) = (g.frame.e_s(), g.frame.n());
    let [cy, cz] = c.reference.normal_yz(j);
    // The row's outward normal in the plane's (s, n).
    let (c_s, c_n) = (cy * e_s.y + cz * e_s.z, cy * n.y + cz * n.z);
    let (v_s, v_n) = (v.dot(&e_s), v.dot(&n));
    [v.x, -c_n * v_s + c_s * v_n, -(c_s * v_s + c_n * v_n)]
}

/// The rigid slip of conformal patch `g` with the wheel `wheel` moving as `v`, the rail as
/// `rail`; the rolling step dq = DX, or with `shift` (T = 1) one step's shifts: VELOC = 1, dt = 1,
/// the spin about the reference itself (`None` in planar contact).
pub fn rigid_slip(
    g: &PatchGeometry,
    wheel: &PlacedWheel,
    (v, rail): (&Velocity, &RailMotion),
    shift: bool,
) -> Option<ConformalSlip> {
    let c = g.curved.as_ref()?;
    let grid = &g.grid;
    let veloc = if shift { 1.0 } else { v.vs_mm_s };
    let n = g.frame.n();
    let mut w = Vec::with_capacity(grid.len());
    for j in 0..grid.ms {
        for i in 0..grid.mx {
            let k = j * grid.mx + i;
            let on_plane = g.frame.at(grid.centre(i, j).0, c.sp_mm[j]);
            let t_r = c.rail_n_mm[k].unwrap_or(0.0);
            let t_w = c.wheel_n_mm[k].unwrap_or(t_r);
            let mut v_r = in_row(g, c, j, rail.at(&(on_plane + n * t_r)));
            let mut v_w = in_row(g, c, j, wheel.material_velocity(&(on_plane + n * t_w), v));
            v_r[0] -= veloc;
            v_w[0] -= veloc;
            // The mid-plane's direction in (x, n): the mean of the two velocities (one material).
            let (mx, mn) = (0.5 * (v_r[0] + v_w[0]), 0.5 * (v_r[2] + v_w[2]));
            let scale = -1.0 / (mx * mx + mn * mn).max(1e-16).sqrt();
            let along = |u: [f64; 3]| (u[0] * mx + u[2] * mn) * scale;
            w.push([(along(v_r) - along(v_w)) / veloc, (v_r[1] - v_w[1]) / veloc]);
        }
    }
    let offset_mm = if shift { 0.0 } else { FACPHI * grid.dx_mm };
    let at = |k: usize| {
        let (x, s) = grid.centre(k % grid.mx, k / grid.mx);
        (x + offset_mm, s)
    };
    let inside: Vec<usize> = (0..grid.len()).filter(|&k| g.h_mm[k] < 0.0).collect();
    let (cksi, ceta, cphi_per_mm) = least_squares(&inside, &at, &w);
    let (wx, wy) = (0..grid.len())
        .map(|k| {
            let (x, y) = at(k);
            (w[k][0] - cksi + y * cphi_per_mm, w[k][1] - ceta - x * cphi_per_mm)
        })
        .unzip();
    Some(ConformalSlip { creepages: Creepages { cksi, ceta, cphi_per_mm, veloc_mm_s: veloc }, extra: (wx, wy) })
}

/// The creepages (CKSI, CETA, CPHI) whose rigid slip `(cksi − y cphi, ceta + x cphi)` fits `w`
/// over the elements `inside` in least squares (CONTACT's `extract_creepages`); zero where none.
fn least_squares(inside: &[usize], at: &dyn Fn(usize) -> (f64, f64), w: &[[f64; 2]]) -> (f64, f64, f64) {
    let n = inside.len() as f64;
    let mean = |f: &dyn Fn(usize) -> f64| inside.iter().map(|&k| f(k)).sum::<f64>() / n;
    let (x, y) = (mean(&|k| at(k).0), mean(&|k| at(k).1));
    let r2 = mean(&|k| at(k).0.powi(2) + at(k).1.powi(2));
    let (wx, wy) = (mean(&|k| w[k][0]), mean(&|k| w[k][1]));
    let wz = mean(&|k| at(k).0 * w[k][1] - at(k).1 * w[k][0]);
    let denom = r2 - x * x - y * y;
    if inside.is_empty() || denom < 1e-12 {
        return (0.0, 0.0, 0.0);
    }
    let cphi = (wz + y * wx - x * wy) / denom;
    (wx + y * cphi, wy - x * cphi, cphi)
}
