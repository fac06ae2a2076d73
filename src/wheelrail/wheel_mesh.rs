//! CONTACT's meshed wheel surface (`wr_ud_planar` in m_wr_undefdist, with `trim_wheel_profile`,
//! `grid_revolve_profile` and `interp_cartz2unif`): the wheel profile sampled every DS of its
//! spline's parameter (the chord length of its points; a closed form: of arc length) from the
//! patch's reference point, revolved into slices every DX along the track from it, placed in the
//! patch's frame and interpolated bilinearly in each quadrilateral's logical (u, v) at the element
//! centres. Between its nodes the mesh lies inside a concave profile.

use super::curve::Curve;
use super::patch::{PatchFrame, PatchGrid};
use super::wheel::PlacedWheel;
use nalgebra::{Point3, Vector3};

/// Which wheel surface the undeformed distance is measured to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum WheelSurface {
    /// The exact surface of revolution of the profile.
    #[default]
    Exact,
    /// CONTACT's mesh: profile points DS apart in the spline's parameter, slices DX apart, bilinear.
    ContactMesh,
}

/// Guard nodes beyond the grid's extent on every side (CONTACT widens by two elements).
const GUARD: f64 = 3.0;
/// Upper bound on profile nodes each way from the reference point.
const MAX_NODES: usize = 20_000;

/// The profile position y_w one arc length `ds` (signed) from y0 (Newton on Simpson's rule), if
/// the profile reaches it.
fn step_arc(curve: &dyn Curve, y0: f64, ds: f64) -> Option<f64> {
    let g = |y: f64| curve.dz_dy(y).map(|d| (1.0 + d * d).sqrt());
    let g0 = g(y0)?;
    // The arc length to y0 + h, and the integrand at its end.
    let length = |h: f64| -> Option<(f64, f64)> {
        const N: usize = 16;
        let dh = h / N as f64;
        let gh = g(y0 + h)?;
        let mut sum = g0 + gh;
        for k in 1..N {
            sum += if k % 2 == 1 { 4.0 } else { 2.0 } * g(y0 + dh * k as f64)?;
        }
        Some((sum * dh / 3.0, gh))
    };
    let mut h = ds / g0;
    for _ in 0..20 {
        let (l, gh) = length(h)?;
        let dh = (l - ds) / gh;
        h -= dh;
        if dh.abs() < 1e-13 {
            break;
        }
    }
    let [lo, hi] = curve.y_range_mm();
    (lo..=hi).contains(&(y0 + h)).then_some(y0 + h)
}

/// A profile node: its lateral place y_w and the wheel's radius there [mm].
type ProfileNode = (f64, Option<f64>);

/// The profile's node `k` steps of `ds` from the anchor (k signed), `prev_y` the node before it
/// on the same side: on a profile's spline at its parameter `s_mid` + k ds (the chord length of
/// its points; CONTACT's `trim_wheel_profile` samples `spline_get_xyz_at_s` from `sw_mid`), on a
/// closed form one arc length ds on from `prev_y`; `None` past the profile's ends.
fn profile_node(wheel: &PlacedWheel, s_mid: Option<f64>, prev_y: f64, k: i64, ds: f64) -> Option<ProfileNode> {
    let radius = |z: f64| wheel.nominal_radius_mm + z;
    match s_mid {
        Some(s_mid) => {
            let p = wheel.curve.spline_point(s_mid + k as f64 * ds)?;
            Some((p.y_mm, Some(radius(p.z_mm))))
        }
        None => {
            let y = step_arc(wheel.curve, prev_y, ds * k.signum() as f64)?;
            Some((y, wheel.curve.z_mm(y).map(radius)))
        }
    }
}

/// The mesh's nodes in plane coordinates (x, s, n): `slices` fastest, then profile points.
struct Mesh {
    slices: usize,
    nodes: Vec<[f64; 3]>,
}

fn mesh(frame: &PatchFrame, grid: &PatchGrid, wheel: &PlacedWheel) -> Mesh {
    let (e_s, n) = (frame.e_s(), frame.n());
    let to_plane = |p: Point3<f64>| {
        let d = p - frame.origin;
        [d.x, d.dot(&e_s), d.dot(&n)]
    };
    // CONTACT's mesh starts at the grid's anchor (`mpot`): the reference in steady rolling.
    let q = wheel.to_wheel(&frame.at(grid.anchor_mm[0], grid.anchor_mm[1]));
    let y_mid = q.y - wheel.y_offset_mm;
    let (s_lo, s_hi) = (grid.s0_mm - GUARD * grid.ds_mm, grid.s0_mm + (grid.ms as f64 + GUARD) * grid.ds_mm);
    let (x_lo, x_hi) = (grid.x0_mm - GUARD * grid.dx_mm, grid.x0_mm + (grid.mx as f64 + GUARD) * grid.dx_mm);
    let node = |x: f64, y_w: f64, rho: f64| -> [f64; 3] {
        let z = (rho * rho - x * x).max(0.0).sqrt();
        to_plane(wheel.to_track(Vector3::new(x, wheel.y_offset_mm + y_w, z)))
    };
    // Profile points each way from the anchor until their s has left the grid's extent (an
    // anchor outside it: until they have crossed it), each with its lateral place and radius.
    let outside = |s: f64| (s_lo - s).max(s - s_hi).max(0.0);
    let s_mid = wheel.curve.s_at_y(y_mid);
    let mid = profile_node(wheel, s_mid, y_mid, 0, grid.ds_mm).unwrap_or((y_mid, None));
    let mut profile = vec![mid];
    for dir in [-1, 1] {
        let mut side = Vec::new();
        let mut last = mid.1.map_or(f64::INFINITY, |rho| outside(node(q.x, mid.0, rho)[1]));
        let mut y = mid.0;
        for k in 1..=MAX_NODES as i64 {
            let Some((next, rho)) = profile_node(wheel, s_mid, y, dir * k, grid.ds_mm) else { break };
            y = next;
            side.push((y, rho));
            let Some([_, s, _]) = rho.map(|rho| node(q.x, y, rho)) else { break };
            let d = outside(s);
            if d > 0.0 && d >= last {
                break;
            }
            last = d;
        }
        if dir < 0 {
            side.reverse();
            side.extend(profile);
            profile = side;
        } else {
            profile.extend(side);
        }
    }
    // Slices on the wheel's x (CONTACT's grid's corners in the wheel's frame).
    let corners = [(x_lo, s_lo), (x_lo, s_hi), (x_hi, s_lo), (x_hi, s_hi)];
    let wx = corners.map(|(x, s)| wheel.to_wheel(&frame.at(x, s)).x);
    let (wx_lo, wx_hi) = (wx.iter().copied().fold(f64::MAX, f64::min), wx.iter().copied().fold(f64::MIN, f64::max));
    let n_lo = ((q.x - wx_lo) / grid.dx_mm).ceil().max(0.0) as i64;
    let n_hi = ((wx_hi - q.x) / grid.dx_mm).ceil().max(0.0) as i64;
    let xs: Vec<f64> = (-n_lo..=n_hi).map(|i| q.x + i as f64 * grid.dx_mm).collect();
    let mut nodes = Vec::with_capacity(xs.len() * profile.len());
    for &(y_w, rho) in &profile {
        for &x in &xs {
            nodes.push(rho.map_or([f64::NAN; 3], |rho| node(x, y_w, rho)));
        }
    }
    Mesh { slices: xs.len(), nodes }
}

/// The logical (u, v) of point p in quadrilateral a-b-c-d (Newton on the bilinear map from
/// (0.5, 0.5), CONTACT's `compute_logical_uv`).
pub(super) fn logical_uv(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2], p: [f64; 2]) -> (f64, f64) {
    let (mut u, mut v) = (0.5, 0.5);
    for _ in 0..20 {
        let cross = |k: usize| (c[k] - b[k]) - (d[k] - a[k]);
        let f = |k: usize| a[k] + (b[k] - a[k]) * u + (d[k] - a[k]) * v + cross(k) * u * v - p[k];
        let j = |k: usize| [(b[k] - a[k]) + cross(k) * v, (d[k] - a[k]) + cross(k) * u];
        let (j0, j1) = (j(0), j(1));
        let det = j0[0] * j1[1] - j1[0] * j0[1];
        if det.abs() < 1e-300 {
            break;
        }
        let du = -(j1[1] * f(0) - j0[1] * f(1)) / det;
        let dv = -(-j1[0] * f(0) + j0[0] * f(1)) / det;
        (u, v) = (u + du, v + dv);
        if du.abs().max(dv.abs()) < 1e-12 {
            break;
        }
    }
    (u, v)
}

/// The wheel's n (distance along the plane's normal from the plane) at every element centre,
/// interpolated in CONTACT's mesh; `None` where no mesh cell covers the centre. The first cell
/// (slices fastest) holding a centre on or inside its edges takes it. The rows lie at the plane's
/// s `rows_s_mm` (ascending; the grid's own centres, or a conformal patch's rows,
/// `curved_sc_to_planar_sp`); the grid gives the columns and the mesh's extent.
pub fn wheel_n_mm(frame: &PatchFrame, grid: &PatchGrid, wheel: &PlacedWheel, rows_s_mm: &[f64]) -> Vec<Option<f64>> {
    let m = mesh(frame, grid, wheel);
    let mut out = vec![None; grid.mx * rows_s_mm.len()];
    let rows = m.nodes.len() / m.slices.max(1);
    let xy = |k: usize| [m.nodes[k][0], m.nodes[k][1]];
    for r in 0..rows.saturating_sub(1) {
        for i in 0..m.slices.saturating_sub(1) {
            let k = [r * m.slices + i, r * m.slices + i + 1, (r + 1) * m.slices + i + 1, (r + 1) * m.slices + i];
            if k.iter().any(|&k| m.nodes[k][2].is_nan()) {
                continue;
            }
            let corners = k.map(xy);
            let area: f64 =
                (0..4).map(|e| corners[e][0] * corners[(e + 1) % 4][1] - corners[(e + 1) % 4][0] * corners[e][1]).sum();
            let sense = area.signum();
            let inside = |p: [f64; 2]| {
                (0..4).all(|e| {
                    let (a, b) = (corners[e], corners[(e + 1) % 4]);
                    sense * ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) >= 0.0
                })
            };
            let lo = |v: f64, v0: f64, d: f64| (((v - v0) / d).floor().max(0.0)) as usize;
            let (bx, by) = (corners.map(|c| c[0]), corners.map(|c| c[1]));
            let min = |a: [f64; 4]| a.iter().copied().fold(f64::MAX, f64::min);
            let max = |a: [f64; 4]| a.iter().copied().fold(f64::MIN, f64::max);
            // A cell beside the grid holds none of its centres.
            let (x_end, s_end) = (grid.x0_mm + grid.dx_mm * grid.mx as f64, grid.s0_mm + grid.ds_mm * grid.ms as f64);
            if max(bx) < grid.x0_mm || min(bx) > x_end || max(by) < grid.s0_mm || min(by) > s_end {
                continue;
            }
            let (i0, i1) = (lo(min(bx), grid.x0_mm, grid.dx_mm), lo(max(bx), grid.x0_mm, grid.dx_mm).min(grid.mx - 1));
            // The rows whose s lies in the cell's range (those beyond it lie outside the cell).
            let (j0, j1) = (rows_s_mm.partition_point(|&s| s < min(by)), rows_s_mm.partition_point(|&s| s <= max(by)));
            for (jj, &s) in rows_s_mm.iter().enumerate().take(j1).skip(j0) {
                for ii in i0..=i1 {
                    let e = jj * grid.mx + ii;
                    let x = grid.centre(ii, jj).0;
                    if out[e].is_some() || !inside([x, s]) {
                        continue;
                    }
                    let (u, v) = logical_uv(corners[0], corners[1], corners[2], corners[3], [x, s]);
                    let n = k.map(|k| m.nodes[k][2]);
                    out[e] =
                        Some((1.0 - u) * (1.0 - v) * n[0] + u * (1.0 - v) * n[1] + u * v * n[2] + (1.0 - u) * v * n[3]);
                }
            }
        }
    }
    out
}
