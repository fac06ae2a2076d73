//! Contact physics written once and shared by every solver: material constants, Hertz,
//! Kalker's coefficients and flexibilities, the grid, the pressure, the rigid slip, the traction
//! bound and the friction law, the spin moment, four-lane sums and the elastic half-space (influence coefficients, the normal problem).
//!
//! Units throughout: mm, N, MPa (N/mm²), s; creepages dimensionless, spin in 1/mm.

pub mod approximate;
pub mod bound;
pub mod friction;
pub mod geometry;
pub mod grid;
pub mod halfspace;
pub mod hertz;
pub mod kalker;
pub mod lanes;
pub mod law_kernel;
pub mod material;
pub mod moment;
pub mod pressure;
pub mod slip;
pub mod temperature;

pub use bound::project_to_bound;
pub use friction::{FallingTerms, FrictionLaw, Memory, RowFriction, TemperatureLaw};
pub use geometry::{ContactGeometry, HertzEllipse, Planform};
pub use grid::{Grid, LeadingEdge};
pub use hertz::{HertzContact, HertzShape, Radii};
pub use kalker::{
    CoefficientSource, Coefficients, Flexibilities, FlexibilityModel, LinearTheory, PatchFlexibility, SlopeReduction,
};
pub use material::Material;
pub use moment::moment_sum;
pub use pressure::{NormalPressure, PressureShape};
pub use slip::RigidSlip;
