//! Displacements, displacement gradients and stresses inside the elastic half-space z ≥ 0 under
//! surface tractions uniform on rectangles (Love 1929; Johnson, Contact Mechanics, Eq. 3.6–3.7:
//! u from the potentials F₁, G₁, H₁ = ∫∫ (qx, qy, p) Ω, Ω = z ln(ρ+z) − ρ), each rectangle's
//! potentials closed-form through the corner primitive Φ of Ω (∂²Φ/∂X∂Y = Ω), as CONTACT's
//! subsurface stresses do (Kalker 1986, "Numerical calculation of the elastic field in a
//! half-space"). Frame: x, y on the surface, z into the body; a traction (px, py, pn) acts on
//! the body's surface, pn > 0 pressing into it (CONTACT's body 1); stress positive in tension.

use super::jet::Jet;
use super::ContactError;

/// One rectangle `[x0, x1] × [y0, y1]` of the surface with a uniform traction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadedRectangle {
    pub x_mm: [f64; 2],
    pub y_mm: [f64; 2],
    /// (px, py, pn) [MPa] on the body, pn > 0 compressive.
    pub traction_mpa: [f64; 3],
}

/// The elastic field at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElasticField {
    /// Displacement (ux, uy, uz) [mm], uz into the body.
    pub u_mm: [f64; 3],
    /// Stress tensor σ_ij [MPa], tension positive.
    pub sigma_mpa: [[f64; 3]; 3],
}

/// Index of the multi-index ∂ˣᵃ∂ʸᵇ∂ᶻᶜ, a, b, c ≤ 4, in a [`Derivs`] table.
const fn at(a: usize, b: usize, c: usize) -> usize {
    a * 25 + b * 5 + c
}

/// Derivatives of orders 2…4 of one potential (the rectangle integral of Ω times a traction).
type Derivs = [f64; 125];

/// ln(s + ρ) without cancellation where s < 0: ln(rest²) − ln(ρ − s), rest² = ρ² − s².
fn ln_plus(s: Jet, rho: Jet, rest2: Jet) -> Jet {
    if s.v >= 0.0 {
        (s + rho).ln()
    } else {
        rest2.ln() - (rho - s).ln()
    }
}

/// ∫ X / (ρ (ρ + z)) dY = atan(Y/X) − atan(zY/(Xρ)), as one arctangent without the branch at X = 0.
fn angle(x: Jet, y: Jet, z: Jet, rho: Jet) -> Jet {
    let r2 = x * x + y * y;
    (x * y * r2 / ((rho + z) * (x * x * rho + z * y * y))).atan()
}

/// The six second derivatives of Φ at a corner offset (X, Y, z), each as a jet (its own
/// derivatives up to two more orders): Ω = Φ_XY, Φ_XX, Φ_YY, Φ_XZ, Φ_YZ, Φ_ZZ, each up to terms
/// in (X, z) or (Y, z) alone, which cancel in a rectangle's corner sum.
fn corner_bases(px: f64, py: f64, pz: f64) -> [Jet; 6] {
    let [x, y, z] = [Jet::variable(px, 0), Jet::variable(py, 1), Jet::variable(pz, 2)];
    let (x2, y2, z2) = (x * x, y * y, z * z);
    let rho = (x2 + y2 + z2).sqrt();
    let ln_rz = (rho + z).ln();
    let ln_yr = ln_plus(y, rho, x2 + z2);
    let ln_xr = ln_plus(x, rho, y2 + z2);
    let ang_x = angle(x, y, z, rho);
    let ang_y = angle(y, x, z, rho);
    let omega = z * ln_rz - rho;
    let phi_xx = z * ang_x - x * ln_yr;
    let phi_yy = z * ang_y - y * ln_xr;
    let phi_xz = y * ln_rz - y + z * ln_yr + x * ang_x;
    let phi_yz = x * ln_rz - x + z * ln_xr + y * ang_y;
    // atan(XY/(zρ)) as a half angle, defined at z = 0 too: z²ρ² + X²Y² = (X²+z²)(Y²+z²)
    let half = x * y / (z * rho + ((x2 + z2) * (y2 + z2)).sqrt());
    let phi_zz = x * ln_yr + y * ln_xr - z * half.atan().scale(2.0);
    [omega, phi_xx, phi_yy, phi_xz, phi_yz, phi_zz]
}

/// ∂ˣᵃ∂ʸᵇ∂ᶻᶜ Φ for 2 ≤ a+b+c ≤ 4 from the corner's bases.
fn from_bases(b: &[Jet; 6], a: usize, bb: usize, c: usize) -> f64 {
    let (base, rest) = match (a, bb) {
        (a, bb) if a >= 1 && bb >= 1 => (0, [a - 1, bb - 1, c]),
        (a, 0) if a >= 2 => (1, [a - 2, 0, c]),
        (0, bb) if bb >= 2 => (2, [0, bb - 2, c]),
        (1, 0) => (3, [0, 0, c - 1]),
        (0, 1) => (4, [0, 0, c - 1]),
        _ => (5, [0, 0, c - 2]),
    };
    let j = &b[base];
    let axes: Vec<usize> = (0..3).flat_map(|k| std::iter::repeat_n(k, rest[k])).collect();
    match axes.as_slice() {
        [] => j.v,
        [i] => j.g[*i],
        [i, k] => j.h[*i][*k],
        _ => unreachable!("residual order above two"),
    }
}

/// The multi-indices of orders 2…4.
fn orders_2_to_4() -> impl Iterator<Item = (usize, usize, usize)> {
    (0..=4usize).flat_map(|a| {
        (0..=4 - a).flat_map(move |b| (0..=4 - a - b).map(move |c| (a, b, c)).filter(|&(a, b, c)| a + b + c >= 2))
    })
}

/// The rectangle integral of Ω over a unit load, derivatives of orders 2…4 at the field point:
/// the corner sum Φ(x−x₀, y−y₀) − Φ(x−x₁, y−y₀) − Φ(x−x₀, y−y₁) + Φ(x−x₁, y−y₁).
fn rectangle_derivs(r: &LoadedRectangle, p: [f64; 3]) -> Derivs {
    let mut d = [0.0; 125];
    for (cx, cy, sign) in [(0, 0, 1.0), (1, 0, -1.0), (0, 1, -1.0), (1, 1, 1.0)] {
        let b = corner_bases(p[0] - r.x_mm[cx], p[1] - r.y_mm[cy], p[2]);
        for (a, bb, c) in orders_2_to_4() {
            d[at(a, bb, c)] += sign * from_bases(&b, a, bb, c);
        }
    }
    d
}

/// The three potentials F₁, G₁, H₁ (tractions px, py, pn) summed over the rectangles.
struct Potentials {
    f: Derivs,
    g: Derivs,
    h: Derivs,
}

impl Potentials {
    fn sum(rects: &[LoadedRectangle], p: [f64; 3]) -> Self {
        let mut out = Self { f: [0.0; 125], g: [0.0; 125], h: [0.0; 125] };
        for r in rects.iter().filter(|r| r.traction_mpa.iter().any(|&t| t != 0.0)) {
            let d = rectangle_derivs(r, p);
            let [tx, ty, tn] = r.traction_mpa;
            for (k, dk) in d.iter().enumerate() {
                out.f[k] += tx * dk;
                out.g[k] += ty * dk;
                out.h[k] += tn * dk;
            }
        }
        out
    }

    /// ψ₁ = ∂F₁/∂x + ∂G₁/∂y + ∂H₁/∂z, differentiated by (a, b, c).
    fn psi1(&self, a: usize, b: usize, c: usize) -> f64 {
        self.f[at(a + 1, b, c)] + self.g[at(a, b + 1, c)] + self.h[at(a, b, c + 1)]
    }

    /// 4πG u (Johnson Eq. 3.7) with every derivative raised by `e` (∂/∂x_m u for e = e_m, but for
    /// the product rule on the factor z, which [`Self::gradient`] adds).
    fn scaled_u(&self, nu: f64, z: f64, e: [usize; 3]) -> [f64; 3] {
        let [a, b, c] = e;
        let ux = 2.0 * self.f[at(a, b, c + 2)] - self.h[at(a + 1, b, c + 1)] + 2.0 * nu * self.psi1(a + 1, b, c)
            - z * self.psi1(a + 1, b, c + 1);
        let uy = 2.0 * self.g[at(a, b, c + 2)] - self.h[at(a, b + 1, c + 1)] + 2.0 * nu * self.psi1(a, b + 1, c)
            - z * self.psi1(a, b + 1, c + 1);
        let uz = self.h[at(a, b, c + 2)] + (1.0 - 2.0 * nu) * self.psi1(a, b, c + 1) - z * self.psi1(a, b, c + 2);
        [ux, uy, uz]
    }

    /// 4πG ∂u_i/∂x_m, as `[i][m]`.
    fn gradient(&self, nu: f64, z: f64) -> [[f64; 3]; 3] {
        let mut grad = [[0.0; 3]; 3];
        for m in 0..3 {
            let mut e = [0; 3];
            e[m] = 1;
            let du = self.scaled_u(nu, z, e);
            for i in 0..3 {
                grad[i][m] = du[i];
            }
        }
        // ∂/∂z of the factor z in −z ∂ψ/∂x_i
        grad[0][2] -= self.psi1(1, 0, 1);
        grad[1][2] -= self.psi1(0, 1, 1);
        grad[2][2] -= self.psi1(0, 0, 2);
        grad
    }
}

/// The elastic field at `point` = (x, y, z) [mm], z ≥ 0, of a half-space with shear modulus
/// `g_mpa` and Poisson's ratio `poisson` under the loaded rectangles (Hooke: σ = 2G ε + λ tr ε I,
/// λ = 2Gν/(1−2ν)).
pub fn elastic_field(
    rects: &[LoadedRectangle],
    g_mpa: f64,
    poisson: f64,
    point: [f64; 3],
) -> Result<ElasticField, ContactError> {
    if !(g_mpa > 0.0 && g_mpa.is_finite()) {
        return Err(ContactError::OutOfRange { name: "g_mpa", value: g_mpa, requirement: "> 0" });
    }
    if !(0.0..0.5).contains(&poisson) {
        return Err(ContactError::OutOfRange { name: "poisson", value: poisson, requirement: "in [0, 0.5)" });
    }
    if !(point[2] >= 0.0 && point.iter().all(|v| v.is_finite())) {
        return Err(ContactError::OutOfRange { name: "z_mm", value: point[2], requirement: "finite and >= 0" });
    }
    let pot = Potentials::sum(rects, point);
    let k = 1.0 / (4.0 * std::f64::consts::PI * g_mpa);
    let u_mm = pot.scaled_u(poisson, point[2], [0; 3]).map(|u| k * u);
    let grad = pot.gradient(poisson, point[2]);
    let lambda = 2.0 * g_mpa * poisson / (1.0 - 2.0 * poisson);
    let trace = k * (grad[0][0] + grad[1][1] + grad[2][2]);
    let mut sigma_mpa = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            sigma_mpa[i][j] = g_mpa * k * (grad[i][j] + grad[j][i]);
        }
        sigma_mpa[i][i] += lambda * trace;
    }
    if sigma_mpa.iter().flatten().chain(&u_mm).any(|v| !v.is_finite()) {
        return Err(ContactError::NonFinite("subsurface stress (a surface point on an element's edge)"));
    }
    Ok(ElasticField { u_mm, sigma_mpa })
}

#[cfg(test)]
#[path = "stress_tests.rs"]
mod tests;
