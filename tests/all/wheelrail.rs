//! The wheel–rail stage end to end on closed forms: a cylindrical wheel on a crowned rail is
//! Hertz's contact, so every model solves Hertz's patch; left and right are mirror images.

use creepbench::physics::Material;
use creepbench::pipeline::wheelrail::{solve, CaseResult};
use creepbench::wheelrail::curve::{Arc, Curve, Line};
use creepbench::wheelrail::rail::{RailPlacement, Track};
use creepbench::wheelrail::side::Side;
use creepbench::wheelrail::wheel::{Pose, Velocity, WheelDeviation, WheelsetGeometry};
use creepbench::wheelrail::{self, Vertical, WheelRailCase};

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
            deviation_velocity: [0.0; 3],
        },
        wheelset: WheelsetGeometry {
            flange_back_distance_mm: 1360.0,
            flange_back_position_mm: -70.0,
            nominal_radius_mm: 460.0,
            deviation: WheelDeviation::NONE,
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
            turn_mm: 12.0,
        },
        wheel_surface: Default::default(),
        search: creepbench::scene::wheelrail::ContactSearch::Locus,
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

/// The Manchester scene with its cases table replaced by `rows` (`vertical` its height mode) in a
/// temporary folder; the `simulate` command's exit status, standard error and the totals' CSV.
fn simulate_rows(vertical: &str, header: &str, rows: &str) -> (Option<i32>, String, Option<String>) {
    simulate_rows_mu(vertical, header, rows, "mu = 0.3")
}

/// [`simulate_rows`] with the scene's `mu = 0.3` replaced by `mu`.
fn simulate_rows_mu(vertical: &str, header: &str, rows: &str, mu: &str) -> (Option<i32>, String, Option<String>) {
    let root = crate::common::root();
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(root.join("scenes/wheelrail/mbench_a22_left.toml")).unwrap();
    let examples = root.join("reference/contact_wheelrail/examples");
    let text = text
        .replace("../../reference/contact_wheelrail/examples", examples.to_str().unwrap())
        .replace("vertical = \"force\"", &format!("vertical = \"{vertical}\""))
        .replace("mu = 0.3", mu)
        .replace("mbench_a22_left_cases.csv", "cases.csv")
        .replace("cases = [1, 21]", "cases = [1, 1]")
        .lines()
        .filter(|l| !["solvers", "contact_output", "patch_cases"].iter().any(|k| l.starts_with(k)))
        .collect::<Vec<_>>()
        .join("\n")
        .replacen("name = ", "solvers = [\"contact\"]\nname = ", 1);
    std::fs::write(dir.path().join("s.toml"), text).unwrap();
    std::fs::write(dir.path().join("cases.csv"), format!("{header}\n{rows}\n")).unwrap();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(dir.path())
        .args(["simulate", "s.toml", "--out", "out"])
        .output()
        .unwrap();
    let csv = std::fs::read_to_string(dir.path().join("out/mbench_a22_left/contact.csv")).ok();
    (o.status.code(), String::from_utf8_lossy(&o.stderr).to_string(), csv)
}

#[test]
fn a_case_without_a_solution_is_an_input_error_and_a_wheel_in_the_air_or_beside_the_rail_a_result() {
    let columns = "vs_mm_s,vy_mm_s,vz_mm_s,vroll_rad_s,vyaw_rad_s,vpitch_rad_s";
    // A load whose patch exceeds the grid limit.
    let header = format!("contact_case,y_mm,fz_n,roll_rad,yaw_rad,{columns}");
    let (code, err, csv) = simulate_rows("force", &header, "1,0.0,1e8,0,0,2000,0,0,0,0,-4.348");
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("scene mbench_a22_left, case 1") && err.contains("exceeds the limit"), "{err}");
    assert!(csv.is_none(), "written despite the error");
    // Profiles that do not overlap laterally with FZ prescribed: no patch, zero forces at height 0,
    // as CONTACT prints it ("NO CONTACT FOUND").
    let (code, err, csv) = simulate_rows("force", &header, "1,200.0,10000,0,0,2000,0,0,0,0,-4.348");
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(csv.unwrap().lines().nth(1), Some("1,0,0,0,0,0,0,0,0,-4.348"));
    // The wheelset 5 mm above the rail (height prescribed): no patch, zero forces, no -0.
    let header = format!("contact_case,y_mm,z_mm,roll_rad,yaw_rad,{columns}");
    let (code, err, csv) = simulate_rows("position", &header, "1,0.0,-5.0,0,0,2000,0,0,0,0,-4.348");
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(csv.unwrap().lines().nth(1), Some("1,0,-5,0,0,0,0,0,0,-4.348"));
}

/// The grid search's gap mesh is refused before it is made when DX and DS would make it beyond
/// `MAX_GAP_MESH_POINTS` (the guard rail with D = 6 at DX = DS = 0.01 mm: 13935 slices by 65962
/// lateral points, 7.4 GB for one array): exit 2 naming the scene, the case and the sizes,
/// nothing written.
#[test]
fn a_grid_search_mesh_beyond_its_limit_is_refused_before_it_is_made() {
    let root = crate::common::root();
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(root.join("scenes/wheelrail/guard_rail_d6_1.toml")).unwrap();
    let text = text
        .replace("../../reference", root.join("reference").to_str().unwrap())
        .replace("dx_mm = 0.5", "dx_mm = 0.01")
        .replace("ds_mm = 0.5", "ds_mm = 0.01");
    std::fs::write(dir.path().join("s.toml"), text).unwrap();
    std::fs::copy(
        root.join("scenes/wheelrail/guard_rail_d6_1_cases.csv"),
        dir.path().join("guard_rail_d6_1_cases.csv"),
    )
    .unwrap();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(dir.path())
        .args(["simulate", "s.toml", "--out", "out"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    let says = format!("gap mesh of 13935 x 65962 points exceeds the limit of {}", wheelrail::MAX_GAP_MESH_POINTS);
    assert!(err.contains("scene guard_rail_d6_1, case 1") && err.contains(&says), "{err}");
    assert!(!dir.path().join("out").exists(), "written despite the error");
}

/// FX_WS prescribed (CONTACT's F = 1): the pitch velocity found gives the exact theory's FX(WS)
/// within 1e-8 FZ and is written with the totals; a force beyond what the patch carries (its mu
/// by contact angle 0.2, though the scene's largest mu is 0.5) stops the run with exit 2 naming
/// the case and fx_ws_n, nothing written.
#[test]
fn fx_ws_prescribed_finds_the_pitch_velocity_and_a_force_the_patch_cannot_carry_is_refused() {
    let header = "contact_case,y_mm,fz_n,roll_rad,yaw_rad,vs_mm_s,vy_mm_s,vz_mm_s,vroll_rad_s,vyaw_rad_s,fx_ws_n";
    let force = "force\"\nlongitudinal = \"force";
    let (code, err, csv) = simulate_rows(force, header, "1,0.0,10000,0,0,2000,0,0,0,0,-2000");
    assert_eq!(code, Some(0), "{err}");
    let csv = csv.unwrap();
    let row: Vec<f64> = csv.lines().nth(1).unwrap().split(',').map(|v| v.parse().unwrap()).collect();
    assert!((row[6] + 2000.0).abs() <= 1e-8 * 10000.0, "FX(WS) {}", row[6]);
    // CONTACT's printed VPITCH for this case (mbench_fx_ws_left.ref_out, case 1): -4.3509212.
    assert!((row[9] + 4.3509212).abs() < 5e-8, "VPITCH {}", row[9]);
    let mu = "mu_by = \"contact_angle\"\nmu_at = [-1.0, -0.5]\nmu_values = [0.5, 0.2]";
    let (code, err, csv) = simulate_rows_mu(force, header, "1,0.0,10000,0,0,2000,0,0,0,0,2500", mu);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("scene mbench_a22_left, case 1 (y_mm = 0): fx_ws_n` = 2500"), "{err}");
    assert!(err.contains("no pitch velocity gives FX(WS) = 2500 N"), "{err}");
    assert!(csv.is_none(), "written despite the error");
}
