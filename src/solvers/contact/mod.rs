//! The compact non-steady CONTACT-style solver (Kalker's exact theory on the same grid).
//! Integration in progress: see issue 3.

use super::Solver;
use crate::error::Error;
use crate::history::History;
use crate::problem::Problem;

/// Kalker's exact theory for quasi-identical half-spaces (CONTACT-style).
pub struct ContactSolver;

impl Solver for ContactSolver {
    fn name(&self) -> &str {
        "contact"
    }

    fn run(&self, problem: &Problem) -> Result<History, Error> {
        Err(super::fail(problem, "contact", "the CONTACT-style solver is not available in this build yet"))
    }
}
