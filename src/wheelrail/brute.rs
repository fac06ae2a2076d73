//! The grid-based contact search CONTACT uses for an out-of-round wheel and with D = 5 (`use_brute`;
//! m_wr_locatecp, `compute_wr_surfc` and `locate_interpen_2d`): a uniform gap mesh over the
//! wheel's mesh in x (`compute_oor_whl` or `compute_round_whl`) and the rail's lateral range in y
//! (step 0.75 DS), the rail's height from its profile (a variable rail: each mesh column's
//! cross-section) and the wheel's interpolated from its mesh (bilinear in each cell's logical
//! (u, v), `interp_cartz2unif`), the local minima of the gap (`find_gap_locmin`), each minimum's
//! region of interpenetration grown to its bounding box plus one guard line
//! (`find_bounding_box_2d`) and its centre weighted by the squared gap (`compute_wgt_center_2d`).

use super::mesh_interp::{apply, locate, Mesh, Scheme, Uniform};
use super::oorwheel;
use super::patch::Candidate;
use super::rail::PlacedRail;
use super::roller::Roller;
use super::varrail::RailSlices;
use super::wheel::PlacedWheel;
use super::{WheelRailError, MAX_GAP_MESH_POINTS};
use nalgebra::Vector3;
use std::sync::Arc;

/// The gap mesh's lateral step over DS (`fac_dyds` 0.5 times 1.5).
const STEP_OVER_DS: f64 = 0.75;
/// The same for steep slopes (D = 6, `use_steep_slopes`: `fac_dyds` 0.2 times 1.5).
const STEEP_STEP_OVER_DS: f64 = 0.3;
/// The gap where the rail or the wheel has no surface (CONTACT's 999).
const NO_GAP_MM: f64 = 999.0;
/// A round wheel's mesh spans x = ±R/8 (`compute_round_whl`: an arc of ±7°).
const ROUND_HALF_SPAN_OVER_R: f64 = 0.125;
/// The same for a small wheel, nominal radius below [`SMALL_WHEEL_MM`], and for steep slopes
/// (`compute_round_whl`: 0.242 R, sin 14°).
const SMALL_HALF_SPAN_OVER_R: f64 = 0.242;
/// The nominal radius [mm] below which a wheel is meshed over the wider span (a roller rig's
/// small wheels).
const SMALL_WHEEL_MM: f64 = 30.5;
/// A round wheel's mesh has slices about 1.5 DX apart (`compute_round_whl`).
const ROUND_STEP_OVER_DX: f64 = 1.5;
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
    /// The rail's height and the gap (rail − wheel) per point, the rail's inclination atan(dz/dy)
    /// per y (the same along x).
    pub z_rail_mm: Arc<Vec<f64>>,
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

/// The wheel's mesh in its own frame (from its centre): the number of slices and the nodes.
fn local_mesh(wheel: &PlacedWheel, dx_mm: f64, steep: bool) -> (usize, Vec<Vector3<f64>>) {
    match &wheel.oor {
        Some(oor) => oorwheel::mesh_local(oor, wheel, dx_mm),
        None => round_local(wheel, dx_mm, steep),
    }
}

/// A round wheel's mesh in its frame (`compute_round_whl`, `grid_revolve_profile`): the profile's
/// points revolved to x = −R/8 … R/8 (sin 7°, R the nominal radius; ±0.242 R below R = 30.5 mm or
/// for steep slopes) in round(2 half-span / (1.5 DX) + 2) slices (odd), the point at x on the
/// circle of radius ρ = R + z_w through the profile point; none where x ≥ ρ.
fn round_local(wheel: &PlacedWheel, dx_mm: f64, steep: bool) -> (usize, Vec<Vector3<f64>>) {
    let radius = wheel.nominal_radius_mm;
    let (n, half) = round_slices(radius, dx_mm, steep);
    let dx = 2.0 * half / (n as f64 - 1.0);
    let points = wheel.curve.points_mm().unwrap_or_default();
    let mut nodes = Vec::with_capacity(n * points.len());
    for &[y, z] in &points {
        let rho = radius + z;
        for i in 0..n {
            let x = -half + i as f64 * dx;
            // CONTACT's −999 off the circle: far above any rail.
            let below = if rho * rho > x * x { (rho * rho - x * x).sqrt() } else { -999.0 - radius };
            nodes.push(Vector3::new(x, wheel.y_offset_mm + y, below));
        }
    }
    (n, nodes)
}

/// A round wheel's slices and the half span [mm] of its mesh ([`round_local`]).
fn round_slices(radius_mm: f64, dx_mm: f64, steep: bool) -> (usize, f64) {
    let wide = radius_mm < SMALL_WHEEL_MM || steep;
    let half = radius_mm * if wide { SMALL_HALF_SPAN_OVER_R } else { ROUND_HALF_SPAN_OVER_R };
    let n = (2.0 * half / (ROUND_STEP_OVER_DX * dx_mm) + 2.0).round() as usize;
    (n + usize::from(n.is_multiple_of(2)), half)
}

/// The number of slices of the wheel's mesh ([`local_mesh`]) without making it.
fn slices(wheel: &PlacedWheel, dx_mm: f64, steep: bool) -> usize {
    match wheel.oor {
        Some(_) => oorwheel::mesh_angles(wheel.nominal_radius_mm, dx_mm),
        None => round_slices(wheel.nominal_radius_mm, dx_mm, steep).0,
    }
}

/// The gap mesh's lateral points over `rail` (step 0.75 DS, 0.3 DS for steep slopes, centred on
/// its lateral range): their number, the first y and the step [mm].
fn lateral_points(rail: &PlacedRail, ds_mm: f64, steep: bool) -> (usize, f64, f64) {
    let [y_lo, y_hi] = rail.mesh_y_range_mm();
    let dy = if steep { STEEP_STEP_OVER_DS } else { STEP_OVER_DS } * ds_mm;
    let ny = ((y_hi - y_lo) / dy).floor() as usize + 1;
    (ny, 0.5 * (y_lo + y_hi) - (ny as f64 - 1.0) * dy / 2.0, dy)
}

/// The rail's surface the gap mesh is made over: a prismatic rail, a rail that varies along the
/// track (its slices at S_WS), or a roller (its profile revolved about its axis).
#[derive(Debug, Clone, Copy)]
pub enum RailSurface<'a> {
    Prismatic,
    Varying(&'a RailSlices<'a>),
    Roller(&'a Roller),
}

/// The rail's height on the gap mesh: the placed profile's at every mesh y, the same in every
/// column; on a variable rail each column's own cross-section at u = S_WS + x_i, placed as the
/// rail at S_WS (`varprof_intpol_grid_old`); on a roller the profile's height at y revolved about
/// the roller's axis to each column's x (`grid_revolve_profile`). 999 mm where the rail does not
/// reach y.
fn rail_heights(rail: &PlacedRail, surface: RailSurface, (nx, x0, dx): (usize, f64, f64), ys: &[f64]) -> Arc<Vec<f64>> {
    match surface {
        // A variable rail's heights are the same for every case at this S_WS over this mesh
        // (with the rail placed alike): made once per scene.
        RailSurface::Varying(v) => {
            let key: Vec<u64> = [v.s_ws_mm, x0, dx, rail.origin_mm[0], rail.origin_mm[1], rail.angle_rad]
                .iter()
                .chain(ys)
                .map(|x| x.to_bits())
                .chain([nx as u64])
                .collect();
            v.slices.memo().get_or_make(&key, || column_heights(rail, surface, (nx, x0, dx), ys))
        }
        _ => Arc::new(column_heights(rail, surface, (nx, x0, dx), ys)),
    }
}

/// [`rail_heights`] made.
fn column_heights(rail: &PlacedRail, surface: RailSurface, (nx, x0, dx): (usize, f64, f64), ys: &[f64]) -> Vec<f64> {
    let ny = ys.len();
    let mut z = vec![NO_GAP_MM; nx * ny];
    let mut fill = |i_cols: std::ops::Range<usize>, placed: &PlacedRail| {
        for (j, &y) in ys.iter().enumerate() {
            let zj = placed.z_mm(y).unwrap_or(NO_GAP_MM);
            for i in i_cols.clone() {
                z[j * nx + i] = zj;
            }
        }
    };
    match surface {
        RailSurface::Prismatic => fill(0..nx, rail),
        RailSurface::Varying(v) => {
            for i in 0..nx {
                if let Some(section) = v.section_at_x(x0 + i as f64 * dx) {
                    fill(
                        i..i + 1,
                        &PlacedRail { curve: &section, origin_mm: rail.origin_mm, angle_rad: rail.angle_rad },
                    );
                }
            }
        }
        RailSurface::Roller(r) => {
            let axis_z_mm = r.axis_z_mm(rail);
            for (j, &y) in ys.iter().enumerate() {
                let Some(zj) = rail.z_mm(y) else { continue };
                for i in 0..nx {
                    z[j * nx + i] = Roller::z_at_x(axis_z_mm, zj, x0 + i as f64 * dx);
                }
            }
        }
    }
    z
}

/// What a gap mesh keeps for the next trial height of the same case: the wheel's mesh in its own
/// frame (it depends on DX, the radius, the lateral offset and the pitch alone) and turned by the
/// wheel's rotation, the rail's heights (they depend on the mesh alone: its (nx, x0, dx, ny, y0)
/// bit for bit), and the wheel's heights on the gap mesh relative to its centre: a vertical shift
/// of the wheelset moves the turned mesh by the centre alone, so that x, y and the cells stay and
/// the wheel's height is the kept one plus the centre's.
#[derive(Debug, Clone, Default)]
pub struct GapMeshKept {
    local_key: Option<[u64; 5]>,
    local: (usize, Vec<Vector3<f64>>),
    /// The local mesh turned by the wheel's rotation (its bits the key).
    turned_key: Option<[u64; 9]>,
    turned: Vec<Vector3<f64>>,
    key: Option<[u64; 5]>,
    z_mm: Arc<Vec<f64>>,
    /// The centre's x and y and the rows (y0, ny) the wheel was interpolated on, with the turned mesh.
    wheel_key: Option<[u64; 4]>,
    /// The gap mesh's x0 and dx, and the turned mesh's height interpolated at its points
    /// (bilinear, `interp_cartz2unif`; none off the wheel's mesh).
    x_mm: (f64, f64),
    z_turned_mm: Vec<Option<f64>>,
}

/// The gap mesh of `wheel` (its mesh: [`local_mesh`] turned and placed) over `rail` (`compute_wr_surfc`): x over
/// the wheel mesh's range in as many steps as it has slices, y over the rail's lateral range
/// (step 0.75 DS, centred; 0.3 DS for steep slopes); the rail's inclination that of `rail` (the
/// rail at the wheelset); what does not change with the wheelset's height taken from `kept`
/// ([`GapMeshKept`]); refused beyond [`MAX_GAP_MESH_POINTS`] before anything is made.
pub fn gap_mesh(
    wheel: &PlacedWheel,
    rail: &PlacedRail,
    surface: RailSurface,
    (dx_mm, ds_mm, steep): (f64, f64, bool),
    kept: &mut GapMeshKept,
) -> Result<GapMesh, WheelRailError> {
    let (ny, y0, dy) = lateral_points(rail, ds_mm, steep);
    let nx = slices(wheel, dx_mm, steep);
    if nx.saturating_mul(ny) > MAX_GAP_MESH_POINTS {
        return Err(WheelRailError::GapMeshTooLarge { slices: nx, lateral: ny, limit: MAX_GAP_MESH_POINTS });
    }
    let local_key = [
        dx_mm,
        wheel.nominal_radius_mm,
        wheel.y_offset_mm,
        wheel.oor.as_ref().map_or(0.0, |o| o.pitch_rad),
        f64::from(u8::from(steep)),
    ]
    .map(f64::to_bits);
    if kept.local_key != Some(local_key) {
        kept.local = local_mesh(wheel, dx_mm, steep);
        (kept.local_key, kept.turned_key) = (Some(local_key), None);
    }
    debug_assert_eq!(kept.local.0, nx, "the mesh has the slices its formula gives");
    let m = wheel.rotation.matrix();
    let turned_key: [u64; 9] = std::array::from_fn(|k| m[(k / 3, k % 3)].to_bits());
    if kept.turned_key != Some(turned_key) {
        kept.turned = kept.local.1.iter().map(|&p| wheel.rotation * p).collect();
        (kept.turned_key, kept.wheel_key) = (Some(turned_key), None);
    }
    if kept.turned.is_empty() {
        // A closed-form wheel has no points to revolve: no mesh, nothing found.
        let empty = Vec::new();
        return Ok(GapMesh {
            nx: 0,
            ny: 0,
            x0_mm: 0.0,
            dx_mm: 0.0,
            y0_mm: 0.0,
            dy_mm: 0.0,
            z_rail_mm: Arc::new(empty.clone()),
            angle_rad: empty.clone(),
            gap_mm: empty,
        });
    }
    let ys: Vec<f64> = (0..ny).map(|j| y0 + j as f64 * dy).collect();
    let wheel_key = [wheel.centre.x.to_bits(), wheel.centre.y.to_bits(), y0.to_bits(), ny as u64];
    if kept.wheel_key != Some(wheel_key) {
        turned_heights(wheel, rail, surface, (nx, &ys, dy), kept);
        kept.wheel_key = Some(wheel_key);
    }
    let (x_lo, dx) = kept.x_mm;
    let z_rail_mm = Arc::clone(&kept.z_mm);
    let angle_rad = ys.iter().map(|&y| rail.dz_dy(y).map_or(0.0, f64::atan)).collect();
    let z_centre = wheel.centre.z;
    let gap_mm = z_rail_mm
        .iter()
        .zip(&kept.z_turned_mm)
        .map(|(&zr, zw)| match zw {
            Some(zw) if zr < 888.0 => zr - (zw + z_centre),
            _ => NO_GAP_MM,
        })
        .collect();
    Ok(GapMesh { nx, ny, x0_mm: x_lo, dx_mm: dx, y0_mm: y0, dy_mm: dy, z_rail_mm, angle_rad, gap_mm })
}

/// The gap mesh's x range from the wheel's mesh placed at its centre's x and y, the rail's heights
/// there (kept while the mesh is the same), and the turned mesh's heights interpolated on it.
fn turned_heights(
    wheel: &PlacedWheel,
    rail: &PlacedRail,
    surface: RailSurface,
    (nx, ys, dy): (usize, &[f64], f64),
    kept: &mut GapMeshKept,
) {
    let c = wheel.centre;
    // The nodes' x and y as `placed` puts them (centre + rotation · p), their height the turned one.
    let nodes: Vec<[f64; 3]> = kept.turned.iter().map(|r| [c.x + r.x, c.y + r.y, r.z]).collect();
    let (x_lo, x_hi) = nodes.iter().fold((f64::MAX, f64::MIN), |(lo, hi), p| (lo.min(p[0]), hi.max(p[0])));
    let dx = (x_hi - x_lo) / (nx as f64 - 1.0);
    let (ny, y0) = (ys.len(), ys[0]);
    let key = [nx as u64, x_lo.to_bits(), dx.to_bits(), ny as u64, y0.to_bits()];
    if kept.key != Some(key) {
        (kept.key, kept.z_mm) = (Some(key), rail_heights(rail, surface, (nx, x_lo, dx), ys));
    }
    let uniform = Uniform { x0: x_lo, dx, nx, y0, dy, ny };
    let mesh = Mesh { nodes: &nodes, n_u: nx };
    kept.z_turned_mm = apply(mesh, &locate(mesh, &uniform), Scheme::Bilinear);
    kept.x_mm = (x_lo, dx);
}

/// The local minima of the gap (`find_gap_locmin`): points below 777 mm no lower than any
/// neighbour (lower or equal to the south and west, lower to the north and east), a neighbour
/// on a plateau within 1e-6 mm extending the plateau instead; (i, j) in the order found (x outer).
fn local_minima(g: &GapMesh) -> Vec<(usize, usize)> {
    let (nx, ny, gap) = (g.nx, g.ny, &g.gap_mm);
    // CONTACT scans x outer, y inner. A point's verdict reads the gaps of its four neighbours and
    // the marks of its south and west neighbours, which either order has made before it: the
    // scan goes row by row in memory order and the minima are put in CONTACT's order after.
    let mut mask = vec![false; nx * ny];
    let mut out = Vec::new();
    // A neighbour on a marked plateau marks the point; a lower one (or an equal one to the south
    // or west) rules it out; the first neighbour that decides, in the order south, north, west,
    // east, decides. The north and east neighbours are not marked yet.
    for j in 0..ny {
        for i in 0..nx {
            let k = j * nx + i;
            let gk = gap[k];
            // Not below 777 mm (no gap there), or not a number: never a minimum.
            if gk.partial_cmp(&777.0) != Some(std::cmp::Ordering::Less) {
                continue;
            }
            if j > 0 {
                let n = k - nx;
                if mask[n] && (gap[n] - gk).abs() < PLATEAU_MM {
                    mask[k] = true;
                    continue;
                }
                if gap[n] <= gk {
                    continue;
                }
            }
            if j + 1 < ny && gap[k + nx] < gk {
                continue;
            }
            if i > 0 {
                let n = k - 1;
                if mask[n] && (gap[n] - gk).abs() < PLATEAU_MM {
                    mask[k] = true;
                    continue;
                }
                if gap[n] <= gk {
                    continue;
                }
            }
            if i + 1 < nx && gap[k + 1] < gk {
                continue;
            }
            mask[k] = true;
            out.push((i, j));
        }
    }
    out.sort_unstable();
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
                pa += g.angle_rad[jj] * w;
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
    let gap = |&(i, j): &(usize, usize)| g.gap_mm[j * g.nx + i];
    // The interpenetrating minima, deepest first (equal gaps in the order found: a stable sort).
    let mut minima: Vec<(usize, usize)> = local_minima(g).into_iter().filter(|m| gap(m) < 0.0).collect();
    minima.sort_by(|a, b| gap(a).total_cmp(&gap(b)));
    let mut taken = vec![false; minima.len()];
    let mut out = Vec::new();
    for (n, &m) in minima.iter().enumerate() {
        if taken[n] {
            continue;
        }
        let bx = bounding_box(g, m);
        out.push(candidate(g, m, bx));
        for (t, &(i, j)) in taken.iter_mut().zip(&minima) {
            *t |= (bx[0]..=bx[1]).contains(&i) && (bx[2]..=bx[3]).contains(&j);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::super::curve::Curve;
    use super::super::rail::PlacedRail;
    use super::super::search;
    use super::super::test_fixtures as fixtures;
    use super::super::wheel::{PlacedWheel, Pose};
    use super::*;

    /// The Manchester profiles with the right wheel on its flange, yawed (y = 6.2 mm, 14.9 mrad):
    /// the round wheel's mesh lies on the wheel's surface of revolution, and the grid search's
    /// deepest interpenetration on the plain rail is the contact locus's within the mesh's steps.
    #[test]
    fn the_grid_search_on_a_plain_rail_meets_the_locus() {
        let (wheel, rail) = fixtures::profiles("MBench_S1002_v3.prw", "MBench_UIC60_v3.prr");
        let rail = PlacedRail::place(&rail, &fixtures::track()).unwrap();
        let g = fixtures::wheelset();
        let pose = Pose { y_mm: 6.2, z_mm: -0.30, roll_rad: -0.00071622, yaw_rad: 0.0149 };
        let placed = PlacedWheel::place(&wheel, &g, &pose);
        // Every node at its profile point's radius R + z_w from the axle, x within ±R/8.
        let (slices, nodes) = round_local(&placed, 0.2, false);
        assert_eq!(slices % 2, 1);
        let points = wheel.points_mm().unwrap();
        for (k, q) in nodes.iter().enumerate().step_by(97) {
            let [_, z_w] = points[k / slices];
            assert!((q.x.hypot(q.z) - (460.0 + z_w)).abs() < 1e-9, "{q:?}");
            assert!(q.x.abs() <= 460.0 / 8.0 + 1e-9, "{q:?}");
        }
        let grid =
            gap_mesh(&placed, &rail, RailSurface::Prismatic, (0.2, 0.2, false), &mut GapMeshKept::default()).unwrap();
        let locus = search::deepest_mm(&search::scan(&placed, &search::RailMesh::new(&rail, 0.2))).unwrap();
        let (ours, locus_gap) = (grid.gap_min_mm(), -locus);
        // Measured 1.6e-4 mm apart (-0.028972 against -0.028809): the bilinear wheel between slices
        // 0.29 mm and profile points apart on the flange's 60 deg slope, the mesh's 0.15 mm across.
        assert!(locus_gap < 0.0 && (ours - locus_gap).abs() < 3e-4, "grid {ours}, locus {locus_gap}");
        let found = candidates(&grid);
        assert!(!found.is_empty(), "{found:?}");
    }

    /// D = 6 (`use_steep_slopes`): the same wheel revolved over ±0.242 R instead of ±R/8 in
    /// round(2 half / (1.5 DX) + 2) slices made odd (385 and 745 at R = 460 mm, DX = 0.2 mm), the
    /// gap mesh 0.3 DS across instead of 0.75 DS; its deepest gap on the flange the locus's too.
    #[test]
    fn the_steep_grid_is_wider_along_and_finer_across() {
        let (wheel, rail) = fixtures::profiles("MBench_S1002_v3.prw", "MBench_UIC60_v3.prr");
        let rail = PlacedRail::place(&rail, &fixtures::track()).unwrap();
        let pose = Pose { y_mm: 6.2, z_mm: -0.30, roll_rad: -0.00071622, yaw_rad: 0.0149 };
        let placed = PlacedWheel::place(&wheel, &fixtures::wheelset(), &pose);
        let reach = |nodes: &[Vector3<f64>]| nodes.iter().map(|q| q.x.abs()).fold(0.0, f64::max);
        let (n5, nodes5) = round_local(&placed, 0.2, false);
        let (n6, nodes6) = round_local(&placed, 0.2, true);
        assert_eq!((n5, n6), (385, 745));
        assert!((reach(&nodes5) - 460.0 / 8.0).abs() < 1e-9 && (reach(&nodes6) - 0.242 * 460.0).abs() < 1e-9);
        let mesh = |steep| {
            gap_mesh(&placed, &rail, RailSurface::Prismatic, (0.2, 0.2, steep), &mut GapMeshKept::default()).unwrap()
        };
        let (coarse, steep) = (mesh(false), mesh(true));
        assert!((coarse.dy_mm - 0.15).abs() < 1e-12 && (steep.dy_mm - 0.06).abs() < 1e-12);
        assert_eq!(steep.nx, 745);
        let locus = -search::deepest_mm(&search::scan(&placed, &search::RailMesh::new(&rail, 0.2))).unwrap();
        assert!((steep.gap_min_mm() - locus).abs() < 3e-4, "steep {}, locus {locus}", steep.gap_min_mm());
    }
}
