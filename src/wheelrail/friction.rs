//! Coulomb's μ of a patch (CONTACT's V digit in module 1, `m_wr_solvecp`): one μ for the whole
//! rail (V = 0), μ at the wheelset's position along the track (V = 2: one value for the case), or
//! μ at the patch's contact angle on the wheel (V = 1: the roll of the contact reference in the
//! wheel's frame, `mref_whl%roll()` of `wr_setup_cp`, read from the rotation matrix as
//! `rotmat_get_rollangle` does: with the wheelset's yaw it is not the track's angle less the
//! wheelset's roll), each interpolated
//! linearly between the control points and constant beyond them (`fric_interp`). With the
//! conformal approach (D = 4) V = 1 gives μ per grid row, at the row's inclination in the track
//! (`m_wr_solvecp`: `fric_interp` on `curv_incln`).

use super::wheel::wheel_rotation;
use super::{NormalPatch, WheelRailCase};
use crate::physics::TemperatureLaw;
use crate::scene::wheelrail::{MuBy, MuVariation};
use nalgebra::{Rotation3, Vector3};

/// A case's friction: its one μ, or the variation each patch takes its μ from.
#[derive(Debug, Clone, Copy)]
pub struct Friction<'a> {
    pub mu: f64,
    pub variation: Option<&'a MuVariation>,
    /// CONTACT's T = 0 (frictionless compression): the tangential problem is not solved.
    pub frictionless: bool,
}

impl Friction<'_> {
    /// μ of patch `p` of `case`.
    pub fn of_patch(&self, p: &NormalPatch, case: &WheelRailCase) -> f64 {
        match self.variation {
            Some(v) => v.at(self.abscissa(v, p, case)),
            None => self.mu,
        }
    }

    /// The temperature law of patch `p` of `case` where its parameters vary (L = 6 with V = 1, 2:
    /// each interpolated as μ is, `fric_interp_arr`); `None` for one law or Coulomb's.
    pub fn temperature_law_of(&self, p: &NormalPatch, case: &WheelRailCase) -> Option<TemperatureLaw> {
        let v = self.variation?;
        v.law_at(self.abscissa(v, p, case))
    }

    /// Whether the temperature law's parameters vary between patches.
    pub fn temperature_varies(&self) -> bool {
        self.variation.is_some_and(|v| v.temperature.is_some())
    }

    /// Where patch `p` of `case` takes its friction on the variation `v`: its contact angle on
    /// the wheel (the reference's roll in the wheel's frame) or the wheelset's S_WS.
    fn abscissa(&self, v: &MuVariation, p: &NormalPatch, case: &WheelRailCase) -> f64 {
        match v.by {
            MuBy::ContactAngle => {
                let wheel = wheel_rotation(&case.side.wheelset(&case.wheelset), &case.side.pose(&case.pose));
                roll_in_wheel_frame(p.geometry.frame.delta_rad, &wheel)
            }
            MuBy::TrackS { s_mm } => s_mm,
        }
    }
}

/// The roll angle [rad] of a contact reference turned by `delta_rad` about the track's x axis,
/// seen in the frame of a wheel turned by `wheel` (wheel → track): CONTACT's
/// `marker_2loc(cp%mref, whl_trk)` then `rotmat_get_rollangle` (roll-yaw-pitch convention: the
/// yaw asin(−r12), the roll asin(r32 / cos yaw)). Without yaw it is `delta_rad` less the wheel's
/// roll; with the wheelset's yaw ψ, sin of it is sin(δ − φ) / √(1 − sin²ψ cos²(δ − φ)).
pub fn roll_in_wheel_frame(delta_rad: f64, wheel: &Rotation3<f64>) -> f64 {
    let m = wheel.inverse() * Rotation3::from_axis_angle(&Vector3::x_axis(), delta_rad);
    let m = m.matrix();
    let yaw = (-m[(0, 1)]).clamp(-1.0, 1.0).asin();
    (m[(2, 1)] / yaw.cos()).clamp(-1.0, 1.0).asin()
}

impl Friction<'_> {
    /// μ per grid row of a conformal patch where it varies with the contact angle (V = 1 with
    /// D = 4): at each row's inclination in the track; `None` for one μ per patch.
    pub fn of_rows(&self, p: &NormalPatch) -> Option<Vec<f64>> {
        let c = p.geometry.curved.as_ref()?;
        let v = self.variation.filter(|v| v.by == MuBy::ContactAngle)?;
        Some((0..c.reference.rows()).map(|j| v.at(c.reference.inclination_rad(j))).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::roll_in_wheel_frame;
    use crate::scene::wheelrail::{MuBy, MuVariation};
    use crate::wheelrail::wheel::{wheel_rotation, Pose, WheelDeviation, WheelsetGeometry};

    fn geometry(droll_rad: f64) -> WheelsetGeometry {
        WheelsetGeometry {
            flange_back_distance_mm: 1360.0,
            flange_back_position_mm: -70.0,
            nominal_radius_mm: 460.0,
            deviation: WheelDeviation { position: [0.0, 0.0, 0.0, droll_rad, 0.0, 0.0], velocity: [0.0; 6] },
        }
    }

    #[test]
    fn without_yaw_the_wheel_frame_roll_is_the_angle_less_the_rolls() {
        let pose = Pose { roll_rad: -0.0004, ..Pose::default() };
        let r = roll_in_wheel_frame(-0.29, &wheel_rotation(&geometry(0.002), &pose));
        assert!((r - (-0.29 + 0.0004 - 0.002)).abs() < 1e-15, "{r}");
    }

    /// The closed form of R_z(−ψ) R_x(a), a = δ − φ: r12 = sin ψ cos a, r32 = sin a, so the roll
    /// is asin(sin a / √(1 − sin²ψ cos²a)); mbench_a22_varfric case 3's patch 2 (δ = −0.2930452,
    /// φ = −0.0003554, ψ = 0.012): 2.0e-5 rad beyond a, μ 1.1e-5 lower (CONTACT's unprinted
    /// patch forces 5e-5 below the angle-less-roll μ's).
    #[test]
    fn with_yaw_the_wheel_frame_roll_is_contacts_rotmat_roll() {
        let (delta, roll, yaw) = (-0.2930452_f64, -0.0003554_f64, 0.012_f64);
        let pose = Pose { roll_rad: roll, yaw_rad: yaw, ..Pose::default() };
        let r = roll_in_wheel_frame(delta, &wheel_rotation(&geometry(0.0), &pose));
        let a = delta - roll;
        let closed = (a.sin() / (1.0 - (yaw.sin() * a.cos()).powi(2)).sqrt()).asin();
        assert!((r - closed).abs() < 1e-14, "{r} against {closed}");
        assert!((r - a + 1.99e-5).abs() < 1e-7, "{} rad beyond a", r - a);
    }

    /// CONTACT's own numbers at mbench_a22_varfric case 3's last height iterate (a debug build's
    /// print after `fric_interp` in `wr_setup_cp`): patch 2's delttr −0.2930451903685212 rad in the
    /// track, ROLL −0.00035540, YAW 0.012, gives `deltcp_w` −0.2927096820117159 and μ
    /// 0.2322897059811229 (ALPHA −20°, −10° with μ 0.2, 0.3); patch 1's −0.2479701154893963 gives
    /// −0.2476318248490664 and μ 0.2581174156302567.
    #[test]
    fn the_wheel_frame_roll_and_mu_are_contacts_at_varfric_case_3() {
        let pose = Pose { roll_rad: -0.00035540, yaw_rad: 0.012, ..Pose::default() };
        let wheel = wheel_rotation(&geometry(0.0), &pose);
        let variation = MuVariation {
            by: MuBy::ContactAngle,
            at: vec![-20f64.to_radians(), -10f64.to_radians()],
            values: vec![0.2, 0.3],
            temperature: None,
        };
        let mu = |x: f64| variation.at(x);
        for (delta, contact, contact_mu) in [
            (-0.2930451903685212, -0.2927096820117159, 0.2322897059811229),
            (-0.2479701154893963, -0.2476318248490664, 0.2581174156302567),
        ] {
            let r = roll_in_wheel_frame(delta, &wheel);
            assert!((r - contact).abs() < 1e-15, "{r} against CONTACT's {contact}");
            assert!((mu(r) - contact_mu).abs() < 1e-15, "{} against CONTACT's {contact_mu}", mu(r));
        }
    }
}
