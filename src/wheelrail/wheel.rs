//! The wheel of a wheelset in the track (user guide, "Wheelset geometry" and "Wheelset degrees of
//! freedom"): the profile origin at `(0, FBDIST/2 − FBPOS, NOMRAD)` from the wheelset centre
//! (right wheel), the centre at `(0, y_ws, z_ws − NOMRAD)` in track coordinates (z down), turned by
//! roll then yaw (pitch does not move a round wheel's surface). A surface point at profile
//! position y_w lies at radius `NOMRAD + z_w(y_w)` from the wheel's own axle. The wheel may deviate
//! from its design place on the wheelset (user guide, "Flexible wheel profile displacements";
//! CONTACT's E = 4, 5, `wr_set_wheel_marker`): its profile origin shifted by DXWHL, DYWHL, DZWHL
//! and the wheel turned about it by DROLLW then DYAWW (DPITCHW does not move a round wheel), all in
//! wheelset coordinates; the wheel's own axle then lies NOMRAD above that origin, turned with it.

use super::curve::Curve;
use super::locus::LocusSpline;
use super::oorwheel::WheelSlices;
use nalgebra::{Point3, Rotation3, Vector3};

/// FBDIST, FBPOS, NOMRAD [mm] and the wheel's deviation from its design place.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelsetGeometry {
    pub flange_back_distance_mm: f64,
    pub flange_back_position_mm: f64,
    pub nominal_radius_mm: f64,
    pub deviation: WheelDeviation,
}

/// The wheel's deviation from its design place on the wheelset and its rate (CONTACT's flexible
/// wheelset deviations, E = 4, 5), in wheelset coordinates.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WheelDeviation {
    /// DXWHL, DYWHL, DZWHL [mm] of the profile origin; DROLLW, DYAWW, DPITCHW [rad] about it.
    pub position: [f64; 6],
    /// VXWHL, VYWHL, VZWHL [mm/s] of the profile origin; VROLLW, VYAWW, VPITCHW [rad/s].
    pub velocity: [f64; 6],
}

impl WheelDeviation {
    /// The wheel at its design place, at rest on the wheelset (a rigid wheelset).
    pub const NONE: WheelDeviation = WheelDeviation { position: [0.0; 6], velocity: [0.0; 6] };

    /// Seen in the frame mirrored by `m` (−1: y → −y): the lateral shift, roll and yaw and their
    /// rates change sign.
    pub fn mirrored(&self, m: f64) -> WheelDeviation {
        let flip = |a: [f64; 6]| [a[0], m * a[1], a[2], m * a[3], m * a[4], a[5]];
        WheelDeviation { position: flip(self.position), velocity: flip(self.velocity) }
    }

    /// The profile origin's velocity [mm/s] and the wheel's angular velocity [rad/s] relative to
    /// the wheelset, in wheelset coordinates (CONTACT's `whl_tvel_ws`, `whl_rvel_ws`: roll about
    /// x, pitch about y, yaw about z).
    fn rates(&self) -> (Vector3<f64>, Vector3<f64>) {
        let [vx, vy, vz, vroll, vyaw, vpitch] = self.velocity;
        (Vector3::new(vx, vy, vz), Vector3::new(vroll, vpitch, vyaw))
    }
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
    /// Lateral position of the profile origin along the wheel's axle [mm] (FBDIST/2 − FBPOS).
    pub y_offset_mm: f64,
    pub nominal_radius_mm: f64,
    /// The wheel's own centre in track coordinates: the point of its axle `y_offset_mm` from the
    /// profile origin's plane (the wheelset centre without a deviation).
    pub centre: Point3<f64>,
    /// Wheel → track orientation: the wheelset's roll about x then yaw about the rolled z, then
    /// the wheel's DROLLW and DYAWW on the wheelset.
    pub rotation: Rotation3<f64>,
    /// The wheelset centre in track coordinates.
    pub wheelset_centre: Point3<f64>,
    /// Wheelset → track orientation.
    pub wheelset_rotation: Rotation3<f64>,
    /// The profile origin in wheelset coordinates (FBDIST/2 − FBPOS, NOMRAD plus the deviation).
    pub origin_ws: Vector3<f64>,
    pub deviation: WheelDeviation,
    pub roll_rad: f64,
    pub yaw_rad: f64,
    /// CONTACT's spline through the locus at the profile's points (a profile file; `None`: the
    /// exact locus of a closed form).
    pub locus_spline: Option<LocusSpline>,
    /// An out-of-round wheel: its surface varies with the material angle (a wheel slices file;
    /// `curve` is then its first slice, not its surface).
    pub oor: Option<WheelSlices<'a>>,
}

/// A rotation by roll about x, then yaw about the rolled z (CONTACT's roll-yaw-pitch convention
/// without the pitch, `marker_rotate`: `rotmat_pure_roll * rotmat_pure_yaw`).
fn roll_yaw(roll_rad: f64, yaw_rad: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&Vector3::x_axis(), roll_rad) * Rotation3::from_axis_angle(&Vector3::z_axis(), yaw_rad)
}

/// Wheel → track orientation of wheelset geometry `g` (its deviation in this side's frame) at
/// `pose`: the wheelset's roll and yaw, then the wheel's DROLLW and DYAWW (CONTACT's `whl_trk`,
/// `wr_set_wheel_marker`: `m_ws` of the wheel on `m_trk` of the wheelset).
pub fn wheel_rotation(g: &WheelsetGeometry, pose: &Pose) -> Rotation3<f64> {
    let [_, _, _, droll, dyaw, _] = g.deviation.position;
    roll_yaw(pose.roll_rad, pose.yaw_rad) * roll_yaw(droll, dyaw)
}

impl<'a> PlacedWheel<'a> {
    /// The wheel of wheelset geometry `g` (its deviation in this side's frame) at `pose`.
    pub fn place(curve: &'a dyn Curve, g: &WheelsetGeometry, pose: &Pose) -> PlacedWheel<'a> {
        let wheelset_rotation = roll_yaw(pose.roll_rad, pose.yaw_rad);
        let wheelset_centre = Point3::new(0.0, pose.y_mm, pose.z_mm - g.nominal_radius_mm);
        let [dx, dy, dz, droll, dyaw, _] = g.deviation.position;
        let y_offset_mm = 0.5 * g.flange_back_distance_mm - g.flange_back_position_mm;
        let origin_ws = Vector3::new(dx, y_offset_mm + dy, g.nominal_radius_mm + dz);
        let turn = roll_yaw(droll, dyaw);
        // The profile origin at `origin_ws`; the wheel's centre y_offset along and NOMRAD above it.
        let centre = wheelset_centre
            + wheelset_rotation * (origin_ws - turn * Vector3::new(0.0, y_offset_mm, g.nominal_radius_mm));
        let rotation = wheel_rotation(g, pose);
        let mut wheel = PlacedWheel {
            curve,
            y_offset_mm,
            nominal_radius_mm: g.nominal_radius_mm,
            centre,
            rotation,
            wheelset_centre,
            wheelset_rotation,
            origin_ws,
            deviation: g.deviation,
            roll_rad: pose.roll_rad,
            yaw_rad: pose.yaw_rad,
            locus_spline: None,
            oor: None,
        };
        wheel.locus_spline =
            LocusSpline::build(curve, &rotation, wheel.y_offset_mm, g.nominal_radius_mm, &|v| wheel.to_track(v));
        wheel
    }

    /// The contact locus at profile position y_w: the point of that circle of the wheel whose
    /// surface normal (sin θ, −z_w', cos θ) in the wheel's frame has no x component in the track
    /// (it can touch the prismatic rail there): `r11 sin θ + r13 cos θ = r12 z_w'`, r the wheel's
    /// first row of rotation; `sin θ = −z_w'(y_w) tan ψ` without the wheel's own roll (CONTACT's
    /// contact locus, Vollebregt 2020 "wr geometry").
    pub fn locus(&self, y_w_mm: f64) -> Option<Point3<f64>> {
        let (z, slope) = self.curve.z_and_slope(y_w_mm)?;
        let rho = self.nominal_radius_mm + z;
        let r = self.rotation.matrix();
        let (r11, r12, r13) = (r[(0, 0)], r[(0, 1)], r[(0, 2)]);
        let (sin_t, cos_t) = if r13 == 0.0 {
            let sin_t = (r12 * slope / r11).clamp(-0.999, 0.999);
            (sin_t, (1.0 - sin_t * sin_t).sqrt())
        } else {
            let sin_a = (r12 * slope / r11.hypot(r13)).clamp(-0.999, 0.999);
            (sin_a.asin() - r13.atan2(r11)).sin_cos()
        };
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

    /// A vector of the wheel's frame from its centre as a track point.
    pub(super) fn to_track(&self, p_ws: Vector3<f64>) -> Point3<f64> {
        self.centre + self.rotation * p_ws
    }

    /// A track point in the wheel's frame (from its centre).
    pub(super) fn to_wheel(&self, p: &Point3<f64>) -> Vector3<f64> {
        self.rotation.inverse() * (p - self.centre)
    }

    /// How far a track point lies outside the wheel [mm]: its distance from the axle less the
    /// wheel's radius at its lateral place and, out of round, its angle (negative inside).
    fn outside_mm(&self, p: &Point3<f64>) -> Option<f64> {
        let q = self.to_wheel(p);
        let y_w = q.y - self.y_offset_mm;
        let z = match &self.oor {
            Some(oor) => oor.z_mm(q.x.atan2(q.z), y_w)?,
            None => self.curve.z_mm(y_w)?,
        };
        let radius = self.nominal_radius_mm + z;
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
    fn wheelset_angular_velocity(&self, v: &Velocity) -> Vector3<f64> {
        let rolled_z = Rotation3::from_axis_angle(&Vector3::x_axis(), self.roll_rad) * Vector3::z();
        Vector3::x() * v.vroll_rad_s + rolled_z * v.vyaw_rad_s + self.wheelset_rotation * Vector3::y() * v.vpitch_rad_s
    }

    /// The wheel's angular velocity in track coordinates: the wheelset's plus the wheel's own
    /// rates on it (VROLLW, VPITCHW, VYAWW about the wheelset's axes; `m_wr_rigslip`).
    pub fn angular_velocity(&self, v: &Velocity) -> Vector3<f64> {
        self.wheelset_angular_velocity(v) + self.wheelset_rotation * self.deviation.rates().1
    }

    /// The part of the material velocity at p that the wheelset's pitch rotation alone gives
    /// [mm/s] (about the wheelset's axle).
    pub fn pitch_velocity(&self, p: &Point3<f64>, v: &Velocity) -> Vector3<f64> {
        (self.wheelset_rotation * Vector3::y() * v.vpitch_rad_s).cross(&(p - self.wheelset_centre))
    }

    /// Velocity [mm/s] of the wheel's material at track point p: the wheelset's motion at p plus,
    /// turned into the track, the wheel's own motion on the wheelset (the profile origin's
    /// velocity and the wheel's rotation about it: v_O + ω_w × (p − O), wheelset coordinates).
    pub fn material_velocity(&self, p: &Point3<f64>, v: &Velocity) -> Vector3<f64> {
        let arm = p - self.wheelset_centre;
        let (v_origin, w_wheel) = self.deviation.rates();
        let own = v_origin + w_wheel.cross(&(self.wheelset_rotation.inverse() * arm - self.origin_ws));
        Vector3::new(v.vs_mm_s, v.vy_mm_s, v.vz_mm_s)
            + self.wheelset_angular_velocity(v).cross(&arm)
            + self.wheelset_rotation * own
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wheelrail::curve::Line;

    fn geometry(deviation: WheelDeviation) -> WheelsetGeometry {
        WheelsetGeometry {
            flange_back_distance_mm: 1360.0,
            flange_back_position_mm: -70.0,
            nominal_radius_mm: 460.0,
            deviation,
        }
    }

    /// The wheel's own rates are rigid-body motion about its profile origin in wheelset
    /// coordinates: a wheelset's yaw rate ψ' about its centre is the wheel's yaw rate ψ' about the
    /// origin (750 mm out, 460 mm down) plus the origin's velocity −ψ' 750 mm along x; a wheel's
    /// VPITCHW w moves its axle's point above the origin by (−w R, 0, 0); VXWHL … VZWHL move every
    /// point alike, turned by the wheelset's yaw.
    #[test]
    fn the_wheels_own_rates_are_rigid_motion_about_its_origin() {
        let curve = Line { z0_mm: 0.0, slope: -0.025, y_range_mm: [-60.0, 60.0] };
        let pose = Pose { y_mm: 2.0, z_mm: 0.3, roll_rad: 0.0, yaw_rad: 0.01 };
        let rigid = PlacedWheel::place(&curve, &geometry(WheelDeviation::NONE), &pose);
        let rate = 0.3;
        let own = WheelDeviation { position: [0.0; 6], velocity: [-rate * 750.0, 0.0, 0.0, 0.0, rate, 0.0] };
        let flexible = PlacedWheel::place(&curve, &geometry(own), &pose);
        let yawing = Velocity { vyaw_rad_s: rate, ..Velocity::default() };
        for p in [Point3::new(0.0, 752.0, 0.3), Point3::new(-3.0, 760.0, -1.0), Point3::new(5.0, 0.0, -460.0)] {
            let (a, b) = (rigid.material_velocity(&p, &yawing), flexible.material_velocity(&p, &Velocity::default()));
            assert!((a - b).norm() < 1e-12 * a.norm().max(1.0), "{p}: {a} {b}");
        }
        let (a, b) = (rigid.angular_velocity(&yawing), flexible.angular_velocity(&Velocity::default()));
        assert!((a - b).norm() < 1e-15, "{a} {b}");
        // VPITCHW about the origin: the axle's point above it moves by −w R along the wheelset's x.
        let w = -0.01;
        let pitching = WheelDeviation { position: [0.0; 6], velocity: [0.0, 0.0, 0.0, 0.0, 0.0, w] };
        let wheel = PlacedWheel::place(&curve, &geometry(pitching), &pose);
        let axle = wheel.wheelset_centre + wheel.wheelset_rotation * Vector3::new(0.0, 750.0, 0.0);
        let v = wheel.material_velocity(&axle, &Velocity::default());
        let expected = wheel.wheelset_rotation * Vector3::new(-w * 460.0, 0.0, 0.0);
        assert!((v - expected).norm() < 1e-12, "{v} {expected}");
        let origin = wheel.wheelset_centre + wheel.wheelset_rotation * wheel.origin_ws;
        assert!(wheel.material_velocity(&origin, &Velocity::default()).norm() < 1e-12);
        // The origin's own velocity, turned by the wheelset's yaw.
        let moving = WheelDeviation { position: [0.0; 6], velocity: [20.0, 10.0, 5.0, 0.0, 0.0, 0.0] };
        let wheel = PlacedWheel::place(&curve, &geometry(moving), &pose);
        let v = wheel.material_velocity(&Point3::new(1.0, 740.0, 2.0), &Velocity::default());
        let expected = wheel.wheelset_rotation * Vector3::new(20.0, 10.0, 5.0);
        assert!((v - expected).norm() < 1e-12, "{v} {expected}");
    }

    /// DXWHL, DYWHL, DZWHL move the profile origin in wheelset coordinates; DROLLW turns the wheel
    /// about it (the origin stays, the axle tilts by the roll).
    #[test]
    fn the_deviation_moves_and_turns_the_wheel_about_its_profile_origin() {
        let curve = Line { z0_mm: 0.0, slope: 0.0, y_range_mm: [-60.0, 60.0] };
        let pose = Pose { y_mm: 2.0, z_mm: 0.3, roll_rad: 0.002, yaw_rad: 0.01 };
        let rigid = PlacedWheel::place(&curve, &geometry(WheelDeviation::NONE), &pose);
        let origin = |w: &PlacedWheel| w.to_track(Vector3::new(0.0, w.y_offset_mm, w.nominal_radius_mm));
        let shift = WheelDeviation { position: [0.5, 1.0, 0.2, 0.0, 0.0, 0.0], velocity: [0.0; 6] };
        let moved = PlacedWheel::place(&curve, &geometry(shift), &pose);
        let expected = origin(&rigid) + rigid.wheelset_rotation * Vector3::new(0.5, 1.0, 0.2);
        assert!((origin(&moved) - expected).norm() < 1e-12, "{} {expected}", origin(&moved));
        let roll = 0.0873;
        let turn = WheelDeviation { position: [0.0, 0.0, 0.0, roll, 0.0, 0.0], velocity: [0.0; 6] };
        let turned = PlacedWheel::place(&curve, &geometry(turn), &pose);
        assert!((origin(&turned) - origin(&rigid)).norm() < 1e-9, "{} {}", origin(&turned), origin(&rigid));
        let (a, b) = (rigid.rotation * Vector3::y(), turned.rotation * Vector3::y());
        assert!((a.angle(&b) - roll).abs() < 1e-12, "{}", a.angle(&b));
    }
}
