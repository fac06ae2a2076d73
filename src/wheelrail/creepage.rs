//! The kinematic creepages of a patch (user guide, "Kinematic configuration"; CONTACT's
//! m_wr_rigslip, planar contact): the velocity of the rail's material less the wheel's at the
//! wheel's surface point below the reference, in the patch's x and s directions over the rolling
//! speed, and the spin: the rail's angular velocity less the wheel's about n over the speed.

use super::patch::PatchFrame;
use super::wheel::{PlacedWheel, Velocity};

/// CKSI, CETA [-], CPHI [1/mm] and the rolling speed VELOC [mm/s] of one patch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Creepages {
    pub cksi: f64,
    pub ceta: f64,
    pub cphi_per_mm: f64,
    pub veloc_mm_s: f64,
}

/// The creepages at the patch's reference, the wheel's material taken where n through the
/// reference meets the wheel's surface.
pub fn at_reference(frame: &PatchFrame, wheel: &PlacedWheel, v: &Velocity) -> Creepages {
    let n = frame.n();
    let t_w = wheel.along(&frame.origin, &n).unwrap_or(0.0);
    let slip = -wheel.material_velocity(&(frame.origin + n * t_w), v);
    let veloc_mm_s = v.vs_mm_s.abs();
    Creepages {
        cksi: slip.x / veloc_mm_s,
        ceta: slip.dot(&frame.e_s()) / veloc_mm_s,
        cphi_per_mm: -wheel.angular_velocity(v).dot(&n) / veloc_mm_s,
        veloc_mm_s,
    }
}
