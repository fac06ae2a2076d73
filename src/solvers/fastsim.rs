//! FASTSIM: Kalker's simplified theory for steady rolling (thesis 2.3.6, Kalker 1990 ch. 3).
//! Each row is integrated element by element from its leading edge, with the traction bound μ p;
//! by default from the grid's edge as CONTACT's FASTSIM does (`[model] leading_edge`). On a transient scene it gives the
//! quasi-steady response at every step's creepage: it has no memory.

use super::brush::{self, Integration, SlipRates, Tractions};
use super::Solver;
use crate::error::Error;
use crate::history::{History, Row};
use crate::problem::{Problem, Sample};

/// Kalker's FASTSIM on the scene's grid.
pub struct Fastsim;

/// Extra columns of `fastsim.csv`.
pub const EXTRA: [&str; 2] = ["n_adhesion", "n_slip"];

impl Fastsim {
    /// Steady tractions for one sample; returns (fx/FN, fy/FN, n_adhesion, n_slip).
    pub fn solve(
        problem: &Problem,
        sample: &Sample,
        local: &crate::problem::LocalContact,
        t: &mut Tractions,
    ) -> (f64, f64, usize, usize) {
        let rates = SlipRates::new(sample.cx, sample.cy, sample.cs, &local.flex);
        let ab = (local.hertz.a_mm, local.hertz.b_mm);
        let n_slip = brush::steady_march(
            &problem.grid,
            &local.pressure_mpa,
            sample.mu,
            &rates,
            problem.model.leading_edge,
            Integration::Exact,
            ab,
            t,
        );
        let (fx, fy) = brush::coefficients(t, &local.pressure_mpa);
        (fx, fy, brush::loaded(&local.pressure_mpa) - n_slip, n_slip)
    }
}

impl Solver for Fastsim {
    fn name(&self) -> &str {
        "fastsim"
    }

    fn run(&self, problem: &Problem) -> Result<History, Error> {
        let mut h = History::new(self.name(), &EXTRA);
        let mut t = Tractions::zero(problem.grid.len());
        let mut local = problem.local_contact(problem.hertz.fn_n);
        let initial = problem.initial.filter(|_| problem.init == crate::scene::InitKind::Steady);
        for s in initial.iter().chain(problem.samples.iter()) {
            if s.fn_n != local.hertz.fn_n {
                local = problem.local_contact(s.fn_n);
            }
            let (fx, fy, na, ns) = Self::solve(problem, s, &local, &mut t);
            h.rows.push(Row::new(s, fx, fy, vec![na as f64, ns as f64]));
        }
        Ok(h)
    }
}
