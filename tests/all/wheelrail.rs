//! The wheel–rail stage end to end on closed forms: a cylindrical wheel on a crowned rail is
//! Hertz's contact, so every model solves Hertz's patch; left and right are mirror images.

use creepbench::physics::Material;
use creepbench::pipeline::wheelrail::{solve, CaseResult};
use creepbench::wheelrail::curve::{Arc, Curve, Line};
use creepbench::wheelrail::rail::{RailPlacement, Track};
use creepbench::wheelrail::side::Side;
use creepbench::wheelrail::wheel::{Pose, Velocity, WheelsetGeometry};
use creepbench::wheelrail::{Vertical, WheelRailCase};

const MODELS: [&str; 8] = ["contact", "fastsim", "uba", "linear", "she", "polach", "fastrip", "relaxation"];

fn case<'a>(rail: &'a dyn Curve, wheel: &'a dyn Curve, side: Side) -> WheelRailCase<'a> {
    let m = side.sign();
    WheelRailCase {
        side,
        rail,
        wheel,
        track: Track {
            placement: RailPlacement::Absolute { y_mm: 750.0, z_mm: 0.0 },
            cant_rad: 0.0,
            deviation_mm_rad: [0.0; 3],
        },
        wheelset: WheelsetGeometry {
            flange_back_distance_mm: 1360.0,
            flange_back_position_mm: -70.0,
            nominal_radius_mm: 460.0,
        },
        pose: Pose { yaw_rad: m * 0.0005, ..Pose::default() },
        velocity: Velocity { vs_mm_s: 2000.0, vpitch_rad_s: -2000.0 / 459.9, ..Velocity::default() },
        vertical: Vertical::Force { fz_n: 10000.0 },
        dx_mm: 0.2,
        ds_mm: 0.2,
        separation: creepbench::wheelrail::patch::Separation {
            angle_rad: std::f64::consts::FRAC_PI_2,
            distance_mm: 8.0,
            combine_mm: 4.0,
        },
        material: Material::from_g(82000.0, 0.28),
    }
}

fn run(side: Side) -> CaseResult {
    let rail = Arc { radius_mm: 300.0, centre_y_mm: 0.0, half_width_mm: 35.0, concave: false };
    let wheel = Line { z0_mm: 0.0, slope: 0.0, y_range_mm: [-60.0, 60.0] };
    let models: Vec<String> = MODELS.iter().map(|s| s.to_string()).collect();
    solve(&case(&rail, &wheel, side), &models, 0.3).unwrap()
}

#[test]
fn hertz_patch_for_every_model_and_mirrored_sides() {
    let (right, left) = (run(Side::Right), run(Side::Left));
    for (r, l) in right.models.iter().zip(&left.models) {
        let (model, pr, tr) = r;
        let (_, pl, tl) = l;
        println!(
            "{model:>10}: FN {:.3} FX {:.4} FS {:.4} MN {:.4} | FTR {:?}",
            pr[0].fn_n, pr[0].fx_n, pr[0].fs_n, pr[0].mn_nmm, tr.track_n
        );
        assert!((pr[0].fx_n - pl[0].fx_n).abs() <= 1e-9 * pr[0].fn_n, "{model}: FX mirrored");
        assert!((pr[0].fs_n + pl[0].fs_n).abs() <= 1e-9 * pr[0].fn_n, "{model}: FS mirrored");
        assert!((tr.track_n[1] + tl.track_n[1]).abs() <= 1e-9 * pr[0].fn_n, "{model}: FY mirrored");
    }
    let (_, _, exact) = &right.models[0];
    // The height iteration stops at a relative force error of 1e-9 (wheelrail::vertical::FORCE_TOL).
    assert!((exact.track_n[2] - 10000.0).abs() < 2e-9 * 10000.0, "FZ(TR) {}", exact.track_n[2]);
}
