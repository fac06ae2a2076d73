//! The Shen–Hedrick–Elkins creep-force law (Shen, Hedrick & Elkins, "A comparison of alternative
//! creep force models for rail vehicle dynamic analysis", Proc. 8th IAVSD Symposium, 1983): Kalker's
//! linear forces (fx, fy incl. spin) saturated along their resultant, with ε = |f_lin|/μ,
//! `|f|/μ = ε − ε²/3 + ε³/27` for ε < 3 and 1 beyond (the curve meets μ with zero slope at ε = 3).
//! Steady, no memory, as the linear theory ([`super::linear::Saturated`]).

use super::linear::Saturated;
use super::stepper::Stepper;
use super::{closed_form, ModelDef, SolveError};
use crate::problem::Problem;
use crate::solvers::style::{muted, Dash, Marker};

/// Shen–Hedrick–Elkins.
pub const MODEL: ModelDef = closed_form(
    "she",
    "Shen–Hedrick–Elkins (1983): Kalker's linear forces saturated by ε − ε²/3 + ε³/27 (ε = |f_lin|/μ < 3)",
    build,
    muted(4, Dash::DashDot, Marker::TriangleDown),
);

/// |f|/μ of the law for the linear |f|/μ = ε ≥ 0.
pub fn law(eps: f64) -> f64 {
    if eps < 3.0 {
        eps * (1.0 - eps / 3.0 + eps * eps / 27.0)
    } else {
        1.0
    }
}

fn build(p: &Problem) -> Result<Box<dyn Stepper + '_>, SolveError> {
    Ok(Box::new(Saturated::new(p, |fx, fy, mu| {
        let eps = fx.hypot(fy) / mu;
        let factor = if eps > 0.0 { law(eps) / eps } else { 1.0 };
        (fx * factor, fy * factor)
    })))
}

#[cfg(test)]
mod tests {
    use super::law;

    /// The published curve: tangent to the linear theory at 0, 0.7037 (= 19/27) at ε = 1, μ with
    /// zero slope at ε = 3, monotone between.
    #[test]
    fn she_curve() {
        assert!((law(1e-6) / 1e-6 - 1.0).abs() < 1e-6);
        assert!((law(1.0) - 19.0 / 27.0).abs() < 1e-15);
        assert!((law(3.0) - 1.0).abs() < 1e-15 && (law(3.0 - 1e-9) - 1.0).abs() < 1e-12);
        assert_eq!(law(10.0), 1.0);
        let mut last = 0.0;
        for k in 1..=300 {
            let v = law(k as f64 * 0.01);
            assert!(v > last && v <= 1.0);
            last = v;
        }
    }
}
