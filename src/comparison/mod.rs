//! The comparison of stored results with reference data (CONTACT, thesis) and baseline data
//! (golden/, a previous run): each comparison's worst point as a finding, judged by the tolerance
//! rules, and the gate's verdict files. Reads stored results only, never solver internals.

pub mod against;
pub mod compare;
pub mod console;
pub mod delay;
pub mod finding;
pub mod gate_output;
pub mod model_error;
pub mod owed;
pub mod references;
pub mod rule;
pub mod strict;
pub mod tolerance_file;
pub mod tolerances;
