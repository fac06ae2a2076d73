//! The compact non-steady CONTACT-style solver: Kalker's exact theory for quasi-identical
//! elastic half-spaces on the scene's grid (Kalker 1990, ch. 5; Vollebregt & Kalker, CONTACT),
//! one module per sub-problem as in CONTACT:
//!
//! - [`influence`], [`convolution`], [`normal`]: the elastic half-space, shared physics
//!   ([`crate::physics::halfspace`]): influence kernels (unshifted and shifted by the rolling
//!   distance per step), u = A p, the normal problem for the prescribed FN (as NormCG);
//! - [`tangential`]: steady and transient rolling with Coulomb friction per time step:
//!   transient steps by a projected CG with FFT products (as CONTACT's TangCG, falling back to
//!   projected Gauss–Seidel as ConvexGS); steady rolling by an Anderson-accelerated projected
//!   iteration (Walker & Ni 2011) that undoes the one-element shift along adhesion rows, stopped
//!   by the same local-change test, Gauss–Seidel sweeps taking over if it stalls. Each transient
//!   step starts from the last two steps' tractions extrapolated in time.
//!
//! [`veldep`]: friction falling with the slip velocity, CONTACT's fixed point on the slip
//! velocity around the tangential solve, with the friction memory; [`tempdep`]: friction of the
//! surface temperature, the same fixed point on the temperature. [`hardening`]: an interface
//! layer that hardens or softens, the fixed point per step on each element's yield limit;
//! [`steady_hardening`]: the same in steady rolling, each limit carried from the element upstream.
//!
//! [`stepper`] maps a resolved problem onto them, one sample at a time; [`restart`] is CONTACT's
//! first transient step after a steady start where μ or FN changed. The undeformed distance
//! comes from the shared geometry seam, the grid from the shared physics.
//! Axes: leading edge at x = −a, material moving in +x (CONTACT rolls the other way: mirror x
//! when comparing fields).

pub mod anderson;
pub mod coupled;
pub mod direction;
pub mod force;
pub mod hardening;
pub mod heat;
pub mod mirror;
pub mod restart;
pub mod steady_hardening;
pub mod stepper;
pub mod tangential;
pub mod tempdep;
pub mod veldep;

pub use crate::physics::halfspace::{convolution, coupling, influence, normal, ContactError};

pub use stepper::{ContactRunError, MODEL, NAME};
