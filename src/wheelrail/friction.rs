//! Coulomb's μ of a patch (CONTACT's V digit in module 1, `m_wr_solvecp`): one μ for the whole
//! rail (V = 0), μ at the wheelset's position along the track (V = 2: one value for the case), or
//! μ at the patch's contact angle on the wheel (V = 1: the roll of the contact reference in the
//! wheel's frame, the angle of the right-side frame less the wheelset's roll and the wheel's DROLLW), each interpolated
//! linearly between the control points and constant beyond them (`fric_interp`). With the
//! conformal approach (D = 4) V = 1 gives μ per grid row, at the row's inclination in the track
//! (`m_wr_solvecp`: `fric_interp` on `curv_incln`).

use super::{NormalPatch, WheelRailCase};
use crate::physics::TemperatureLaw;
use crate::scene::wheelrail::{MuBy, MuVariation};

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
    /// the wheel (less the wheelset's roll and the wheel's own) or the wheelset's S_WS.
    fn abscissa(&self, v: &MuVariation, p: &NormalPatch, case: &WheelRailCase) -> f64 {
        match v.by {
            MuBy::ContactAngle => {
                let droll = case.side.wheelset(&case.wheelset).deviation.position[3];
                p.geometry.frame.delta_rad - case.side.pose(&case.pose).roll_rad - droll
            }
            MuBy::TrackS { s_mm } => s_mm,
        }
    }
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
