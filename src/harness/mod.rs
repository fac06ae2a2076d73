//! Steps 6–7 of the pipeline: running a suite of scenes, comparing their results with
//! reference data (CONTACT, thesis) and golden data (this project's blessed results), and the
//! Markdown report. Only solver outputs (histories, metrics) are used here, never solver internals.

pub mod against;
pub mod calibration;
pub mod compare;
pub mod envelope;
pub mod fit;
pub mod gate_output;
pub mod ladder;
pub mod linked_table;
pub mod model_error;
pub mod plot;
pub mod references;
pub mod report;
pub mod results;
pub mod sections;
pub mod studies;
pub mod suite;
pub mod table;
pub mod tolerance_file;
pub mod tolerances;
pub mod work_precision;
