//! The compact non-steady CONTACT-style solver: Kalker's exact theory for quasi-identical
//! elastic half-spaces on the scene's grid (Kalker 1990, ch. 5; Vollebregt & Kalker, CONTACT),
//! one module per sub-problem as in CONTACT:
//!
//! - [`influence`]: influence coefficients of uniformly loaded rectangles (Boussinesq, Cerruti),
//!   kept as translation-invariant kernels, once unshifted and once shifted by the rolling
//!   distance per step;
//! - [`convolution`]: u = A p by direct sums (small grids) or zero-padded 2-D FFT;
//! - [`normal`]: the normal problem for the prescribed FN (bound-constrained CG, as NormCG);
//! - [`tangential`]: steady and transient rolling with Coulomb friction per time step:
//!   transient steps by a projected CG with FFT products (as CONTACT's TangCG, falling back to
//!   projected Gauss–Seidel as ConvexGS); steady rolling by an Anderson-accelerated projected
//!   iteration (Walker & Ni 2011) that undoes the one-element shift along adhesion rows, stopped
//!   by the same local-change test, Gauss–Seidel sweeps taking over if it stalls. Each transient
//!   step starts from the last two steps' tractions extrapolated in time.
//!
//! [`stepper`] maps a resolved problem onto them, one sample at a time. The undeformed distance
//! comes from the shared geometry seam, the grid from the shared physics.
//! Axes: leading edge at x = −a, material moving in +x (CONTACT rolls the other way: mirror x
//! when comparing fields).

pub mod convolution;
pub mod influence;
pub mod normal;
pub mod stepper;
pub mod tangential;

use std::fmt;

pub use stepper::{run_with_fields, ContactRunError, Field, MODEL};

/// Errors of the contact core; no function of these modules panics on bad numbers.
#[derive(Debug, Clone, PartialEq)]
pub enum ContactError {
    /// An input value is out of range or not finite (which, and why).
    InvalidInput(String),
    /// Array lengths do not match the grid (what was expected).
    SizeMismatch(String),
    /// No grid element can carry load (e.g. the grid is too coarse to hold any contact).
    NoContact(String),
    /// A computation produced a non-finite number (where).
    NonFinite(String),
}

impl fmt::Display for ContactError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ContactError::InvalidInput(s) => write!(f, "invalid input: {s}"),
            ContactError::SizeMismatch(s) => write!(f, "size mismatch: {s}"),
            ContactError::NoContact(s) => write!(f, "no contact: {s}"),
            ContactError::NonFinite(s) => write!(f, "non-finite result: {s}"),
        }
    }
}

impl std::error::Error for ContactError {}

