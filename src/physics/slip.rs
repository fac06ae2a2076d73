//! The rigid slip of the contact per unit rolling distance, in CONTACT's convention (Kalker 1990,
//! Eq. 1.6; CONTACT user guide, CKSI, CETA, CPHI): `w = (cx − cs·y, cy + cs·x_C)`, where `x_C`
//! is CONTACT's x, along which the contact rolls (material enters at `x_C = +a`).
//!
//! The grid of this crate numbers elements from the leading edge: its `x` runs with the material,
//! `x = −x_C` (see [`crate::physics::Grid`]). In grid coordinates the rigid slip is therefore
//! `w = (cx − cs·y, cy − cs·x)`: a positive spin gives a positive lateral slip, and so a positive
//! fy, ahead of the centre line, as a positive cy does (Kalker's C23 > 0). Every solver takes its
//! rigid slip from here: the exact-theory solver as `w·dq` over one time step, the brush models
//! with each component divided by its flexibility (thesis Eq. 3.4, converted to this convention).

/// Creepages (cx, cy [-], spin cs [1/mm]), or the same divided by flexibilities.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidSlip {
    pub cx: f64,
    pub cy: f64,
    pub cs: f64,
}

impl RigidSlip {
    pub fn new(cx: f64, cy: f64, cs_per_mm: f64) -> Self {
        RigidSlip { cx, cy, cs: cs_per_mm }
    }

    /// Each component divided by its flexibility (`cx/L1, cy/L2, cs/L3`, thesis Eq. 3.4).
    pub fn over_flexibilities(&self, l1: f64, l2: f64, l3: f64) -> Self {
        RigidSlip { cx: self.cx / l1, cy: self.cy / l2, cs: self.cs / l3 }
    }

    /// The slip as an affine field in grid coordinates, `[wx0, dwx/dy, wy0, dwy/dx]`:
    /// `wx = wx0 + (dwx/dy)·y`, `wy = wy0 + (dwy/dx)·x`.
    #[inline]
    pub fn affine(&self) -> [f64; 4] {
        [self.cx, -self.cs, self.cy, -self.cs]
    }

    /// Slip per unit rolling distance at grid point (x, y) [mm]: `(cx − cs y, cy − cs x)`.
    #[inline]
    pub fn at(&self, x_mm: f64, y_mm: f64) -> (f64, f64) {
        let [wx0, wx_y, wy0, wy_x] = self.affine();
        (wx0 + wx_y * y_mm, wy0 + wy_x * x_mm)
    }

    /// The slip rolled from grid x0 to x1 along row y, integrated exactly (thesis Eq. 2.34).
    #[inline]
    pub fn between(&self, x0_mm: f64, x1_mm: f64, y_mm: f64) -> (f64, f64) {
        let [wx0, wx_y, wy0, wy_x] = self.affine();
        ((wx0 + wx_y * y_mm) * (x1_mm - x0_mm), wy0 * (x1_mm - x0_mm) + 0.5 * wy_x * (x1_mm * x1_mm - x0_mm * x0_mm))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spin_slip_follows_contact_convention() {
        // CONTACT: w_y = CETA + CPHI·x_C. Grid x = −x_C, so a point at x_C = +2 mm is x = −2 mm.
        let w = RigidSlip::new(0.0, 0.0, 0.001);
        let (_, wy) = w.at(-2.0, 0.0);
        assert_eq!(wy, 0.001 * 2.0);
        let (wx, _) = w.at(0.0, 3.0);
        assert_eq!(wx, -0.001 * 3.0);
        // The exact integral over [x0, x1] is the mean of `at` at the ends times the length.
        let (ix, iy) = w.between(-1.0, 0.5, 3.0);
        let (a, b) = (w.at(-1.0, 3.0), w.at(0.5, 3.0));
        assert!((ix - 1.5 * 0.5 * (a.0 + b.0)).abs() < 1e-15 && (iy - 1.5 * 0.5 * (a.1 + b.1)).abs() < 1e-15);
    }
}
