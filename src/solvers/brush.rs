//! The brush (simplified-theory) machinery shared by FASTSIM and the UBA: slip rates per unit
//! rolling distance, the steady march along each row from the leading edge with the traction
//! bound, and the traction coefficients. The two solvers differ only in how they march.

pub use crate::physics::LeadingEdge;
use crate::physics::{project_to_bound, Flexibilities, Grid};

/// Rigid slip per unit rolling distance divided by the flexibility [MPa/mm]
/// (the left side of thesis Eq. 3.4/3.6): `kx = cx/L1 − cs y/L3`, `ky = cy/L2 + cs x/L3`.
#[derive(Debug, Clone, Copy)]
pub struct SlipRates {
    pub cx_l1: f64,
    pub cy_l2: f64,
    pub cs_l3: f64,
}

impl SlipRates {
    pub fn new(cx: f64, cy: f64, cs_per_mm: f64, flex: &Flexibilities) -> Self {
        SlipRates { cx_l1: cx / flex.l1_mm3_n, cy_l2: cy / flex.l2_mm3_n, cs_l3: cs_per_mm / flex.l3_mm3_n }
    }

    /// Traction gained over one element length dx at centre (x, y), source at the centre
    /// (the UBA's discretisation, Eq. 3.9–3.10 times dt·V = dx at courant 1).
    #[inline]
    pub fn over_element(&self, x: f64, y: f64, dx: f64) -> (f64, f64) {
        ((self.cx_l1 - self.cs_l3 * y) * dx, (self.cy_l2 + self.cs_l3 * x) * dx)
    }

    /// Traction gained rolling from x0 to x1 at row y, integrated exactly (thesis Eq. 2.34).
    #[inline]
    pub fn between(&self, x0: f64, x1: f64, y: f64) -> (f64, f64) {
        ((self.cx_l1 - self.cs_l3 * y) * (x1 - x0), self.cy_l2 * (x1 - x0) + 0.5 * self.cs_l3 * (x1 * x1 - x0 * x0))
    }
}

/// How a solver integrates the slip rate over one element.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Integration {
    /// Rate at the element centre times dx (the UBA's source term, Eq. 3.9–3.10).
    Centre,
    /// Exact integral over [x − dx, x] (FASTSIM, Eq. 2.34).
    Exact,
}

/// The traction upstream of a row's first loaded element at x (centre), row j.
#[inline]
pub fn ghost(
    grid: &Grid,
    edge: LeadingEdge,
    rates: &SlipRates,
    i: usize,
    j: usize,
    a_mm: f64,
    b_mm: f64,
) -> (f64, f64) {
    match edge {
        LeadingEdge::Grid => (0.0, 0.0),
        LeadingEdge::Exact => {
            let x = grid.x_mm[i];
            let x_le = (-grid.chord_half_length_mm(j, a_mm, b_mm)).clamp(x - grid.dx_mm, x);
            rates.between(x_le, x - grid.dx_mm, grid.y_mm[j])
        }
    }
}

impl Integration {
    #[inline]
    fn increment(self, rates: &SlipRates, x: f64, y: f64, dx: f64) -> (f64, f64) {
        match self {
            Integration::Centre => rates.over_element(x, y, dx),
            Integration::Exact => rates.between(x - dx, x, y),
        }
    }
}

/// Traction field on the grid [MPa], flat order.
#[derive(Debug, Clone, PartialEq)]
pub struct Tractions {
    pub tx: Vec<f64>,
    pub ty: Vec<f64>,
}

impl Tractions {
    pub fn zero(n: usize) -> Self {
        Tractions { tx: vec![0.0; n], ty: vec![0.0; n] }
    }
}

/// Steady rolling by marching each row from its leading edge, with the traction bound `μ p`
/// after every element (thesis 2.3.6 and Eq. 2.29). `a_mm`, `b_mm`: the ellipse of the pressure.
/// Returns the number of slipping elements.
#[allow(clippy::too_many_arguments)]
pub fn steady_march(
    grid: &Grid,
    pressure: &[f64],
    mu: f64,
    rates: &SlipRates,
    edge: LeadingEdge,
    integration: Integration,
    (a_mm, b_mm): (f64, f64),
    out: &mut Tractions,
) -> usize {
    let mut n_slip = 0;
    for j in 0..grid.my {
        let y = grid.y_mm[j];
        let (mut tx, mut ty) = (0.0, 0.0);
        let mut upstream_loaded = false;
        for i in 0..grid.mx {
            let k = grid.index(i, j);
            if pressure[k] <= 0.0 {
                out.tx[k] = 0.0;
                out.ty[k] = 0.0;
                upstream_loaded = false;
                continue;
            }
            if !upstream_loaded {
                (tx, ty) = ghost(grid, edge, rates, i, j, a_mm, b_mm);
            }
            let (dtx, dty) = integration.increment(rates, grid.x_mm[i], y, grid.dx_mm);
            let (px, py, slip) = project_to_bound(tx + dtx, ty + dty, mu * pressure[k]);
            (tx, ty) = (px, py);
            out.tx[k] = tx;
            out.ty[k] = ty;
            n_slip += slip as usize;
            upstream_loaded = true;
        }
    }
    n_slip
}

/// Traction coefficients `(Σ τx / Σ p, Σ τy / Σ p)` on the grid (thesis Eq. 3.12).
pub fn coefficients(t: &Tractions, pressure: &[f64]) -> (f64, f64) {
    let p: f64 = pressure.iter().sum();
    if p <= 0.0 {
        return (0.0, 0.0);
    }
    (t.tx.iter().sum::<f64>() / p, t.ty.iter().sum::<f64>() / p)
}

/// Number of loaded elements (p > 0).
pub fn loaded(pressure: &[f64]) -> usize {
    pressure.iter().filter(|&&p| p > 0.0).count()
}

/// Spatial sawtooth indicator of a traction field: the fraction of interior loaded elements
/// (along x, in each row) where the first difference of τx changes sign between significant
/// differences. A smooth field scores near 0 (one change per row at most, at the peak); the
/// odd-even mode of an unstable (e.g. downwind) scheme scores near 1 — even when the traction
/// bound keeps |τ| ≤ μp, so bound checks alone would not see it.
pub fn sawtooth_index(grid: &Grid, pressure: &[f64], t: &Tractions) -> f64 {
    let scale = t.tx.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if scale == 0.0 {
        return 0.0;
    }
    let tiny = 1e-9 * scale;
    let (mut changes, mut interior) = (0usize, 0usize);
    for j in 0..grid.my {
        // Each maximal run of three or more loaded elements along x.
        let mut i = 0;
        while i < grid.mx {
            let start = i;
            while i < grid.mx && pressure[grid.index(i, j)] > 0.0 {
                i += 1;
            }
            if i - start >= 3 {
                interior += i - start - 2;
                changes += crate::metrics::turns((start..i).map(|ii| t.tx[grid.index(ii, j)]), tiny);
            }
            i += 1;
        }
    }
    let rows_with_peak = grid.my as f64;
    if interior == 0 {
        0.0
    } else {
        ((changes as f64 - rows_with_peak).max(0.0) / interior as f64).min(1.0)
    }
}
