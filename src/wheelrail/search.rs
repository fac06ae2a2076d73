//! The contact search (user guide, "Identification of contact patches"; CONTACT's
//! m_wr_locatecp): the wheel's contact locus scanned across its profile, its height over the rail
//! below each locus point (the gap function), and the interpenetration regions where the wheel
//! reaches below the rail.

use super::rail::PlacedRail;
use super::wheel::PlacedWheel;

/// Lateral step [mm] of the scan over the wheel profile.
pub const SCAN_STEP_MM: f64 = 0.02;

/// One locus point with the rail below it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocusSample {
    /// The locus point in track coordinates [mm].
    pub x_mm: f64,
    pub y_mm: f64,
    pub z_mm: f64,
    /// The wheel's reach below the rail surface [mm] (positive: interpenetration).
    pub pen_mm: f64,
    /// The rail's slope dz/dy there.
    pub rail_slope: f64,
}

/// The gap function over the wheel profile, in the order of the profile's y.
pub fn scan(wheel: &PlacedWheel, rail: &PlacedRail) -> Vec<LocusSample> {
    let [lo, hi] = wheel.curve.y_range_mm();
    let n = ((hi - lo) / SCAN_STEP_MM).ceil() as usize;
    (0..=n)
        .filter_map(|k| {
            let p = wheel.locus((lo + SCAN_STEP_MM * k as f64).min(hi))?;
            let z_rail = rail.z_mm(p.y)?;
            Some(LocusSample { x_mm: p.x, y_mm: p.y, z_mm: p.z, pen_mm: p.z - z_rail, rail_slope: rail.dz_dy(p.y)? })
        })
        .collect()
}

/// The deepest reach of the wheel below the rail [mm] (negative: the smallest gap).
pub fn deepest_mm(samples: &[LocusSample]) -> Option<f64> {
    samples.iter().map(|s| s.pen_mm).reduce(f64::max)
}

/// The interpenetration regions: the maximal runs of samples with pen > 0.
pub fn regions(samples: &[LocusSample]) -> Vec<&[LocusSample]> {
    samples.split(|s| s.pen_mm <= 0.0).filter(|r| !r.is_empty()).collect()
}
