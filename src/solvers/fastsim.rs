//! FASTSIM: Kalker's simplified theory for steady rolling (thesis 2.3.6, Kalker 1990 ch. 3).
//! Each row is integrated element by element from its leading edge, with the traction bound μ p;
//! by default from the grid's edge as CONTACT's FASTSIM does (`[model] leading_edge`). On a
//! transient scene it gives the quasi-steady response at every step's creepage: it has no memory.

use super::brush::{self, Falling, Integration, Tractions};
use super::stepper::{FieldView, Step, Stepper};
use super::{always, grid_model, ModelDef, SolveError};
use crate::problem::{LocalContact, Problem, Sample};
use crate::solvers::style::{muted, Dash, Marker};

/// Kalker's FASTSIM on the scene's grid.
pub const MODEL: ModelDef = grid_model(
    "fastsim",
    "Kalker's simplified theory for steady rolling, FASTSIM (Kalker 1982; thesis 2.3.6), quasi-steady at every step",
    always,
    build,
    muted(2, Dash::Dashed, Marker::TriangleUp),
);

fn build(p: &Problem) -> Result<Box<dyn Stepper + '_>, SolveError> {
    with_contact(p, |p, fn_n| Ok(p.local_contact(fn_n)))
}

/// The contact FASTSIM marches over at a load: the problem's own, or one a normal model finds.
pub type ContactAt = fn(&Problem, f64) -> Result<LocalContact, SolveError>;

/// FASTSIM on the contact `contact` gives at each load.
pub fn with_contact(p: &Problem, contact: ContactAt) -> Result<Box<dyn Stepper + '_>, SolveError> {
    let local = contact(p, p.loading.first().fn_n)?;
    let mu = vec![p.friction.mu_static(); p.grid.len()];
    Ok(Box::new(Fastsim { p, contact, local, t: Tractions::zero(p.grid.len()), mu }))
}

struct Fastsim<'a> {
    p: &'a Problem,
    contact: ContactAt,
    local: LocalContact,
    t: Tractions,
    /// Each element's coefficient of the last solve with a falling law (its bound's start).
    mu: Vec<f64>,
}

impl Stepper for Fastsim<'_> {
    fn load(&mut self, at: &Sample) -> Result<(), SolveError> {
        if at.fn_n != self.local.planform.ellipse.fn_n {
            self.local = (self.contact)(self.p, at.fn_n)?;
        }
        Ok(())
    }

    fn steady(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let rates = brush::slip_rates(at, &self.local);
        let how = (self.p.model.leading_edge, Integration::Exact);
        let n_slip = match Falling::of(self.p, at, &self.local, self.p.grid.dx_mm) {
            None => brush::steady_march(&self.p.grid, &self.local, at.mu, &rates, how, &mut self.t),
            Some(bound) => {
                brush::steady_march_with(&self.p.grid, &self.local, &bound, &rates, how, (&mut self.t, &mut self.mu))
            }
        };
        let (grid, planform) = (&self.p.grid, &self.local.planform);
        Ok(brush::step(planform, self.t.sums(grid), planform.loaded, n_slip))
    }

    /// No memory: the steady response at this step's creepage.
    fn transient(&mut self, at: &Sample) -> Result<Step, SolveError> {
        self.steady(at)
    }

    fn field(&self) -> Option<FieldView<'_>> {
        Some(self.t.view(&self.p.grid, &self.local.planform))
    }
}
