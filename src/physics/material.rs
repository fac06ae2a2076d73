//! Elastic constants of two quasi-identical bodies (thesis Eq. 2.1 with K = 0).

/// Combined elastic constants of the two bodies.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Material {
    /// Combined shear modulus G [MPa] (thesis Table 4.1 prints "82000 GPa"; it is 82000 MPa).
    pub g_mpa: f64,
    /// Combined Poisson's ratio ν [-].
    pub poisson: f64,
    /// Young's modulus E [MPa]; `2 G (1 + ν)` unless given explicitly.
    pub e_mpa: f64,
}

impl Material {
    /// From G and ν; E follows as `2 G (1 + ν)`.
    pub fn from_g(g_mpa: f64, poisson: f64) -> Self {
        Self { g_mpa, poisson, e_mpa: 2.0 * g_mpa * (1.0 + poisson) }
    }

    /// From E and ν; G follows as `E / (2 (1 + ν))`.
    pub fn from_e(e_mpa: f64, poisson: f64) -> Self {
        Self { g_mpa: e_mpa / (2.0 * (1.0 + poisson)), poisson, e_mpa }
    }

    /// Two-body contact modulus E* [MPa] with `1/E* = 2 (1 − ν²) / E` (two identical bodies).
    pub fn e_star_mpa(&self) -> f64 {
        self.e_mpa / (2.0 * (1.0 - self.poisson * self.poisson))
    }
}
