//! The rigid slip on the actual surfaces (CONTACT's D = 3 and 4, `m_wr_rigslip`
//! `wr_rigslip_wrsurf` with `project_midplane` and `extract_creepages`): the rail's (or roller's)
//! and the wheel's material velocities at each element's points of the two surfaces, less the
//! wheelset's forward speed along the track (on a roller rig the frame stands still), in the
//! patch's frame — on a conformal patch turned into the row's frame of the curved reference (a
//! roll by the row's normal, `gf3_cart2curv`) — their longitudinal parts taken along the
//! mid-plane of the two velocities; their difference over the speed is the rigid slip per
//! element. Its least-squares creepages over the interpenetration (CKSI, CETA, CPHI, the spin
//! about the point cos CHI · dq/6 ahead of each element's centre as the solver takes it) are the
//! patch's; the rest is an extra rigid slip per element (module 3's E = 9).

use super::conformal_grid::ConformalPatch;
use super::creepage::{backwards, Creepages, RailMotion};
use super::patch::{PatchGeometry, Surfaces};
use super::roller::Roller;
use super::wheel::{PlacedWheel, Velocity};
use nalgebra::{Point3, Vector3};

/// CONTACT's offset of the spin term, as a fraction of dq (FACPHI in rolling; none in shifts).
const FACPHI: f64 = 1.0 / 6.0;

/// A patch's creepages and the rest of its rigid slip.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceSlip {
    pub creepages: Creepages,
    /// The extra rigid slip per element (wx, wy) [-]: CONTACT's element order, its x and the
    /// row's lateral direction.
    pub extra: (Vec<f64>, Vec<f64>),
}

/// The velocity `v` (track) in row j's frame: (along x, along the row's tangent, along its
/// normal); in planar contact the patch's own (x, s, n), on a conformal patch the row's tangent
/// is the plane's e_s turned by the angle between the normals.
fn in_row(g: &PatchGeometry, curved: Option<&ConformalPatch>, j: usize, v: Vector3<f64>) -> [f64; 3] {
    let (e_s, n) = (g.frame.e_s(), g.frame.n());
    let (v_s, v_n) = (v.dot(&e_s), v.dot(&n));
    let Some(c) = curved else { return [v.x, v_s, v_n] };
    let [cy, cz] = c.reference.normal_yz(j);
    // The row's outward normal in the plane's (s, n).
    let (c_s, c_n) = (cy * e_s.y + cz * e_s.z, cy * n.y + cz * n.z);
    [v.x, -c_n * v_s + c_s * v_n, -(c_s * v_s + c_n * v_n)]
}

/// The rail's (or the roller's) and the wheel's velocities at element k's points of the surfaces,
/// in row j's frame.
struct Velocities<'a> {
    g: &'a PatchGeometry,
    s: &'a Surfaces,
    wheel: &'a PlacedWheel<'a>,
    v: &'a Velocity,
    rail: &'a RailMotion,
    roller: Option<&'a Roller>,
}

impl Velocities<'_> {
    fn at(&self, j: usize, i: usize) -> ([f64; 3], [f64; 3]) {
        let (g, k) = (self.g, j * self.g.grid.mx + i);
        let curved = g.curved.as_ref();
        let (x, s) = g.grid.centre(i, j);
        let on_plane = g.frame.at(x, curved.map_or(s, |c| c.sp_mm[j]));
        let t_r = self.s.rail_n_mm[k].unwrap_or(0.0);
        let t_w = self.s.wheel_n_mm[k].unwrap_or(t_r);
        let n = g.frame.n();
        let (p_r, p_w): (Point3<f64>, Point3<f64>) = (on_plane + n * t_r, on_plane + n * t_w);
        let v_r = self.rail.at(&p_r) + self.roller.map_or(Vector3::zeros(), |r| r.material_velocity(&p_r));
        let v_w = self.wheel.material_velocity(&p_w, self.v);
        (in_row(g, curved, j, v_r), in_row(g, curved, j, v_w))
    }
}

/// The step a patch's rigid slip is taken over (`wr_rigslip_wrsurf`: `dq`, VELOC).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SlipStep {
    /// Rolling, steady or transient: the spin about the point cos CHI · dq/6 ahead of each
    /// element's centre, dq = DQREL · DX (DX in steady rolling).
    Rolling { dq_mm: f64 },
    /// A shift (T = 1): one step's shifts, VELOC = 1, dt = 1, the spin about the element itself.
    Shift,
}

/// The rigid slip of patch `g` on its surfaces (`None` where it has none: D = 2) with the wheel
/// `wheel` moving as `v`, the rail as `rail` (on a roller rig the roller turning too), over `step`.
pub fn rigid_slip(
    g: &PatchGeometry,
    wheel: &PlacedWheel,
    (v, rail, roller): (&Velocity, &RailMotion, Option<&Roller>),
    step: SlipStep,
) -> Option<SurfaceSlip> {
    let shift = step == SlipStep::Shift;
    let s = g.surfaces.as_ref()?;
    let grid = &g.grid;
    let at = Velocities { g, s, wheel, v, rail, roller };
    let vel: Vec<([f64; 3], [f64; 3])> =
        (0..grid.ms).flat_map(|j| (0..grid.mx).map(move |i| (j, i))).map(|(j, i)| at.at(j, i)).collect();
    // The speed and direction (`wr_rigslip_wrsurf`): one in shifts; the wheelset's forward speed
    // on a track; on a roller rig the mean of the surfaces' speeds at the element nearest the
    // reference.
    let (veloc, reversed) = match roller {
        _ if shift => (1.0, false),
        None => (v.vs_mm_s.abs(), v.vs_mm_s < 0.0),
        Some(_) => {
            let (v_r, v_w) = vel[nearest_the_reference(g)];
            (0.5 * (v_r[0] + v_w[0]).abs(), backwards(v_r[0], v_w[0]))
        }
    };
    let sgn = if reversed { -1.0 } else { 1.0 };
    // The frame moves with the wheelset along the track (not on a roller rig).
    let frame_speed = if roller.is_some() { 0.0 } else { sgn * veloc };
    let w: Vec<[f64; 2]> = vel
        .into_iter()
        .map(|(mut v_r, mut v_w)| {
            v_r[0] -= frame_speed;
            v_w[0] -= frame_speed;
            // The mid-plane's direction in (x, n): the mean of the two velocities (one material).
            let (mx, mn) = (0.5 * (v_r[0] + v_w[0]), 0.5 * (v_r[2] + v_w[2]));
            let scale = -sgn / (mx * mx + mn * mn).max(1e-16).sqrt();
            let along = |u: [f64; 3]| (u[0] * mx + u[2] * mn) * scale;
            [(along(v_r) - along(v_w)) / veloc, (v_r[1] - v_w[1]) / veloc]
        })
        .collect();
    let offset_mm = match step {
        SlipStep::Shift => 0.0,
        SlipStep::Rolling { dq_mm } => sgn * FACPHI * dq_mm,
    };
    let centre = |k: usize| {
        let (x, s) = grid.centre(k % grid.mx, k / grid.mx);
        (x + offset_mm, s)
    };
    let inside: Vec<usize> = (0..grid.len()).filter(|&k| g.h_mm[k] < 0.0).collect();
    let (cksi, ceta, cphi_per_mm) = least_squares(&inside, &centre, &w);
    let (wx, wy) = (0..grid.len())
        .map(|k| {
            let (x, y) = centre(k);
            (w[k][0] - cksi + y * cphi_per_mm, w[k][1] - ceta - x * cphi_per_mm)
        })
        .unzip();
    let creepages = Creepages { cksi, ceta, cphi_per_mm, veloc_mm_s: veloc, reversed };
    Some(SurfaceSlip { creepages, extra: (wx, wy) })
}

/// The element whose centre lies nearest the patch's reference (CONTACT's `iimin`, the first
/// of equals).
fn nearest_the_reference(g: &PatchGeometry) -> usize {
    let grid = &g.grid;
    let d2 = |k: usize| {
        let (x, s) = grid.centre(k % grid.mx, k / grid.mx);
        x * x + s * s
    };
    (0..grid.len()).fold(0, |best, k| if d2(k) < d2(best) { k } else { best })
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
