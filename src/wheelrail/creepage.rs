//! The kinematic creepages of a patch (user guide, "Kinematic configuration"; CONTACT's
//! m_wr_rigslip, `wr_creep_cref`, planar contact): the velocity of the rail's material less the
//! wheel's at the wheel's point Q, the approach `pen` below the reference along n, in the patch's
//! x and s directions over the rolling speed, and the spin: the rail's angular velocity less the
//! wheel's about n over the speed. The rolling speed is the mean of the wheelset's forward speed
//! and Q's speed from the pitch rotation alone.

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

/// The creepages at the patch's reference with the approach `pen_mm` (the deepest overlap).
pub fn at_reference(frame: &PatchFrame, wheel: &PlacedWheel, v: &Velocity, pen_mm: f64) -> Creepages {
    let n = frame.n();
    let q = frame.origin + n * pen_mm;
    let v_q = wheel.material_velocity(&q, v);
    let pitch_x = wheel.pitch_velocity(&q, v).x;
    let veloc_mm_s = 0.5 * ((v_q.x - pitch_x).abs() + pitch_x.abs());
    let slip = -v_q;
    Creepages {
        cksi: slip.x / veloc_mm_s,
        ceta: slip.dot(&frame.e_s()) / veloc_mm_s,
        cphi_per_mm: -wheel.angular_velocity(v).dot(&n) / veloc_mm_s,
        veloc_mm_s,
    }
}
