//! creepbench: a harness that validates and benchmarks wheel–rail rolling-contact models.
//!
//! The data flow is one straight path, one module per stage, each importing only from the stages
//! below it (the order: README, "The code"; checked by tests/layering.rs):
//! [`scene`] (file, validated) → [`problem`] (resolved: Hertz, Kalker, grid, samples) →
//! [`solvers`] (UBA, FASTSIM, CONTACT-style) → [`history`] (the sample loop, external models) → [`metrics`] →
//! [`harness`] (reference and golden comparison, report). [`physics`] is shared by all solvers;
//! [`export`] writes a resolved scene as another program's input (CONTACT).

pub mod commands;
pub mod error;
pub mod export;
pub mod harness;
pub mod history;
pub mod metrics;
pub mod physics;
pub mod pipeline;
pub mod problem;
pub mod safety;
pub mod scene;
pub mod simd;
pub mod solvers;

pub use error::{Error, InputError};
