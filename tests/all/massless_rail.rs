//! Issue 44 item 2: a rail deflecting on springs under the contact forces (`[massless_rail]`,
//! CONTACT's F = 3) against CONTACT's printed results for the Manchester benchmark's right wheel
//! (reference/contact_wheelrail/examples/mbench_massless_right, computed by CONTACT from this
//! project's exported deck) and its left wheel (testbank/generated_hunt/mbench_massless_left), and
//! against the balance it solves: the left wheel as CONTACT balances it (not the right's mirror),
//! the height given (N = 0) the same state as FZ prescribed (N = 1) at the force it finds.

use crate::common::root;
use creepbench::comparison::references::contact_output::wheelrail::read;
use creepbench::comparison::references::contact_wheelrail::{compare_case, Deviation};
use creepbench::comparison::references::wheelrail_cases::measure;
use creepbench::pipeline::wheelrail::CaseResult;
use creepbench::pipeline::wheelrail_scene::run_scene;
use creepbench::scene::wheelrail::WheelRailScene;

fn scene_text(name: &str) -> String {
    std::fs::read_to_string(root().join(format!("scenes/wheelrail/{name}.toml"))).unwrap()
}

/// The scene `text` read as if it were in scenes/wheelrail/, solved case by case.
fn run(text: &str) -> Vec<(u64, CaseResult)> {
    let scene = WheelRailScene::from_toml(text, &root().join("scenes/wheelrail")).unwrap();
    run_scene(&scene).unwrap().cases
}

/// DY_DEFL (the side's own y) and DZ_DEFL [mm].
/// The scene's cases and their deviations from CONTACT's printed output `ref_out` (under
/// reference/), each with the gate's bound (counts exact, 1.5 half-units otherwise).
type Run = (Vec<(u64, CaseResult)>, Vec<(Deviation, f64)>);

fn deviations(scene: &str, ref_out: &str) -> Run {
    let cases = run(&scene_text(scene));
    let printed = read(&root().join("reference").join(ref_out)).unwrap();
    let counts = ["n_patches", "npot", "ncon", "nadh", "nslip"];
    let devs = cases
        .iter()
        .flat_map(|(case, r)| compare_case(*case, r, 0, printed.iter().find(|p| u64::from(p.case) == *case).unwrap()))
        .map(|d| {
            let bound = if counts.contains(&d.quantity) { 0.0 } else { 1.5 };
            (d, bound)
        })
        .collect();
    (cases, devs)
}

fn deflection(r: &CaseResult) -> [f64; 2] {
    r.rail_deflection_mm.expect("a massless rail's deflection")
}

/// FZ prescribed: every case's forces, positions, creepages and counts within CONTACT's printed
/// digits (the gate's rules, 1.5 half-units; counts exact), DY_DEFL and DZ_DEFL where CONTACT
/// prints them (its first case: -0.0728 and 0.1000 mm); case 1's CKSI of -9.9e-8 excepted, set by
/// CONTACT's stopping tolerance on the lateral balance (a declared gap, 4.89 half-units of its
/// 1e-10 floor).
#[test]
fn the_massless_rail_with_fz_prescribed_against_contact() {
    let (cases, devs) = deviations("mbench_massless_right", "contact_wheelrail/examples/mbench_massless_right.ref_out");
    let off: Vec<String> = devs
        .iter()
        .filter(|(d, _)| !(d.contact_case == 1 && d.quantity == "cksi"))
        .filter(|(d, bound)| measure(d) > *bound)
        .map(|(d, _)| format!("{d:?}"))
        .collect();
    assert!(off.is_empty(), "{off:#?}");
    let (dy, _) = devs.iter().find(|(d, _)| d.quantity == "dy_defl_mm").unwrap();
    assert!((dy.contact + 0.0728).abs() < 1e-12 && (dy.ours - dy.contact).abs() <= 5e-5, "{dy:?}");
    assert_eq!(devs.iter().filter(|(d, _)| d.quantity.ends_with("_defl_mm")).count(), 2);
    // The flange (y = 8 mm): the rail pushed 0.36 mm to the field side by FY(TR) = 8750 N.
    let [dy4, dz4] = deflection(&cases[3].1);
    assert!((dy4 - (8750.3 - 1500.0) / 20000.0).abs() < 1e-4 && (dz4 - 0.1).abs() < 1e-12, "{dy4} {dz4}");
}

/// The left wheel balances FY(TR) as CONTACT prints it against DY_DEFL along its own y (CONTACT's
/// `get_f_toty` and `wr_set_rail_marker`), so it is not the right one's mirror: at the right
/// scene's mirrored positions every case satisfies FY(TR) - k_y DY_DEFL + F*_y = 0, and at y = 0
/// (a symmetric wheelset) DY_DEFL is -0.0770 mm where the right wheel's is -0.0728 mm, as CONTACT
/// prints them (docs/wheelrail.md, "A massless rail").
#[test]
fn a_left_wheel_on_a_massless_rail_balances_fy_tr_as_contact_prints_it() {
    let right = scene_text("mbench_massless_right");
    let rows = std::fs::read_to_string(root().join("scenes/wheelrail/mbench_massless_right_cases.csv")).unwrap();
    let negate = |v: &str| v.strip_prefix('-').map_or_else(|| format!("-{v}"), str::to_string);
    let mirrored: Vec<String> = rows
        .lines()
        .enumerate()
        .map(|(k, line)| {
            let mut v: Vec<String> = line.split(',').map(str::to_string).collect();
            if k > 0 {
                for c in [1, 3, 4] {
                    v[c] = negate(&v[c]);
                }
            }
            v.join(",")
        })
        .collect();
    let dir = crate::common::tempdir("massless_left");
    std::fs::write(dir.join("l_cases.csv"), mirrored.join("\n")).unwrap();
    let left = right
        .replace("side = \"right\"", "side = \"left\"")
        .replace("name = \"mbench_massless_right\"", "name = \"l\"")
        .replace("file = \"mbench_massless_right_cases.csv\"", "file = \"l_cases.csv\"")
        .replace("../../reference", root().join("reference").to_str().unwrap());
    let left = WheelRailScene::from_toml(left.split("[origin]").next().unwrap(), &dir).unwrap();
    let (r, l) = (run(&right), run_scene(&left).unwrap().cases);
    let (ky, fy_rail) = (20000.0, -1500.0);
    for (case, b) in &l {
        let [dy, dz] = deflection(b);
        let fy = b.models[0].2.track_n[1];
        assert!((fy - ky * dy + fy_rail).abs() < 1e-6 * fy.abs().max(1.0), "case {case}: {fy} {dy}");
        assert!((dz - 0.1).abs() < 1e-12, "case {case}: {dz}");
    }
    let (dy_right, dy_left) = (deflection(&r[0].1)[0], deflection(&l[0].1)[0]);
    assert!((dy_right + 0.0728).abs() < 5e-5 && (dy_left + 0.0770).abs() < 5e-5, "{dy_right} {dy_left}");
}

/// The left wheel's deck written by hand (`mbench_massless_left`, computed by CONTACT with
/// EPS = 1e-9: y = -3 and -7.5 mm, FZ = 12 kN, F*_y = 1.2 kN): every printed value within
/// CONTACT's digits (counts exact), DY_DEFL 0.2251 mm as CONTACT prints it in case 1.
#[test]
fn the_left_wheels_massless_rail_against_contact() {
    let (_, devs) =
        deviations("mbench_massless_left_1", "contact_wheelrail/testbank/generated_hunt/mbench_massless_left.ref_out");
    let off: Vec<String> =
        devs.iter().filter(|(d, bound)| measure(d) > *bound).map(|(d, _)| format!("{d:?}")).collect();
    assert!(off.is_empty(), "{off:#?}");
    let (dy, _) = devs.iter().find(|(d, _)| d.quantity == "dy_defl_mm").unwrap();
    assert!((dy.contact - 0.2251).abs() < 1e-12 && (dy.ours - dy.contact).abs() <= 5e-5, "{dy:?}");
}

/// The height given (N = 0) balances the vertical spring, F_z(tr) = k_z DZ_DEFL - F*_z, and the
/// same rail with FZ prescribed at that F_z (N = 1, DZ_DEFL then from the spring's formula alone)
/// finds the same deflections and the height given.
#[test]
fn the_height_given_and_fz_prescribed_meet_on_a_massless_rail() {
    let text = scene_text("mbench_massless_position_right");
    let cases = run(&text);
    let (kz, fz_rail, ky, fy_rail) = (50000.0, -5000.0, 20000.0, -1500.0);
    for (case, r) in &cases {
        let [dy, dz] = deflection(r);
        let t = r.models[0].2.track_n;
        assert!((t[2] - (kz * dz - fz_rail)).abs() < 1e-6 * t[2], "case {case}: {t:?} {dz}");
        assert!((t[1] - ky * dy + fy_rail).abs() < 1e-6 * t[2], "case {case}: {t:?} {dy}");
    }
    let (_, r4) = &cases[3];
    let fz = r4.models[0].2.track_n[2];
    let rows = format!(
        "contact_case,y_mm,fz_n,roll_rad,yaw_rad,vs_mm_s,vy_mm_s,vz_mm_s,vroll_rad_s,vyaw_rad_s,vpitch_rad_s\n4,8.0,{fz:?},-0.00860600,0.0192,2000,0.0,0.0,0.0,0.0,-4.25348570\n"
    );
    let dir = crate::common::tempdir("massless_force");
    std::fs::write(dir.join("f_cases.csv"), rows).unwrap();
    let force = text
        .replace("vertical = \"position\"", "vertical = \"force\"")
        .replace("file = \"mbench_massless_position_right_cases.csv\"", "file = \"f_cases.csv\"")
        .replace("../../reference", root().join("reference").to_str().unwrap());
    let force = force.split("[origin]").next().unwrap();
    let scene = WheelRailScene::from_toml(force, &dir).unwrap();
    let (_, f) = &run_scene(&scene).unwrap().cases[0];
    let ([dy0, dz0], [dy1, dz1]) = (deflection(r4), deflection(f));
    assert!((dy0 - dy1).abs() < 1e-6 && (dz0 - dz1).abs() < 1e-6, "{dy0} {dy1} {dz0} {dz1}");
    assert!((f.normal.z_ws_mm - (-5.64)).abs() < 1e-6, "{}", f.normal.z_ws_mm);
}
