//! A rail whose profile varies along the track (CONTACT's variable rail profile, a `.slcs` slices
//! file: switches and crossings; user guide, "Module 1", "Variable profiles"): the rail surface
//! z(x, y) from [`Slices`] at u = S_WS + x, and what the contact search and the patches take from
//! it. The contact locus is iterated on the surface (`m_wr_locatecp`, `locus_iterate_varprof`):
//! the wheel's locus point at each profile point is where the wheel's circle there is tangent to
//! the rail along the track, dz/dx of the rail taken into account; the rail below the locus
//! (`prr_lc`) is a spline of its own (`compute_wr_locus`). A patch takes the cross-section at its
//! reference's x for its reference point and lateral extent (`complete_patches`,
//! `varprof_intpol_xunif`) and each grid column's own cross-section for the undeformed distance
//! (`varprof_get_loc_z_at_xy`).

use super::locus::LocusSpline;
use super::profile::slices::Slices;
use super::profile::Profile;
use super::wheel::PlacedWheel;
use nalgebra::{Point3, Vector3};

/// The step of the forward difference dz/dx [mm] (`varprof_get_z_at_xy`).
const DX_SLOPE_MM: f64 = 0.01;
/// The height given where the surface does not reach y [mm] (the iteration's `exterval`).
const OFF_SURFACE_MM: f64 = 987.0;
/// The locus iteration's tolerance on x [mm] and its largest number of sweeps (`epslc`, `maxit`).
const LOCUS_TOL_MM: f64 = 1e-3;
const LOCUS_SWEEPS: usize = 150;
/// The half-width of the track section searched, over the nominal radius (`0.6 ws%nom_radius`).
const SEARCH_OVER_RADIUS: f64 = 0.6;

/// A variable rail at the wheelset's position S_WS along the track.
#[derive(Debug, Clone, Copy)]
pub struct RailSlices<'a> {
    pub slices: &'a Slices,
    /// S_WS [mm]: the track's x = 0 lies at u = S_WS on the slices.
    pub s_ws_mm: f64,
}

/// The rail profile's frame in the track: a profile point (y_r, z_r) lies at
/// `origin + R(angle) (y_r, z_r)` (as [`super::rail::PlacedRail`]).
#[derive(Debug, Clone, Copy)]
pub struct RailFrame {
    pub origin_mm: [f64; 2],
    pub angle_rad: f64,
}

impl RailFrame {
    /// A track point (y, z) in rail profile coordinates.
    fn to_rail(self, y: f64, z: f64) -> [f64; 2] {
        let (s, c) = self.angle_rad.sin_cos();
        let (dy, dz) = (y - self.origin_mm[0], z - self.origin_mm[1]);
        [c * dy + s * dz, -s * dy + c * dz]
    }

    /// A rail profile point (y_r, z_r) in track coordinates.
    fn to_track(self, y_r: f64, z_r: f64) -> [f64; 2] {
        let (s, c) = self.angle_rad.sin_cos();
        [self.origin_mm[0] + c * y_r - s * z_r, self.origin_mm[1] + s * y_r + c * z_r]
    }
}

impl RailSlices<'_> {
    /// The cross-section at track x (u = S_WS + x, held to the first and last slice).
    pub fn section_at_x(&self, x_mm: f64) -> Option<Profile> {
        self.slices.section_at(self.s_ws_mm + x_mm).ok()
    }

    /// [`Self::section_at_x`] cut to the samples near the lateral range `y_r_mm` (rail profile y)
    /// ([`Slices::section_near`]).
    pub fn section_near_x(&self, x_mm: f64, y_r_mm: [f64; 2]) -> Option<Profile> {
        self.slices.section_near(self.s_ws_mm + x_mm, y_r_mm).ok()
    }

    /// The surface's height and dz/dx at rail point (x, y_r) (`varprof_get_z_at_xy`: a forward
    /// difference of 0.01 mm; 987 mm off the surface).
    fn z_and_dz_dx(&self, x_mm: f64, y_r_mm: f64) -> (f64, f64) {
        let u = self.s_ws_mm + x_mm;
        let z0 = self.slices.surface_z_at(u, y_r_mm).unwrap_or(OFF_SURFACE_MM);
        let z1 = self.slices.surface_z_at(u + DX_SLOPE_MM, y_r_mm).unwrap_or(OFF_SURFACE_MM);
        (z0, (z1 - z0) / DX_SLOPE_MM)
    }

    /// Per lateral position y_r the range of x within ±`x_max_mm` where slices hold it
    /// (`varprof_available_x` with `varprof_find_slices_xrange`: the slices over
    /// [S_WS − x_max, S_WS + x_max] and one beyond each end, each slice's lateral range its first
    /// and last point's y, held open beyond the first and last slice); an empty range is [0, 0].
    fn available_x(&self, y_r_mm: &[f64], x_max_mm: f64) -> Vec<[f64; 2]> {
        let u = self.slices.positions();
        let n = u.len();
        let (umin, umax) = (self.s_ws_mm - x_max_mm, self.s_ws_mm + x_max_mm);
        let (first, last) = if umax <= u[0] {
            (0, 0)
        } else if umin >= u[n - 1] {
            (n - 1, n - 1)
        } else {
            let mut i0 = n - 1;
            while u[i0] > umin && i0 > 0 {
                i0 -= 1;
            }
            let mut i1 = 0;
            while u[i1] <= umax && i1 < n - 1 {
                i1 += 1;
            }
            (i0, i1)
        };
        let mut out = vec![[1e9_f64, -1e9_f64]; y_r_mm.len()];
        for (i, &u_i) in u.iter().enumerate().take(last + 1).skip(first) {
            let x_slice = u_i - self.s_ws_mm;
            let ys = self.slices.slice(i).y_mm();
            let (lo, hi) = (ys[0], ys[ys.len() - 1]);
            for (r, &y) in out.iter_mut().zip(y_r_mm) {
                if y >= lo && y <= hi {
                    r[0] = r[0].min(x_slice);
                    r[1] = r[1].max(x_slice);
                    if i == 0 {
                        r[0] = -x_max_mm;
                    }
                    if i == n - 1 {
                        r[1] = x_max_mm;
                    }
                }
            }
        }
        for r in &mut out {
            *r = [r[0].max(-x_max_mm), r[1].min(x_max_mm)];
            if r[0] > r[1] {
                *r = [0.0, 0.0];
            }
        }
        out
    }
}

/// The contact locus on a variable rail: the wheel's locus and the rail below it, each CONTACT's
/// spline through its points (track coordinates).
#[derive(Debug, Clone)]
pub struct Loci {
    pub wheel: LocusSpline,
    pub rail: LocusSpline,
}

impl Loci {
    /// The loci through the wheel's points (at the wheel profile's arc lengths `s_wheel`) and the
    /// rail's points (parametrised by their own chord length in the track's (y, z)).
    pub fn through(s_wheel: Vec<f64>, wheel_pts: &[Point3<f64>], rail_pts: &[Point3<f64>]) -> Loci {
        let mut s_rail = Vec::with_capacity(rail_pts.len());
        let mut s = 0.0;
        for (k, p) in rail_pts.iter().enumerate() {
            if k > 0 {
                let q = &rail_pts[k - 1];
                s += (p.y - q.y).hypot(p.z - q.z);
            }
            s_rail.push(s);
        }
        Loci { wheel: LocusSpline::through(s_wheel, wheel_pts), rail: LocusSpline::through(s_rail, rail_pts) }
    }
}

/// One wheel profile point's state in the iteration: x on the wheel, its z (CONTACT's `prw_lc%z`,
/// from the x before the last step), the bracket of x with the rail's dz/dx at its ends.
#[derive(Debug, Clone, Copy)]
struct Point {
    x: f64,
    z_lc: f64,
    bracket: [f64; 2],
    dz_dx_at: [f64; 2],
    done: bool,
    /// Whether `rail_pts` and `dz_dx` hold this point's current x and z.
    evaluated: bool,
}

/// CONTACT's contact locus of `wheel` on the variable rail (`locus_iterate_varprof`): from x = 0,
/// per profile point the x where the wheel's circle there, of radius ρ = R + z_w, has the rail's
/// slope dz/dx along the track (Newton's step with the second derivative from the bracket's
/// ends, kept inside the bracket by halving and at most 0.7 of the way to its upper end), until
/// every point moves by less than 1e-3 mm; then the splines through the wheel's points (in the
/// profile's arc length) and through the rail's points of the last sweep (in their own arc
/// length in y, z). `None` for a wheel without profile points.
pub fn loci(rail: &RailSlices, frame: RailFrame, wheel: &PlacedWheel) -> Option<Loci> {
    let nodes = wheel.curve.locus_nodes()?;
    if nodes.len() < 2 {
        return None;
    }
    let radius = wheel.nominal_radius_mm;
    let r = wheel.rotation.matrix();
    let to_track =
        |i: usize, p: &Point| wheel.to_track(Vector3::new(p.x, wheel.y_offset_mm + nodes[i].y_mm, radius + p.z_lc));
    let x_max = SEARCH_OVER_RADIUS * radius;
    let mut pts: Vec<Point> = nodes
        .iter()
        .map(|n| Point { x: 0.0, z_lc: n.z_mm, bracket: [0.0; 2], dz_dx_at: [0.0; 2], done: false, evaluated: false })
        .collect();
    let y_r: Vec<f64> = pts
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let q = to_track(i, p);
            frame.to_rail(q.y, q.z)[0]
        })
        .collect();
    for (p, b) in pts.iter_mut().zip(rail.available_x(&y_r, x_max)) {
        p.bracket = b;
    }
    let mut rail_pts = vec![Point3::origin(); nodes.len()];
    let mut dz_dx = vec![0.0; nodes.len()];
    for _ in 0..LOCUS_SWEEPS {
        for (i, p) in pts.iter_mut().enumerate() {
            // A point whose x and z have not moved since its last evaluation keeps its rail point.
            if p.evaluated {
                continue;
            }
            let q = to_track(i, p);
            let [y_r, _] = frame.to_rail(q.y, q.z);
            let (z_r, slope) = rail.z_and_dz_dx(q.x, y_r);
            let [y, z] = frame.to_track(y_r, z_r);
            rail_pts[i] = Point3::new(q.x, y, z);
            dz_dx[i] = slope;
            p.evaluated = true;
        }
        let mut dx_max: f64 = 0.0;
        for (i, p) in pts.iter_mut().enumerate() {
            if p.done {
                continue;
            }
            let step = step(p, (nodes[i].z_mm, nodes[i].dz_dy), dz_dx[i], radius, r);
            dx_max = dx_max.max(step.abs());
        }
        if dx_max < LOCUS_TOL_MM {
            break;
        }
    }
    let wheel_pts: Vec<Point3<f64>> = pts.iter().enumerate().map(|(i, p)| to_track(i, p)).collect();
    let s_wheel: Vec<f64> = nodes.iter().map(|n| n.s_mm).collect();
    Some(Loci::through(s_wheel, &wheel_pts, &rail_pts))
}

/// One point's step of the iteration (`locus_iterate_varprof`'s loop body): its z from the
/// current x, the new x, the bracket updated; returns the step taken.
fn step(p: &mut Point, (z_w, dz_dy): (f64, f64), dz_dx: f64, radius: f64, r: &nalgebra::Matrix3<f64>) -> f64 {
    let ry = radius + z_w;
    p.z_lc = if ry * ry - p.x * p.x > 0.0 { (ry * ry - p.x * p.x).sqrt() - radius } else { -999.0 };
    let rnom_z = radius + p.z_lc;
    let a_y = ry * dz_dy;
    let denom = p.x * r[(2, 0)] - a_y * r[(2, 1)] + rnom_z * r[(2, 2)];
    let [lo, hi] = p.bracket;
    let width = hi - lo;
    let d2 = if width <= LOCUS_TOL_MM || width > 0.1 * radius {
        0.0
    } else {
        ((p.dz_dx_at[1] - p.dz_dx_at[0]) / width).max(-0.5 / denom).min(0.5 / denom)
    };
    let mut x_new = (a_y * r[(0, 1)] - denom * dz_dx + denom * d2 * p.x) / (r[(0, 0)] + denom * d2);
    let dx1 = x_new - p.x;
    let room = if dx1 < 0.0 { lo - p.x } else { hi - p.x };
    if x_new < lo {
        x_new = 0.5 * lo + 0.5 * p.x;
    } else if x_new > hi {
        x_new = 0.5 * hi + 0.5 * p.x;
    } else if dx1 / room.max(1e-6) > 0.7 {
        x_new = p.x + 0.7 * room;
    }
    if x_new > p.x {
        p.bracket[0] = p.x;
        p.dz_dx_at[0] = dz_dx;
    }
    if x_new < p.x {
        p.bracket[1] = p.x;
        p.dz_dx_at[1] = dz_dx;
    }
    let x_new = x_new.min(0.5 * radius).max(-0.5 * radius);
    let moved = x_new - p.x;
    if moved.abs() < LOCUS_TOL_MM {
        p.done = true;
    }
    p.x = x_new;
    p.evaluated = false;
    moved
}
