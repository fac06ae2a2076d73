//! How a step (or a steady point) ended, as argmin's `TerminationReason`: every stepper returns
//! one, and the sample loop writes it to the history of the models that iterate.

/// How one solve ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Termination {
    /// Closed form or one pass: nothing to iterate (brush models, linear theory).
    Direct,
    /// The method met its stopping test.
    Converged,
    /// The first method stalled; its fallback (Gauss–Seidel) met the stopping test.
    FallbackConverged,
    /// The iteration limit was reached without meeting the test.
    IterationLimit,
    /// Prescribed forces (CONTACT F = 1, 2): the outer iteration on the creepages stopped without
    /// reaching the force within its tolerance (`contact::force::FORCE_TOL`).
    ForceNotReached,
}

impl Termination {
    /// Code written to the history's `termination` column: 0 converged (or direct), 1 converged
    /// after the fallback, 2 iteration limit, 3 prescribed force not reached.
    pub fn code(self) -> f64 {
        match self {
            Termination::Direct | Termination::Converged => 0.0,
            Termination::FallbackConverged => 1.0,
            Termination::IterationLimit => 2.0,
            Termination::ForceNotReached => 3.0,
        }
    }

    /// Whether the result meets the stopping test.
    pub fn converged(self) -> bool {
        !matches!(self, Termination::IterationLimit | Termination::ForceNotReached)
    }
}
