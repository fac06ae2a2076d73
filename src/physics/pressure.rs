//! Normal pressure on the grid for the simplified models (UBA and FASTSIM).

use super::grid::Grid;
use std::f64::consts::PI;

/// Shape of the pressure that bounds the tangential traction, `μ p`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum PressureShape {
    /// Kalker's parabolic pressure `p = 2FN/(πab) (1 − x²/a² − y²/b²)` (thesis Eq. 2.32–2.33).
    Parabolic,
    /// Hertz's ellipsoidal pressure `p = 3FN/(2πab) √(1 − x²/a² − y²/b²)` (thesis Eq. 2.9, 2.17).
    Ellipsoidal,
}

impl PressureShape {
    /// Peak pressure [MPa] of this shape for load `fn_n` [N] on an ellipse a × b [mm].
    pub fn peak_mpa(self, fn_n: f64, a_mm: f64, b_mm: f64) -> f64 {
        match self {
            PressureShape::Parabolic => 2.0 * fn_n / (PI * a_mm * b_mm),
            PressureShape::Ellipsoidal => 1.5 * fn_n / (PI * a_mm * b_mm),
        }
    }

    /// Pressure [MPa] at every element centre (zero outside the ellipse a × b), flat order.
    pub fn on_grid(self, grid: &Grid, fn_n: f64, a_mm: f64, b_mm: f64) -> Vec<f64> {
        let p0 = self.peak_mpa(fn_n, a_mm, b_mm);
        let mut p = vec![0.0; grid.len()];
        for j in 0..grid.my {
            for i in 0..grid.mx {
                let level = grid.ellipse_level(i, j, a_mm, b_mm);
                if level > 0.0 {
                    p[grid.index(i, j)] = match self {
                        PressureShape::Parabolic => p0 * level,
                        PressureShape::Ellipsoidal => p0 * level.sqrt(),
                    };
                }
            }
        }
        p
    }
}
