//! Kalker's linear theory of rolling contact (Kalker 1967; Kalker 1990, sec. 1.5 and Table A1
//! via the thesis's App. A): `Fx = G a b C11 cx`, `Fy = G a b C22 cy + G (ab)^(3/2) C23 cs`,
//! `Mz = −G (ab)^(3/2) C23 cy + G (ab)^2 C33 cs` (the references' sign convention), forces
//! divided by FN, the (fx, fy) vector then saturated at μ (direction kept, Mz scaled alike). Steady, no memory: on
//! a time history it gives the steady value at every step. Signs: positive creepage and positive
//! spin give positive coefficients (CONTACT's convention, C23 > 0).
//!
//! [`Saturated`] is the stepper of every law that saturates these linear forces (this one and
//! the Shen–Hedrick–Elkins law, [`super::she`]): they differ only in the saturation curve.

use super::stepper::{FieldView, Step, Stepper};
use super::termination::Termination;
use super::{closed_form, ModelDef, SolveError};
use crate::physics::{project_to_bound, LinearTheory};
use crate::problem::{Problem, Sample};
use crate::solvers::style::{muted, Dash, Marker};

/// Kalker's linear theory, saturated at μ.
pub const MODEL: ModelDef = closed_form(
    "linear",
    "Kalker's linear theory (Kalker 1967; C11, C22, C23, C33 of Table A1), f saturated at μ",
    build,
    muted(3, Dash::Dashed, Marker::Diamond),
);

fn build(p: &Problem) -> Result<Box<dyn Stepper + '_>, SolveError> {
    Ok(Box::new(Saturated::new(p, |fx, fy, mu| {
        let (x, y, _) = project_to_bound(fx, fy, mu);
        (x, y)
    })))
}

/// A saturation law: the linear (fx/FN, fy/FN) and μ in, the saturated pair out (direction kept).
pub type Law = fn(f64, f64, f64) -> (f64, f64);

/// Kalker's linear forces saturated by a law, Mz scaled as |f| is.
pub struct Saturated<'a> {
    p: &'a Problem,
    law: Law,
    /// Kalker's linear theory at the current load, per FN.
    linear: LinearTheory,
}

impl<'a> Saturated<'a> {
    pub fn new(p: &'a Problem, law: Law) -> Self {
        Saturated { p, law, linear: LinearTheory::default() }
    }
}

impl Stepper for Saturated<'_> {
    fn load(&mut self, at: &Sample) -> Result<(), SolveError> {
        let e = self.p.geometry.ellipse_at(at.fn_n);
        self.linear = LinearTheory::new(self.p.material.g_mpa, e.a_mm, e.b_mm, at.fn_n);
        Ok(())
    }

    fn steady(&mut self, at: &Sample) -> Result<Step, SolveError> {
        let (fx, fy, mz_over_fn) = self.linear.forces(&self.p.coefficients, (at.cx, at.cy, at.cs));
        let (sx, sy) = (self.law)(fx, fy, at.mu);
        let saturation = if fx != 0.0 || fy != 0.0 { sx.hypot(sy) / fx.hypot(fy) } else { 1.0 };
        Ok(Step {
            fx_over_fn: sx,
            fy_over_fn: sy,
            mz_nmm: mz_over_fn * saturation * at.fn_n,
            extra: Vec::new(),
            termination: Termination::Direct,
        })
    }

    fn transient(&mut self, at: &Sample) -> Result<Step, SolveError> {
        self.steady(at)
    }

    fn field(&self) -> Option<FieldView<'_>> {
        None
    }
}
