//! The grid and undeformed distance of a conformal patch (CONTACT's D = 4: `m_wr_solvecp`
//! `wr_setup_cp`, `m_wr_undefdist` `wr_ud_planar` with `curved_sc_to_planar_sp`): the grid's
//! columns are the planar patch's, its rows the curved reference's, DS apart in its arc length
//! (the elastic problem is the half-space's on that uniform grid). Each row's gap is measured as
//! the planar patch's, along the reference's normal, at the row point's lateral place in the
//! tangent plane (sp), and multiplied by the cosine between the reference's normal and the row's.

use super::conformal_reference::CurvedReference;
use super::patch::{PatchFrame, PatchGrid, Surfaces};
use super::rail::PlacedRail;
use super::wheel::PlacedWheel;
use super::wheel_mesh::{self, WheelSurface};

/// The conformal grid: the planar grid's columns, one row per point of the curved reference
/// (its arc length sc from the reference in place of the plane's s; on the super-grid of shifts
/// the rows' lattice is the rail's arc length from its origin, the anchor at −s_ref).
pub fn grid(planar: &PatchGrid, reference: &CurvedReference) -> PatchGrid {
    let first = reference.first_row;
    PatchGrid {
        ms: reference.rows(),
        s0_mm: planar.anchor_mm[1] + (first as f64 - 0.5) * planar.ds_mm,
        first_index: [planar.first_index[0], first],
        ..planar.clone()
    }
}

/// Row j's factor on the planar gap: the cosine between the reference's normal and the row's.
pub fn row_factor(frame: &PatchFrame, reference: &CurvedReference, j: usize) -> f64 {
    let [ny, nz] = reference.normal_yz(j);
    let n = frame.n();
    // The reference's outward normal is −n.
    -(n.y * ny + n.z * nz)
}

/// A conformal patch's reference and the surfaces over its grid.
#[derive(Debug, Clone, PartialEq)]
pub struct ConformalPatch {
    pub reference: CurvedReference,
    /// Each row's lateral place in the tangent plane, sp [mm].
    pub sp_mm: Vec<f64>,
}

/// The conformal patch on `grid` and its surfaces along the reference's normal n at each element's
/// (x_i, sp_j): the rail's, and the wheel's exact surface or CONTACT's mesh of it (`surface`).
pub fn surfaces(
    frame: &PatchFrame,
    grid: &PatchGrid,
    reference: CurvedReference,
    (wheel, rail): (&PlacedWheel, &PlacedRail),
    surface: WheelSurface,
) -> (ConformalPatch, Surfaces) {
    let n = frame.n();
    let sp: Vec<f64> = (0..grid.ms).map(|j| reference.sp_mm(frame, j)).collect();
    debug_assert!(sp.windows(2).all(|w| w[0] < w[1]), "the rows' sp ascend");
    let meshed = (surface == WheelSurface::ContactMesh).then(|| {
        // The mesh's extent: a planar grid over the rows' sp.
        let (lo, hi) = (sp[0].min(sp[grid.ms - 1]), sp[0].max(sp[grid.ms - 1]));
        let ms = ((hi - lo) / grid.ds_mm).ceil() as usize + 1;
        let cover = PatchGrid { ms, s0_mm: lo - 0.5 * grid.ds_mm, ..grid.clone() };
        wheel_mesh::wheel_n_mm(frame, &cover, wheel, &sp)
    });
    let mut surfaces = Surfaces::with_capacity(grid.len());
    for (j, &s) in sp.iter().enumerate() {
        let row = frame.at(0.0, s);
        let t_r = rail.along([row.y, row.z], [n.y, n.z]);
        for i in 0..grid.mx {
            let t_w = match &meshed {
                Some(m) => m[j * grid.mx + i],
                None => wheel.along(&frame.at(grid.centre(i, j).0, s), &n),
            };
            surfaces.push(t_r, t_w);
        }
    }
    (ConformalPatch { reference, sp_mm: sp }, surfaces)
}

/// The undeformed distance at every element of the conformal `grid` (CONTACT's element order):
/// the planar gap between the surfaces along n, times row j's factor.
pub fn undeformed_distance(frame: &PatchFrame, grid: &PatchGrid, c: &ConformalPatch, s: &Surfaces) -> Vec<f64> {
    let mut h = Vec::with_capacity(grid.len());
    for j in 0..grid.ms {
        let factor = row_factor(frame, &c.reference, j);
        for k in j * grid.mx..(j + 1) * grid.mx {
            h.push(s.gap_mm(k, factor));
        }
    }
    h
}

/// The pressure's force along the reference's normal [N]: each row's pressure along its own
/// normal, projected (the tractions' part is the tangential problem's, `aggregate_forces`).
pub fn normal_force_n(frame: &PatchFrame, grid: &PatchGrid, c: &ConformalPatch, pn_mpa: &[f64]) -> f64 {
    let row = |j: usize| pn_mpa[j * grid.mx..(j + 1) * grid.mx].iter().sum::<f64>();
    (0..grid.ms).map(|j| row_factor(frame, &c.reference, j) * row(j)).sum::<f64>() * grid.dx_mm * grid.ds_mm
}

/// Each grid row's inclination [rad] for Blanco's correction (CONTACT's `wr_setup_cp`: the table
/// of the rows' sc and the curved reference's inclination, `curv_incln`, taken by `influe_blanco`
/// at each row's sc: interpolated, its own value, or the least-squares line, [`Blanco`]).
pub fn blanco_rows(
    grid: &PatchGrid,
    c: &ConformalPatch,
    b: crate::physics::halfspace::blanco::Blanco,
) -> Result<Vec<f64>, crate::physics::halfspace::ContactError> {
    use crate::physics::halfspace::blanco::row_inclinations;
    let sc: Vec<f64> = (0..grid.ms).map(|j| grid.centre(0, j).1).collect();
    let table: Vec<[f64; 2]> = sc.iter().enumerate().map(|(j, &s)| [s, c.reference.inclination_rad(j)]).collect();
    row_inclinations(b.inclination, &table, &sc)
}
