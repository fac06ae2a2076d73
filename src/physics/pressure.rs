//! Normal pressure on the grid: the simplified models' (UBA and FASTSIM) and the exact solver's
//! imposed Hertzian pressure (CONTACT's B = 2, 3).

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

/// The exact solver's normal problem (`[normal] pressure`, CONTACT's B digit): solved on the
/// half-space (B = 0), or Hertz's ellipse of the load imposed as the pressure (B = 2, 3: "traction
/// bound derived from Hertzian problem data", CONTACT user guide §"B - BOUND").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum NormalPressure {
    /// The normal contact problem solved on the grid (B = 0).
    #[default]
    Solved,
    /// `3FN/(2πab) √(1 − x²/a² − y²/b²)` at the element centres (B = 2).
    Elliptical,
    /// `2FN/(πab) (1 − x²/a² − y²/b²)` at the element centres (B = 3).
    Parabolic,
}

impl NormalPressure {
    /// The imposed shape; `None`: solved.
    pub fn shape(self) -> Option<PressureShape> {
        match self {
            NormalPressure::Solved => None,
            NormalPressure::Elliptical => Some(PressureShape::Ellipsoidal),
            NormalPressure::Parabolic => Some(PressureShape::Parabolic),
        }
    }

    /// The scene's name of it.
    pub fn name(self) -> &'static str {
        match self {
            NormalPressure::Solved => "solved",
            NormalPressure::Elliptical => "elliptical",
            NormalPressure::Parabolic => "parabolic",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Hertz's ellipsoidal pressure sampled at the element centres: its peak is 3FN/(2πab) and
    /// its sum tends to FN as the grid refines (the midpoint rule on √(1 − r²): error O(h^1.5)).
    #[test]
    fn elliptical_pressure_is_hertz_closed_form() {
        let (a, b, fn_n) = (4.1, 2.05, 0.7563);
        for (n, tol) in [(41, 2e-3), (201, 2e-4)] {
            let grid = Grid::new(n, n, 1.17143 * a, 1.17143 * b);
            let p = NormalPressure::Elliptical.shape().unwrap().on_grid(&grid, fn_n, a, b);
            let total: f64 = p.iter().sum::<f64>() * grid.element_area_mm2();
            assert!((total / fn_n - 1.0).abs() < tol, "n = {n}: sum {total} vs FN {fn_n}");
            let centre = p[grid.index(n / 2, n / 2)];
            assert!((centre - 1.5 * fn_n / (PI * a * b)).abs() < 1e-15);
            // On the axis x = x_i, y = 0: p0 √(1 − x²/a²).
            let i = n / 2 + n / 5;
            let x = grid.x_mm[i];
            let want = 1.5 * fn_n / (PI * a * b) * (1.0 - (x / a).powi(2)).sqrt();
            assert!((p[grid.index(i, n / 2)] - want).abs() < 1e-15);
        }
        // CONTACT's case (testbank.inp 13): 973 loaded elements, sum 0.75692 for FN = 0.7563.
        let grid = Grid::new(41, 41, 1.17143 * 4.1, 1.17143 * 4.1);
        let p = NormalPressure::Elliptical.shape().unwrap().on_grid(&grid, 0.7563, 4.1, 4.1);
        assert_eq!(p.iter().filter(|&&v| v > 0.0).count(), 973);
        let peak = p.iter().fold(0.0f64, |m, &v| m.max(v));
        assert!((peak - 2.148e-2).abs() < 0.5e-5, "PMAX {peak} vs CONTACT's 2.148e-2");
    }

    /// The parabolic pressure's peak is 4/3 of the elliptical one (CONTACT's "33% higher").
    #[test]
    fn parabolic_peak_is_four_thirds_of_elliptical() {
        let (e, p) =
            (PressureShape::Ellipsoidal.peak_mpa(1.0, 2.0, 3.0), PressureShape::Parabolic.peak_mpa(1.0, 2.0, 3.0));
        assert!((p / e - 4.0 / 3.0).abs() < 1e-15);
        assert_eq!(NormalPressure::Solved.shape(), None);
    }
}
