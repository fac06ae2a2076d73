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

mod falling;
mod flat;

use super::brush::{self, Falling, Integration, LeadingEdge, Tractions};
use super::stepper::{FieldView, Step, Stepper};
use super::{grid_model, ModelDef, SolveError};
use crate::error::InputError;
use crate::physics::{Grid, Planform, RigidSlip};
use crate::problem::{LocalContact, Problem, Sample};
use crate::solvers::style::{muted, Dash, Marker};

/// The Unsteady Brush Algorithm.
pub const MODEL: ModelDef = grid_model(
    "uba",
    "Unsteady Brush Algorithm (Diaz de la Fuente 2012, ch. 3): explicit upwind transport of the tangential tractions with the traction bound",
    check,
    build,
    muted(1, Dash::Solid, Marker::Square),
);

/// Largest Courant number the UBA accepts: it sub-steps (see [`substeps`]), and a scene asking
/// for more than this many sub-steps per time step is almost certainly a unit mistake.
pub const MAX_COURANT: f64 = 64.0;

/// The explicit scheme is stable only for a Courant number ≤ 1 (CFL); larger time steps are
/// split into `ceil(courant)` equal sub-steps.
fn check(p: &Problem) -> Result<(), InputError> {
    let c = p.rolling.courant;
    if c > 0.0 && c <= MAX_COURANT {
        return check_falling(p);
    }
    Err(InputError::new(
        "rolling.courant",
        c,
        format!("(0, {MAX_COURANT}] when the scene runs uba (its upwind step is stable for courant <= 1; larger steps are split into ceil(courant) sub-steps)"),
    ))
}

/// Largest stiffness κ of a time step with a memoryless falling law ([`stiffness`]).
pub const MAX_STIFFNESS: f64 = 1.0;

/// A memoryless falling law on a time history: each element's bound g = p μ(s(g)), with the slip
/// velocity s = c (|u| − g), c = V L/(gain C dx), has one root for every traction only when
/// κ = p c max|dμ/ds| < 1 ([`MAX_STIFFNESS`]); above it the explicit step's bound may jump
/// between roots from one step to the next. Sub-stepping cannot help (c grows as C dx shrinks),
/// so the UBA refuses. With a memory μ follows the slip velocity over the relaxation distance
/// (backward Euler, unconditionally stable) and the step is accepted.
fn check_falling(p: &Problem) -> Result<(), InputError> {
    if !p.friction.is_falling() || p.memory.is_active() || !p.loading.is_transient() {
        return Ok(());
    }
    let kappa = stiffness(p);
    if kappa < MAX_STIFFNESS {
        return Ok(());
    }
    Err(InputError::new(
        "friction.memory_mm",
        format!("none (uba's kappa = {})", kappa_text(kappa)),
        format!(
            "uba's stiffness kappa = p_max V L max|dmu/ds| / (gain C dx) < {MAX_STIFFNESS} with a falling law and no friction memory (each element's bound mu(s) p then has one root; sub-steps only raise kappa): give memory_mm > 0, a flatter law (larger sabsh1_mm_s), a lower speed, a larger courant, or leave uba out"
        ),
    ))
}

/// κ as a message shows it: three decimals, with an exponent where that would be longer than a
/// message's excerpt keeps (κ reaches 1e300 with a tiny sabsh1_mm_s).
fn kappa_text(kappa: f64) -> String {
    if kappa < 1e9 {
        format!("{kappa:.3}")
    } else {
        format!("{kappa:.3e}")
    }
}

/// κ = max over the history of p_max V max(L1, L2) max|dμ_s/ds| / (min gain · C dx), C the
/// sub-step's Courant number ([`substeps`]).
pub fn stiffness(p: &Problem) -> f64 {
    let (_, courant) = substeps(p.rolling.courant);
    let slope = p.friction.steepest_fall_per_mm_s();
    let mut local = p.local_contact(p.loading.first().fn_n);
    let mut kappa = 0.0f64;
    for at in p.loading.rows() {
        p.reload_local(&mut local, at.fn_n);
        let p_max = local.planform.pressure_mpa.iter().fold(0.0f64, |m, &v| m.max(v));
        let gain = local.row_gain.iter().copied().filter(|g| *g > 0.0).fold(f64::INFINITY, f64::min);
        let (l1, l2, _) = brush::flexibilities(at, &local);
        let c = at.speed_mm_s(p.rolling.v_mm_s) * l1.max(l2) / (gain * courant * p.grid.dx_mm);
        kappa = kappa.max(p_max * c * slope);
    }
    kappa
}

/// Sub-steps per time step and the Courant number of each: `n = ceil(C)`, `C/n ≤ 1`.
fn substeps(courant: f64) -> (usize, f64) {
    let n = courant.ceil().max(1.0) as usize;
    (n, courant / n as f64)
}

fn build(p: &Problem) -> Result<Box<dyn Stepper + '_>, SolveError> {
    Ok(continuing(p, Tractions::zero(p.grid.len())))
}

/// The UBA from the tractions `t` (grid order) instead of rest: a wheel–rail transient rolling
/// step continuing the case before (CONTACT's T = 2 with P = 0); elements without pressure carry
/// nothing from the first step on (the bound μ p).
pub fn continuing(p: &Problem, t: Tractions) -> Box<dyn Stepper + '_> {
    let n = p.grid.len();
    let first = p.loading.first();
    let local = p.local_contact(first.fn_n);
    let prep = Prepared::new(&p.grid, &local, first.mu);
    let fresh = vec![p.friction.mu_static(); n];
    let scratch = Tractions::zero(n);
    Box::new(Uba { p, local, prep, prep_mu: first.mu, t, scratch, mu: (fresh.clone(), fresh) })
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
    /// Each element's friction coefficient and its scratch (the memory's state; a falling law only).
    mu: (Vec<f64>, Vec<f64>),
}

impl Uba<'_> {
    fn row(&self, n_slip: usize, sums: (f64, f64, f64)) -> Step {
        brush::step(&self.local.planform, sums, self.prep.loaded(), n_slip)
    }
}

impl Stepper for Uba<'_> {
    fn load(&mut self, at: &Sample) -> Result<(), SolveError> {
        if self.p.reload_local(&mut self.local, at.fn_n) {
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
        let n_slip = match Falling::of(self.p, at, &self.local, self.p.grid.dx_mm) {
            None => brush::steady_march(&self.p.grid, &self.local, at.mu, &rates, how, &mut self.t),
            Some(bound) => {
                let out = (&mut self.t, self.mu.0.as_mut_slice());
                brush::steady_march_with(&self.p.grid, &self.local, &bound, &rates, how, out)
            }
        };
        Ok(self.row(n_slip, self.t.sums(&self.p.grid)))
    }

    /// One time step: `ceil(C)` explicit sub-steps of Courant number `C/ceil(C)` each.
    fn transient(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let rates = brush::slip_rates(at, &self.local);
        let (n, courant) = substeps(self.p.rolling.courant);
        let scheme = (courant, self.p.model.leading_edge);
        let mut sums = StepSums { n_slip: 0, sum_tx: 0.0, sum_ty: 0.0, moment: 0.0 };
        let falling = Falling::of(self.p, at, &self.local, courant * self.p.grid.dx_mm);
        for _ in 0..n {
            let contact = (&self.p.grid, &self.local.planform);
            sums = match &falling {
                None => step(contact, &mut self.prep, &rates, scheme, &self.t, &mut self.scratch),
                Some(bound) => {
                    let sums = step_falling(
                        contact,
                        &mut self.prep,
                        (bound, &rates),
                        scheme,
                        &self.t,
                        &mut self.scratch,
                        &mut self.mu,
                    );
                    std::mem::swap(&mut self.mu.0, &mut self.mu.1);
                    sums
                }
            };
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
    let (ghost, spin, consts) = prepare_step((grid, planform), prep, rates, (courant, edge));
    let io = (old.tx.as_slice(), old.ty.as_slice(), new.tx.as_mut_slice(), new.ty.as_mut_slice());
    match (ghost, spin) {
        (false, false) => flat::step::<false, false>(prep, io, consts),
        (false, true) => flat::step::<false, true>(prep, io, consts),
        (true, false) => flat::step::<true, false>(prep, io, consts),
        (true, true) => flat::step::<true, true>(prep, io, consts),
    }
}

/// [`step`] with a falling friction law's bound ([`falling::step`]); the coefficients from
/// `mu.0` into `mu.1`.
fn step_falling(
    (grid, planform): (&Grid, &Planform),
    prep: &mut Prepared,
    (bound, rates): (&Falling, &RigidSlip),
    scheme: (f64, LeadingEdge),
    old: &Tractions,
    new: &mut Tractions,
    mu: &mut (Vec<f64>, Vec<f64>),
) -> StepSums {
    let (ghost, spin, consts) = prepare_step((grid, planform), prep, rates, scheme);
    let io = (old.tx.as_slice(), old.ty.as_slice(), new.tx.as_mut_slice(), new.ty.as_mut_slice());
    let b = (bound, (planform.pressure_mpa.as_slice(), planform.inv_pressure_per_mpa.as_slice()));
    let m = (mu.0.as_slice(), mu.1.as_mut_slice());
    match (ghost, spin) {
        (false, false) => falling::step::<false, false>(prep, b, io, m, consts),
        (false, true) => falling::step::<false, true>(prep, b, io, m, consts),
        (true, false) => falling::step::<true, false>(prep, b, io, m, consts),
        (true, true) => falling::step::<true, true>(prep, b, io, m, consts),
    }
}

/// The ghost inflow of each run (exact leading edge) and the step's constants
/// [C, C·dx·kx0, C·dx·dkx/dy, C·dx·ky0, C·dx·dky/dx]: (ghost, spin, constants).
fn prepare_step(
    (grid, planform): (&Grid, &Planform),
    prep: &mut Prepared,
    rates: &RigidSlip,
    (courant, edge): (f64, LeadingEdge),
) -> (bool, bool, [f64; 5]) {
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
    (ghost, spin, consts)
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
