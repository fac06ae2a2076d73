//! The wheel of a wheelset in the track (user guide, "Wheelset geometry" and "Wheelset degrees of
//! freedom"): the profile origin at `(0, FBDIST/2 − FBPOS, NOMRAD)` from the wheelset centre
//! (right wheel), the centre at `(0, y_ws, z_ws − NOMRAD)` in track coordinates (z down), turned by
//! roll then yaw (pitch does not move a round wheel's surface). A surface point at profile
//! position y_w lies at radius `NOMRAD + z_w(y_w)` from the axle.

use super::curve::Curve;
use super::locus::LocusSpline;
use nalgebra::{Point3, Rotation3, Vector3};

/// FBDIST, FBPOS, NOMRAD [mm].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelsetGeometry {
    pub flange_back_distance_mm: f64,
    pub flange_back_position_mm: f64,
    pub nominal_radius_mm: f64,
}

/// The wheelset's position and orientation in track coordinates (Y, Z, ROLL, YAW).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose {
    pub y_mm: f64,
    pub z_mm: f64,
    pub roll_rad: f64,
    pub yaw_rad: f64,
}

/// The wheelset's velocities (VS, VY, VZ, VROLL, VYAW, VPITCH).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Velocity {
    pub vs_mm_s: f64,
    pub vy_mm_s: f64,
    pub vz_mm_s: f64,
    pub vroll_rad_s: f64,
    pub vyaw_rad_s: f64,
    pub vpitch_rad_s: f64,
}

/// The right wheel's surface placed in the track.
#[derive(Debug)]
pub struct PlacedWheel<'a> {
    pub curve: &'a dyn Curve,
    /// Lateral position of the profile origin in wheelset coordinates [mm].
    pub y_offset_mm: f64,
    pub nominal_radius_mm: f64,
    /// The wheelset centre in track coordinates.
    pub centre: Point3<f64>,
    /// Wheelset → track orientation: roll about x, then yaw about the rolled z.
    pub rotation: Rotation3<f64>,
    pub roll_rad: f64,
    pub yaw_rad: f64,
    /// CONTACT's spline through the locus at the profile's points (a profile file; `None`: the
    /// exact locus of a closed form).
    pub locus_spline: Option<LocusSpline>,
}

impl<'a> PlacedWheel<'a> {
    pub fn place(curve: &'a dyn Curve, g: &WheelsetGeometry, pose: &Pose) -> PlacedWheel<'a> {
        let rotation = Rotation3::from_axis_angle(&Vector3::x_axis(), pose.roll_rad)
            * Rotation3::from_axis_angle(&Vector3::z_axis(), pose.yaw_rad);
        let mut wheel = PlacedWheel {
            curve,
            y_offset_mm: 0.5 * g.flange_back_distance_mm - g.flange_back_position_mm,
            nominal_radius_mm: g.nominal_radius_mm,
            centre: Point3::new(0.0, pose.y_mm, pose.z_mm - g.nominal_radius_mm),
            rotation,
            roll_rad: pose.roll_rad,
            yaw_rad: pose.yaw_rad,
            locus_spline: None,
        };
        wheel.locus_spline =
            LocusSpline::build(curve, &rotation, wheel.y_offset_mm, g.nominal_radius_mm, &|v| wheel.to_track(v));
        wheel
    }

    /// The contact locus at profile position y_w: the point of that circle of the wheel whose
    /// surface normal has no x component in the track (it can touch the prismatic rail there):
    /// `sin θ = −z_w'(y_w) tan ψ` (CONTACT's contact locus, Vollebregt 2020 "wr geometry").
    pub fn locus(&self, y_w_mm: f64) -> Option<Point3<f64>> {
        let (z, slope) = self.curve.z_and_slope(y_w_mm)?;
        let rho = self.nominal_radius_mm + z;
        let (sin_yaw, cos_yaw) = self.yaw_rad.sin_cos();
        let sin_t = (-slope * sin_yaw / cos_yaw).clamp(-0.999, 0.999);
        let cos_t = (1.0 - sin_t * sin_t).sqrt();
        Some(self.to_track(Vector3::new(rho * sin_t, self.y_offset_mm + y_w_mm, rho * cos_t)))
    }

    /// The locus point above track y: on CONTACT's locus spline where the wheel is a profile
    /// file ([`LocusSpline`]), else the profile position y_w whose exact locus point lies at y
    /// (secant steps from the unturned wheel's y_w), if the profile reaches it.
    pub fn locus_at_track_y(&self, y_mm: f64) -> Option<Point3<f64>> {
        if let Some(spline) = &self.locus_spline {
            return spline.at_y(y_mm);
        }
        let lateral = |y_w: f64| self.locus(y_w).map(|p| p.y - y_mm);
        let [lo, hi] = self.curve.y_range_mm();
        let start = (y_mm - self.centre.y - self.y_offset_mm).clamp(lo, hi);
        let (mut w0, mut f0) = (start, lateral(start)?);
        let mut w1 = (w0 - f0).clamp(lo, hi);
        for _ in 0..30 {
            let f1 = lateral(w1)?;
            if f1.abs() < 1e-12 || f1 == f0 {
                break;
            }
            let w2 = (w1 - f1 * (w1 - w0) / (f1 - f0)).clamp(lo, hi);
            (w0, f0, w1) = (w1, f1, w2);
        }
        let p = self.locus(w1)?;
        ((p.y - y_mm).abs() < 1e-9).then_some(p)
    }

    /// A wheelset-frame vector from the centre as a track point.
    pub(super) fn to_track(&self, p_ws: Vector3<f64>) -> Point3<f64> {
        self.centre + self.rotation * p_ws
    }

    /// A track point in the wheelset frame (from the centre).
    pub(super) fn to_wheelset(&self, p: &Point3<f64>) -> Vector3<f64> {
        self.rotation.inverse() * (p - self.centre)
    }

    /// How far a track point lies outside the wheel [mm]: its distance from the axle less the
    /// wheel's radius at its lateral place (negative inside the wheel).
    fn outside_mm(&self, p: &Point3<f64>) -> Option<f64> {
        let q = self.to_wheelset(p);
        let radius = self.nominal_radius_mm + self.curve.z_mm(q.y - self.y_offset_mm)?;
        Some((q.x * q.x + q.z * q.z).sqrt() - radius)
    }

    /// Distance t [mm] along the unit direction `n` from `p` to the wheel surface (secant steps
    /// from t = 0), if the line meets it within the profile.
    pub fn along(&self, p: &Point3<f64>, n: &Vector3<f64>) -> Option<f64> {
        let f = |t: f64| self.outside_mm(&(p + n * t));
        let (mut t0, mut f0) = (0.0, f(0.0)?);
        let (mut t1, mut f1) = (-f0, f(-f0)?);
        for _ in 0..60 {
            if f1 == f0 {
                break;
            }
            let t2 = t1 - f1 * (t1 - t0) / (f1 - f0);
            (t0, f0) = (t1, f1);
            t1 = t2;
            f1 = f(t1)?;
            if (t1 - t0).abs() < 1e-13 {
                break;
            }
        }
        Some(t1)
    }

    /// The wheelset's angular velocity in track coordinates: roll rate about x, yaw rate about the
    /// rolled z, pitch rate about the axle.
    pub fn angular_velocity(&self, v: &Velocity) -> Vector3<f64> {
        let rolled_z = Rotation3::from_axis_angle(&Vector3::x_axis(), self.roll_rad) * Vector3::z();
        Vector3::x() * v.vroll_rad_s + rolled_z * v.vyaw_rad_s + self.rotation * Vector3::y() * v.vpitch_rad_s
    }

    /// The part of the material velocity at p that the pitch rotation alone gives [mm/s].
    pub fn pitch_velocity(&self, p: &Point3<f64>, v: &Velocity) -> Vector3<f64> {
        (self.rotation * Vector3::y() * v.vpitch_rad_s).cross(&(p - self.centre))
    }

    /// Velocity [mm/s] of the wheel's material at track point p.
    pub fn material_velocity(&self, p: &Point3<f64>, v: &Velocity) -> Vector3<f64> {
        Vector3::new(v.vs_mm_s, v.vy_mm_s, v.vz_mm_s) + self.angular_velocity(v).cross(&(p - self.centre))
    }
}
