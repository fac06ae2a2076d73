//! Issue 44 items 4 and 6 (and CONTACT's site B test of module 1) against CONTACT's printed results at their printed precision
//! (reference/contact_wheelrail/examples/): the Manchester benchmark's variants with friction
//! varying across the rail or along the track (mbench_a22_varfric: V = 1, 2) and with KPEC and
//! ANALYN (mbench_a22_kpec: B = 5, 6 with FASTSIM), each deck imported with `creepbench import
//! contact` and its scenes run through the wheel–rail pipeline.

use crate::common::{self, root};
use creepbench::comparison::references::contact_output::wheelrail::read;
use creepbench::comparison::references::contact_wheelrail::{compare_case, Deviation};
use creepbench::pipeline::wheelrail::CaseResult;
use creepbench::pipeline::wheelrail_scene::run_scene;
use creepbench::scene::wheelrail::WheelRailScene;
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::process::Command;

/// The gate's tolerances (the rules "CONTACT wheel-rail" of tolerances.toml): largest deviation
/// allowed per quantity, in half-units of CONTACT's printing (1 = its printed digits reproduced),
/// set to what is measured on CONTACT's meshed wheel surface: the printed digits but the
/// reference's x (3: right case 14 on the flange at 66°, 1.4e-4 mm).
const HALF_UNITS: &[(&str, f64)] = &[
    ("fn_n", 1.5),
    ("fs_n", 1.5),
    ("fy_tr_n", 1.5),
    ("fy_ws_n", 1.5),
    ("fz_tr_n", 1.5),
    ("fz_ws_n", 1.5),
    ("deltcp_rad", 1.5),
    ("ceta", 1.5),
    ("cphi_per_mm", 1.5),
    ("npot", 0.0),
    ("nadh", 0.0),
    ("ncon", 0.0),
    ("nslip", 0.0),
    ("zcp_tr_mm", 1.5),
    ("zcp_r_mm", 1.5),
    ("xcp_tr_mm", 3.0),
    ("ycp_tr_mm", 1.5),
    ("ycp_r_mm", 1.5),
    ("pen_mm", 1.5),
    ("cksi", 1.5),
];

/// The Manchester benchmark's first measured tolerances, on the exact wheel surface (the KPEC
/// deck's exact cases, whose KPEC and ANALYN cases must share their patches): the flange contacts
/// a few digits off in the reference's x and the approach, CONTACT's mesh interpolation against
/// the exact surfaces.
const EXACT_SURFACE_HALF_UNITS: &[(&str, f64)] = &[
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
fn loose(d: &Deviation) -> Option<bool> {
    let within = |abs: f64| Some(d.half_units <= 1.5 || (d.ours - d.contact).abs() <= abs);
    match d.quantity {
        "fx_n" | "fx_tr_n" | "fx_ws_n" => within(1.0),
        "mn_nmm" => within(12.0),
        _ => None,
    }
}

/// Import `deck` (a file of reference/contact_wheelrail/examples/); the scenes written and the
/// command's standard error (its per-case verdicts).
fn import(deck: &str) -> (Vec<PathBuf>, String) {
    let out = common::tempdir(&format!("variants_{deck}"));
    let path = root().join("reference/contact_wheelrail").join(format!("{}.inp", in_reference(deck)));
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .args(["import", "contact", path.to_str().unwrap(), "--out", out.to_str().unwrap(), "--supported-only"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let scenes = String::from_utf8_lossy(&o.stdout).lines().map(PathBuf::from).collect();
    (scenes, String::from_utf8_lossy(&o.stderr).into_owned())
}

/// Where `deck` lies under reference/contact_wheelrail/ (without its extension).
fn in_reference(deck: &str) -> String {
    match deck {
        "iestim_site_b" | "t3_t1_conformal" | "t3_t2_conformal" => format!("testbank/examples_trans/{deck}"),
        _ => format!("examples/{deck}"),
    }
}

/// Every imported case of `deck` run with its scene's model: (case, model, result), and the
/// import's verdicts.
fn runs(deck: &str) -> (Vec<(u64, String, CaseResult)>, String) {
    let (scenes, verdicts) = import(deck);
    let mut out = Vec::new();
    for path in scenes.iter().filter(|p| p.extension().is_some_and(|e| e == "toml")) {
        let mut scene = WheelRailScene::from_file(path).unwrap();
        // On CONTACT's meshed wheel surface, as the gated scenes of scenes/wheelrail.
        scene.wheel_mesh = true;
        let run = run_scene(&scene).unwrap();
        out.extend(run.cases.into_iter().map(|(c, r)| (c, scene.solvers[0].clone(), r)));
    }
    out.sort_by_key(|(c, _, _)| *c);
    (out, verdicts)
}

/// Every imported case of `deck` against the printed results: deviations, cases, verdicts.
fn deviations(deck: &str) -> (Vec<Deviation>, Vec<u64>, String) {
    let (runs, verdicts) = runs(deck);
    let reference = read(&root().join(format!("reference/contact_wheelrail/{}.ref_out", in_reference(deck)))).unwrap();
    let devs = runs
        .iter()
        .flat_map(|(case, _, result)| {
            compare_case(*case, result, 0, reference.iter().find(|r| u64::from(r.case) == *case).unwrap())
        })
        .collect();
    (devs, runs.iter().map(|(c, _, _)| *c).collect(), verdicts)
}

/// The largest deviation per quantity [half-units] with its case.
fn worst(devs: &[Deviation]) -> BTreeMap<&'static str, (f64, u64)> {
    let mut w: BTreeMap<&'static str, (f64, u64)> = BTreeMap::new();
    for d in devs {
        let e = w.entry(d.quantity).or_insert((0.0, 0));
        if d.half_units > e.0 {
            *e = (d.half_units, d.contact_case);
        }
    }
    for (q, (h, c)) in &w {
        println!("{q:>12}: {h:10.2} half-units (case {c})");
    }
    w
}

/// Whether `d` is within the gate's tolerances ([`HALF_UNITS`]: CONTACT's printed digits but the
/// reference's x).
fn within_mbench(d: &Deviation) -> bool {
    within(d, HALF_UNITS)
}

/// Whether `d` is within `limits` [half-units] (1 where a quantity has none), FX and MN as the
/// benchmark takes them.
fn within(d: &Deviation, limits: &[(&str, f64)]) -> bool {
    loose(d).unwrap_or_else(|| d.half_units <= limits.iter().find(|(q, _)| *q == d.quantity).map_or(1.0, |(_, l)| *l))
}

/// V = 1 (μ at each patch's contact angle on the wheel: ALPHA −20°, −10° with μ 0.2, 0.3) and
/// V = 2 (μ at S_WS = 60 mm between SVF 0, 100 mm with μ 0.2, 0.3), on CONTACT's meshed wheel
/// surface: every imported case within the Manchester benchmark's tolerances, case 3 too (y = 5 mm,
/// yaw 12 mrad: two patches 6.9 mm apart whose reference angles CONTACT turns towards each other,
/// D_SEP = 6, D_TURN = 9 mm; patch 1 at −0.24797 rad against CONTACT's −0.2480, −0.1326
/// unturned; 8.5 half-units before the rail's gauge point was found on its spline; its totals
/// FY(TR), FY(WS) 646.30 N, 650.35 N against 646.3 N, 650.4 N, 1.9 and 2.9 half-units before μ was
/// taken at the reference's roll in the yawed wheel's frame as CONTACT reads it); the conformal
/// cases 5 (V = 1: μ per grid row at its inclination) and 7 (V = 2 at S_WS = 70 mm: μ = 0.27),
/// D = 4 at y = 5.5 mm on the flange root, every printed value within its digits (BAR_FN 9897.4
/// against 9897., 9713.6 against 9714.: 0.89 and 0.80 half-units; MN 45.393, 16.815 against
/// 45.39, 16.82; NPOT, NCON, NSLIP exact).
#[test]
fn friction_varying_across_the_rail_and_along_the_track_against_contact() {
    let (devs, cases, verdicts) = deviations("mbench_a22_varfric");
    assert_eq!(cases, [1, 2, 3, 4, 5, 6, 7]);
    assert!(!verdicts.contains("skipped case"), "{verdicts}");
    worst(&devs);
    let conformal: Vec<String> = devs
        .iter()
        .filter(|d| matches!(d.contact_case, 5 | 7) && !loose(d).unwrap_or(d.half_units <= 1.0))
        .map(|d| format!("{d:?}"))
        .collect();
    assert!(conformal.is_empty(), "conformal cases beyond CONTACT's printed digits:\n{}", conformal.join("\n"));
    // 27 printed values per case, CHI and VELOC among them.
    assert_eq!(devs.iter().filter(|d| matches!(d.contact_case, 5 | 7)).count(), 54);
    let failures: Vec<String> = devs.iter().filter(|d| !within_mbench(d)).map(|d| format!("{d:?}")).collect();
    assert!(failures.is_empty(), "{} deviations beyond the tolerances:\n{}", failures.len(), failures.join("\n"));
}

/// The conformal approach with adhesion and two patches (`t3_t1_conformal` case 1: the worn
/// site-B flange and tread at y = 14.74 mm, FZ = 137 kN, 321 elements in adhesion on the tread's
/// patch of 124 rows): every printed value within its digits (worst FS 0.98, FY(WS) 0.96, CETA
/// 0.94 half-units; NPOT, NCON, NADH, NSLIP exact). Its 15 shifts of 0.4 mm continuing it (T = 1,
/// P = 0, D = 4: the tractions carried on the super-grid, rows on the rail's arc length from its
/// origin, the grid widened to the contact of the time before): every value within the gate's
/// rules (CONTACT's printed digits, 1.5 half-units; worst FN 1.25 on the flange's patch), counts
/// exact but case 7's NADH, NSLIP (one element, the declared gap).
#[test]
fn the_conformal_approach_with_adhesion_on_two_patches_against_contact() {
    let (devs, cases, verdicts) = deviations("t3_t1_conformal");
    assert_eq!(cases, (1..=16).collect::<Vec<u64>>(), "{verdicts}");
    worst(&devs);
    for case in 1..=16 {
        let of_case = devs.iter().filter(|d| d.contact_case == case);
        let w = of_case.max_by(|a, b| a.half_units.total_cmp(&b.half_units)).unwrap();
        println!("case {case:>2}: worst {} {:.2} half-units (patch {})", w.quantity, w.half_units, w.patch);
    }
    let steady = |d: &&Deviation| d.contact_case == 1;
    let failures: Vec<String> = devs
        .iter()
        .filter(steady)
        .filter(|d| !loose(d).unwrap_or(d.half_units <= 1.0))
        .map(|d| format!("{d:?}"))
        .collect();
    assert!(failures.is_empty(), "beyond CONTACT's printed digits:\n{}", failures.join("\n"));
    assert!(devs.iter().any(|d| d.quantity == "nadh" && d.contact > 300.0), "{devs:?}");
    // The declared gap: case 7's adhesion and slip counts one element off.
    let counts = |d: &&Deviation| d.contact_case == 7 && matches!(d.quantity, "nadh" | "nslip");
    let gap: Vec<f64> = devs.iter().filter(counts).map(|d| (d.ours - d.contact).abs()).collect();
    assert!(gap.iter().all(|&e| e <= 1.0) && gap.contains(&1.0), "case 7's counts: {gap:?}");
    let shifts: Vec<String> =
        devs.iter().filter(|d| !steady(d) && !counts(d) && !within_mbench(d)).map(|d| format!("{d:?}")).collect();
    assert!(shifts.is_empty(), "shifts beyond the gate's rules:\n{}", shifts.join("\n"));
}

/// Transient rolling on the conformal approach (`t3_t2_conformal`: the steady case of
/// `t3_t1_conformal`, then five steps of DQ = 0.4 mm continuing it, T = 2 with P = 0 and D = 4, at
/// FZ = 137, 117, 127, 137, 137 kN). At 117 kN (case 3) the tread's patch splits in two, 14 mm
/// apart, both continuing it on its widened grid (117 and 116 rows), the flange's the third; at
/// the trial heights between, the two touch as one patch with two sub-patches between D_COMB and
/// D_SEP. Every printed value within the gate's rules (worst FX 1.08 half-units of its printed
/// digit, 0.54 N on case 5's flange patch; FS 0.99, YCP 0.99, CETA 0.98), NPOT, NCON, NADH, NSLIP
/// exact in every case.
#[test]
fn transient_rolling_on_the_conformal_approach_against_contact() {
    let (devs, cases, verdicts) = deviations("t3_t2_conformal");
    assert_eq!(cases, (1..=6).collect::<Vec<u64>>(), "{verdicts}");
    assert!(!verdicts.contains("skipped case"), "{verdicts}");
    worst(&devs);
    for case in 1..=6 {
        let of_case = devs.iter().filter(|d| d.contact_case == case);
        let w = of_case.max_by(|a, b| a.half_units.total_cmp(&b.half_units)).unwrap();
        println!("case {case}: worst {} {:.2} half-units (patch {})", w.quantity, w.half_units, w.patch);
    }
    // Case 3's three patches (the split), two in every other case.
    let patches = |case: u64| devs.iter().filter(|d| d.contact_case == case && d.quantity == "npot").count();
    assert_eq!((1..=6).map(patches).collect::<Vec<usize>>(), [2, 2, 3, 2, 2, 2]);
    let counts = ["npot", "ncon", "nadh", "nslip"];
    let counted: Vec<&Deviation> = devs.iter().filter(|d| counts.contains(&d.quantity)).collect();
    assert!(counted.iter().any(|d| d.quantity == "nadh" && d.contact > 400.0), "{counted:?}");
    assert!(counted.iter().all(|d| d.ours == d.contact), "{counted:?}");
    let failures: Vec<String> = devs.iter().filter(|d| !within_mbench(d)).map(|d| format!("{d:?}")).collect();
    assert!(failures.is_empty(), "beyond the gate's rules:\n{}", failures.join("\n"));
}

/// The KPEC deck: cases 1–3 KPEC, 4–6 ANALYN (both with CONTACT's FASTSIM), 7–9 the exact theory,
/// each at y = 0, 0.5, 5 mm. The imported scenes name `kpec`, `analyn` and `contact`; the exact
/// cases 7 and 8 are within the benchmark's first tolerances (9 is the benchmark's right case 11,
/// two regions blended by CONTACT, see tests/all/wheelrail_mbench.rs). KPEC and ANALYN take their
/// own patches and wheelset height, as CONTACT balances FZ with their own normal forces: ANALYN's
/// cases are CONTACT's to the printed digits, KPEC's within the bounds of their declared gaps
/// (docs/wheelrail.md, "KPEC and ANALYN").
#[test]
fn kpec_and_analyn_against_contact() {
    let (runs, _) = runs("mbench_a22_kpec");
    let models: Vec<(u64, &str)> = runs.iter().map(|(c, m, _)| (*c, m.as_str())).collect();
    let names = ["kpec", "kpec", "kpec", "analyn", "analyn", "analyn", "contact", "contact", "contact"];
    assert_eq!(models, (1..=9).zip(names).collect::<Vec<_>>());
    let reference = read(&root().join("reference/contact_wheelrail/examples/mbench_a22_kpec.ref_out")).unwrap();
    let devs = |case: u64| {
        let (_, _, r) = &runs[case as usize - 1];
        compare_case(case, r, 0, reference.iter().find(|t| u64::from(t.case) == case).unwrap())
    };
    let exact: Vec<Deviation> = [7, 8].into_iter().flat_map(devs).collect();
    worst(&exact);
    let failures: Vec<String> =
        exact.iter().filter(|d| !within(d, EXACT_SURFACE_HALF_UNITS)).map(|d| format!("{d:?}")).collect();
    assert!(failures.is_empty(), "exact cases: {}", failures.join("\n"));
    // Their own patches: the approximations carry FZ at heights of their own.
    for k in 0..6 {
        let (ours, exact_case) = (&runs[k].2, &runs[6 + k % 3].2);
        assert_ne!(ours.normal.z_ws_mm, exact_case.normal.z_ws_mm, "case {}: a height of its own", k + 1);
    }
    let analyn: Vec<Deviation> = (4..=6).flat_map(devs).collect();
    println!("ANALYN against CONTACT's:");
    worst(&analyn);
    let failures: Vec<String> = analyn.iter().filter(|d| !within_mbench(d)).map(|d| format!("{d:?}")).collect();
    assert!(failures.is_empty(), "ANALYN: {}", failures.join("\n"));
    // KPEC at y = 0.5 and 5 mm: within 4.5 half-units (the contact one element off at y = 0.5).
    let kpec: Vec<Deviation> = (2..=3).flat_map(devs).collect();
    println!("KPEC (cases 2, 3) against CONTACT's:");
    worst(&kpec);
    let beyond: Vec<&Deviation> = kpec.iter().filter(|d| !loose(d).unwrap_or(d.half_units <= 4.5)).collect();
    assert!(beyond.is_empty(), "{beyond:?}");
    // KPEC at y = 0: CONTACT's height iteration stopped at FZ = 9982 N; this project's carries 10000
    // (10000.021 N: since KPEC's ellipse is CONTACT's, its force jumps over FZ at this height and
    // the upper height is taken, docs/wheelrail.md "Models"; before, it met FZ within 1e-3 N).
    let fz = devs(1).into_iter().find(|d| d.quantity == "fz_tr_n").unwrap();
    assert_eq!((fz.contact, (fz.ours - 10_000.0).abs() < 0.05), (9982.0, true), "{fz:?}");
}

/// CONTACT's test of the initial estimate on worn profiles (testbank/examples_trans/iestim_site_b:
/// the height prescribed from 1.13 to 1.23 mm and back, one to three patches, μ by contact
/// angle), imported and run on CONTACT's meshed wheel surface: every case's patches are CONTACT's
/// (regions 3 to 6 mm apart blended, 6 to 9 mm apart turned; before, case 9 patch 2's angle was
/// −0.579 rad against CONTACT's −0.368) and every quantity within the Manchester benchmark's
/// tolerances (the shipped scene `scenes/wheelrail/iestim_site_b_1` is gated at CONTACT's digits:
/// `wheelrail_mbench`). On the exact wheel surface the worn flange root's FN is up to 1.8 % below
/// CONTACT's at the same approach (docs/wheelrail.md).
#[test]
fn site_b_cases_are_contacts_on_its_meshed_wheel_surface() {
    let (devs, cases, _) = deviations("iestim_site_b");
    assert_eq!(cases, (1..=21).collect::<Vec<u64>>());
    let w = worst(&devs);
    assert!(w.contains_key("n_patches") && w.contains_key("fn_n"), "{w:?}");
    let failures: Vec<String> = devs.iter().filter(|d| !within_mbench(d)).map(|d| format!("{d:?}")).collect();
    assert!(failures.is_empty(), "{} deviations beyond the tolerances:\n{}", failures.len(), failures.join("\n"));
}
