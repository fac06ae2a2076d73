//! The grid-based contact search CONTACT uses for an out-of-round wheel (`use_brute`: a wheel
//! slices file; m_wr_locatecp, `compute_wr_surfc` and `locate_interpen_2d`): a uniform gap mesh
//! over the wheel's mesh in x and the rail's lateral range in y (step 0.75 DS), the rail's height
//! from its profile and the wheel's interpolated from its mesh (bilinear in each cell's logical
//! (u, v), `interp_cartz2unif`), the local minima of the gap (`find_gap_locmin`), each minimum's
//! region of interpenetration grown to its bounding box plus one guard line
//! (`find_bounding_box_2d`) and its centre weighted by the squared gap (`compute_wgt_center_2d`).

use super::mesh_interp::{interpolate, Mesh, Scheme, Uniform};
use super::oorwheel::{self, WheelSlices};
use super::patch::Candidate;
use super::rail::PlacedRail;
use super::wheel::PlacedWheel;

/// The gap mesh's lateral step over DS (`fac_dyds` 0.5 times 1.5).
const STEP_OVER_DS: f64 = 0.75;
/// The gap where the rail or the wheel has no surface (CONTACT's 999).
const NO_GAP_MM: f64 = 999.0;
/// Neighbours whose gaps differ by less than this make a plateau (`find_gap_locmin`).
const PLATEAU_MM: f64 = 1e-6;

/// The gap on the uniform mesh: x_i = x0 + i dx (fastest), y_j = y0 + j dy.
#[derive(Debug, Clone)]
pub struct GapMesh {
    pub nx: usize,
    pub ny: usize,
    pub x0_mm: f64,
    pub dx_mm: f64,
    pub y0_mm: f64,
    pub dy_mm: f64,
    /// The rail's height, its inclination atan(dz/dy) and the gap (rail − wheel) per point.
    pub z_rail_mm: Vec<f64>,
    pub angle_rad: Vec<f64>,
    pub gap_mm: Vec<f64>,
}

impl GapMesh {
    fn x(&self, i: usize) -> f64 {
        self.x0_mm + i as f64 * self.dx_mm
    }
    fn y(&self, j: usize) -> f64 {
        self.y0_mm + j as f64 * self.dy_mm
    }

    /// The smallest gap [mm] (negative: the deepest interpenetration).
    pub fn gap_min_mm(&self) -> f64 {
        self.gap_mm.iter().copied().fold(f64::INFINITY, f64::min)
    }
}

/// The gap mesh of `oor` on `wheel` over `rail` (`compute_wr_surfc`).
pub fn gap_mesh(oor: &WheelSlices, wheel: &PlacedWheel, rail: &PlacedRail, (dx_mm, ds_mm): (f64, f64)) -> GapMesh {
    let mesh = oorwheel::mesh(oor, wheel, dx_mm);
    let nx = mesh.slices;
    let (x_lo, x_hi) = mesh.nodes.iter().fold((f64::MAX, f64::MIN), |(lo, hi), p| (lo.min(p.x), hi.max(p.x)));
    let dx = (x_hi - x_lo) / (nx as f64 - 1.0);
    let [y_lo, y_hi] = rail.mesh_y_range_mm();
    let dy = STEP_OVER_DS * ds_mm;
    let ny = ((y_hi - y_lo) / dy).floor() as usize + 1;
    let y0 = 0.5 * (y_lo + y_hi) - (ny as f64 - 1.0) * dy / 2.0;
    let mut z_rail_mm = vec![NO_GAP_MM; nx * ny];
    let mut angle_rad = vec![0.0; nx * ny];
    for j in 0..ny {
        let y = y0 + j as f64 * dy;
        let (z, a) = match (rail.z_mm(y), rail.dz_dy(y)) {
            (Some(z), Some(d)) => (z, d.atan()),
            _ => (NO_GAP_MM, 0.0),
        };
        for i in 0..nx {
            z_rail_mm[j * nx + i] = z;
            angle_rad[j * nx + i] = a;
        }
    }
    let nodes: Vec<[f64; 3]> = mesh.nodes.iter().map(|p| [p.x, p.y, p.z]).collect();
    let uniform = Uniform { x0: x_lo, dx, nx, y0, dy, ny };
    let z_wheel = interpolate(Mesh { nodes: &nodes, n_u: nx }, &uniform, Scheme::Bilinear);
    let gap_mm = z_rail_mm
        .iter()
        .zip(&z_wheel)
        .map(|(&zr, zw)| match zw {
            Some(zw) if zr < 888.0 => zr - zw,
            _ => NO_GAP_MM,
        })
        .collect();
    GapMesh { nx, ny, x0_mm: x_lo, dx_mm: dx, y0_mm: y0, dy_mm: dy, z_rail_mm, angle_rad, gap_mm }
}

/// The local minima of the gap (`find_gap_locmin`): points below 777 mm no lower than any
/// neighbour (lower or equal to the south and west, lower to the north and east), a neighbour
/// on a plateau within 1e-6 mm extending the plateau instead; (i, j) in the order found (x outer).
fn local_minima(g: &GapMesh) -> Vec<(usize, usize)> {
    let (nx, ny) = (g.nx, g.ny);
    let gap = &g.gap_mm;
    let mut mask = vec![false; nx * ny];
    let mut out = Vec::new();
    for i in 0..nx {
        for j in 0..ny {
            let k = j * nx + i;
            let mut is_min = gap[k] < 777.0;
            // (neighbour, whether an equal gap there rules k out)
            let neighbours = [
                (j > 0).then(|| (k - nx, true)),
                (j + 1 < ny).then(|| (k + nx, false)),
                (i > 0).then(|| (k - 1, true)),
                (i + 1 < nx).then(|| (k + 1, false)),
            ];
            for (n, equal_out) in neighbours.into_iter().flatten() {
                if !is_min {
                    break;
                }
                if mask[n] && (gap[n] - gap[k]).abs() < PLATEAU_MM {
                    mask[k] = true;
                    is_min = false;
                } else if gap[n] < gap[k] || (equal_out && gap[n] == gap[k]) {
                    is_min = false;
                }
            }
            if is_min {
                mask[k] = true;
                out.push((i, j));
            }
        }
    }
    out
}

/// The bounding box [i0, i1] × [j0, j1] of the interpenetration grown from (i, j): each side
/// moved out while the line beyond it (one wider each way) has a point with a negative gap,
/// then one guard line on each side (`find_bounding_box_2d`, `nguard = 1`).
fn bounding_box(g: &GapMesh, (i, j): (usize, usize)) -> [usize; 4] {
    let inside = |i: usize, j: usize| g.gap_mm[j * g.nx + i] < 0.0;
    let [mut i0, mut i1, mut j0, mut j1] = [i, i, j, j];
    let (nx, ny) = (g.nx, g.ny);
    let mut changed = true;
    while changed {
        changed = false;
        while i0 > 0 && (j0.saturating_sub(1)..=(j1 + 1).min(ny - 1)).any(|j| inside(i0 - 1, j)) {
            i0 -= 1;
            changed = true;
        }
        while i1 + 1 < nx && (j0.saturating_sub(1)..=(j1 + 1).min(ny - 1)).any(|j| inside(i1 + 1, j)) {
            i1 += 1;
            changed = true;
        }
        while j0 > 0 && (i0.saturating_sub(1)..=(i1 + 1).min(nx - 1)).any(|i| inside(i, j0 - 1)) {
            j0 -= 1;
            changed = true;
        }
        while j1 + 1 < ny && (i0.saturating_sub(1)..=(i1 + 1).min(nx - 1)).any(|i| inside(i, j1 + 1)) {
            j1 += 1;
            changed = true;
        }
    }
    [i0.saturating_sub(1), (i1 + 1).min(nx - 1), j0.saturating_sub(1), (j1 + 1).min(ny - 1)]
}

/// The candidate of the box: the centre weighted by dx dy gap² over its interpenetrating points
/// (`compute_wgt_center_2d`, squared weights), its extent the box's lines.
fn candidate(g: &GapMesh, (i, j): (usize, usize), [i0, i1, j0, j1]: [usize; 4]) -> Candidate {
    let (mut wx, mut wy, mut wa, mut total) = (0.0, 0.0, 0.0, 0.0);
    for jj in j0..=j1 {
        let (mut px, mut py, mut pa, mut pt) = (0.0, 0.0, 0.0, 0.0);
        for ii in i0..=i1 {
            let k = jj * g.nx + ii;
            if -g.gap_mm[k] > 0.0 {
                let w = g.dx_mm * (g.gap_mm[k] * g.gap_mm[k]).max(1e-20);
                px += g.x(ii) * w;
                py += g.y(jj) * w;
                pa += g.angle_rad[k] * w;
                pt += w;
            }
        }
        wx += g.dy_mm * px;
        wy += g.dy_mm * py;
        wa += g.dy_mm * pa;
        total += g.dy_mm * pt;
    }
    let t = total.max(1e-40);
    Candidate {
        x_mm: [g.x(i0), g.x(i1)],
        y_mm: [g.y(j0), g.y(j1)],
        z_mm: [g.z_rail_mm[j0 * g.nx + i], g.z_rail_mm[j1 * g.nx + i]],
        wgt_x_mm: wx / t,
        wgt_y_mm: wy / t,
        wgt_angle_rad: wa / t,
        total_weight: total,
        pen_max_mm: -g.gap_mm[j * g.nx + i],
        parts: Vec::new(),
    }
}

/// The candidate patches of the gap mesh (`locate_interpen_2d` without near misses): from the
/// deepest local minimum on, each with its bounding box, the minima inside it taken with it.
pub fn candidates(g: &GapMesh) -> Vec<Candidate> {
    let mut minima: Vec<Option<(usize, usize)>> = local_minima(g).into_iter().map(Some).collect();
    let gap = |&(i, j): &(usize, usize)| g.gap_mm[j * g.nx + i];
    let mut out = Vec::new();
    while let Some(m) = minima.iter().flatten().copied().min_by(|a, b| gap(a).total_cmp(&gap(b))) {
        if gap(&m) >= 0.0 {
            break;
        }
        let bx = bounding_box(g, m);
        out.push(candidate(g, m, bx));
        for slot in minima.iter_mut() {
            if slot.is_some_and(|(i, j)| (bx[0]..=bx[1]).contains(&i) && (bx[2]..=bx[3]).contains(&j)) {
                *slot = None;
            }
        }
    }
    out
}
