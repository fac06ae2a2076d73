//! Hertz's ellipse as a contact geometry (thesis ch. 2.2): `h = A x² + B y²` with the curvatures
//! that give the ellipse under its load, and an ellipse that scales with FN^(1/3).

use super::{ContactGeometry, Planform};
use crate::physics::{Grid, HertzContact, Material, PressureShape};

/// The Hertzian contact of the scene, given by its ellipse at the nominal load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzEllipse {
    pub nominal: HertzContact,
}

impl ContactGeometry for HertzEllipse {
    fn kind(&self) -> &'static str {
        "hertz"
    }

    fn nominal(&self) -> HertzContact {
        self.nominal
    }

    /// The one place the ellipse follows the load (Hertz: both semi-axes ∝ FN^(1/3)).
    fn ellipse_at(&self, fn_n: f64) -> HertzContact {
        if fn_n == self.nominal.fn_n {
            self.nominal
        } else {
            self.nominal.at_load(fn_n)
        }
    }

    fn undeformed_distance_mm(&self, grid: &Grid, fn_n: f64, material: &Material) -> Vec<f64> {
        let (ca, cb) = self.ellipse_at(fn_n).undeformed_curvatures(material);
        let (x, y) = grid.centres();
        x.iter().zip(&y).map(|(x, y)| ca * x * x + cb * y * y).collect()
    }

    fn planform(&self, grid: &Grid, fn_n: f64, shape: PressureShape) -> Planform {
        let e = self.ellipse_at(fn_n);
        let pressure = shape.on_grid(grid, fn_n, e.a_mm, e.b_mm);
        let half_chord: Vec<f64> = (0..grid.my).map(|j| grid.chord_half_length_mm(j, e.a_mm, e.b_mm)).collect();
        let leading_edge = half_chord.iter().map(|h| -h).collect();
        Planform::new(e, pressure, leading_edge, half_chord)
    }
}
