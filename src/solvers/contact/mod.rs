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

pub mod anderson;
pub mod convolution;
pub mod influence;
pub mod normal;
pub mod stepper;
pub mod tangential;

pub use stepper::{run_with_fields, ContactRunError, Field, MODEL};

/// Errors of the contact core; no function of these modules panics on bad numbers.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ContactError {
    /// An input value is out of range or not finite.
    #[error("invalid input: {name} = {value} (must be {requirement})")]
    OutOfRange { name: &'static str, value: f64, requirement: &'static str },
    /// An input array holds a non-finite value.
    #[error("invalid input: {name} is not finite at element {index}")]
    NotFinite { name: &'static str, index: usize },
    /// A grid needs at least one element along each axis.
    #[error("invalid input: a grid of {mx} x {my} elements (needs mx, my >= 1)")]
    EmptyGrid { mx: usize, my: usize },
    /// An array's length does not match the grid.
    #[error("size mismatch: {name} has {len} entries, expected {expected}")]
    SizeMismatch { name: &'static str, len: usize, expected: usize },
    /// Two kernels belong to different grids (elements along x and y).
    #[error("size mismatch: kernels of a {}x{} and a {}x{} grid (or of different element sizes)", expected.0, expected.1, got.0, got.1)]
    GridMismatch { expected: (usize, usize), got: (usize, usize) },
    /// The rolling step of a solve differs from the shift of the solver's shifted kernel.
    #[error("invalid input: dq = {dq_mm} mm differs from the shifted kernel's shift {shift_mm} mm")]
    ShiftMismatch { dq_mm: f64, shift_mm: f64 },
    /// No grid element can carry load (e.g. the grid is too coarse to hold any contact).
    #[error("no contact: no grid element carries load")]
    NoContact,
    /// A computation produced a non-finite number (where).
    #[error("non-finite result: {0}")]
    NonFinite(&'static str),
    /// A convolver on the FFT path has no FFT data (an internal inconsistency).
    #[error("internal: FFT data missing for the FFT path")]
    MissingFft,
}
