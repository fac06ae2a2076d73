//! Kalker's creepage coefficients c11, c22, c23, c33 and the flexibilities of the simplified theory.
//!
//! Sources: thesis App. A (Kalker's Table A1, Kalker 1990 p. 125) and the polynomial fit Eq. 2.36;
//! flexibilities Eq. 2.35 (Kalker) or Eq. 3.5 (the thesis's own, kept as an option).

use super::material::Material;
use std::f64::consts::PI;

/// Where c11, c22, c23 come from (`[model] coefficients`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum CoefficientSource {
    /// Table A1, quadratic in ν through ν = 0, 0.25, 0.5 and linear in the axis ratio.
    Table,
    /// The polynomial fit Eq. 2.36 (made for ν = 0.27, valid for 1/25 ≤ b/a ≤ 25).
    Fit,
}

/// Which flexibilities L1, L2, L3 the simplified models use (`[model] flexibility`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum FlexibilityModel {
    /// Kalker's simplified theory, Eq. 2.35: `L1 = 8a/(3 c11 G)`, `L2 = 8a/(3 c22 G)`,
    /// `L3 = π a √(a/b) / (4 c23 G)`.
    Kalker,
    /// Thesis Eq. 3.5: `L1 = L2 = 2b(1+ν)/E`, `L3 = b(1+ν)(1−2ν)/((1−ν)E)`. Not Kalker's.
    Thesis,
}

/// How the simplified models set the flexibility of each strip (grid row) on a contact that is
/// not Hertz's ellipse (`[model] nonhertz_flexibility`; an ellipse always uses its own).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PatchFlexibility {
    /// Per strip from its local half-length: `L(y) = L · a(y)/a_e`, Kalker's L of the
    /// equivalent ellipse scaled as Kalker's `L ∝ a` for a strip of half-length a(y) (the strip
    /// idea of FaStrip: Sichani, Enblom & Berg, Vehicle System Dynamics 54(6), 2016).
    Strip,
    /// Uniform, Kalker's L of the equivalent ellipse (Kik & Piotrowski 2008), as CONTACT's FASTSIM
    /// on non-Hertzian contacts (m_scontc.f90: `equiv_ellipse`, then `simpflex`). The default:
    /// closer to the exact solver than `Strip` on the CONTACT non-Hertzian cases (README).
    #[default]
    EquivalentEllipse,
}

impl PatchFlexibility {
    pub fn is_default(&self) -> bool {
        *self == PatchFlexibility::default()
    }
}

/// Kalker's creepage coefficients [-].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Coefficients {
    pub c11: f64,
    pub c22: f64,
    pub c23: f64,
    /// Spin–moment coefficient (Table A1; `Mz = G (ab)^2 c33 cs` for pure spin).
    #[serde(default)]
    pub c33: f64,
}

/// Kalker's linear theory on an ellipse a × b (Kalker 1967; thesis App. A), every force divided by
/// `per` (FN for traction coefficients, 1 for newtons): `Fx = G a b C11 cx`,
/// `Fy = G a b C22 cy + G (ab)^(3/2) C23 cs`, `Mz = −G (ab)^(3/2) C23 cy + G (ab)^2 C33 cs`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LinearTheory {
    /// (G a b, G (ab)^(3/2), G (ab)^2) / per.
    scale: (f64, f64, f64),
}

impl LinearTheory {
    /// The theory for shear modulus `g_mpa` on an ellipse `a_mm` × `b_mm`, forces divided by `per`.
    pub fn new(g_mpa: f64, a_mm: f64, b_mm: f64, per: f64) -> Self {
        let gab = g_mpa * a_mm * b_mm;
        let ab = a_mm * b_mm;
        LinearTheory { scale: (gab / per, gab * ab.sqrt() / per, gab * ab / per) }
    }

    /// (Fx, Fy, Mz) / per for creepages (cx, cy, cs [1/mm]); Mz in N·mm / per, the references' sign
    /// convention. Every model's results are compared bit for bit: keep the order of operations.
    pub fn forces(&self, c: &Coefficients, (cx, cy, cs_per_mm): (f64, f64, f64)) -> (f64, f64, f64) {
        let (s0, s1, s2) = self.scale;
        (s0 * c.c11 * cx, s0 * c.c22 * cy + s1 * c.c23 * cs_per_mm, -s1 * c.c23 * cy + s2 * c.c33 * cs_per_mm)
    }
}

/// Flexibilities of the brush [mm³/N] (τ = u / L).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Flexibilities {
    pub l1_mm3_n: f64,
    pub l2_mm3_n: f64,
    pub l3_mm3_n: f64,
}

/// Axis-ratio rows of Table A1 as one monotone parameter s: s = a/b for a ≤ b (upper half,
/// s = 0.1 … 0.9) and s = 2 − b/a for a ≥ b (lower half, s = 1.0 … 1.9).
/// Each row: c11, c22, c23, c33 at ν = 0, 0.25, 0.5.
#[rustfmt::skip]
#[allow(clippy::approx_constant)] // 3.14 is Kalker's c22 at b/a = 0.5, ν = 0.5, not π
const TABLE_A1: [[[f64; 3]; 4]; 19] = [
    [[2.51, 3.31, 4.85], [2.51, 2.52, 2.53], [0.334, 0.473, 0.731], [6.42, 8.28, 11.7]], // a/b = 0.1
    [[2.59, 3.37, 4.81], [2.59, 2.63, 2.66], [0.483, 0.603, 0.809], [3.46, 4.27, 5.66]],
    [[2.68, 3.44, 4.80], [2.68, 2.75, 2.81], [0.607, 0.715, 0.889], [2.49, 2.96, 3.72]],
    [[2.78, 3.53, 4.82], [2.78, 2.88, 2.98], [0.720, 0.823, 0.977], [2.02, 2.32, 2.77]],
    [[2.88, 3.62, 4.83], [2.88, 3.01, 3.14], [0.827, 0.929, 1.07], [1.74, 1.93, 2.22]],
    [[2.98, 3.72, 4.91], [2.98, 3.14, 3.31], [0.930, 1.03, 1.18], [1.56, 1.68, 1.86]],
    [[3.09, 3.81, 4.97], [3.09, 3.28, 3.48], [1.03, 1.14, 1.29], [1.43, 1.50, 1.60]],
    [[3.19, 3.91, 5.05], [3.19, 3.41, 3.65], [1.13, 1.25, 1.40], [1.34, 1.37, 1.42]],
    [[3.29, 4.01, 5.12], [3.29, 3.54, 3.82], [1.23, 1.36, 1.51], [1.27, 1.27, 1.27]],    // a/b = 0.9
    [[3.40, 4.12, 5.20], [3.40, 3.67, 3.98], [1.33, 1.47, 1.63], [1.21, 1.19, 1.16]],    // a = b
    [[3.51, 4.22, 5.30], [3.51, 3.81, 4.16], [1.44, 1.59, 1.77], [1.16, 1.11, 1.06]],    // b/a = 0.9
    [[3.65, 4.36, 5.42], [3.65, 3.99, 4.39], [1.58, 1.75, 1.94], [1.10, 1.04, 0.954]],
    [[3.82, 4.54, 5.58], [3.82, 4.21, 4.67], [1.76, 1.95, 2.18], [1.05, 0.965, 0.852]],
    [[4.06, 4.78, 5.80], [4.06, 4.50, 5.04], [2.01, 2.23, 2.50], [1.01, 0.892, 0.751]],
    [[4.37, 5.10, 6.11], [4.37, 4.90, 5.56], [2.35, 2.62, 2.96], [0.958, 0.819, 0.650]],
    [[4.84, 5.57, 6.57], [4.84, 5.48, 6.31], [2.88, 3.24, 3.70], [0.912, 0.747, 0.549]],
    [[5.57, 6.34, 7.34], [5.57, 6.40, 7.51], [3.79, 4.32, 5.01], [0.868, 0.674, 0.446]],
    [[6.96, 7.78, 8.82], [6.96, 8.14, 9.79], [5.72, 6.63, 7.89], [0.828, 0.601, 0.341]],
    [[10.7, 11.7, 12.9], [10.7, 12.8, 16.0], [12.2, 14.6, 18.0], [0.795, 0.526, 0.228]],    // b/a = 0.1
];

/// Quadratic Lagrange interpolation in ν through the table's ν = 0, 0.25, 0.5.
fn in_poisson(v: [f64; 3], nu: f64) -> f64 {
    let (l0, l1, l2) = (
        (nu - 0.25) * (nu - 0.5) / ((0.0 - 0.25) * (0.0 - 0.5)),
        (nu - 0.0) * (nu - 0.5) / ((0.25 - 0.0) * (0.25 - 0.5)),
        (nu - 0.0) * (nu - 0.25) / ((0.5 - 0.0) * (0.5 - 0.25)),
    );
    l0 * v[0] + l1 * v[1] + l2 * v[2]
}

fn table_row(row: usize, nu: f64) -> [f64; 4] {
    TABLE_A1[row].map(|c| in_poisson(c, nu))
}

impl Coefficients {
    /// Table A1 for semi-axes a (x) and b (y) and Poisson's ratio ν ∈ [0, 0.5]: quadratic in ν,
    /// linear in the axis-ratio parameter s between rows. Beyond the table (axis ratio < 0.1) it
    /// is extrapolated: for a/b → 0 towards Kalker's limits c11 = π²/(4(1−ν)), c22 = π²/4
    /// (linearly) and c23 ∝ √(a/b); for b/a → 0 by the power law through the 0.2 and 0.1 rows.
    /// (The g → 0 closed forms as printed in the thesis's App. A do not meet the table, so they
    /// are not used.)
    pub fn from_table(a_mm: f64, b_mm: f64, nu: f64) -> Self {
        let s = if a_mm <= b_mm { a_mm / b_mm } else { 2.0 - b_mm / a_mm };
        let v = if s < 0.1 {
            let w = s / 0.1;
            let edge = table_row(0, nu);
            let limit = [PI * PI / (4.0 * (1.0 - nu)), PI * PI / 4.0];
            // c33 → π²/(16(1−ν)g): grows as 1/g.
            [limit[0] + w * (edge[0] - limit[0]), limit[1] + w * (edge[1] - limit[1]), edge[2] * w.sqrt(), edge[3] / w]
        } else if s > 1.9 {
            let g = 2.0 - s;
            let (r1, r2) = (table_row(18, nu), table_row(17, nu));
            [0, 1, 2, 3].map(|c| r1[c] * (0.1 / g).powf((r1[c] / r2[c]).ln() / 2f64.ln()))
        } else {
            let pos = (s - 0.1) / 0.1;
            let row = (pos.floor() as usize).min(17);
            let t = pos - row as f64;
            let (lo, hi) = (table_row(row, nu), table_row(row + 1, nu));
            [0, 1, 2, 3].map(|c| lo[c] + t * (hi[c] - lo[c]))
        };
        Coefficients { c11: v[0], c22: v[1], c23: v[2], c33: v[3] }
    }

    /// CONTACT's own interpolation of the same table (`linrol`, m_hertz.f90; used by its FASTSIM
    /// and FaStrip): g = min(a/b, b/a), linear in g between the rows of its half of the table,
    /// quadratic in ν through ν = 0, 0.25, 0.5 on the reciprocals 1/c; for g < 0.101 Kalker's
    /// slender-ellipse asymptotes (a < b: c11 = π²/(4(1−ν)), c22 = π²/4, c23 = π√g (1 + ν(ln(16/g) − 5))
    /// /(3(1−ν)); a > b: its closed forms in ln(16/g²)). c33 (which CONTACT's table has not) is
    /// [`Coefficients::from_table`]'s.
    pub fn from_contact(a_mm: f64, b_mm: f64, nu: f64) -> Self {
        let c33 = Self::from_table(a_mm, b_mm, nu).c33;
        let (g, a_le_b) = if a_mm <= b_mm { (a_mm / b_mm, true) } else { (b_mm / a_mm, false) };
        let [c11, c22, c23] = if g < 0.101 {
            slender_asymptotes(g, nu, a_le_b)
        } else {
            // CONTACT's row k (1-based) is g = k/10: rows 0..9 of TABLE_A1 for a <= b, 18..9 for a > b.
            let k = (10.0 * g - 0.005) as usize;
            let w = 10.0 * g - k as f64;
            let row = |k: usize| if a_le_b { TABLE_A1[k - 1] } else { TABLE_A1[19 - k] };
            let (lo, hi) = (row(k), row(k + 1));
            [0, 1, 2].map(|c| {
                let at = |n: usize| w * hi[c][n] + (1.0 - w) * lo[c][n];
                let inv = (nu - 0.25) * (nu - 0.5) * 8.0 / at(0) - (nu - 0.5) * nu * 16.0 / at(1)
                    + nu * (nu - 0.25) * 8.0 / at(2);
                1.0 / inv
            })
        };
        Coefficients { c11, c22, c23, c33 }
    }

    /// The polynomial fit Eq. 2.36 (ν = 0.27; stated for 1/25 ≤ b/a ≤ 25); it has no c33, which
    /// comes from Table A1 at ν = 0.27.
    pub fn from_fit(a_mm: f64, b_mm: f64) -> Self {
        let r = b_mm / a_mm;
        Coefficients {
            c11: 3.2893 + 0.975 / r - 0.012 / (r * r),
            c22: 2.4014 + 1.3179 / r - 0.02 / (r * r),
            c23: 0.4147 + 1.0184 / r + 0.0565 / (r * r) - 0.0013 / (r * r * r),
            c33: Self::from_table(a_mm, b_mm, 0.27).c33,
        }
    }

    /// Coefficients from the chosen source.
    pub fn new(source: CoefficientSource, a_mm: f64, b_mm: f64, nu: f64) -> Self {
        match source {
            CoefficientSource::Table => Self::from_table(a_mm, b_mm, nu),
            CoefficientSource::Fit => Self::from_fit(a_mm, b_mm),
        }
    }
}

/// The modified FASTSIM's slope reduction (Spiryagin, Polach, Cole, Vehicle System Dynamics 51(6),
/// 2013; CONTACT's `fastsim_params`, m_solvpt.f90): `k = k0 (α + (1 − α)/(1 + β ε))` with
/// `ε = G π a b k0 C11 w / (4 μ FN)`, `w = √(cx² + ν²)`, `ν = cy + a cs` (cy where |cy + a cs| < |cy|).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlopeReduction {
    pub k0: f64,
    pub alpha: f64,
    pub beta: f64,
    /// `G π a b k0 C11 / (4 FN)` of the contact at this load.
    pub eps_scale: f64,
    pub a_mm: f64,
}

impl SlopeReduction {
    /// k for creepages (cx, cy, cs) and friction μ.
    pub fn factor(&self, (cx, cy, cs_per_mm): (f64, f64, f64), mu: f64) -> f64 {
        let nu = cy + self.a_mm * cs_per_mm;
        let nu = if nu.abs() < cy.abs() { cy } else { nu };
        let eps = self.eps_scale * cx.hypot(nu) / mu;
        self.k0 * (self.alpha + (1.0 - self.alpha) / (1.0 + self.beta * eps))
    }
}

/// Kalker's asymptotes of c11, c22, c23 for a slender ellipse, g = min(a/b, b/a) → 0, as CONTACT's
/// `linrol` takes them below g = 0.101 (`a_le_b`: the ellipse long across the rolling direction).
fn slender_asymptotes(g: f64, nu: f64, a_le_b: bool) -> [f64; 3] {
    if a_le_b {
        let c23 = PI * g.sqrt() / (3.0 * (1.0 - nu)) * (1.0 + nu * ((16.0 / g).ln() - 5.0));
        return [PI * PI / (4.0 * (1.0 - nu)), PI * PI / 4.0, c23];
    }
    let al = (16.0 / (g * g)).ln();
    let k = 3.0 - 4f64.ln();
    let c11 = 2.0 * PI / (al - 2.0 * nu) / g * (1.0 + k / (al - 2.0 * nu));
    let d = (1.0 - nu) * al + 2.0 * nu;
    let c22 = 2.0 * PI / g * (1.0 + (1.0 - nu) * k / d) / d;
    let c23 = 2.0 * PI / 3.0 / g.powf(1.5) / ((1.0 - nu) * al - 2.0 + 4.0 * nu);
    [c11, c22, c23]
}

impl Flexibilities {
    /// Kalker's single flexibility for the creepages (cx, cy, cs) (Kalker 1982, FASTSIM with one
    /// flexibility): `L = (|cx| L1 + |cy| L2 + c |cs| L3) / √(cx² + cy² + c² cs²)`, c = √(ab) [mm];
    /// L1 at zero creepage.
    pub fn single_mm3_n(&self, (cx, cy, cs_per_mm): (f64, f64, f64), c_mm: f64) -> f64 {
        let norm = (cx * cx + cy * cy + (c_mm * cs_per_mm).powi(2)).sqrt();
        if norm > 0.0 {
            (cx.abs() * self.l1_mm3_n + cy.abs() * self.l2_mm3_n + c_mm * cs_per_mm.abs() * self.l3_mm3_n) / norm
        } else {
            self.l1_mm3_n
        }
    }

    /// Flexibilities for an ellipse a × b [mm] (thesis Eq. 2.35 or Eq. 3.5).
    pub fn new(model: FlexibilityModel, c: &Coefficients, a_mm: f64, b_mm: f64, mat: &Material) -> Self {
        let (g, nu, e) = (mat.g_mpa, mat.poisson, mat.e_mpa);
        match model {
            FlexibilityModel::Kalker => Flexibilities {
                l1_mm3_n: 8.0 * a_mm / (3.0 * c.c11 * g),
                l2_mm3_n: 8.0 * a_mm / (3.0 * c.c22 * g),
                l3_mm3_n: PI * a_mm * (a_mm / b_mm).sqrt() / (4.0 * c.c23 * g),
            },
            FlexibilityModel::Thesis => Flexibilities {
                l1_mm3_n: b_mm * 2.0 * (1.0 + nu) / e,
                l2_mm3_n: b_mm * 2.0 * (1.0 + nu) / e,
                l3_mm3_n: b_mm * (1.0 + nu) * (1.0 - 2.0 * nu) / ((1.0 - nu) * e),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The linear theory's forces: G a b C11 cx, the spin's G (ab)^(3/2) C23 in Fy and −Mz, per `per`.
    #[test]
    fn linear_theory_forces() {
        let c = Coefficients { c11: 4.0, c22: 3.0, c23: 1.5, c33: 0.5 };
        // G a b = 80000 · 2 · 0.5 = 80000 N, √(ab) = 1 mm, per FN = 1000 N.
        let lin = LinearTheory::new(80000.0, 2.0, 0.5, 1000.0);
        assert_eq!(lin.forces(&c, (1e-3, 0.0, 0.0)), (0.32, 0.0, 0.0));
        assert_eq!(lin.forces(&c, (0.0, 1e-3, 0.0)), (0.0, 0.24, -0.12));
        assert_eq!(lin.forces(&c, (0.0, 0.0, 1e-3)), (0.0, 0.12, 0.04));
    }

    #[test]
    fn table_nodes_are_reproduced() {
        // b/a = 0.5, ν = 0.25: 5.10, 4.90, 2.62 (Table A1); a = b, ν = 0: 3.40, 3.40, 1.33.
        let c = Coefficients::from_table(2.0, 1.0, 0.25);
        assert!((c.c11 - 5.10).abs() < 1e-12 && (c.c22 - 4.90).abs() < 1e-12 && (c.c23 - 2.62).abs() < 1e-12);
        let c = Coefficients::from_table(1.0, 1.0, 0.0);
        assert!((c.c11 - 3.40).abs() < 1e-12 && (c.c23 - 1.33).abs() < 1e-12);
        // a/b = 0.3, ν = 0.5 (upper half): 4.80, 2.81, 0.889.
        let c = Coefficients::from_table(0.3, 1.0, 0.5);
        assert!((c.c11 - 4.80).abs() < 1e-12 && (c.c22 - 2.81).abs() < 1e-12 && (c.c23 - 0.889).abs() < 1e-12);
        assert!((c.c33 - 3.72).abs() < 1e-12, "{c:?}");
        // c33: a = b, ν = 0.25: 1.19; b/a = 0.2, ν = 0.5: 0.341.
        assert!((Coefficients::from_table(1.0, 1.0, 0.25).c33 - 1.19).abs() < 1e-12);
        assert!((Coefficients::from_table(5.0, 1.0, 0.5).c33 - 0.341).abs() < 1e-12);
    }

    #[test]
    fn table_beyond_range_is_continuous_and_reaches_the_limits() {
        let at = |r: f64| Coefficients::from_table(1.0, r, 0.28);
        let (inside, outside) = (at(0.1 + 1e-9), at(0.1 - 1e-9));
        assert!(
            (inside.c11 - outside.c11).abs() < 1e-6 && (inside.c23 - outside.c23).abs() < 1e-6,
            "{inside:?} {outside:?}"
        );
        let slender = Coefficients::from_table(1e-6, 1.0, 0.28);
        assert!((slender.c11 - PI * PI / (4.0 * 0.72)).abs() < 1e-3, "{slender:?}");
        assert!((slender.c22 - PI * PI / 4.0).abs() < 1e-3 && slender.c23 < 0.01);
        let (a, b) = (at(0.1 + 1e-9), at(0.1 - 1e-9));
        assert!((a.c22 - b.c22).abs() < 1e-6, "{a:?} {b:?}");
        let c = at(1.0 / 25.0);
        assert!(c.c11.is_finite() && c.c11 > 11.7 && c.c23 > 14.6, "{c:?}");
    }

    /// CONTACT's interpolation gives the flexibility it printed: examples/tractcurv.inp case 61
    /// (a = 6.304, b = 12.61 mm, ν = 0.28, G = 82000 MPa, pure cx, which its blending leaves
    /// L1 as it is) FLX1 = 0.5491e-4 mm³/N; Table A1's own interpolation differs in the fourth
    /// digit (c11 3.740 against CONTACT's 3.7335).
    #[test]
    fn contact_interpolation_gives_contacts_printed_flexibilities() {
        let (a, b, g) = (6.304, 12.61, 82000.0);
        let c = Coefficients::from_contact(a, b, 0.28);
        let l1 = 8.0 * a / (3.0 * c.c11 * g);
        assert!((l1 - 0.5491e-4).abs() <= 0.5e-8, "{l1:e}");
        assert!((Coefficients::from_table(a, b, 0.28).c11 - c.c11).abs() > 5e-3);
        // Nodes: a = b, ν = 0.25 gives the table's 4.12, 3.67, 1.47; b/a = 0.5 the second half's row.
        let n = Coefficients::from_contact(1.0, 1.0, 0.25);
        assert!((n.c11 - 4.12).abs() < 1e-12 && (n.c22 - 3.67).abs() < 1e-12 && (n.c23 - 1.47).abs() < 1e-12);
        let h = Coefficients::from_contact(2.0, 1.0, 0.5);
        assert!((h.c11 - 6.11).abs() < 1e-12 && (h.c22 - 5.56).abs() < 1e-12 && (h.c23 - 2.96).abs() < 1e-12);
        // Below g = 0.101 the asymptotes, finite and positive on both sides.
        for (a, b) in [(0.05, 1.0), (1.0, 0.05)] {
            let s = Coefficients::from_contact(a, b, 0.28);
            assert!([s.c11, s.c22, s.c23].iter().all(|c| c.is_finite() && *c > 0.0), "{s:?}");
        }
    }

    #[test]
    fn fit_close_to_table_near_poisson_027() {
        // The fit was made for ν = 0.27; over the table's range it follows the table within ~3 %.
        for r in [0.2, 0.4766, 1.0, 2.0, 5.0] {
            let (t, f) = (Coefficients::from_table(1.0, r, 0.27), Coefficients::from_fit(1.0, r));
            assert!((f.c11 / t.c11 - 1.0).abs() < 0.03, "b/a {r}: {t:?} {f:?}");
            assert!((f.c22 / t.c22 - 1.0).abs() < 0.03, "b/a {r}: {t:?} {f:?}");
        }
    }
}
