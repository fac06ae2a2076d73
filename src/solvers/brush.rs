//! The brush (simplified-theory) machinery shared by FASTSIM and the UBA (and FaStrip, for its
//! slip area's direction): slip rates per unit rolling distance over the flexibilities, the steady
//! march along each row from the leading edge with the traction bound, and the traction field.
//! FASTSIM and the UBA differ only in how they march.

use crate::physics::bound::within_bound;
pub use crate::physics::LeadingEdge;
use crate::physics::{moment_sum, project_to_bound, Flexibilities, Grid, Planform, RigidSlip};
use crate::problem::{LocalContact, Sample};
use crate::solvers::{FieldView, Step, Termination};

/// The rigid slip over the flexibilities [MPa/mm] (the left side of thesis Eq. 3.4/3.6):
/// `kx = cx/L1 − cs y/L3`, `ky = cy/L2 − cs x/L3` (grid x; CONTACT's spin sign, [`RigidSlip`]).
/// With Kalker's single flexibility ([`LocalContact::single_flexibility`]) every component is
/// divided by the same L of this sample's creepages.
/// With the modified FASTSIM's slope reduction ([`LocalContact::slope`]) the flexibilities are
/// divided by its factor k.
pub fn slip_rates(s: &Sample, local: &LocalContact) -> RigidSlip {
    let c = (s.cx, s.cy, s.cs);
    let (l1, l2, l3) = match local.single_flexibility {
        None => (local.flex.l1_mm3_n, local.flex.l2_mm3_n, local.flex.l3_mm3_n),
        Some(c_mm) => {
            let l = local.flex.single_mm3_n(c, c_mm);
            (l, l, l)
        }
    };
    // k = 1 without a slope reduction: l / 1 is l exactly.
    let k = local.slope.map_or(1.0, |r| r.factor(c, s.mu));
    RigidSlip::new(s.cx, s.cy, s.cs).over_flexibilities(l1 / k, l2 / k, l3 / k)
}

/// [`slip_rates`] of creepages (cx, cy, cs [1/mm]).
pub fn rates(cx: f64, cy: f64, cs_per_mm: f64, flex: &Flexibilities) -> RigidSlip {
    RigidSlip::new(cx, cy, cs_per_mm).over_flexibilities(flex.l1_mm3_n, flex.l2_mm3_n, flex.l3_mm3_n)
}

/// How a solver integrates the slip rate over one element.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Integration {
    /// Rate at the element centre times dx (the UBA's source term, Eq. 3.9–3.10).
    Centre,
    /// Exact integral over [x − dx, x] (FASTSIM, Eq. 2.34).
    Exact,
}

impl Integration {
    #[inline]
    fn increment(self, rates: &RigidSlip, x: f64, y: f64, dx: f64) -> (f64, f64) {
        match self {
            Integration::Centre => {
                let (kx, ky) = rates.at(x, y);
                (kx * dx, ky * dx)
            }
            Integration::Exact => rates.between(x - dx, x, y),
        }
    }
}

/// The traction upstream of a row's first loaded element at column i, row j.
#[inline]
pub fn ghost(grid: &Grid, planform: &Planform, edge: LeadingEdge, rates: &RigidSlip, i: usize, j: usize) -> (f64, f64) {
    match edge {
        LeadingEdge::Grid => (0.0, 0.0),
        LeadingEdge::Exact => {
            let x = grid.x_mm[i];
            let x_le = planform.leading_edge_mm[j].clamp(x - grid.dx_mm, x);
            rates.between(x_le, x - grid.dx_mm, grid.y_mm[j])
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

    /// The field view of these tractions on the planform's pressure.
    pub fn view<'a>(&'a self, grid: &'a Grid, planform: &'a Planform) -> FieldView<'a> {
        FieldView { grid, pressure_mpa: &planform.pressure_mpa, tx_mpa: &self.tx, ty_mpa: &self.ty, state: None }
    }

    /// Σ τx, Σ τy (one running sum each, flat order) and the moment sum [`moment_sum`].
    pub fn sums(&self, grid: &Grid) -> (f64, f64, f64) {
        (self.tx.iter().sum(), self.ty.iter().sum(), moment_sum(grid, &self.tx, &self.ty))
    }
}

/// A brush model's solve: the coefficients from the traction sums over the planform, the spin
/// moment from the moment sum [`moment_sum`] scaled the same way (`FN Σ m / Σ p`, so that it is
/// consistent with f = Σ τ / Σ p),
/// and the adhesion and slip counts (the extra columns `n_adhesion, n_slip`).
pub fn step(planform: &Planform, (sum_tx, sum_ty, moment): (f64, f64, f64), n_loaded: usize, n_slip: usize) -> Step {
    let (fx, fy) = planform.coefficients(sum_tx, sum_ty);
    let mz_nmm =
        if planform.pressure_sum_mpa > 0.0 { planform.ellipse.fn_n * moment / planform.pressure_sum_mpa } else { 0.0 };
    Step {
        fx_over_fn: fx,
        fy_over_fn: fy,
        mz_nmm,
        extra: vec![(n_loaded - n_slip) as f64, n_slip as f64],
        termination: Termination::Direct,
    }
}

/// Steady rolling by marching each row from its leading edge, with the traction bound `μ p`
/// after every element (thesis 2.3.6 and Eq. 2.29), the slip of row j times `row_gain[j]`.
/// Returns the number of slipping elements.
pub fn steady_march(
    grid: &Grid,
    local: &LocalContact,
    mu: f64,
    rates: &RigidSlip,
    how: (LeadingEdge, Integration),
    out: &mut Tractions,
) -> usize {
    let row = |j| RowMarch { j, local, rates };
    let mut n_slip = 0;
    for j in (0..grid.my).step_by(2) {
        n_slip += if j + 1 < grid.my {
            march_rows(grid, mu, how, [row(j), row(j + 1)], out).iter().sum::<usize>()
        } else {
            march_rows(grid, mu, how, [row(j)], out)[0]
        };
    }
    n_slip
}

/// A row to march: its index, and the contact and slip rates it is marched with.
#[derive(Clone, Copy)]
pub struct RowMarch<'a> {
    pub j: usize,
    pub local: &'a LocalContact,
    pub rates: &'a RigidSlip,
}

/// [`steady_march`] of N rows (their elements of `out` are overwritten), element by element in
/// step so that their independent chains of bounds overlap; each row's arithmetic is the same as
/// marched alone. Returns the number of slipping elements per row.
pub fn march_rows<const N: usize>(
    grid: &Grid,
    mu: f64,
    how: (LeadingEdge, Integration),
    rows: [RowMarch; N],
    out: &mut Tractions,
) -> [usize; N] {
    let mut n_slip = [0; N];
    // (τx, τy) of the last element and whether it was loaded, per row.
    let mut upstream = [(0.0, 0.0, false); N];
    for i in 0..grid.mx {
        for (r, row) in rows.iter().enumerate() {
            let k = grid.index(i, row.j);
            let p = row.local.planform.pressure_mpa[k];
            let (tx, ty, loaded) = upstream[r];
            if p <= 0.0 {
                out.tx[k] = 0.0;
                out.ty[k] = 0.0;
                upstream[r].2 = false;
                continue;
            }
            let (ux, uy) = unbounded(grid, row.local, row.rates, how, (i, row.j), loaded.then_some((tx, ty)));
            let (px, py, slip) = project_to_bound(ux, uy, mu * p);
            out.tx[k] = px;
            out.ty[k] = py;
            n_slip[r] += slip as usize;
            upstream[r] = (px, py, true);
        }
    }
    n_slip
}

/// Whether the first loaded element of row j slips in [`march_rows`] (without marching the row).
pub fn leading_slips(
    grid: &Grid,
    local: &LocalContact,
    mu: f64,
    rates: &RigidSlip,
    how: (LeadingEdge, Integration),
    j: usize,
) -> bool {
    let pressure = &local.planform.pressure_mpa;
    (0..grid.mx).find(|&i| pressure[grid.index(i, j)] > 0.0).is_some_and(|i| {
        let (ux, uy) = unbounded(grid, local, rates, how, (i, j), None);
        !within_bound(ux, uy, mu * pressure[grid.index(i, j)])
    })
}

/// The traction of loaded element (i, j) before the bound: the upstream element's traction (or,
/// at the start of a loaded run, the inflow) plus the element's slip times the row's gain.
#[inline(always)]
fn unbounded(
    grid: &Grid,
    local: &LocalContact,
    rates: &RigidSlip,
    (edge, integration): (LeadingEdge, Integration),
    (i, j): (usize, usize),
    upstream: Option<(f64, f64)>,
) -> (f64, f64) {
    let gain = local.row_gain[j];
    let (tx, ty) = upstream.unwrap_or_else(|| {
        let (gx, gy) = ghost(grid, &local.planform, edge, rates, i, j);
        (gain * gx, gain * gy)
    });
    let (dtx, dty) = integration.increment(rates, grid.x_mm[i], grid.y_mm[j], grid.dx_mm);
    (tx + gain * dtx, ty + gain * dty)
}
