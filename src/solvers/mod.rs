//! Step 3 of the pipeline: the solvers, interchangeable behind one small trait. The harness only
//! sees [`Solver::run`]: a resolved [`Problem`] in, a [`History`] out.

pub mod brush;
pub mod contact;
pub mod external;
pub mod fastsim;
pub mod termination;
pub mod uba;

use crate::error::Error;
use crate::history::History;
use crate::problem::Problem;

/// A creep-force model run over a whole scene.
pub trait Solver: Send + Sync {
    /// The name used in scenes (`solvers = [...]`) and for `<name>.csv`.
    fn name(&self) -> &str;
    /// March (or sweep) the problem's creepage history.
    fn run(&self, problem: &Problem) -> Result<History, Error>;
}

/// The solver of that name for this problem: a built-in one or one of the scene's external models.
pub fn by_name(name: &str, problem: &Problem) -> Option<Box<dyn Solver>> {
    match name {
        "uba" => Some(Box::new(uba::Uba)),
        "fastsim" => Some(Box::new(fastsim::Fastsim)),
        "contact" => Some(Box::new(contact::ContactSolver)),
        other => problem
            .external
            .iter()
            .find(|e| e.name == other)
            .map(|e| Box::new(external::External::new(e.clone())) as Box<dyn Solver>),
    }
}

/// A solver failure for `problem`.
pub(crate) fn fail(problem: &Problem, solver: &str, message: impl Into<String>) -> Error {
    Error::Solve { scene: problem.name.clone(), solver: solver.into(), message: message.into() }
}
