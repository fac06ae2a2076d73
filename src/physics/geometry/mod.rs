//! The geometry seam: what every solver needs of the contact's shape, behind one trait. The
//! exact-theory solver takes the undeformed distance per element; the simplified models take a
//! planform (their pressure on the grid, each row's leading edge, the ellipse that sets their
//! flexibilities). Hertz's ellipse is one geometry ([`hertz::HertzEllipse`]); an element-wise
//! geometry is one more file here plus its scene keys.

pub mod hertz;

use super::{Grid, HertzContact, Material, PressureShape, Radii};
use crate::error::InputError;
use std::fmt::Debug;
use std::sync::Arc;

pub use hertz::HertzEllipse;

/// The geometry as a scene gives it.
#[derive(Debug, Clone, PartialEq)]
pub enum GeometrySpec {
    /// Hertz's ellipse by its semi-axes (`contact.a_mm`, `contact.b_mm`).
    SemiAxes { a_mm: f64, b_mm: f64 },
    /// Hertz's ellipse from the principal radii (`contact.r_wx_mm`, …) and the load.
    Radii(Radii),
}

impl GeometrySpec {
    /// The contact geometry at the nominal load `fn_n` [N]; errors name the scene field.
    pub fn build(&self, fn_n: f64, material: &Material) -> Result<Arc<dyn ContactGeometry>, InputError> {
        let nominal = match self {
            GeometrySpec::SemiAxes { a_mm, b_mm } => HertzContact { a_mm: *a_mm, b_mm: *b_mm, fn_n },
            GeometrySpec::Radii(r) => HertzContact::from_radii(r, fn_n, material).map_err(|e| {
                InputError::new("contact.r_wx_mm", format!("{r:?}"), format!("radii of a convex contact ({e})"))
            })?,
        };
        Ok(Arc::new(HertzEllipse { nominal }))
    }
}

/// The simplified models' contact at one load.
#[derive(Debug, Clone, PartialEq)]
pub struct Planform {
    /// The ellipse at this load: its semi-axes set the flexibilities (thesis Eq. 2.35).
    pub ellipse: HertzContact,
    /// Pressure per element [MPa], flat order; zero outside the contact.
    pub pressure_mpa: Vec<f64>,
    /// Σ pressure over the grid [MPa], the denominator of the traction coefficients (Eq. 3.12).
    pub pressure_sum_mpa: f64,
    /// Number of loaded elements (p > 0).
    pub loaded: usize,
    /// Half-length of the contact chord of each grid row [mm] (0 where the row has no contact):
    /// the row's exact leading edge is at x = −half chord (`[model] leading_edge = "exact"`).
    pub half_chord_mm: Vec<f64>,
}

impl Planform {
    /// A planform from its pressure, summing it once in flat order.
    pub fn new(ellipse: HertzContact, pressure_mpa: Vec<f64>, half_chord_mm: Vec<f64>) -> Self {
        let pressure_sum_mpa = pressure_mpa.iter().sum();
        let loaded = pressure_mpa.iter().filter(|&&p| p > 0.0).count();
        Planform { ellipse, pressure_mpa, pressure_sum_mpa, loaded, half_chord_mm }
    }

    /// Traction coefficients `(Σ τx / Σ p, Σ τy / Σ p)` from the traction sums (thesis Eq. 3.12).
    pub fn coefficients(&self, sum_tx: f64, sum_ty: f64) -> (f64, f64) {
        if self.pressure_sum_mpa <= 0.0 {
            return (0.0, 0.0);
        }
        (sum_tx / self.pressure_sum_mpa, sum_ty / self.pressure_sum_mpa)
    }
}

/// A contact geometry: the undeformed distance and the planform at any load.
pub trait ContactGeometry: Send + Sync + Debug {
    /// Name written to scene.json (`geometry`).
    fn kind(&self) -> &'static str;
    /// The ellipse at the scene's nominal load: it sizes the grid (times `[grid] scale`) and
    /// gives Kalker's coefficients (Table A1 is tabulated by the axis ratio).
    fn nominal(&self) -> HertzContact;
    /// The ellipse at load `fn_n` [N].
    fn ellipse_at(&self, fn_n: f64) -> HertzContact;
    /// Undeformed distance [mm] at every element centre at load `fn_n`, flat order.
    fn undeformed_distance_mm(&self, grid: &Grid, fn_n: f64, material: &Material) -> Vec<f64>;
    /// The simplified models' planform at load `fn_n` with pressure shape `shape`.
    fn planform(&self, grid: &Grid, fn_n: f64, shape: PressureShape) -> Planform;
}
