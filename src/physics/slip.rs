//! The rigid slip of the contact per unit rolling distance (Kalker 1990, Eq. 1.6 with the
//! creepages of thesis Eq. 2.21): `w(x, y) = (cx − cs·y, cy + cs·x)`. Every solver takes its
//! rigid slip from here: the exact-theory solver as `w·dq` over one time step, the brush models
//! with each component divided by its flexibility (thesis Eq. 3.4).

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

    /// Slip per unit rolling distance at (x, y) [mm]: `(cx − cs y, cy + cs x)`.
    #[inline]
    pub fn at(&self, x_mm: f64, y_mm: f64) -> (f64, f64) {
        (self.cx - self.cs * y_mm, self.cy + self.cs * x_mm)
    }

    /// The slip rolled from x0 to x1 along row y, integrated exactly (thesis Eq. 2.34).
    #[inline]
    pub fn between(&self, x0_mm: f64, x1_mm: f64, y_mm: f64) -> (f64, f64) {
        (
            (self.cx - self.cs * y_mm) * (x1_mm - x0_mm),
            self.cy * (x1_mm - x0_mm) + 0.5 * self.cs * (x1_mm * x1_mm - x0_mm * x0_mm),
        )
    }
}
