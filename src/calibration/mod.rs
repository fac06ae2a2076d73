//! Calibration: fitting a model's free parameters to a target's histories (`creepbench fit`) and
//! the report section of the stored fits. Sits above the report, whose section type it fills.

pub mod fit;
pub mod section;
