//! The elastic half-space on the element grid, shared by every solver: influence coefficients of
//! uniformly loaded rectangles ([`influence`], kept per element size and material by offset in
//! `table.rs`) or bilinear tractions ([`bilinear`]), an interface layer in series ([`layer`]), u = A p by direct sums (`direct.rs`) or FFT ([`convolution`]),
//! viscoelastic bodies' memory in steady rolling ([`visco`]),
//! and the normal contact problem for a prescribed FN or approach on any undeformed distance ([`normal`]),
//! whose pressure the exact solver uses and the simplified models take on non-Hertzian contacts.

pub mod bilinear;
pub mod blanco;
pub mod blend;
pub mod convolution;
pub mod coupling;
mod direct;
pub mod influence;
pub mod invariants;
pub mod jet;
pub mod layer;
pub mod normal;
mod normal_dense;
mod real_fft;
pub mod sheet;
pub mod stress;
mod table;
pub mod visco;

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
    /// An iteration ended without meeting its stopping test.
    #[error("not converged: {what} after {passes} passes")]
    NotConverged { what: &'static str, passes: usize },
    /// A convolver on the FFT path has no FFT data (an internal inconsistency).
    #[error("internal: FFT data missing for the FFT path")]
    MissingFft,
}
