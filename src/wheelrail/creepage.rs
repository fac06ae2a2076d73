//! The kinematic creepages of a patch (user guide, "Kinematic configuration"; CONTACT's
//! m_wr_rigslip, `wr_creep_cref`, planar contact): the velocity of the rail's material less the
//! wheel's at the wheel's point Q, the approach `pen` below the reference along n, in the patch's
//! x and s directions over the rolling speed, and the spin: the rail's angular velocity less the
//! wheel's about n over the speed. The rolling speed is the mean of the wheelset's forward speed
//! and Q's speed from the pitch rotation alone. A rail moving from its design position (VYRAIL,
//! VZRAIL, VROLLR: `m_wr_rigslip` `rail_tvel_trk`, `rail_rvel_trk`, rolling about the rail
//! profile's origin) adds its material's velocity at the reference P and its roll rate.

use super::patch::PatchFrame;
use super::roller::Roller;
use super::wheel::{PlacedWheel, Velocity};
use nalgebra::{Point3, Vector3};

/// CKSI, CETA [-], CPHI [1/mm], the rolling speed VELOC [mm/s] and direction of one patch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Creepages {
    pub cksi: f64,
    pub ceta: f64,
    pub cphi_per_mm: f64,
    pub veloc_mm_s: f64,
    /// The contact rolls towards −x (CONTACT's CHI = 180°: the wheel moving backwards, or a
    /// roller rig turning the other way); the tangential problem is then solved mirrored.
    pub reversed: bool,
}

impl Creepages {
    /// CONTACT's rolling direction CHI [rad]: 0 or π.
    pub fn chi_rad(&self) -> f64 {
        if self.reversed {
            std::f64::consts::PI
        } else {
            0.0
        }
    }
}

/// The rail's motion (right-side frame): its profile origin (y, z) in the track [mm] and the
/// velocities VYRAIL, VZRAIL [mm/s] and VROLLR [rad/s] of that origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RailMotion {
    pub origin_mm: [f64; 2],
    pub velocity: [f64; 3],
}

impl RailMotion {
    /// The velocity of the rail's material at `p`: v_O + ω × (p − O), ω = (VROLLR, 0, 0).
    pub(super) fn at(&self, p: &Point3<f64>) -> Vector3<f64> {
        let [vy, vz, vroll] = self.velocity;
        let (ry, rz) = (p.y - self.origin_mm[0], p.z - self.origin_mm[1]);
        Vector3::new(0.0, vy - vroll * rz, vz + vroll * ry)
    }
}

/// The rolling speed [mm/s] below which the contact stands and its creepages are 0 (`wr_creep_cref`).
const STANDING_MM_S: f64 = 1e-6;

/// The creepages at the patch's reference with the approach `pen_mm` (the deepest overlap):
/// (v_rail(P) − v_wheel(Q)) / VELOC, the spin (ω_rail − ω_wheel) · n / VELOC. With `shift`
/// (CONTACT's T = 1: dt = 1, VELOC = 1) the velocities are one step's shifts and so are the
/// "creepages": CKSI, CETA [mm], CPHI [rad]. On a roller rig the roller's material moves too, and
/// the speed is the mean of the roller's and the wheel's at the contact ([`Roller`]).
pub fn at_reference(
    frame: &PatchFrame,
    wheel: &PlacedWheel,
    v: &Velocity,
    pen_mm: f64,
    (rail, roller): (&RailMotion, Option<&Roller>),
    shift: bool,
) -> Creepages {
    let n = frame.n();
    let q = frame.origin + n * pen_mm;
    let v_q = wheel.material_velocity(&q, v);
    let mut v_p = rail.at(&frame.origin);
    let mut spin = Vector3::new(rail.velocity[2], 0.0, 0.0) - wheel.angular_velocity(v);
    let pitch_x = wheel.pitch_velocity(&q, v).x;
    let (veloc_mm_s, reversed) = match roller {
        _ if shift => (1.0, false),
        // On a roller rig the mean of the roller's and the wheel's speeds at the contact
        // (`wr_creep_cref`: |v_P,x + v_Q,x| / 2), towards −x when the faster one moves along +x.
        Some(r) => {
            v_p += r.material_velocity(&frame.origin);
            spin += r.angular_velocity();
            (0.5 * (v_p.x + v_q.x).abs(), backwards(v_p.x, v_q.x))
        }
        None => {
            // The wheelset's forward speed against the pitch's part (`wr_creep_cref`: sign(VS) or
            // −sign(ω) of the larger one).
            let vs_est = v_q.x - v_p.x - pitch_x;
            (0.5 * (vs_est.abs() + pitch_x.abs()), backwards(-vs_est, pitch_x))
        }
    };
    let slip = v_p - v_q;
    // Rolling at V = 0 (a wheel standing on a roller that does not turn): zero creepages, as
    // `wr_creep_cref` sets them below 1e-6 mm/s.
    let over_v = if veloc_mm_s.abs() < STANDING_MM_S { 0.0 } else { 1.0 / veloc_mm_s };
    Creepages {
        cksi: slip.x * over_v,
        ceta: slip.dot(&frame.e_s()) * over_v,
        cphi_per_mm: spin.dot(&n) * over_v,
        veloc_mm_s,
        reversed,
    }
}

/// Whether the contact rolls towards −x, from the two surfaces' speeds along x: forwards when
/// the faster one moves along −x (`wr_creep_cref`, `wr_rigslip_wrsurf`: CHI = 0 if the larger
/// |v| has v ≤ 0, else 180°).
pub fn backwards(a_mm_s: f64, b_mm_s: f64) -> bool {
    let faster = if a_mm_s.abs() >= b_mm_s.abs() { a_mm_s } else { b_mm_s };
    faster > 0.0
}
