//! The stage against closed forms: a cylindrical wheel on a crowned rail is Hertz's contact; a
//! yawed cone's contact moves along the track by the locus's closed form.

use super::curve::{Arc, Line};
use super::rail::{RailPlacement, Track};
use super::side::Side;
use super::wheel::{Pose, Velocity, WheelDeviation, WheelsetGeometry};
use super::*;
use crate::physics::hertz::Radii;
use crate::physics::HertzContact;

const WHEELSET: WheelsetGeometry = WheelsetGeometry {
    flange_back_distance_mm: 1360.0,
    flange_back_position_mm: -70.0,
    nominal_radius_mm: 460.0,
    deviation: WheelDeviation::NONE,
};

fn case<'a>(rail: &'a dyn Curve, wheel: &'a dyn Curve, side: Side, pose: Pose) -> WheelRailCase<'a> {
    WheelRailCase {
        side,
        rail,
        wheel,
        track: Track {
            placement: RailPlacement::Absolute { y_mm: 750.0, z_mm: 0.0 },
            cant_rad: 0.0,
            deviation_mm_rad: [0.0; 3],
            deviation_velocity: [0.0; 3],
        },
        wheelset: WHEELSET,
        pose,
        velocity: Velocity { vs_mm_s: 2000.0, vpitch_rad_s: -2000.0 / 460.0, ..Velocity::default() },
        vertical: Vertical::Force { fz_n: 10000.0 },
        dx_mm: 0.2,
        ds_mm: 0.2,
        separation: super::patch::Separation {
            angle_rad: std::f64::consts::FRAC_PI_2,
            distance_mm: 8.0,
            combine_mm: 4.0,
            turn_mm: 12.0,
        },
        wheel_surface: Default::default(),
        search: ContactSearch::Locus,
        approach: Default::default(),
        material: Material::from_g(82000.0, 0.28),
        heat: None,
        tangential: Default::default(),
        motion: Default::default(),
        previous: None,
        rail_slices: None,
        roller: None,
        wheel_slices: None,
    }
}

fn crown() -> Arc {
    Arc { radius_mm: 300.0, centre_y_mm: 0.0, half_width_mm: 35.0, concave: false }
}

#[test]
fn a_cylinder_on_a_crowned_rail_is_hertz() {
    let (rail, wheel) = (crown(), Line { z0_mm: 0.0, slope: 0.0, y_range_mm: [-60.0, 60.0] });
    let c = case(&rail, &wheel, Side::Right, Pose::default());
    let contact = normal_contact(&c, None).unwrap();
    assert_eq!(contact.patches.len(), 1);
    let p = &contact.patches[0];
    let radii = Radii { r_wx_mm: 460.0, r_wy_mm: f64::INFINITY, r_ry_mm: 300.0 };
    let hertz = HertzContact::from_radii(&radii, 10000.0, &c.material).unwrap();
    // Height: first touch at z = 0, so z_ws is the approach (Hertz: 1.7 % on a 0.2 mm grid).
    let approach = hertz.approach_mm(&c.material);
    assert!((contact.z_ws_mm / approach - 1.0).abs() < 0.02, "z_ws {} approach {approach}", contact.z_ws_mm);
    assert!((p.fn_n - 10000.0).abs() < 1e-5, "{}", p.fn_n);
    // The crown is symmetric: only the gap mesh's placement (0.06 mm steps) tilts the weighted
    // angle and centre.
    assert!(p.geometry.frame.delta_rad.abs() < 1e-5, "{}", p.geometry.frame.delta_rad);
    assert!((p.geometry.frame.origin.y - 750.0).abs() < 1e-3, "{}", p.geometry.frame.origin.y);
    let area = p.pn_mpa.iter().filter(|&&v| v > 0.0).count() as f64 * 0.04;
    let ellipse = std::f64::consts::PI * hertz.a_mm * hertz.b_mm;
    assert!((area / ellipse - 1.0).abs() < 0.03, "area {area} ellipse {ellipse}");
    // No yaw, no lateral motion: spin and lateral creepage only from the mesh's tilt of δ.
    assert!(p.creepages.cphi_per_mm.abs() < 1e-8 && p.creepages.ceta.abs() < 1e-8, "{:?}", p.creepages);
}

#[test]
fn a_yawed_cone_touches_where_the_locus_says() {
    let slope = 1.0 / 40.0;
    let (rail, wheel) = (crown(), Line { z0_mm: 0.0, slope: -slope, y_range_mm: [-60.0, 60.0] });
    let yaw = 0.01f64;
    for side in [Side::Right, Side::Left] {
        let c = case(&rail, &wheel, side, Pose { yaw_rad: side.sign() * yaw, ..Pose::default() });
        let contact = normal_contact(&c, None).unwrap();
        let f = &contact.patches[0].geometry.frame;
        // Locus: sin θ = slope tan ψ, x = ρ sin θ cos ψ − Y sin ψ with ρ ≈ 460, Y ≈ 750 + y_w.
        let y_w = f.origin.y - 750.0;
        let rho = 460.0 - slope * y_w;
        let x = rho * slope * yaw.tan() * yaw.cos() - (750.0 + y_w) * yaw.sin();
        assert!((f.origin.x - x).abs() < 0.02, "{side:?}: x {} expected {x}", f.origin.x);
    }
}

/// CONTACT's mesh of a cylinder is exact where its slices meet the element centres (no yaw:
/// slices DX apart from the reference, the profile straight), and of an arc (radius R) it is
/// off by at most the chord's sag DS²/(8R) (its nodes DS apart from the reference, as the
/// element centres are, it is nearly exact on a level patch; the flange root's tilt moves them).
#[test]
fn contacts_wheel_mesh_is_the_surface_at_its_nodes_and_within_a_chords_sag_between() {
    let rail = crown();
    let flat = Line { z0_mm: 0.0, slope: 0.0, y_range_mm: [-60.0, 60.0] };
    let hollow = Arc { radius_mm: 320.0, centre_y_mm: 0.0, half_width_mm: 50.0, concave: true };
    for (wheel, sag_mm) in [(&flat as &dyn Curve, 0.0), (&hollow as &dyn Curve, 0.2f64.powi(2) / (8.0 * 320.0))] {
        let mut c = case(&rail, wheel, Side::Right, Pose::default());
        let z = normal_contact(&c, None).unwrap().z_ws_mm;
        let exact = geometry(&c, z).unwrap();
        c.wheel_surface = wheel_mesh::WheelSurface::ContactMesh;
        let meshed = geometry(&c, z).unwrap();
        let (e, m) = (&exact[0].h_mm, &meshed[0].h_mm);
        assert_eq!(e.len(), m.len());
        let worst = e.iter().zip(m).map(|(he, hm)| (hm - he).abs()).fold(0.0, f64::max);
        assert!(worst <= sag_mm * 1.05 + 1e-9, "worst {worst} sag {sag_mm}");
    }
}

/// A wheel turned on its wheelset by DROLLW, DYAWW and shifted so that its own centre is the
/// wheelset's is the same surface as the wheelset turned by that roll and yaw: the same height,
/// patch and contact (CONTACT's `wr_set_wheel_marker` places the wheel so; the two rotate about
/// different points, the profile origin and the wheelset's centre).
#[test]
fn a_wheel_turned_on_its_wheelset_is_a_turned_wheelset() {
    let slope = 1.0 / 40.0;
    let (rail, wheel) = (crown(), Line { z0_mm: 0.0, slope: -slope, y_range_mm: [-60.0, 60.0] });
    let (roll, yaw) = (0.001f64, 0.005f64);
    for side in [Side::Right, Side::Left] {
        let m = side.sign();
        let turned = case(&rail, &wheel, side, Pose { roll_rad: m * roll, yaw_rad: m * yaw, ..Pose::default() });
        let design = nalgebra::Vector3::new(0.0, 750.0, 460.0);
        let turn = nalgebra::Rotation3::from_axis_angle(&nalgebra::Vector3::x_axis(), roll)
            * nalgebra::Rotation3::from_axis_angle(&nalgebra::Vector3::z_axis(), yaw);
        let d = turn * design - design;
        let deviation = WheelDeviation { position: [d.x, m * d.y, d.z, m * roll, m * yaw, 0.0], velocity: [0.0; 6] };
        let mut flexible = case(&rail, &wheel, side, Pose::default());
        flexible.wheelset.deviation = deviation;
        let (a, b) = (normal_contact(&turned, None).unwrap(), normal_contact(&flexible, None).unwrap());
        assert!((a.z_ws_mm - b.z_ws_mm).abs() < 1e-9, "{side:?}: z_ws {} {}", a.z_ws_mm, b.z_ws_mm);
        assert_eq!(a.patches.len(), b.patches.len());
        for (p, q) in a.patches.iter().zip(&b.patches) {
            let (f, g) = (&p.geometry.frame, &q.geometry.frame);
            assert!((f.origin - g.origin).norm() < 1e-9, "{side:?}: {:?} {:?}", f.origin, g.origin);
            assert!((f.delta_rad - g.delta_rad).abs() < 1e-12, "{side:?}: {} {}", f.delta_rad, g.delta_rad);
            assert!((p.fn_n - q.fn_n).abs() < 1e-6 * p.fn_n, "{side:?}: {} {}", p.fn_n, q.fn_n);
        }
        // Without the deviation the wheel stands elsewhere: the comparison can fail.
        let rigid = normal_contact(&case(&rail, &wheel, side, Pose::default()), None).unwrap();
        assert!((rigid.z_ws_mm - a.z_ws_mm).abs() > 0.1, "{side:?}: {} {}", rigid.z_ws_mm, a.z_ws_mm);
    }
}

#[test]
fn a_rail_profile_keeps_its_placements_by_track_and_ds_and_they_are_the_placements_made_afresh() {
    use super::profile::{Profile, ProfileKind, ProfileOptions};
    let arc = crown();
    let y: Vec<f64> = (0..=140).map(|k| 0.5 * k as f64 - 35.0).collect();
    let z: Vec<f64> = y.iter().map(|&y| arc.z_mm(y).unwrap()).collect();
    let rail = Profile::from_points(&y, &z, ProfileKind::Rail, &ProfileOptions::default()).unwrap();
    let wheel = Line { z0_mm: 0.0, slope: 0.0, y_range_mm: [-60.0, 60.0] };
    let at = case(&rail, &wheel, Side::Right, Pose::default());
    let first = RailSetup::new(&at).unwrap();
    let again = RailSetup::new(&at).unwrap();
    assert!(std::sync::Arc::ptr_eq(&first.placement, &again.placement));
    // Another DS: another placement, the same rail placed.
    let other = RailSetup::new(&WheelRailCase { ds_mm: 0.1, ..at }).unwrap();
    assert!(!std::sync::Arc::ptr_eq(&first.placement, &other.placement));
    assert_eq!(other.placement.origin_mm, first.placement.origin_mm);
    // A kept placement is the one made afresh, bit for bit.
    let fresh = RailSetup::afresh(&at).unwrap();
    assert!(!std::sync::Arc::ptr_eq(&first.placement, &fresh.placement));
    assert_eq!(first.placement.origin_mm, fresh.placement.origin_mm);
    assert_eq!(first.placement.angle_rad, fresh.placement.angle_rad);
    assert_eq!(first.placement.mesh, fresh.placement.mesh);
}
