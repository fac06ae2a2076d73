//! The Unsteady Brush Algorithm (thesis ch. 3): explicit upwind time stepping of the transport
//! equation for the tangential tractions (Eq. 3.6, discretised as Eq. 3.9–3.10), then the traction
//! bound (Eq. 3.11) and zero traction outside the ellipse.
//!
//! Direction of the difference: material enters at the leading edge x = −a and moves in +x, so
//! information travels in +x and the stable (upwind) difference takes the element *upstream*,
//! `τ_{i−1}` (smaller x). Eq. 3.9 as printed uses `τ_{i+1} − τ_i`, a downwind difference: it
//! transports against the flow, is unconditionally unstable for this advection, and its
//! growing odd-even mode is what appears as a sawtooth (clipped by the bound, hence bounded but
//! wrong). Eq. 3.10 also prints Δy where the transport is along x for both components.
//!
//! Update for each loaded element, with Courant number C = V dt / dx ≤ 1 (a larger time step is
//! split into ceil(C) sub-steps):
//! `τ_i ← τ_i − C (τ_i − τ_{i−1}) + C dx k_i`, `k = (cx/L1 − cs y/L3, cy/L2 − cs x/L3)`
//! (the thesis's Eq. 3.4 with its spin sign converted to CONTACT's, see [`crate::physics::RigidSlip`]);
//! at C = 1 material moves exactly one element per step: `τ_i ← τ_{i−1} + dx k_i`.

mod flat;

use super::brush::{self, Integration, LeadingEdge, Tractions};
use super::stepper::{FieldView, Step, Stepper};
use super::{linear_in_elements, ModelDef, SolveError};
use crate::error::InputError;
use crate::physics::{Grid, Planform, RigidSlip};
use crate::problem::{LocalContact, Problem, Sample};

/// The Unsteady Brush Algorithm.
pub const MODEL: ModelDef = ModelDef {
    name: "uba",
    summary: "Unsteady Brush Algorithm (Diaz de la Fuente 2012, ch. 3): explicit upwind transport of the tangential tractions with the traction bound",
    extra_columns: &["n_adhesion", "n_slip"],
    iterative: false,
    prescribed_forces: false,
    shifts: false,
    check,
    cost_per_row: linear_in_elements,
    params: None,
    build,
};

/// Largest Courant number the UBA accepts: it sub-steps (see [`substeps`]), and a scene asking
/// for more than this many sub-steps per time step is almost certainly a unit mistake.
const MAX_COURANT: f64 = 64.0;

/// The explicit scheme is stable only for a Courant number ≤ 1 (CFL); larger time steps are
/// split into `ceil(courant)` equal sub-steps.
fn check(p: &Problem) -> Result<(), InputError> {
    let c = p.rolling.courant;
    if c > 0.0 && c <= MAX_COURANT {
        return Ok(());
    }
    Err(InputError::new(
        "rolling.courant",
        c,
        format!("(0, {MAX_COURANT}] when the scene runs uba (its upwind step is stable for courant <= 1; larger steps are split into ceil(courant) sub-steps)"),
    ))
}

/// Sub-steps per time step and the Courant number of each: `n = ceil(C)`, `C/n ≤ 1`.
fn substeps(courant: f64) -> (usize, f64) {
    let n = courant.ceil().max(1.0) as usize;
    (n, courant / n as f64)
}

fn build(p: &Problem) -> Result<Box<dyn Stepper + '_>, SolveError> {
    let n = p.grid.len();
    let first = p.loading.first();
    let local = p.local_contact(first.fn_n);
    let prep = Prepared::new(&p.grid, &local, first.mu);
    Ok(Box::new(Uba { p, local, prep, prep_mu: first.mu, t: Tractions::zero(n), scratch: Tractions::zero(n) }))
}

/// The UBA's state: the contact at the current load, the prepared step and the tractions.
struct Uba<'a> {
    p: &'a Problem,
    local: LocalContact,
    prep: Prepared,
    /// The μ `prep` was made for.
    prep_mu: f64,
    t: Tractions,
    scratch: Tractions,
}

impl Uba<'_> {
    fn row(&self, n_slip: usize, sums: (f64, f64, f64)) -> Step {
        brush::step(&self.local.planform, sums, self.prep.loaded(), n_slip)
    }
}

impl Stepper for Uba<'_> {
    fn load(&mut self, at: &Sample) -> Result<(), SolveError> {
        if at.fn_n != self.local.planform.ellipse.fn_n {
            self.local = self.p.local_contact(at.fn_n);
            // Elements that left the contact carry nothing.
            for (k, p) in self.local.planform.pressure_mpa.iter().enumerate() {
                if *p <= 0.0 {
                    for v in [&mut self.t.tx, &mut self.t.ty, &mut self.scratch.tx, &mut self.scratch.ty] {
                        v[k] = 0.0;
                    }
                }
            }
            self.prep = Prepared::new(&self.p.grid, &self.local, at.mu);
        } else if at.mu != self.prep_mu {
            self.prep = Prepared::new(&self.p.grid, &self.local, at.mu);
        }
        self.prep_mu = at.mu;
        Ok(())
    }

    /// The fixed point of [`step`] for any C ∈ (0, 1], marched directly.
    fn steady(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let rates = brush::slip_rates(at, &self.local);
        let how = (self.p.model.leading_edge, Integration::Centre);
        let n_slip = brush::steady_march(&self.p.grid, &self.local, at.mu, &rates, how, &mut self.t);
        Ok(self.row(n_slip, self.t.sums(&self.p.grid)))
    }

    /// One time step: `ceil(C)` explicit sub-steps of Courant number `C/ceil(C)` each.
    fn transient(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let rates = brush::slip_rates(at, &self.local);
        let (n, courant) = substeps(self.p.rolling.courant);
        let scheme = (courant, self.p.model.leading_edge);
        let mut sums = StepSums { n_slip: 0, sum_tx: 0.0, sum_ty: 0.0, moment: 0.0 };
        for _ in 0..n {
            sums =
                step((&self.p.grid, &self.local.planform), &mut self.prep, &rates, scheme, &self.t, &mut self.scratch);
            std::mem::swap(&mut self.t, &mut self.scratch);
        }
        Ok(self.row(sums.n_slip, (sums.sum_tx, sums.sum_ty, sums.moment)))
    }

    fn field(&self) -> Option<FieldView<'_>> {
        Some(self.t.view(&self.p.grid, &self.local.planform))
    }
}

/// What a UBA step needs of the pressure, prepared once per load and friction: the loaded runs
/// of each row, the bound μ p per element, whether an element's upstream
/// neighbour is loaded, and the element centres in flat order.
#[derive(Debug, Clone)]
pub struct Prepared {
    /// (row j, first i, one past the last i) of each contiguous loaded run.
    runs: Vec<(usize, usize, usize)>,
    bound: Vec<f64>,
    /// 1.0 where the upstream element (i − 1, same row) is loaded, else 0.0 (ghost inflow).
    upstream: Vec<f64>,
    x_mm: Vec<f64>,
    y_mm: Vec<f64>,
    /// The row's slip factor per element ([`LocalContact::row_gain`]).
    gain: Vec<f64>,
    /// Inflow (ghost) traction per element, non-zero only at run starts with the exact edge.
    ghost_x: Vec<f64>,
    ghost_y: Vec<f64>,
}

impl Prepared {
    pub fn new(grid: &Grid, local: &LocalContact, mu: f64) -> Self {
        let pressure = &local.planform.pressure_mpa;
        let n = grid.len();
        let mut runs = Vec::new();
        let mut upstream = vec![0.0; n];
        for j in 0..grid.my {
            let mut i = 0;
            while i < grid.mx {
                if pressure[grid.index(i, j)] > 0.0 {
                    let start = i;
                    while i < grid.mx && pressure[grid.index(i, j)] > 0.0 {
                        if i > start {
                            upstream[grid.index(i, j)] = 1.0;
                        }
                        i += 1;
                    }
                    runs.push((j, start, i));
                } else {
                    i += 1;
                }
            }
        }
        let bound: Vec<f64> = pressure.iter().map(|p| mu * p.max(0.0)).collect();
        let x_mm = (0..n).map(|k| grid.x_mm[k % grid.mx]).collect();
        let y_mm = (0..n).map(|k| grid.y_mm[k / grid.mx]).collect();
        let gain = (0..n).map(|k| local.row_gain[k / grid.mx]).collect();
        Prepared { runs, bound, upstream, x_mm, y_mm, gain, ghost_x: vec![0.0; n], ghost_y: vec![0.0; n] }
    }

    /// Number of loaded elements.
    pub fn loaded(&self) -> usize {
        self.runs.iter().map(|r| r.2 - r.1).sum()
    }
}

/// One explicit upwind step (corrected Eq. 3.9–3.10) with the traction bound, from `old` into
/// `new` (double-buffered: every update reads only old values, so the step is one flat,
/// branch-free pass over the grid, `uba/flat.rs`). `edge` sets the inflow value upstream of each row's
/// first loaded element of the planform.
/// Returns the number of elements on the bound, the traction sums and the moment sum.
/// `courant` must be in (0, 1].
pub fn step(
    (grid, planform): (&Grid, &Planform),
    prep: &mut Prepared,
    rates: &RigidSlip,
    (courant, edge): (f64, LeadingEdge),
    old: &Tractions,
    new: &mut Tractions,
) -> StepSums {
    let ghost = edge == LeadingEdge::Exact;
    if ghost {
        for &(j, first, _) in &prep.runs {
            let (gx, gy) = brush::ghost(grid, planform, edge, rates, first, j);
            let k = grid.index(first, j);
            prep.ghost_x[k] = prep.gain[k] * gx;
            prep.ghost_y[k] = prep.gain[k] * gy;
        }
    }
    // Source per step, C·dx·k(x, y) (Eq. 3.4), k the rigid slip over the flexibilities.
    let (c, cdx) = (courant, courant * grid.dx_mm);
    let [kx0, kx_y, ky0, ky_x] = rates.affine();
    let consts = [c, cdx * kx0, cdx * kx_y, cdx * ky0, cdx * ky_x];
    let spin = kx_y != 0.0 || ky_x != 0.0;
    let io = (old.tx.as_slice(), old.ty.as_slice(), new.tx.as_mut_slice(), new.ty.as_mut_slice());
    match (ghost, spin) {
        (false, false) => flat::step::<false, false>(prep, io, consts),
        (false, true) => flat::step::<false, true>(prep, io, consts),
        (true, false) => flat::step::<true, false>(prep, io, consts),
        (true, true) => flat::step::<true, true>(prep, io, consts),
    }
}

/// What a step returns besides the new tractions: the elements on the bound, the traction sums
/// Σ τx, Σ τy and the moment sum, taken in the pass in the four-lane order of
/// [`crate::physics::lanes`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepSums {
    pub n_slip: usize,
    pub sum_tx: f64,
    pub sum_ty: f64,
    /// `Σ (x_C τy − y τx)` [MPa·mm], the sum of [`crate::physics::moment_sum`] (in the four-lane order).
    pub moment: f64,
}
