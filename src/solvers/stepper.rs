//! The one small trait every built-in model implements (as argmin's `Solver`: the loop is not
//! the model's). A stepper solves one sample at a time — steady rolling or one time step from its
//! own state — and is told when the load or the friction changes; [`crate::history::sample_loop`] owns
//! the order of the samples.

use super::termination::Termination;
use super::SolveError;
use crate::physics::Grid;
use crate::problem::Sample;

pub use super::contact::tangential::ElementState;

/// What one solve gives.
#[derive(Debug, Clone, PartialEq)]
pub struct Step {
    /// Fx/FN and Fy/FN (thesis Eq. 3.12).
    pub fx_over_fn: f64,
    pub fy_over_fn: f64,
    /// Moment about z of the tractions [N·mm], the references' sign convention
    /// ([`crate::physics::moment`]).
    pub mz_nmm: f64,
    /// Values of the model's extra columns ([`super::ModelDef::extra_columns`]), in order.
    pub extra: Vec<f64>,
    pub termination: Termination,
}

/// The traction field of the last solve, for the metrics of a field (e.g. the sawtooth
/// indicator) and for field comparisons with CONTACT.
#[derive(Debug, Clone, Copy)]
pub struct FieldView<'a> {
    pub grid: &'a Grid,
    /// The pressure that bounds the traction [MPa] (the model's own).
    pub pressure_mpa: &'a [f64],
    pub tx_mpa: &'a [f64],
    pub ty_mpa: &'a [f64],
    /// Adhesion / slip / exterior per element, where the model tells them apart.
    pub state: Option<&'a [ElementState]>,
    /// Both bodies' surface temperatures per element [°C] where the model computes them
    /// (`[material]`'s heat keys, [`crate::physics::temperature`]).
    pub temperature_c: Option<[&'a [f64]; 2]>,
}

/// A creep-force model that solves one sample at a time.
pub trait Stepper {
    /// Set up the contact for this sample's load and friction: called before the first solve and
    /// again whenever FN or μ changes.
    fn load(&mut self, at: &Sample) -> Result<(), SolveError>;
    /// Steady rolling at this sample (sweep points, the steady initial state).
    fn steady(&mut self, at: &Sample) -> Result<Step, SolveError>;
    /// One time step from the model's current state to this sample.
    fn transient(&mut self, at: &Sample) -> Result<Step, SolveError>;
    /// A shift from rest at this sample (`[init] kind = "shift"`): only models with
    /// `ModelDef::shifts` are run on such a scene (`solvers::check_applicable`).
    fn shift(&mut self, at: &Sample) -> Result<Step, SolveError> {
        Err(SolveError::NoShifts { step: at.step })
    }
    /// The traction field of the last solve, if the model has one.
    fn field(&self) -> Option<FieldView<'_>>;
    /// Columns this run writes after the model's `extra_columns` (their values end `Step::extra`):
    /// the exact solver's fixed point with falling friction.
    fn more_columns(&self) -> &'static [&'static str] {
        &[]
    }

    /// The creepages (cx, cy) the last solve found where its sample prescribed forces in their
    /// place (CONTACT F = 1, 2); `None`: the sample's creepages were used.
    fn solved_creepage(&self) -> Option<[f64; 2]> {
        None
    }

    /// The total normal force [N] the last load found where its sample prescribed the approach
    /// in its place (CONTACT N = 0); `None`: the sample's FN was used.
    fn solved_fn_n(&self) -> Option<f64> {
        None
    }
}
