//! creepbench: a harness that validates and benchmarks wheel–rail rolling-contact models.
//!
//! The data flow is one straight path, one module per stage, each importing only from the stages
//! below it (the order: README, "The code"; checked by tests/all/layering.rs):
//! [`scene`] (file, validated) → [`wheelrail`] (profiles; CONTACT's module 1) → [`problem`] (resolved: Hertz, Kalker, grid, samples) →
//! [`solvers`] (UBA, FASTSIM, CONTACT-style, external) → [`history`] (the sample loop, external models) → [`metrics`] →
//! [`pipeline`] (wires one scene through them) → [`suite`] (many scenes, result folders) →
//! [`comparison`] (reference and golden data, tolerances, findings) → [`report`] →
//! [`calibration`] (fits). [`physics`] is shared by all solvers; [`export`] writes a resolved
//! scene as another program's input (CONTACT); [`import`] reads another program's files (CONTACT's
//! printed output).

pub mod calibration;
pub mod commands;
pub mod comparison;
pub mod error;
pub mod export;
pub mod history;
pub mod import;
pub mod metrics;
pub mod physics;
pub mod pipeline;
pub mod problem;
pub mod report;
pub mod safety;
pub mod scene;
pub mod simd;
pub mod solvers;
pub mod suite;
pub mod wheelrail;

pub use error::{Error, InputError};
