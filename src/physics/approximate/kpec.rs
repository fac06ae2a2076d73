//! KPEC: Kik & Piotrowski's contact area from the virtual interpenetration (Kik & Piotrowski
//! 1996; Piotrowski & Kik 2008) with CONTACT's ellipse correction (user guide §"Fast or detailed
//! solution"; `m_snorm`): the threshold ε(y) of the interpenetration taken from Hertz's theory
//! for the equivalent ellipse (exact for elliptic contacts) instead of KP's 0.55; per row a
//! semi-elliptic pressure along x over the row's contact, all rows scaled by one peak chosen so
//! that the elastic displacement at the deepest point equals its interpenetration.

use super::{first_min, hertz_of_curvatures_coarse, ApproximateError, Method};
use crate::physics::halfspace::influence::rect_integrals;
use crate::physics::{Grid, Material};
use std::f64::consts::PI;

/// Kik–Piotrowski's original scaling of the interpenetration used for the equivalent ellipse.
const EPS_KP: f64 = 0.5;
/// Smallest lateral curvature taken [1/mm].
const MIN_CURVATURE: f64 = 1e-4;

/// The equivalent ellipse: curvatures (A, B) [1/mm] of the interpenetration, Hertz's semi-axes
/// (a, b) [mm] at the deepest interpenetration and the lateral centre `y_mid` [mm].
struct Equivalent {
    a1: f64,
    b1: f64,
    aa: f64,
    bb: f64,
    y_mid: f64,
}

/// The KPEC pressure [MPa] of the gap `gap` (undeformed distance less the approach, negative
/// where the bodies interpenetrate; grid order).
pub fn pressure(grid: &Grid, gap: &[f64], material: &Material) -> Result<Vec<f64>, ApproximateError> {
    let deepest = first_min(gap);
    let pentot = -gap[deepest];
    let e = equivalent(grid, gap, deepest)?;
    let (mx, my) = (grid.mx, grid.my);
    // Each row's threshold: ε(y) = (A a² − (A a² − B b²) ((y − y_mid)/b)²) / pen.
    let eps = |j: usize| {
        let r = (grid.y_mm[j] - e.y_mid) / e.bb;
        (e.a1 * e.aa * e.aa - (e.a1 * e.aa * e.aa - e.b1 * e.bb * e.bb) * r * r) / pentot
    };
    // The contact set: per row the elements at or below the threshold, ε clamped to [0, 1].
    let area_thr = |j: usize| -(1.0 - eps(j).clamp(0.0, 1.0)) * pentot;
    let rows: Vec<Option<(usize, usize, f64)>> = (0..my)
        .map(|j| {
            let thr = area_thr(j);
            let row = &gap[j * mx..(j + 1) * mx];
            let first = row.iter().position(|&g| g <= thr)?;
            let last = row.iter().rposition(|&g| g <= thr)?;
            Some((first, last, -(1.0 - eps(j).max(0.0)) * pentot))
        })
        .collect();
    let longest = rows.iter().flatten().map(|(f, l, _)| l - f + 1).max().unwrap_or(0);
    let half_max = 0.5 * longest as f64 * grid.dx_mm;
    let mut p = vec![0.0; grid.len()];
    for (j, r) in rows.iter().enumerate() {
        let Some((first, last, thr)) = *r else { continue };
        let row = &gap[j * mx..(j + 1) * mx];
        let t = |i: usize| i as f64 * grid.dx_mm;
        // Edges on the contour gap = thr, linear between element centres (at the grid's edge: its face).
        let trailing = if first == 0 {
            t(0) - 0.5 * grid.dx_mm
        } else {
            (t(first - 1) + grid.dx_mm * (thr - row[first - 1]) / (row[first] - row[first - 1])).min(t(first))
        };
        let leading = if last + 1 >= mx {
            t(last) + 0.5 * grid.dx_mm
        } else {
            (t(last) + grid.dx_mm * (thr - row[last]) / (row[last + 1] - row[last])).max(t(last))
        };
        let (half, mid) = (0.5 * (leading - trailing), 0.5 * (leading + trailing));
        for i in first..=last {
            let xi = t(i) - mid;
            p[j * mx + i] = (half * half - xi * xi).max(0.0).sqrt() / half_max;
        }
    }
    // Scale: the normal displacement of this shape at the deepest point equals its interpenetration.
    let un = displacement_at(grid, &p, deepest, material);
    let pmax = pentot / un;
    // Between a row's first and last element of the set, an element above the threshold is
    // outside the contact: its pressure is cleared after the scale is set (CONTACT's `panprc`,
    // m_scontc.f90, clears the exterior of every normal solution, KPEC's included).
    Ok(p.iter().enumerate().map(|(k, v)| if gap[k] <= area_thr(k / mx) { v * pmax } else { 0.0 }).collect())
}

/// The normal displacement [mm] at element `at` of the pressure `p` [MPa] on the half-space pair
/// (`Azz = (1 − ν)/(π G) I[1/r]`, [`rect_integrals`]; `I[1/r]` of each offset computed once per
/// thread and element size, [`OneOverR`]).
fn displacement_at(grid: &Grid, p: &[f64], at: usize, material: &Material) -> f64 {
    let (i0, j0) = (at % grid.mx, at / grid.mx);
    let c = (1.0 - material.poisson) / (PI * material.g_mpa);
    ONE_OVER_R.with_borrow_mut(|kept| {
        let table = kept.for_grid(grid);
        let mut u = 0.0;
        for (k, &pk) in p.iter().enumerate().filter(|(_, &v)| v > 0.0) {
            let (di, dj) = (i0 as isize - (k % grid.mx) as isize, j0 as isize - (k / grid.mx) as isize);
            u += c * table.at(di, dj) * pk;
        }
        u
    })
}

/// `I[1/r]` of the element size `(dx, dy)` [mm] at offsets `|di| ≤ hx`, `|dj| ≤ hy` (NaN until
/// asked for), index `(dj + hy)(2hx + 1) + di + hx`: a KPEC pressure's scale reads one element's
/// displacement from every loaded element, at every trial height of a case.
#[derive(Default)]
struct OneOverR {
    size_mm: [u64; 2],
    hx: usize,
    hy: usize,
    values: Vec<f64>,
}

thread_local! {
    static ONE_OVER_R: std::cell::RefCell<OneOverR> = std::cell::RefCell::new(OneOverR::default());
}

impl OneOverR {
    /// This table made to serve `grid` (its element size; offsets up to its extent), keeping
    /// what it holds of the same element size.
    fn for_grid(&mut self, grid: &Grid) -> &mut OneOverR {
        let size_mm = [grid.dx_mm.to_bits(), grid.dy_mm.to_bits()];
        let (hx, hy) = (grid.mx.saturating_sub(1), grid.my.saturating_sub(1));
        if size_mm != self.size_mm || self.values.is_empty() {
            *self = OneOverR { size_mm, hx, hy, values: vec![f64::NAN; (2 * hx + 1) * (2 * hy + 1)] };
        } else if hx > self.hx || hy > self.hy {
            let (hx, hy) = (hx.max(self.hx), hy.max(self.hy));
            let mut values = vec![f64::NAN; (2 * hx + 1) * (2 * hy + 1)];
            for dj in -(self.hy as isize)..=self.hy as isize {
                for di in -(self.hx as isize)..=self.hx as isize {
                    values[Self::index(hx, hy, di, dj)] = self.values[Self::index(self.hx, self.hy, di, dj)];
                }
            }
            (self.hx, self.hy, self.values) = (hx, hy, values);
        }
        self
    }

    fn index(hx: usize, hy: usize, di: isize, dj: isize) -> usize {
        (dj + hy as isize) as usize * (2 * hx + 1) + (di + hx as isize) as usize
    }

    /// `I[1/r]` at offset `(di, dj)` (computed on first use).
    fn at(&mut self, di: isize, dj: isize) -> f64 {
        let k = Self::index(self.hx, self.hy, di, dj);
        if self.values[k].is_nan() {
            let [dx, dy] = self.size_mm.map(f64::from_bits);
            self.values[k] = rect_integrals(di as f64 * dx, dj as f64 * dy, dx, dy).one_over_r;
        }
        self.values[k]
    }
}

/// The equivalent ellipse of the KP region (gap ≤ (1 − 0.5) × deepest): A from a parabola
/// through the deepest row, B from the region's lateral extent, Hertz's (a, b) at the deepest
/// interpenetration as CONTACT's `hzcalc3d` finds them (k to 1e-6: [`hertz_of_curvatures_coarse`];
/// CONTACT's `kpec_equiv_ellipse`).
fn equivalent(grid: &Grid, gap: &[f64], deepest: usize) -> Result<Equivalent, ApproximateError> {
    let (mx, my) = (grid.mx, grid.my);
    let (i_min, j_min) = (deepest % mx, deepest / mx);
    if i_min == 0 || i_min + 1 >= mx || my < 3 {
        return Err(ApproximateError::OnEdge { method: Method::Kpec, row: j_min, element: i_min });
    }
    let h_min = gap[deepest];
    let thr = (1.0 - EPS_KP) * h_min;
    let row = &gap[j_min * mx..(j_min + 1) * mx];
    let (mut i0, mut i1) = (i_min - 1, i_min + 1);
    while !(i0 == 0 || i1 + 1 >= mx || row[i0].max(row[i1]) > thr) {
        i0 -= 1;
        i1 += 1;
    }
    let dx = (i1 - i_min) as f64 * grid.dx_mm;
    let a1 = (row[i1] - 2.0 * h_min + row[i0]) / (2.0 * dx * dx);
    let in_region: Vec<usize> = (0..my).filter(|&j| gap[j * mx..(j + 1) * mx].iter().any(|&g| g <= thr)).collect();
    let (mut j0, mut j1) = (in_region[0], in_region[in_region.len() - 1]);
    let dy = grid.dy_mm;
    j0 = j0.max(1);
    j1 = j1.min(my - 2);
    let single = j0 >= j1;
    let at = |j: usize, i: usize| gap[j * mx + i];
    let i_start = first_min(&gap[j0 * mx..(j0 + 1) * mx]);
    let y_start = grid.y_mm[j0] - (thr - at(j0, i_start)) * dy / (at(j0 - 1, i_start) - at(j0, i_start));
    let i_end = first_min(&gap[j1 * mx..(j1 + 1) * mx]);
    let y_end = grid.y_mm[j1] + (thr - at(j1, i_end)) * dy / (at(j1 + 1, i_end) - at(j1, i_end));
    let y_mid = 0.5 * (y_start + y_end);
    let b1 = ((thr - h_min) / (y_end - y_mid).powi(2)).max(MIN_CURVATURE);
    let (aa, mut bb) = hertz_of_curvatures_coarse(a1, b1, -h_min).ok_or(ApproximateError::NotConvex {
        method: Method::Kpec,
        a_per_mm: a1,
        b_per_mm: b1,
    })?;
    if single {
        bb = bb.max(1.1 * (grid.y_mm[j_min] - y_mid).abs());
    }
    Ok(Equivalent { a1, b1, aa, bb, y_mid })
}
