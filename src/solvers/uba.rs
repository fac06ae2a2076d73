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
//! Update for each loaded element, with Courant number C = V dt / dx ≤ 1:
//! `τ_i ← τ_i − C (τ_i − τ_{i−1}) + C dx k_i`, `k = (cx/L1 − cs y/L3, cy/L2 + cs x/L3)`;
//! at C = 1 material moves exactly one element per step: `τ_i ← τ_{i−1} + dx k_i`.

use super::brush::{self, Integration, LeadingEdge, SlipRates, Tractions};
use super::Solver;
use crate::error::Error;
use crate::history::{History, Row};
use crate::physics::{project_to_bound, Grid};
use crate::problem::{LocalContact, Problem};
use crate::scene::InitKind;

/// The Unsteady Brush Algorithm.
pub struct Uba;

/// Extra columns of `uba.csv`.
pub const EXTRA: [&str; 2] = ["n_adhesion", "n_slip"];

/// One explicit upwind step (corrected Eq. 3.9–3.10) with the traction bound, in place.
/// `edge` sets the inflow value upstream of each row's first loaded element; `ab` is the ellipse
/// of the pressure. Returns the number of elements on the bound. `courant` must be in (0, 1].
#[allow(clippy::too_many_arguments)]
pub fn step(
    grid: &Grid,
    pressure: &[f64],
    mu: f64,
    rates: &SlipRates,
    courant: f64,
    edge: LeadingEdge,
    ab: (f64, f64),
    t: &mut Tractions,
) -> usize {
    let mut n_slip = 0;
    let dx = grid.dx_mm;
    for j in 0..grid.my {
        let y = grid.y_mm[j];
        let row = j * grid.mx;
        // Descending i: τ_{i−1} is still the old value when τ_i is updated.
        for i in (0..grid.mx).rev() {
            let k = row + i;
            let p = pressure[k];
            if p <= 0.0 {
                t.tx[k] = 0.0;
                t.ty[k] = 0.0;
                continue;
            }
            let (ux, uy) = if i > 0 && pressure[k - 1] > 0.0 {
                (t.tx[k - 1], t.ty[k - 1])
            } else {
                brush::ghost(grid, edge, rates, i, j, ab.0, ab.1)
            };
            let (sx, sy) = rates.over_element(grid.x_mm[i], y, dx);
            let nx = t.tx[k] + courant * (ux - t.tx[k] + sx);
            let ny = t.ty[k] + courant * (uy - t.ty[k] + sy);
            let (px, py, slip) = project_to_bound(nx, ny, mu * p);
            t.tx[k] = px;
            t.ty[k] = py;
            n_slip += slip as usize;
        }
    }
    n_slip
}

/// The UBA's steady state: the fixed point of [`step`] for any C ∈ (0, 1], marched directly.
pub fn steady(
    grid: &Grid,
    local: &LocalContact,
    mu: f64,
    rates: &SlipRates,
    edge: LeadingEdge,
    t: &mut Tractions,
) -> usize {
    let ab = (local.hertz.a_mm, local.hertz.b_mm);
    brush::steady_march(
        grid,
        &local.pressure_mpa,
        mu,
        rates,
        edge,
        Integration::Centre,
        ab,
        t,
    )
}

impl Solver for Uba {
    fn name(&self) -> &str {
        "uba"
    }

    fn run(&self, problem: &Problem) -> Result<History, Error> {
        if !(problem.courant > 0.0 && problem.courant <= 1.0) {
            return Err(super::fail(
                problem,
                "uba",
                format!("courant {} outside (0, 1]", problem.courant),
            ));
        }
        let grid = &problem.grid;
        let edge = problem.model.leading_edge;
        let mut h = History::new(self.name(), &EXTRA);
        let mut t = Tractions::zero(grid.len());
        let mut local = problem.local_contact(problem.hertz.fn_n);
        let row =
            |s: &crate::problem::Sample, t: &Tractions, local: &LocalContact, n_slip: usize| {
                let (fx, fy) = brush::coefficients(t, &local.pressure_mpa);
                Row::new(
                    s,
                    fx,
                    fy,
                    vec![
                        (brush::loaded(&local.pressure_mpa) - n_slip) as f64,
                        n_slip as f64,
                    ],
                )
            };
        if !problem.is_transient() {
            for s in &problem.samples {
                let rates = SlipRates::new(s.cx, s.cy, s.cs, &local.flex);
                let n_slip = steady(grid, &local, s.mu, &rates, edge, &mut t);
                h.rows.push(row(s, &t, &local, n_slip));
            }
            return Ok(h);
        }
        if let (InitKind::Steady, Some(s0)) = (problem.init, problem.initial) {
            local = problem.local_contact(s0.fn_n);
            let rates = SlipRates::new(s0.cx, s0.cy, s0.cs, &local.flex);
            let n_slip = steady(grid, &local, s0.mu, &rates, edge, &mut t);
            h.rows.push(row(&s0, &t, &local, n_slip));
        }
        for s in &problem.samples {
            if s.fn_n != local.hertz.fn_n {
                local = problem.local_contact(s.fn_n);
            }
            let rates = SlipRates::new(s.cx, s.cy, s.cs, &local.flex);
            let ab = (local.hertz.a_mm, local.hertz.b_mm);
            let n_slip = step(
                grid,
                &local.pressure_mpa,
                s.mu,
                &rates,
                problem.courant,
                edge,
                ab,
                &mut t,
            );
            h.rows.push(row(s, &t, &local, n_slip));
        }
        Ok(h)
    }
}
