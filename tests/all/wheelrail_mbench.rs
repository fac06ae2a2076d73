//! The gate of the wheel–rail suite (issue 44 item 7): `check --suite scenes/wheelrail` runs the
//! Manchester contact benchmark (case, left and right wheels, 21 lateral shifts and yaw
//! angles each) and compares the exact solver case by case and patch by patch with CONTACT's
//! printed results (reference/contact_wheelrail/: the decks' `.ref_out` and the library's
//! `contact_mbench.ref_out`), by the rules "CONTACT wheel-rail" of `tolerances.toml`; a perturbed
//! result fails it, naming scene, case, patch, quantity and both values.

use creepbench::comparison::compare::{failures, Finding};
use creepbench::comparison::references::wheelrail_cases::{self, WheelRailCases, AGAINST};
use creepbench::comparison::references::References;
use creepbench::comparison::tolerances;
use creepbench::pipeline::wheelrail_scene::run_scene;
use creepbench::scene::wheelrail::WheelRailScene;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The largest measure per quantity (half-units of CONTACT's printing), with where it is.
fn worst(fs: &[&Finding]) -> BTreeMap<String, (f64, String)> {
    let mut w: BTreeMap<String, (f64, String)> = BTreeMap::new();
    for f in fs {
        let e = w.entry(f.quantity.clone()).or_insert((0.0, String::new()));
        if f.diff > e.0 {
            *e = (f.diff, format!("{}: {}", f.scene, f.note));
        }
    }
    w
}

#[test]
fn the_wheelrail_suite_passes_its_gate_against_contacts_printed_results() {
    // `run --suite scenes/wheelrail`: its verdict is `check`'s (the same rules and findings).
    let gate = &crate::common::wheelrail_suite_run().outcome;
    let ours: Vec<&Finding> = gate.findings.iter().filter(|f| f.against == AGAINST).collect();
    for (q, (h, at)) in worst(&ours) {
        println!("{q:>22}: {h:10.2} half-units ({at})");
    }
    let fails = failures(&gate.findings);
    assert!(fails.is_empty(), "{} gated deviations:\n{}", fails.len(), fails.join("\n"));
    // The benchmark's two scenes, each against its deck's output and the library's, the KPEC
    // deck's full-solution cases 7-9 and the two worn-profile decks: 25 quantities each, all gated.
    let gated = ours.iter().filter(|f| f.gated).count();
    println!("{gated} gated comparisons of {}", ours.len());
    assert!(gated >= 7 * 25, "{gated}");
    for scene in ["mbench_a22_left", "mbench_a22_right"] {
        let sources: std::collections::BTreeSet<&str> = ours
            .iter()
            .filter(|f| f.scene == scene)
            .filter_map(|f| f.note.split('(').nth(1).map(|s| s.trim_end_matches(')')))
            .collect();
        assert!(sources.iter().any(|s| s.starts_with("contact_mbench.ref_out")), "{scene}: {sources:?}");
        assert!(sources.iter().any(|s| s.starts_with(scene)), "{scene}: {sources:?}");
    }
    // No benchmark case is a declared gap (right case 11: the test below); four of the testbank's
    // cases are (29: FS, CONTACT's stopping tolerance; 36, 37 on the conformal approach), the KPEC
    // deck's KPEC cases 1-3, the interrupted crossing's
    // cases 24, 28 (CETA), the rounded wheel flat's total FY (CONTACT's residue of a symmetric
    // contact), mbench_brute's case 30 (FN of a two-element patch) and mbench_locus's case 30 (FS
    // of a three-element patch), both CONTACT's stopping tolerance, and t3_t1_conformal's case 7
    // (one element's adhesion, CONTACT's stopping tolerance), each bounded at its measured gap
    // (tolerances.toml).
    let all_gaps: Vec<&&Finding> = ours.iter().filter(|f| f.quantity.ends_with(wheelrail_cases::GAP_SUFFIX)).collect();
    let testbank_gaps = [29, 36, 37];
    let in_testbank = |f: &&&Finding| f.scene.starts_with("testbank_") && testbank_gaps.contains(&f.step.unwrap_or(0));
    let kpec = |f: &&&Finding| f.scene.starts_with("mbench_a22_kpec_") && (1..=3).contains(&f.step.unwrap_or(0));
    let totforce = |f: &&&Finding| f.scene == "m1_totforce_1" && [66, 70, 72, 73, 80].contains(&f.step.unwrap_or(0));
    let intrup = |f: &&&Finding| f.scene == "mbench_intrup_1" && [24, 28].contains(&f.step.unwrap_or(0));
    let rounded_flat = |f: &&&Finding| f.scene == "rounded_flat_d09_1";
    let brute = |f: &&&Finding| f.scene == "mbench_brute_1" && f.step == Some(30);
    let locus = |f: &&&Finding| f.scene == "mbench_locus_1" && f.step == Some(30);
    let conformal_shift = |f: &&&Finding| f.scene == "t3_t1_conformal_1" && f.step == Some(7);
    // The massless rail (F = 3): CKSI at y = 0 to CONTACT's stopping tolerance (case 1), and with
    // the height given every case (CONTACT moves that height).
    let massless = |f: &&&Finding| {
        (f.scene == "mbench_massless_right" && f.step == Some(1)) || f.scene == "mbench_massless_position_right"
    };
    // examples_conformal: test-rollers2 cases 3, 4 (the yawed sphere's free-rolling residues),
    // 7, 8, 9 (the yawed and the tilted roller's) and groove_li 1-8 (the lateral residues of a
    // symmetric contact in a deep groove, 5-8 with Blanco's correction); test-rollers3 cases 1, 5, 6, 9 (the rigid slip on the
    // actual surfaces, D = 3: the free-rolling lateral residues of symmetric contacts).
    let conformal_decks = |f: &&&Finding| {
        let residues = ["test_rollers2_3", "test_rollers2_7", "test_rollers2_8", "test_rollers2_9"];
        let surface_slip = ["test_rollers3_1", "test_rollers3_5", "test_rollers3_6", "test_rollers3_9"];
        residues.contains(&f.scene.as_str())
            || surface_slip.contains(&f.scene.as_str())
            || f.scene.starts_with("groove_li_")
    };
    // The planar approach in a sequence of shifts (issue 45): d3_shift_site_b case 4, CONTACT's
    // grid of its trial heights' patch links (D = 3; the same deck with D = 2 as far off).
    let planar_sequence = |f: &&&Finding| f.scene == "d3_shift_site_b" && f.step == Some(4);
    assert!(
        all_gaps.iter().all(|f| in_testbank(f)
            || kpec(f)
            || totforce(f)
            || intrup(f)
            || rounded_flat(f)
            || brute(f)
            || locus(f)
            || conformal_shift(f)
            || conformal_decks(f)
            || massless(f)
            || planar_sequence(f)),
        "{all_gaps:?}"
    );
    let outside: Vec<_> = all_gaps.iter().filter(|f| planar_sequence(f) && !(f.gated && f.passed())).collect();
    assert!(outside.is_empty(), "d3_shift_site_b 4 within its bound: {outside:?}");
    assert!(
        all_gaps.iter().filter(|f| conformal_shift(f)).all(|f| f.gated && f.passed()),
        "t3_t1_conformal 7 within its bound"
    );
    assert!(
        all_gaps.iter().filter(|f| conformal_decks(f)).all(|f| f.gated && f.passed()),
        "examples_conformal's gaps within their bounds"
    );
    assert!(all_gaps.iter().filter(|f| brute(f)).all(|f| f.gated && f.passed()), "mbench_brute 30 within its bound");
    assert!(all_gaps.iter().filter(|f| locus(f)).all(|f| f.gated && f.passed()), "mbench_locus 30 within its bound");
    assert!(
        all_gaps.iter().filter(|f| massless(f)).all(|f| f.gated && f.passed()),
        "the massless rail's gaps within their bounds"
    );
    assert!(
        all_gaps.iter().filter(|f| intrup(f)).all(|f| f.gated && f.passed()),
        "mbench_intrup 24, 28 within their bound"
    );
    assert!(
        all_gaps.iter().filter(|f| totforce(f)).all(|f| f.gated && f.passed()),
        "m1_totforce cases 66-80 within their bound"
    );
    assert!(all_gaps.iter().filter(|f| kpec(f)).all(|f| f.gated && f.passed()), "KPEC's gaps within their bounds");
    assert!(
        all_gaps.iter().filter(|f| rounded_flat(f)).all(|f| f.gated && f.passed()),
        "rounded_flat_d09's FY within its bound"
    );
    for case in testbank_gaps {
        let scene = format!("testbank_{case}");
        let of_case: Vec<_> = all_gaps.iter().filter(|f| f.scene == scene).collect();
        assert!(of_case.iter().any(|f| f.gated) && of_case.iter().all(|f| f.passed()), "{scene}: {of_case:?}");
    }
    // The reproduced testbank cases (rail deviations, frictionless, smoothing, MIRRORZ) and the
    // moving rail's decks: gated under the benchmark's rules, no gap. Cases 22, 27, 28, 31 and 34
    // (smoothed measured profiles, a flange at 74 deg, a guard rail, the worn flange root) since
    // the wheel is meshed at its profile spline's parameter DS apart (CONTACT's
    // `trim_wheel_profile`). Case 35 (the conformal approach over 173 rows from the worn flange to
    // the tread) since the rail is met along the rows' normals that start beside its profile's
    // lateral range (its creepages' least squares over CONTACT's 4198 interpenetrating elements).
    for scene in [
        "testbank_18",
        "testbank_19",
        "testbank_22",
        "testbank_23",
        "testbank_27",
        "testbank_28",
        "testbank_30",
        "testbank_31",
        "testbank_32",
        "testbank_33",
        "testbank_34",
        "testbank_35",
        "mbench_rail_velocity_left",
        // Cases written by hand off the benchmark's path (negative shifts, 5-50 kN, braking and
        // traction, a yaw rate) and on the worn site-B profiles, computed by CONTACT.
        "mbench_off_design_left",
        "mbench_off_design_right",
        "site_b_off_design_left",
        "site_b_off_design_right",
        "site_b_varfric_right",
        "mbench_a22_varfric_6",
        "site_b_two_patch_left",
        "site_b_two_patch_right",
        // The right wheel's flange with yaw, cut from CONTACT's performance decks (the contact
        // locus as CONTACT splines it through the wheel profile's points).
        "mbench_flange_yaw_right",
        "mbench_flange_yaw_coarse_right",
        // A wheel rolled 5 degrees on its wheelset (CONTACT's flexible wheelset deviations, E = 5):
        // steady rolling, a shift from rest and 81 steps of transient rolling from rest.
        "m1_steady_roll_1",
        "m1_catt_shift_1",
        "m1_trans_roll_1",
        // Every deviation and rate on the benchmark's wheels, computed by CONTACT.
        "mbench_wheel_deviation_left",
        "mbench_wheel_deviation_right",
        // Frictional heating (H = 3) and friction of the surface temperature (L = 6) on a
        // circular wheel: each patch's MAX(T1,T2) among the gated quantities; the law across the
        // rail (V = 1) in the third.
        "m1_tempdep_1",
        "m1_tempdep_2",
        "m1_tempdep_3",
        // Out-of-round wheels (a measured wheel flat, wheel slices; CONTACT's grid search) and
        // rails with parts missing (interruptions: the nose absent on the first slices).
        "wheelflat_1",
        "chalmers_flat_fz125_1",
        "mbench_intrup_1",
        "cw_interrupt_1",
        // CONTACT's brute-force grid search (D = 5) on rail slices, with and without interruptions.
        "mbench_brute_1",
        "wing_brute_1",
        "cross_brute_1",
        "two_patches_1",
        "cw_interrupt_2",
        // The grid search for steep slopes (D = 6) on a guard rail and on the UK crossing, and the
        // guard rail with D = 5, whose coarser mesh misses its contact in three cases (decks
        // computed by CONTACT).
        "guard_rail_d6_1",
        "guard_rail_d5_1",
        "mbench_steep_1",
        // A sphere on a flat plane placed absolutely (examples_conformal/test-rollers2 case 1),
        // yawed (case 2) and rolled (case 5) on CONTACT's wheel mesh; mbench_conf case 1 (the
        // conformal approach with the flange in contact, yaw and cant).
        "test_rollers2_1",
        "test_rollers2_2",
        "test_rollers2_5",
        "mbench_conf_1",
        // KPEC (B = 5) on the benchmark's right wheel, cases 1-3 of mbench_a22_kpec run by CONTACT
        // with EPS = 1e-9: the KPEC deck's declared gaps are CONTACT's stopping tolerance (case
        // 1's FY within its measured 1.7 half-units, tolerances.toml).
        "mbench_a22_kpec_eps9_1",
        // Decks written by hand for the hidden-case hunt (issues 44, 45: DX = 0.5, DS = 0.4 mm on
        // the flange with negative shifts, FX_WS prescribed on the left wheel with mu by contact
        // angle, the conformal approach with FZ prescribed, the UK crossing's contact locus with FZ
        // prescribed), computed by CONTACT and imported as they are: on the exact wheel surface,
        // what the import wrote before, they missed by 10 to 1563 half-units.
        "mbench_neg_coarse_right_1",
        "mbench_neg_coarse_right_3",
        "mbench_neg_coarse_right_4",
        "mbench_fx_varfric_left_1",
        "mbench_conf_force_1",
        "uk_crossing_locus_force_1",
        // The left wheel on a rail placed absolutely (RAILY0 in the track's y on either side).
        "sphere_left_absolute_1",
    ] {
        let of: Vec<_> = ours.iter().filter(|f| f.scene == scene).collect();
        assert!(of.len() >= 20 && of.iter().all(|f| f.gated && f.passed()), "{scene}: {of:?}");
    }
    for scene in ["m1_tempdep_1", "m1_tempdep_2", "m1_tempdep_3"] {
        assert!(ours.iter().any(|f| f.scene == scene && f.quantity == "temp_max_c" && f.gated), "{scene}");
    }
    // FX_WS prescribed (F = 1): every quantity gated, VPITCH found among them (beyond CONTACT's
    // stopping tolerance).
    for scene in ["mbench_fx_ws_left", "mbench_fx_ws_right"] {
        let of: Vec<_> = ours.iter().filter(|f| f.scene == scene).collect();
        assert!(of.len() >= 25 && of.iter().all(|f| f.gated && f.passed()), "{scene}: {of:?}");
        assert!(of.iter().any(|f| f.quantity == "vpitch_rad_s"), "{scene}: {of:?}");
    }
    // The worn-profile decks (iestim_site_b: one to three patches, height prescribed; force_site_b:
    // FZ prescribed) gated on CONTACT's meshed wheel surface (a case printed and not run, or the
    // reverse, fails the gate above).
    for scene in ["iestim_site_b_1", "force_site_b_1"] {
        let gated: Vec<&&Finding> = ours.iter().filter(|f| f.scene == scene && f.gated).collect();
        assert!(gated.len() >= 25 && gated.iter().all(|f| f.passed()), "{scene}: {gated:?}");
    }
    // Every rule of the label decides a comparison here (the shipped suites' golden results hold
    // no wheel–rail scene), but "case", which only a missing case meets (the test below).
    let decides = |r: &&tolerances::Rule| {
        r.against == AGAINST && !r.is_catch_all() && r.quantity != "case" && !r.quantity.ends_with("_known_gap")
    };
    for r in tolerances::defaults().iter().filter(decides) {
        let n = ours.iter().filter(|f| r.covers(f.against, &f.scene, &f.solver, &f.quantity)).count();
        assert!(n > 0, "{} decides nothing: {r:?}", r.origin);
    }
}

/// Right case 11 (two regions 6.8 mm apart, blended as CONTACT blends them, on its meshed wheel
/// surface), a declared gap until the rail's gauge point was found on its spline, is reproduced:
/// every quantity gated, none beyond its rule, against both sources (FY(TR) 131.61 N against
/// 131.6 N; 131.85 N before).
#[test]
fn right_case_11_is_reproduced() {
    let path = root().join("scenes/wheelrail/mbench_a22_right.toml");
    let mut scene = WheelRailScene::from_file(&path).unwrap();
    scene.solvers = vec!["contact".into()];
    scene.cases.retain(|c| c.contact_case == 11);
    let origin = scene.origin.clone().map(|mut o| {
        o.cases = [11, 11];
        o
    });
    let refs = References::load(Path::new(&root().join("reference"))).unwrap();
    let set = refs.get::<WheelRailCases>(AGAINST).unwrap();
    let findings = set.compare_run(&run_scene(&scene).unwrap(), origin.as_ref(), tolerances::defaults());
    assert!(failures(&findings).is_empty(), "{:?}", failures(&findings));
    assert!(findings.iter().filter(|f| f.gated).count() >= 2 * 25, "{findings:?}");
    assert!(!findings.iter().any(|f| f.quantity.ends_with(wheelrail_cases::GAP_SUFFIX)), "{findings:?}");
}

/// One case of the right wheel (14: full slip on the flange), its result perturbed: the gate
/// fails, its message naming scene, case, patch, quantity and both values; unperturbed it passes.
#[test]
fn a_perturbed_wheelrail_result_fails_the_gate() {
    let path = root().join("scenes/wheelrail/mbench_a22_right.toml");
    let mut scene = WheelRailScene::from_file(&path).unwrap();
    scene.solvers = vec!["contact".into()];
    scene.cases.retain(|c| c.contact_case == 14);
    let origin = scene.origin.clone().map(|mut o| {
        o.cases = [14, 14];
        o
    });
    let refs = References::load(Path::new(&root().join("reference"))).unwrap();
    let set = refs.get::<WheelRailCases>(AGAINST).unwrap();
    let run = run_scene(&scene).unwrap();
    let judge = |run| set.compare_run(run, origin.as_ref(), tolerances::defaults());
    let real = judge(&run);
    assert!(failures(&real).is_empty(), "{:?}", failures(&real));
    assert!(real.iter().filter(|f| f.gated).count() >= 2 * 25);

    // FN of patch 1 up by 1 % (about 100 N; CONTACT prints it to 10 N or finer): one failure per
    // source (the deck's output and the library's).
    let mut bad = run.clone();
    bad.cases[0].1.models[0].1[0].fn_n *= 1.01;
    let fails = failures(&judge(&bad));
    assert_eq!(fails.len(), 2, "{fails:?}");
    for line in &fails {
        for part in ["scene mbench_a22_right", "metric fn_n", "step 14", "case 14 patch 1", "ours ", "CONTACT "] {
            assert!(line.contains(part), "{part:?} not in {line}");
        }
    }
    // A case CONTACT printed that the scene did not run.
    let mut short = run.clone();
    short.cases.clear();
    let fails = failures(&judge(&short));
    assert!(fails.iter().any(|l| l.contains("case 14: printed in")), "{fails:?}");
}

/// The report of `run --suite scenes/wheelrail` counts its wheel–rail scenes in its head, names
/// their suite in the verdict's table (the gated count is the gate's), says how many comparisons
/// are declared gaps, and lists as closest to their tolerance only comparisons that are not.
#[test]
fn the_reports_verdict_names_the_wheelrail_suite_and_sets_declared_gaps_apart() {
    let run = crate::common::wheelrail_suite_run();
    let md = std::fs::read_to_string(run.report_dir().join("validation.md")).unwrap();
    let scenes = std::fs::read_dir(root().join("scenes/wheelrail"))
        .unwrap()
        .flatten()
        .filter(|e| e.path().extension().is_some_and(|x| x == "toml"))
        .count();
    assert!(md.contains(&format!("from {scenes} wheel–rail scene(s).")), "{}", &md[..600]);
    let findings = &run.outcome.findings;
    let gated = findings.iter().filter(|f| f.gated).count();
    assert!(md.contains(&format!("| wheelrail | {gated} | 0 |")), "{}", &md[..1500]);
    let gaps = findings.iter().filter(|f| f.gated && f.quantity.ends_with(wheelrail_cases::GAP_SUFFIX)).count();
    assert!(gaps > 0);
    let line = format!("{gaps} of the gated comparisons are of declared-gap cases");
    assert!(md.contains(&line), "{line}\n{}", &md[..1500]);
    let verdict = md.split("## Contents").next().unwrap();
    let closest = verdict.split("declared gaps aside:").nth(1).expect("a list of the closest comparisons");
    assert_eq!(closest.lines().filter(|l| l.starts_with("- ")).count(), 5, "{closest}");
    assert!(!closest.contains(wheelrail_cases::GAP_SUFFIX), "{closest}");
}

#[test]
fn kpecs_height_search_finds_fz_where_its_force_falls_as_the_wheel_sinks() {
    // The Manchester path at 200 positions (benches/scenes/mbench_200_right.toml), right wheel,
    // KPEC: at y = 0.05 mm its force falls from 98 % to 60 % of FZ where its two patches merge,
    // at y = 6.55 mm (flange) it falls as the wheel sinks near the final round's target. The
    // height search once followed the secant back through the fall until its 100 iterations ran
    // out ("no wheelset height gives FZ"), and a flat secant made a NaN height that hung the
    // contact search.
    let path = root().join("benches/scenes/mbench_200_right.toml");
    let mut scene =
        WheelRailScene::from_toml(&std::fs::read_to_string(&path).unwrap(), path.parent().unwrap()).unwrap();
    scene.cases.retain(|c| [2, 132].contains(&c.contact_case));
    let y_mm: Vec<f64> = scene.cases.iter().map(|c| c.y_mm).collect();
    assert!(y_mm.len() == 2 && (y_mm[0] - 0.05).abs() < 1e-12 && (y_mm[1] - 6.55).abs() < 1e-12, "{y_mm:?}");
    scene.solvers = vec!["kpec".into(), "analyn".into()];
    let run = run_scene(&scene).expect("KPEC and ANALYN find the height at both positions");
    for (case, result) in &run.cases {
        for (model, _, totals) in &result.models {
            let fz_n = totals.track_n[2];
            // FZ = 10 kN prescribed (the search's tolerance 1e-9 of it; here 1e-6).
            assert!((fz_n - 10000.0).abs() < 1e-2, "case {case} {model}: FZ(TR) {fz_n} N");
        }
    }
}
