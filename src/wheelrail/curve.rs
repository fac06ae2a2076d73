//! A profile as the contact search uses it: the height z [mm] (CONTACT's z, pointing down into the
//! rail) as a function of the lateral position y [mm] in the profile's own frame (user guide,
//! "Form as needed by CONTACT"). Profiles read from files and the closed forms below both give it.

use std::fmt::Debug;

/// z(y) with its slope; `None` outside the profile's lateral range.
pub trait Curve: Send + Sync + Debug {
    /// z [mm] at y [mm].
    fn z_mm(&self, y_mm: f64) -> Option<f64>;
    /// dz/dy at y.
    fn dz_dy(&self, y_mm: f64) -> Option<f64>;
    /// The lateral range [y_min, y_max] [mm] the curve is defined on.
    fn y_range_mm(&self) -> [f64; 2];
    /// z and dz/dy at y together (one search where a curve must find its point first).
    fn z_and_slope(&self, y_mm: f64) -> Option<(f64, f64)> {
        Some((self.z_mm(y_mm)?, self.dz_dy(y_mm)?))
    }
    /// The profile's points (y, z) [mm] where it is made of points (a profile file), `None` for a
    /// closed form.
    fn points_mm(&self) -> Option<Vec<[f64; 2]>> {
        None
    }
    /// The placements of this curve as a rail made so far ([`super::RailPlacements`]), where the
    /// curve keeps them (a profile, with its data); `None`: each case places it afresh.
    fn placements(&self) -> Option<&super::RailPlacements> {
        None
    }
    /// The spline's parameter s [mm] (CONTACT's arc length along the profile) at y, where the
    /// curve is a profile's spline; `None` for a closed form.
    fn s_at_y(&self, _y_mm: f64) -> Option<f64> {
        None
    }
    /// The points CONTACT computes a wheel's contact locus at (its `compute_wr_locus`: the
    /// profile's uni-valued part, with the spline's slope at each), where the curve is a wheel
    /// profile's spline; `None` for a closed form (its locus is exact).
    fn locus_nodes(&self) -> Option<Vec<super::locus::Node>> {
        None
    }
    /// The spline's point at its parameter s [mm] with its derivatives, where the curve is a
    /// profile's spline; `None` for a closed form or outside the spline (CONTACT's
    /// `spline_get_xyz_at_s`, the conformal approach's curved reference).
    fn spline_point(&self, _s_mm: f64) -> Option<super::profile::ProfilePoint> {
        None
    }
}

/// A circular arc `z = z0 ± (R − √(R² − (y − yc)²))` over `|y − yc| ≤ half_width`: convex (a rail
/// crown, z grows away from the top) or, with `concave`, a hollow (a wheel tread of lateral
/// radius R seen from the rail: z falls away from yc). Closed form for tests and Hertz's case.
#[derive(Debug, Clone, PartialEq)]
pub struct Arc {
    pub radius_mm: f64,
    pub centre_y_mm: f64,
    pub half_width_mm: f64,
    /// Hollow instead of crowned.
    pub concave: bool,
}

impl Arc {
    fn sign(&self) -> f64 {
        if self.concave {
            -1.0
        } else {
            1.0
        }
    }
    fn inside(&self, y_mm: f64) -> Option<f64> {
        let u = y_mm - self.centre_y_mm;
        (u.abs() <= self.half_width_mm).then_some(u)
    }
}

impl Curve for Arc {
    fn z_mm(&self, y_mm: f64) -> Option<f64> {
        let u = self.inside(y_mm)?;
        let r = self.radius_mm;
        Some(self.sign() * (r - (r * r - u * u).sqrt()))
    }
    fn dz_dy(&self, y_mm: f64) -> Option<f64> {
        let u = self.inside(y_mm)?;
        let r = self.radius_mm;
        Some(self.sign() * u / (r * r - u * u).sqrt())
    }
    fn y_range_mm(&self) -> [f64; 2] {
        [self.centre_y_mm - self.half_width_mm, self.centre_y_mm + self.half_width_mm]
    }
}

/// A straight line `z = z0 + slope · y` over a lateral range (a cone's tread, a flat rail).
#[derive(Debug, Clone, PartialEq)]
pub struct Line {
    pub z0_mm: f64,
    pub slope: f64,
    pub y_range_mm: [f64; 2],
}

impl Curve for Line {
    fn z_mm(&self, y_mm: f64) -> Option<f64> {
        let [lo, hi] = self.y_range_mm;
        (lo..=hi).contains(&y_mm).then_some(self.z0_mm + self.slope * y_mm)
    }
    fn dz_dy(&self, y_mm: f64) -> Option<f64> {
        self.z_mm(y_mm).map(|_| self.slope)
    }
    fn y_range_mm(&self) -> [f64; 2] {
        self.y_range_mm
    }
}

/// A profile read from a file: CONTACT's spline through its cleaned points.
impl Curve for super::profile::Profile {
    fn z_mm(&self, y_mm: f64) -> Option<f64> {
        self.z_at(y_mm)
    }
    fn dz_dy(&self, y_mm: f64) -> Option<f64> {
        self.slope_at(y_mm)
    }
    fn y_range_mm(&self) -> [f64; 2] {
        let (lo, hi) = self.y_range();
        [lo, hi]
    }
    fn z_and_slope(&self, y_mm: f64) -> Option<(f64, f64)> {
        self.z_and_slope_at(y_mm)
    }
    fn points_mm(&self) -> Option<Vec<[f64; 2]>> {
        Some(self.y_mm().iter().zip(self.z_mm()).map(|(&y, &z)| [y, z]).collect())
    }
    fn s_at_y(&self, y_mm: f64) -> Option<f64> {
        self.point_at_y(y_mm).map(|p| p.s_mm)
    }
    fn spline_point(&self, s_mm: f64) -> Option<super::profile::ProfilePoint> {
        self.point_at_s(s_mm)
    }
    fn placements(&self) -> Option<&super::RailPlacements> {
        Some(self.kept_placements())
    }
    fn locus_nodes(&self) -> Option<Vec<super::locus::Node>> {
        self.kept_locus_nodes(|| {
            if self.kind() != super::profile::ProfileKind::Wheel {
                return None;
            }
            let range = self.uni_valued_range().ok()?;
            let s = self.s_mm();
            range
                .map(|i| {
                    let p = self.point_at_s(s[i])?;
                    let dz_dy = p.dz_ds / p.dy_ds.min(-1e-6);
                    Some(super::locus::Node { s_mm: s[i], y_mm: p.y_mm, z_mm: p.z_mm, dz_dy })
                })
                .collect()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_arc_has_its_radius_and_slope() {
        let a = Arc { radius_mm: 300.0, centre_y_mm: 2.0, half_width_mm: 30.0, concave: false };
        assert_eq!(a.z_mm(2.0), Some(0.0));
        let z = a.z_mm(12.0).unwrap();
        assert!((z - (300.0 - (300.0f64 * 300.0 - 100.0).sqrt())).abs() < 1e-15);
        let h = 1e-5;
        let fd = (a.z_mm(12.0 + h).unwrap() - a.z_mm(12.0 - h).unwrap()) / (2.0 * h);
        assert!((a.dz_dy(12.0).unwrap() - fd).abs() < 1e-9);
        assert_eq!(a.z_mm(40.0), None);
    }
}
