//! Hertz's normal contact (thesis ch. 2.2): semi-axes and peak pressure from the radii, and the
//! undeformed distance that yields prescribed semi-axes.

use super::material::Material;
use super::pressure::PressureShape;
use ellip::{ellipke, elliprd, elliprf};
use std::f64::consts::PI;

/// Principal radii of wheel and rail [mm] (thesis Fig. 2.4; the rail is straight along x).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Radii {
    /// Wheel rolling radius R_wx.
    pub r_wx_mm: f64,
    /// Wheel transverse radius R_wy.
    pub r_wy_mm: f64,
    /// Rail transverse radius R_ry.
    pub r_ry_mm: f64,
}

/// A Hertzian contact ellipse under a load.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct HertzContact {
    /// Semi-axis along x, the rolling direction [mm].
    pub a_mm: f64,
    /// Semi-axis along y [mm].
    pub b_mm: f64,
    /// Normal load [N].
    pub fn_n: f64,
}

/// Failure of the Hertz solve (only for inputs the scene validation lets through by mistake).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum HertzError {
    /// A concave or flat contact (or a load that is not a positive number).
    #[error("Hertz: curvatures A = {curv_x} /mm and B = {curv_y} /mm must be positive (convex contact)")]
    NotConvex { curv_x: f64, curv_y: f64 },
    /// Larger over smaller curvature: not a number ≥ 1.
    #[error("Hertz: curvature ratio {ratio} must be finite and >= 1")]
    Ratio { ratio: f64 },
    /// An ellipse more slender than the bisection resolves.
    #[error("Hertz: curvature ratio {ratio} is beyond b/a = 3e-8")]
    TooSlender { ratio: f64 },
}

impl HertzContact {
    /// Peak of the ellipsoidal (Hertz) pressure `p0 = 3 FN / (2 π a b)` [MPa] (thesis Eq. 2.17).
    pub fn p0_mpa(&self) -> f64 {
        PressureShape::Ellipsoidal.peak_mpa(self.fn_n, self.a_mm, self.b_mm)
    }

    /// The same ellipse at another load: both semi-axes scale with `(FN'/FN)^(1/3)` (Hertz).
    pub fn at_load(&self, fn_n: f64) -> HertzContact {
        let s = (fn_n / self.fn_n).cbrt();
        HertzContact { a_mm: self.a_mm * s, b_mm: self.b_mm * s, fn_n }
    }

    /// Semi-axes from the radii, the load and the material (thesis Eq. 2.13–2.19): the ratio
    /// `B/A = ((a/b)² E(e) − K(e)) / (K(e) − E(e))` fixes the eccentricity, Eq. 2.13 with
    /// `A = M/(π E*)` the size. K and E are the complete elliptic integrals of parameter `m = e²`.
    pub fn from_radii(radii: &Radii, fn_n: f64, material: &Material) -> Result<Self, HertzError> {
        if !(fn_n.is_finite() && fn_n > 0.0) {
            let (curv_x, curv_y) = HertzShape::curvatures(radii);
            return Err(HertzError::NotConvex { curv_x, curv_y });
        }
        HertzShape::of(radii)?.at_load(fn_n, material)
    }

    /// Curvatures (A, B) [1/mm] of the undeformed distance `h = A x² + B y²` for which Hertz's
    /// theory gives exactly this ellipse under this load (inverse of Eq. 2.13–2.14, written with
    /// Carlson's R_D so that a = b is regular): `A = FN R_D(0, b², a²)/(2π E*)`, B likewise.
    pub fn undeformed_curvatures(&self, material: &Material) -> (f64, f64) {
        let e_star = material.e_star_mpa();
        let (a2, b2) = (self.a_mm * self.a_mm, self.b_mm * self.b_mm);
        let rd = |x: f64, y: f64, z: f64| elliprd(x, y, z).unwrap_or(f64::NAN);
        let c = self.fn_n / (2.0 * PI * e_star);
        (c * rd(0.0, b2, a2), c * rd(0.0, a2, b2))
    }

    /// Tangential stiffness (kx, ky) [N/mm] of the contact in full adhesion: the tangential force
    /// over the rigid shift of one body against the other under Mindlin's no-slip traction
    /// `q = Q/(2πab) (1 − x²/a² − y²/b²)^(−1/2)` (Mindlin 1949; Johnson 1985, ch. 7), whose surface displacement
    /// is uniform over the ellipse. Integrating Cerruti's point-force displacement
    /// `u_x = Q ((1 − ν)/r + ν x²/r³)/(2π G)` (Johnson 1985, ch. 3) over it and doubling for two
    /// identical bodies: `δx/Q = ((1 − ν) R_F(0, a², b²) + ν a² R_D(0, b², a²)/3)/(π G)`, likewise
    /// y with a ↔ b (Carlson's R_F, R_D). A circle gives Mindlin's `k = 4 G a/(2 − ν)`.
    pub fn tangential_stiffness_n_mm(&self, material: &Material) -> (f64, f64) {
        let (g, nu) = (material.g_mpa, material.poisson);
        let (a2, b2) = (self.a_mm * self.a_mm, self.b_mm * self.b_mm);
        let rf = elliprf(0.0, a2, b2).unwrap_or(f64::NAN);
        let rd = |x: f64, y: f64, z: f64| elliprd(x, y, z).unwrap_or(f64::NAN);
        let compliance = |c2: f64, rd_value: f64| ((1.0 - nu) * rf + nu * c2 * rd_value / 3.0) / (PI * g);
        (1.0 / compliance(a2, rd(0.0, b2, a2)), 1.0 / compliance(b2, rd(0.0, a2, b2)))
    }
    /// Hertz's approach δ [mm] of this ellipse under its load: δ = p0 b K(e)/E* (Johnson 1985,
    /// §4.2, a ≥ b), written with Carlson's R_F as `δ = 3 FN R_F(0, a², b²)/(2π E*)`,
    /// symmetric in a and b; a circle gives δ = a²/R (Johnson §4.2).
    pub fn approach_mm(&self, material: &Material) -> f64 {
        let rf = elliprf(0.0, self.a_mm * self.a_mm, self.b_mm * self.b_mm).unwrap_or(f64::NAN);
        3.0 * self.fn_n * rf / (2.0 * PI * material.e_star_mpa())
    }

    /// The ellipse of semi-axes `a_mm`, `b_mm` whose approach is `pen_mm` (CONTACT IPOTCN = −3,
    /// N = 0: the curvatures follow): FN = 2π E* δ/(3 R_F(0, a², b²)), [`Self::approach_mm`] inverted.
    pub fn with_approach(a_mm: f64, b_mm: f64, pen_mm: f64, material: &Material) -> HertzContact {
        let unit = HertzContact { a_mm, b_mm, fn_n: 1.0 }.approach_mm(material);
        HertzContact { a_mm, b_mm, fn_n: pen_mm / unit }
    }

    /// The ellipse of the radii whose approach is `pen_mm` (CONTACT IPOTCN = −1, −2 with N = 0):
    /// δ ∝ FN^(2/3) at fixed curvatures, so FN = (δ/δ₁)^(3/2) with δ₁ the approach under 1 N.
    pub fn from_radii_and_approach(radii: &Radii, pen_mm: f64, material: &Material) -> Result<Self, HertzError> {
        HertzShape::of(radii)?.at_approach(pen_mm, material)
    }
}

/// The shape Hertz's theory gives a pair of curvatures (the eccentricity, thesis Eq. 2.19),
/// found once and scaled to any load or approach ([`HertzContact::from_radii`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzShape {
    /// Curvatures A, B [1/mm].
    curv_x: f64,
    curv_y: f64,
    /// m = e² and (K − E)/m of it.
    m: f64,
    k_minus_e_over_m: f64,
}

impl HertzShape {
    /// The shape of `radii`'s curvatures `A = 1/(2 R_wx)`, `B = (1/R_wy + 1/R_ry)/2`.
    pub fn of(radii: &Radii) -> Result<Self, HertzError> {
        let (curv_x, curv_y) = Self::curvatures(radii);
        if !(curv_x > 0.0 && curv_y > 0.0) {
            return Err(HertzError::NotConvex { curv_x, curv_y });
        }
        // Solve with the long axis along the direction of the smaller curvature, then map back.
        let (small, large) = if curv_y >= curv_x { (curv_x, curv_y) } else { (curv_y, curv_x) };
        let m = solve_eccentricity(large / small)?;
        let (k_minus_e_over_m, _) = complete_ke_over_m(m);
        Ok(HertzShape { curv_x, curv_y, m, k_minus_e_over_m })
    }

    /// A = 1/(2 R_wx) (the rail straight: 1/R_rx = 0), B = (1/R_wy + 1/R_ry)/2 [1/mm].
    fn curvatures(radii: &Radii) -> (f64, f64) {
        (0.5 / radii.r_wx_mm, 0.5 * (1.0 / radii.r_wy_mm + 1.0 / radii.r_ry_mm))
    }

    /// The ellipse under load `fn_n` [N] (thesis Eq. 2.13).
    pub fn at_load(&self, fn_n: f64, material: &Material) -> Result<HertzContact, HertzError> {
        let (curv_x, curv_y) = (self.curv_x, self.curv_y);
        if !(fn_n.is_finite() && fn_n > 0.0) {
            return Err(HertzError::NotConvex { curv_x, curv_y });
        }
        let e_star = material.e_star_mpa();
        let small = if curv_y >= curv_x { curv_x } else { curv_y };
        // Eq. 2.13: A = p0 b (K − E) / (E* e² a²) with p0 = 3FN/(2πab)  ⇒  a³ = 3FN (K−E)/(2π E* e² A).
        let long = (3.0 * fn_n * self.k_minus_e_over_m / (2.0 * PI * e_star * small)).cbrt();
        let short = long * (1.0 - self.m).sqrt();
        let (a_mm, b_mm) = if curv_y >= curv_x { (long, short) } else { (short, long) };
        Ok(HertzContact { a_mm, b_mm, fn_n })
    }

    /// The approach under 1 N [mm]: δ ∝ FN^(2/3) at fixed curvatures ([`HertzContact::approach_mm`]).
    pub fn unit_approach_mm(&self, material: &Material) -> Result<f64, HertzError> {
        Ok(self.at_load(1.0, material)?.approach_mm(material))
    }

    /// The ellipse whose approach is `pen_mm`: FN = (δ/δ₁)^(3/2) with δ₁ the approach under 1 N.
    pub fn at_approach(&self, pen_mm: f64, material: &Material) -> Result<HertzContact, HertzError> {
        self.at_unit_approach(pen_mm, self.unit_approach_mm(material)?, material)
    }

    /// [`Self::at_approach`] with δ₁ given ([`Self::unit_approach_mm`], found once per shape).
    pub fn at_unit_approach(&self, pen_mm: f64, unit_mm: f64, material: &Material) -> Result<HertzContact, HertzError> {
        self.at_load((pen_mm / unit_mm).powf(1.5), material)
    }
}

/// `((K − E)/m, ((1/(1−m)) E − K)/m)` for parameter m = e² ∈ [0, 1): the two brackets of
/// Eq. 2.13–2.14 divided by e². For small m the Legendre forms cancel, so there the exact
/// identities `(K−E)/m = R_D(0, 1−m, 1)/3` and `(E/(1−m) − K)/m = R_D(0, 1, 1−m)/3` are used.
fn complete_ke_over_m(m: f64) -> (f64, f64) {
    if m < 1e-3 {
        let rd = |y: f64, z: f64| elliprd(0.0, y, z).unwrap_or(f64::NAN) / 3.0;
        (rd(1.0 - m, 1.0), rd(1.0, 1.0 - m))
    } else {
        let (k, e) = ellipke(m).unwrap_or((f64::NAN, f64::NAN));
        ((k - e) / m, (e / (1.0 - m) - k) / m)
    }
}

/// Eq. 2.19: find m = e² with `((a/b)² E − K)/(K − E) = ratio` (ratio ≥ 1), by bisection.
fn solve_eccentricity(ratio: f64) -> Result<f64, HertzError> {
    if !ratio.is_finite() || ratio < 1.0 {
        return Err(HertzError::Ratio { ratio });
    }
    let f = |m: f64| {
        let (ke, ek) = complete_ke_over_m(m);
        ek / ke - ratio
    };
    let (mut lo, mut hi) = (0.0_f64, 1.0 - 1e-15);
    if f(hi) < 0.0 {
        return Err(HertzError::TooSlender { ratio });
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        let last = (lo, hi);
        if f(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
        // Where lo and hi are neighbouring doubles (m > 1/2) mid is one of them: a step that
        // changes neither would repeat unchanged to the last one.
        if hi - lo < 1e-16 || (lo, hi) == last {
            break;
        }
    }
    Ok(0.5 * (lo + hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn thesis() -> (Radii, Material) {
        (Radii { r_wx_mm: 575.0, r_wy_mm: 500.0, r_ry_mm: 300.0 }, Material::from_e(210000.0, 0.28))
    }

    /// Thesis 4.1.1: a = 8.56, b = 4.08 mm (rounded); the exact two-body solution is 8.556 / 4.070.
    #[test]
    fn thesis_ellipse_from_radii() {
        let (r, mat) = thesis();
        let h = HertzContact::from_radii(&r, 100_000.0, &mat).unwrap();
        assert!((h.a_mm / 8.556 - 1.0).abs() < 0.003, "a = {}", h.a_mm);
        assert!((h.b_mm / 4.070 - 1.0).abs() < 0.003, "b = {}", h.b_mm);
    }

    /// The curvatures that give an ellipse, fed back through Eq. 2.19 and 2.13, give it again.
    #[test]
    fn curvatures_round_trip() {
        let mat = Material::from_g(82000.0, 0.28);
        for (a, b) in [(8.56, 4.08), (5.888, 5.888), (3.0, 9.0), (10.0, 0.4)] {
            let h = HertzContact { a_mm: a, b_mm: b, fn_n: 1e5 };
            let (ca, cb) = h.undeformed_curvatures(&mat);
            // A = 1/(2 R_wx), B = (1/R_wy + 1/R_ry)/2 with R_ry → ∞.
            let r = Radii { r_wx_mm: 0.5 / ca, r_wy_mm: 0.5 / cb, r_ry_mm: f64::INFINITY };
            let back = HertzContact::from_radii(&r, 1e5, &mat).unwrap();
            assert!((back.a_mm / a - 1.0).abs() < 1e-9, "{a} {b}: {back:?}");
            assert!((back.b_mm / b - 1.0).abs() < 1e-9, "{a} {b}: {back:?}");
        }
    }

    /// Circle: a³ = 3 FN R / (4 E*) with R = 1/(2A) (Johnson 1985, Eq. 4.22).
    #[test]
    fn circle_limit() {
        let mat = Material::from_g(82000.0, 0.28);
        let r = Radii { r_wx_mm: 400.0, r_wy_mm: 400.0, r_ry_mm: f64::INFINITY };
        let h = HertzContact::from_radii(&r, 1e5, &mat).unwrap();
        let a = (3.0 * 1e5 * 400.0 / (4.0 * mat.e_star_mpa())).cbrt();
        assert!((h.a_mm / a - 1.0).abs() < 1e-9 && (h.b_mm / a - 1.0).abs() < 1e-9, "{h:?} vs {a}");
    }

    /// The tangential stiffness against the defining integral, `δx/Q = ∫₀^2π R(θ) ((1 − ν) +
    /// ν cos²θ) dθ / (4π G a b)` with the ellipse's radius R(θ) (Cerruti's displacement under
    /// Mindlin's traction, in polar coordinates), summed by the midpoint rule on 20000 angles; and
    /// Mindlin's circle `k = 4 G a/(2 − ν)` (Johnson 1985, ch. 7).
    #[test]
    fn tangential_stiffness_against_its_integral() {
        let mat = Material::from_g(82000.0, 0.28);
        for (a, b) in [(8.56, 4.08), (4.0, 8.0), (10.0, 2.0), (5.0, 5.0)] {
            let (kx, ky) = HertzContact { a_mm: a, b_mm: b, fn_n: 1e5 }.tangential_stiffness_n_mm(&mat);
            let n = 20000;
            let (mut ix, mut iy) = (0.0, 0.0);
            for k in 0..n {
                let t = (k as f64 + 0.5) * 2.0 * PI / n as f64;
                let r = a * b / (b * b * t.cos().powi(2) + a * a * t.sin().powi(2)).sqrt();
                ix += r * (0.72 + 0.28 * t.cos().powi(2));
                iy += r * (0.72 + 0.28 * t.sin().powi(2));
            }
            let scale = 2.0 * PI / n as f64 / (4.0 * PI * mat.g_mpa * a * b);
            assert!((kx * ix * scale - 1.0).abs() < 1e-10, "{a} x {b}: kx {kx}");
            assert!((ky * iy * scale - 1.0).abs() < 1e-10, "{a} x {b}: ky {ky}");
        }
        let (kx, ky) = HertzContact { a_mm: 5.0, b_mm: 5.0, fn_n: 1e5 }.tangential_stiffness_n_mm(&mat);
        let mindlin = 4.0 * 82000.0 * 5.0 / (2.0 - 0.28);
        assert!((kx / mindlin - 1.0).abs() < 1e-13 && (ky / mindlin - 1.0).abs() < 1e-13, "{kx} {ky} {mindlin}");
    }

    /// The small-m identities agree with the Legendre forms where both are accurate.
    #[test]
    fn identities_match_legendre() {
        for m in [2e-3_f64, 1e-2, 0.3] {
            let (k, e) = ellipke(m).unwrap();
            let rd1 = elliprd(0.0, 1.0 - m, 1.0).unwrap() / 3.0;
            let rd2 = elliprd(0.0, 1.0, 1.0 - m).unwrap() / 3.0;
            assert!(((k - e) / m / rd1 - 1.0).abs() < 1e-9);
            assert!(((e / (1.0 - m) - k) / m / rd2 - 1.0).abs() < 1e-9);
        }
    }

    /// Johnson 1985 §4.2 (circle): δ = a²/R and FN = (4/3) E* R^(1/2) δ^(3/2).
    #[test]
    fn approach_of_a_circle_is_johnsons() {
        let mat = Material::from_g(82000.0, 0.28);
        let r_mm: f64 = 400.0;
        let radii = Radii { r_wx_mm: r_mm, r_wy_mm: r_mm, r_ry_mm: f64::INFINITY };
        let h = HertzContact::from_radii(&radii, 1e5, &mat).unwrap();
        let delta = h.a_mm * h.a_mm / r_mm;
        assert!((h.approach_mm(&mat) / delta - 1.0).abs() < 1e-12, "{} vs {delta}", h.approach_mm(&mat));
        let pen: f64 = 0.05;
        let fn_n = 4.0 / 3.0 * mat.e_star_mpa() * r_mm.sqrt() * pen.powf(1.5);
        let back = HertzContact::from_radii_and_approach(&radii, pen, &mat).unwrap();
        assert!((back.fn_n / fn_n - 1.0).abs() < 1e-12, "{} vs {fn_n}", back.fn_n);
        assert!((back.a_mm / (pen * r_mm).sqrt() - 1.0).abs() < 1e-9, "{back:?}");
    }

    /// An ellipse: δ = p0 b K(e)/E*, e² = 1 − b²/a² (Johnson 1985, §4.2) with Legendre's K;
    /// [`HertzContact::with_approach`] inverts it, and its curvatures give the ellipse back.
    #[test]
    fn approach_of_an_ellipse_is_johnsons() {
        let mat = Material::from_g(82000.0, 0.28);
        for (a, b) in [(8.56, 4.08), (4.25, 7.0), (3.0, 9.0)] {
            let h = HertzContact { a_mm: a, b_mm: b, fn_n: 42000.0 };
            let (long, short) = if a >= b { (a, b) } else { (b, a) };
            let (k, _) = ellipke(1.0 - short * short / (long * long)).unwrap();
            let delta = h.p0_mpa() * short * k / mat.e_star_mpa();
            assert!((h.approach_mm(&mat) / delta - 1.0).abs() < 1e-12, "{a} {b}: {} vs {delta}", h.approach_mm(&mat));
            let back = HertzContact::with_approach(a, b, delta, &mat);
            assert!((back.fn_n / 42000.0 - 1.0).abs() < 1e-12, "{back:?}");
        }
    }
}
