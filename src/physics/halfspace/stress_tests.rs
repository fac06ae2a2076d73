//! The rectangle primitives against their defining derivatives, and the field against the closed
//! forms of Boussinesq, Cerruti and Love.

use super::*;
use std::f64::consts::PI;

const G: f64 = 1.0;
const NU: f64 = 0.28;

fn rel(got: f64, want: f64) -> f64 {
    (got - want).abs() / want.abs()
}

/// Each base differentiates to what it integrates: ∂Φ_XX/∂Y = ∂Ω/∂X = −X/(ρ+z), ∂Φ_XZ/∂Y = ∂Ω/∂z
/// = ln(ρ+z), ∂²Φ_ZZ/∂X∂Y = ∂²Ω/∂z² = 1/ρ, and the same with X and Y swapped; Ω's own gradient.
#[test]
fn stress_corner_bases_differentiate_to_omega() {
    for p in [[0.3f64, -0.7, 0.45], [-1.2, 0.4, 0.05], [-0.5, -0.6, 0.0], [2.0, 3.0, 1.5], [-3.0, 0.2, 1e-3]] {
        let [x, y, z] = p;
        let rho = (x * x + y * y + z * z).sqrt();
        let b = corner_bases(x, y, z);
        let checks = [
            (b[0].g[0], -x / (rho + z)),
            (b[0].g[1], -y / (rho + z)),
            (b[0].g[2], (rho + z).ln()),
            (b[1].g[1], -x / (rho + z)),
            (b[2].g[0], -y / (rho + z)),
            (b[3].g[1], (rho + z).ln()),
            (b[4].g[0], (rho + z).ln()),
            (b[5].h[0][1], 1.0 / rho),
        ];
        for (k, (got, want)) in checks.iter().enumerate() {
            assert!((got - want).abs() < 1e-12 * (1.0 + want.abs()), "{p:?} check {k}: {got} vs {want}");
        }
    }
}

/// A small square loaded by P = 1 N acts as Boussinesq's point load far from it (Johnson Eq.
/// 3.20): σzz = −3Pz³/(2πρ⁵), σxz = −3Pxz²/(2πρ⁵), uz = P/(4πG) (z²/ρ³ + 2(1−ν)/ρ).
#[test]
fn stress_boussinesq_point_load() {
    let d = 1e-3;
    let sq = LoadedRectangle {
        x_mm: [-d / 2.0, d / 2.0],
        y_mm: [-d / 2.0, d / 2.0],
        traction_mpa: [0.0, 0.0, 1.0 / (d * d)],
    };
    for p in [[0.3f64, -0.2, 0.5], [0.0, 0.0, 1.0], [-0.8, 0.6, 0.25]] {
        let [x, y, z] = p;
        let rho = (x * x + y * y + z * z).sqrt();
        let f = elastic_field(&[sq], G, NU, p).unwrap();
        let k = 3.0 / (2.0 * PI * rho.powi(5));
        let szz = -k * z.powi(3);
        let sxz = -k * x * z * z;
        let syz = -k * y * z * z;
        let uz = (z * z / rho.powi(3) + 2.0 * (1.0 - NU) / rho) / (4.0 * PI * G);
        assert!(rel(f.sigma_mpa[2][2], szz) < 1e-6, "{p:?}: szz {} vs {szz}", f.sigma_mpa[2][2]);
        if x != 0.0 {
            assert!(rel(f.sigma_mpa[0][2], sxz) < 1e-6, "{p:?}: sxz {} vs {sxz}", f.sigma_mpa[0][2]);
            assert!(rel(f.sigma_mpa[1][2], syz) < 1e-6, "{p:?}: syz {} vs {syz}", f.sigma_mpa[1][2]);
        }
        assert!(rel(f.u_mm[2], uz) < 1e-6, "{p:?}: uz {} vs {uz}", f.u_mm[2]);
    }
}

/// Cerruti's tangential point load Q = 1 N along x (Johnson Eq. 3.xx; ν-independent parts):
/// σzz = −3Qxz²/(2πρ⁵), σxz = −3Qx²z/(2πρ⁵), σyz = −3Qxyz/(2πρ⁵),
/// ux = Q/(4πG) (1/ρ + x²/ρ³ + (1−2ν)(1/(ρ+z) − x²/(ρ(ρ+z)²))).
#[test]
fn stress_cerruti_tangential_point_load() {
    let d = 1e-4;
    let sq = LoadedRectangle {
        x_mm: [-d / 2.0, d / 2.0],
        y_mm: [-d / 2.0, d / 2.0],
        traction_mpa: [1.0 / (d * d), 0.0, 0.0],
    };
    for p in [[0.3f64, -0.2, 0.5], [-0.8, 0.6, 0.25], [0.5, 0.4, 1.0]] {
        let [x, y, z] = p;
        let rho = (x * x + y * y + z * z).sqrt();
        let f = elastic_field(&[sq], G, NU, p).unwrap();
        let k = 3.0 / (2.0 * PI * rho.powi(5));
        let want = [(2, 2, -k * x * z * z), (0, 2, -k * x * x * z), (1, 2, -k * x * y * z)];
        for (i, j, w) in want {
            assert!(rel(f.sigma_mpa[i][j], w) < 1e-6, "{p:?}: s{i}{j} {} vs {w}", f.sigma_mpa[i][j]);
        }
        let rz = rho + z;
        let ux = (1.0 / rho + x * x / rho.powi(3) + (1.0 - 2.0 * NU) * (1.0 / rz - x * x / (rho * rz * rz)))
            / (4.0 * PI * G);
        assert!(rel(f.u_mm[0], ux) < 1e-6, "{p:?}: ux {} vs {ux}", f.u_mm[0]);
    }
}

/// Uniform pressure p on the rectangle [−a, a] × [−b, b], below its centre (Love 1929; four
/// corners of Holl's corner formula): σzz = −(2p/π) (atan(ab/(zR)) + abz/R (1/(a²+z²) + 1/(b²+z²))),
/// R = √(a²+b²+z²); at z = 0, σzz = −p.
#[test]
fn stress_love_uniform_rectangle_below_centre() {
    let (a, b, p) = (1.5, 0.5, 2.0);
    let r = LoadedRectangle { x_mm: [-a, a], y_mm: [-b, b], traction_mpa: [0.0, 0.0, p] };
    for z in [0.0, 0.05, 0.3, 1.0, 2.5, 10.0] {
        let f = elastic_field(&[r], G, NU, [0.0, 0.0, z]).unwrap();
        let want = if z == 0.0 {
            -p
        } else {
            let big_r = (a * a + b * b + z * z).sqrt();
            -(2.0 * p / PI)
                * ((a * b / (z * big_r)).atan() + a * b * z / big_r * (1.0 / (a * a + z * z) + 1.0 / (b * b + z * z)))
        };
        assert!(rel(f.sigma_mpa[2][2], want) < 1e-12, "z = {z}: {} vs {want}", f.sigma_mpa[2][2]);
        // on the axis of symmetry no shear
        for (i, j) in [(0, 1), (0, 2), (1, 2)] {
            assert!(f.sigma_mpa[i][j].abs() < 1e-12, "z = {z}: s{i}{j} = {}", f.sigma_mpa[i][j]);
        }
    }
}

/// Splitting a loaded rectangle into four changes nothing (the corner sums are exact).
#[test]
fn stress_split_rectangle_is_additive() {
    let t = [0.3, -0.2, 1.0];
    let whole = [LoadedRectangle { x_mm: [-1.0, 1.0], y_mm: [-0.5, 0.5], traction_mpa: t }];
    let parts: Vec<_> =
        [([-1.0, 0.2], [-0.5, 0.1]), ([0.2, 1.0], [-0.5, 0.1]), ([-1.0, 0.2], [0.1, 0.5]), ([0.2, 1.0], [0.1, 0.5])]
            .map(|(x_mm, y_mm)| LoadedRectangle { x_mm, y_mm, traction_mpa: t })
            .to_vec();
    for p in [[0.4, 0.3, 0.2], [-1.3, 0.7, 0.6], [0.0, -0.2, 0.0]] {
        let (a, b) = (elastic_field(&whole, G, NU, p).unwrap(), elastic_field(&parts, G, NU, p).unwrap());
        for i in 0..3 {
            assert!((a.u_mm[i] - b.u_mm[i]).abs() < 1e-12);
            for j in 0..3 {
                assert!((a.sigma_mpa[i][j] - b.sigma_mpa[i][j]).abs() < 1e-11, "{p:?} s{i}{j}");
            }
        }
        // the surface inside the load carries the traction itself: σzz = −pn, σxz = −px, σyz = −py
        if p[2] == 0.0 {
            assert!((a.sigma_mpa[2][2] + t[2]).abs() < 1e-12 && (a.sigma_mpa[0][2] + t[0]).abs() < 1e-12);
            assert!((a.sigma_mpa[1][2] + t[1]).abs() < 1e-12);
        }
    }
}

#[test]
fn stress_refuses_points_above_the_surface() {
    let r = [LoadedRectangle { x_mm: [-1.0, 1.0], y_mm: [-1.0, 1.0], traction_mpa: [0.0, 0.0, 1.0] }];
    assert!(elastic_field(&r, G, NU, [0.0, 0.0, -0.1]).is_err());
    assert!(elastic_field(&r, G, 0.5, [0.0, 0.0, 0.1]).is_err());
}
