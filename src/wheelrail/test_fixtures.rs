//! The Manchester benchmark's set-up the unit tests share: its profiles (shipped in
//! reference/contact_wheelrail/examples), the track with the gauge point 14 mm down and gauge
//! 1435 mm, and the wheelset (FBDIST 1360 mm, FBPOS −70 mm, NOMRAD 460 mm).

use super::profile::{read_profile, Profile, ProfileKind, ProfileOptions};
use super::rail::{RailPlacement, Track};
use super::wheel::{WheelDeviation, WheelsetGeometry};
use std::path::Path;

/// The wheel profile `wheel` and the rail profile `rail` of CONTACT's examples folder.
pub fn profiles(wheel: &str, rail: &str) -> (Profile, Profile) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("reference/contact_wheelrail/examples");
    let read = |f: &str, kind| read_profile(&dir.join(f), kind, &ProfileOptions::default()).unwrap();
    (read(wheel, ProfileKind::Wheel), read(rail, ProfileKind::Rail))
}

/// The benchmark's track: no cant, the rail placed by its gauge point.
pub fn track() -> Track {
    Track {
        placement: RailPlacement::Gauge { height_mm: 14.0, width_mm: 1435.0 },
        cant_rad: 0.0,
        deviation_mm_rad: [0.0; 3],
        deviation_velocity: [0.0; 3],
    }
}

/// The benchmark's wheelset, without deviations.
pub fn wheelset() -> WheelsetGeometry {
    WheelsetGeometry {
        flange_back_distance_mm: 1360.0,
        flange_back_position_mm: -70.0,
        nominal_radius_mm: 460.0,
        deviation: WheelDeviation::NONE,
    }
}
