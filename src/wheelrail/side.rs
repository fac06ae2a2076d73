//! Left and right (user guide, "Half wheelset on half track model"): CONTACT solves a left wheel
//! as the mirror image of a right one (y → −y) and mirrors the results back. The profiles are the
//! right side's; the wheelset's lateral position, roll and yaw and their rates change sign.

use super::wheel::{Pose, Velocity, WheelsetGeometry};

#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    Left,
    Right,
}

impl Side {
    /// +1 on the right, −1 on the left: the factor of every lateral quantity.
    pub fn sign(self) -> f64 {
        match self {
            Side::Left => -1.0,
            Side::Right => 1.0,
        }
    }

    /// The wheelset's pose seen from the right side's frame.
    pub fn pose(self, p: &Pose) -> Pose {
        let m = self.sign();
        Pose { y_mm: m * p.y_mm, z_mm: p.z_mm, roll_rad: m * p.roll_rad, yaw_rad: m * p.yaw_rad }
    }

    /// The wheelset's dimensions and the wheel's deviation (wheelset coordinates) seen from the
    /// right side's frame.
    pub fn wheelset(self, g: &WheelsetGeometry) -> WheelsetGeometry {
        WheelsetGeometry { deviation: g.deviation.mirrored(self.sign()), ..*g }
    }

    /// The wheelset's velocities seen from the right side's frame.
    pub fn velocity(self, v: &Velocity) -> Velocity {
        let m = self.sign();
        Velocity { vy_mm_s: m * v.vy_mm_s, vroll_rad_s: m * v.vroll_rad_s, vyaw_rad_s: m * v.vyaw_rad_s, ..*v }
    }
}
