//! What CONTACT derives from a stress tensor (user guide, "Subsurface stresses"): the mean
//! hydrostatic stress σ_hyd = tr σ / 3, von Mises' σ_vm = √(3 J₂), the principal stresses
//! σ₁ ≥ σ₂ ≥ σ₃ (eigenvalues of the symmetric tensor, Smith 1961's trigonometric form) and
//! Tresca's σ_tr = σ₁ − σ₃.

/// The invariants of one stress tensor [MPa].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StressInvariants {
    pub hydrostatic_mpa: f64,
    pub von_mises_mpa: f64,
    /// σ₁ ≥ σ₂ ≥ σ₃.
    pub principal_mpa: [f64; 3],
    pub tresca_mpa: f64,
}

/// The invariants of a symmetric tensor `s`.
pub fn invariants(s: &[[f64; 3]; 3]) -> StressInvariants {
    let mean = (s[0][0] + s[1][1] + s[2][2]) / 3.0;
    let dev = |i: usize, j: usize| s[i][j] - if i == j { mean } else { 0.0 };
    let mut j2 = 0.0;
    for i in 0..3 {
        for j in 0..3 {
            j2 += dev(i, j) * dev(i, j);
        }
    }
    j2 *= 0.5;
    let von_mises_mpa = (3.0 * j2).sqrt();
    let principal_mpa = eigenvalues(s, mean, j2);
    StressInvariants {
        hydrostatic_mpa: mean,
        von_mises_mpa,
        principal_mpa,
        tresca_mpa: principal_mpa[0] - principal_mpa[2],
    }
}

/// Eigenvalues, largest first, from the deviator's J₂ and J₃ = det(s − mean I):
/// λ = mean + 2√(J₂/3) cos(θ − 2πk/3), cos 3θ = (J₃/2)(3/J₂)^{3/2}.
fn eigenvalues(s: &[[f64; 3]; 3], mean: f64, j2: f64) -> [f64; 3] {
    if j2 <= f64::MIN_POSITIVE {
        return [mean; 3];
    }
    let d = |i: usize, j: usize| s[i][j] - if i == j { mean } else { 0.0 };
    let j3 = d(0, 0) * (d(1, 1) * d(2, 2) - d(1, 2) * d(2, 1)) - d(0, 1) * (d(1, 0) * d(2, 2) - d(1, 2) * d(2, 0))
        + d(0, 2) * (d(1, 0) * d(2, 1) - d(1, 1) * d(2, 0));
    let r = (j2 / 3.0).sqrt();
    let c = (0.5 * j3 / (r * r * r)).clamp(-1.0, 1.0);
    let theta = c.acos() / 3.0;
    let tau = 2.0 * std::f64::consts::PI / 3.0;
    let mut e = [0.0, tau, -tau].map(|off| mean + 2.0 * r * (theta + off).cos());
    e.sort_by(|a, b| b.total_cmp(a));
    e
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stress_invariants_of_a_known_tensor() {
        // eigenvalues 3, 1, −2 rotated by 30° about z: the invariants must not see the rotation
        let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
        let (a, b) = (3.0, 1.0);
        let t = [
            [a * c * c + b * s * s, (a - b) * c * s, 0.0],
            [(a - b) * c * s, a * s * s + b * c * c, 0.0],
            [0.0, 0.0, -2.0],
        ];
        let inv = invariants(&t);
        for (got, want) in inv.principal_mpa.iter().zip([3.0, 1.0, -2.0]) {
            assert!((got - want).abs() < 1e-12, "{got} vs {want}");
        }
        assert!((inv.hydrostatic_mpa - 2.0 / 3.0).abs() < 1e-14);
        // σ_vm² = ½((σ1−σ2)² + (σ2−σ3)² + (σ3−σ1)²) = ½(4 + 9 + 25)
        assert!((inv.von_mises_mpa - 19f64.sqrt()).abs() < 1e-12);
        assert!((inv.tresca_mpa - 5.0).abs() < 1e-12);
    }
}
