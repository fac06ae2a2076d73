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
use crate::physics::Grid;
use crate::problem::{LocalContact, Problem, Sample};
use crate::scene::InitKind;

/// The Unsteady Brush Algorithm.
pub struct Uba;

/// Extra columns of `uba.csv`.
pub const EXTRA: [&str; 3] = ["n_adhesion", "n_slip", "sawtooth"];

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
    /// Inflow (ghost) traction per element, non-zero only at run starts with the exact edge.
    ghost_x: Vec<f64>,
    ghost_y: Vec<f64>,
}

impl Prepared {
    pub fn new(grid: &Grid, pressure: &[f64], mu: f64) -> Self {
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
        Prepared { runs, bound, upstream, x_mm, y_mm, ghost_x: vec![0.0; n], ghost_y: vec![0.0; n] }
    }

    /// Number of loaded elements.
    pub fn loaded(&self) -> usize {
        self.runs.iter().map(|r| r.2 - r.1).sum()
    }
}

/// One explicit upwind step (corrected Eq. 3.9–3.10) with the traction bound, from `old` into
/// `new` (double-buffered: every update reads only old values, so the loop is one flat,
/// branch-free pass over the grid that the compiler vectorises). `edge` sets the inflow value
/// upstream of each row's first loaded element; `ab` is the ellipse of the pressure.
/// Returns the number of elements on the bound. `courant` must be in (0, 1].
#[allow(clippy::too_many_arguments)]
pub fn step(
    grid: &Grid,
    prep: &mut Prepared,
    rates: &SlipRates,
    courant: f64,
    edge: LeadingEdge,
    ab: (f64, f64),
    old: &Tractions,
    new: &mut Tractions,
) -> usize {
    if edge == LeadingEdge::Exact {
        for &(j, first, _) in &prep.runs {
            let (gx, gy) = brush::ghost(grid, edge, rates, first, j, ab.0, ab.1);
            prep.ghost_x[grid.index(first, j)] = gx;
            prep.ghost_y[grid.index(first, j)] = gy;
        }
    }
    // Source per step, C·dx·k(x, y) (Eq. 3.4): kx = cx/L1 − cs y/L3, ky = cy/L2 + cs x/L3.
    let (c, cdx) = (courant, courant * grid.dx_mm);
    let consts = [c, cdx * rates.cx_l1, -cdx * rates.cs_l3, cdx * rates.cy_l2, cdx * rates.cs_l3];
    flat_step(prep, &old.tx, &old.ty, &mut new.tx, &mut new.ty, consts)
}

/// The flat pass: `consts` = [C, C·dx·cx/L1, −C·dx·cs/L3, C·dx·cy/L2, C·dx·cs/L3].
/// Compiled twice, plain and (when the CPU has it) with AVX2: the same IEEE operations and no
/// fused multiply-add, so both give bit-identical results.
#[inline(always)]
fn flat_body(p: &Prepared, ox: &[f64], oy: &[f64], nx: &mut [f64], ny: &mut [f64], k: [f64; 5]) -> usize {
    let n = ox.len();
    let (oy, nx, ny) = (&oy[..n], &mut nx[..n], &mut ny[..n]);
    let (g, up, xs, ys) = (&p.bound[..n], &p.upstream[..n], &p.x_mm[..n], &p.y_mm[..n]);
    let (gx, gy) = (&p.ghost_x[..n], &p.ghost_y[..n]);
    let [c, sx0, sx1, sy0, sy1] = k;
    let mut slips = 0usize;
    for m in 0..n {
        let (px, py) = if m > 0 { (ox[m - 1], oy[m - 1]) } else { (0.0, 0.0) };
        let ux = up[m] * px + gx[m];
        let uy = up[m] * py + gy[m];
        let vx = ox[m] + c * (ux - ox[m]) + (sx0 + sx1 * ys[m]);
        let vy = oy[m] + c * (uy - oy[m]) + (sy0 + sy1 * xs[m]);
        let n2 = vx * vx + vy * vy;
        // Direction-keeping projection (Eq. 2.29): scale = min(1, g/|v|); unloaded (g = 0) → 0.
        let scale = (g[m] / n2.sqrt()).min(1.0);
        nx[m] = vx * scale;
        ny[m] = vy * scale;
        slips += ((n2 > g[m] * g[m]) & (g[m] > 0.0)) as usize;
    }
    slips
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn flat_avx2(p: &Prepared, ox: &[f64], oy: &[f64], nx: &mut [f64], ny: &mut [f64], k: [f64; 5]) -> usize {
    flat_body(p, ox, oy, nx, ny, k)
}

fn flat_step(p: &Prepared, ox: &[f64], oy: &[f64], nx: &mut [f64], ny: &mut [f64], k: [f64; 5]) -> usize {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2 (checked just above).
            return unsafe { flat_avx2(p, ox, oy, nx, ny, k) };
        }
    }
    flat_body(p, ox, oy, nx, ny, k)
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
    brush::steady_march(grid, &local.pressure_mpa, mu, rates, edge, Integration::Centre, ab, t)
}

impl Solver for Uba {
    fn name(&self) -> &str {
        "uba"
    }

    fn run(&self, problem: &Problem) -> Result<History, Error> {
        if !(problem.courant > 0.0 && problem.courant <= 1.0) {
            return Err(super::fail(problem, "uba", format!("courant {} outside (0, 1]", problem.courant)));
        }
        let grid = &problem.grid;
        let edge = problem.model.leading_edge;
        let mut h = History::new(self.name(), &EXTRA);
        let mut t = Tractions::zero(grid.len());
        let mut scratch = Tractions::zero(grid.len());
        let row = |s: &Sample, t: &Tractions, local: &LocalContact, n_loaded: usize, n_slip: usize| {
            let (fx, fy) = brush::coefficients(t, &local.pressure_mpa);
            let saw = brush::sawtooth_index(&problem.grid, &local.pressure_mpa, t);
            Row::new(s, fx, fy, vec![(n_loaded - n_slip) as f64, n_slip as f64, saw])
        };
        let mut local = problem.local_contact(problem.hertz.fn_n);
        if !problem.is_transient() {
            let n_loaded = brush::loaded(&local.pressure_mpa);
            for s in &problem.samples {
                let rates = SlipRates::new(s.cx, s.cy, s.cs, &local.flex);
                let n_slip = steady(grid, &local, s.mu, &rates, edge, &mut t);
                h.rows.push(row(s, &t, &local, n_loaded, n_slip));
            }
            return Ok(h);
        }
        let first = problem.initial.unwrap_or(problem.samples[0]);
        local = problem.local_contact(first.fn_n);
        let mut prep = Prepared::new(grid, &local.pressure_mpa, first.mu);
        let mut prep_mu = first.mu;
        if let (InitKind::Steady, Some(s0)) = (problem.init, problem.initial) {
            let rates = SlipRates::new(s0.cx, s0.cy, s0.cs, &local.flex);
            let n_slip = steady(grid, &local, s0.mu, &rates, edge, &mut t);
            h.rows.push(row(&s0, &t, &local, prep.loaded(), n_slip));
        }
        for s in &problem.samples {
            if s.fn_n != local.hertz.fn_n || s.mu != prep_mu {
                if s.fn_n != local.hertz.fn_n {
                    local = problem.local_contact(s.fn_n);
                    // Elements that left the contact carry nothing.
                    for (k, p) in local.pressure_mpa.iter().enumerate() {
                        if *p <= 0.0 {
                            t.tx[k] = 0.0;
                            t.ty[k] = 0.0;
                            scratch.tx[k] = 0.0;
                            scratch.ty[k] = 0.0;
                        }
                    }
                }
                prep = Prepared::new(grid, &local.pressure_mpa, s.mu);
                prep_mu = s.mu;
            }
            let rates = SlipRates::new(s.cx, s.cy, s.cs, &local.flex);
            let ab = (local.hertz.a_mm, local.hertz.b_mm);
            let n_slip = step(grid, &mut prep, &rates, problem.courant, edge, ab, &t, &mut scratch);
            std::mem::swap(&mut t, &mut scratch);
            h.rows.push(row(s, &t, &local, prep.loaded(), n_slip));
        }
        Ok(h)
    }
}
