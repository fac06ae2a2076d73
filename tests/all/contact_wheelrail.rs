//! CONTACT's module 1 (wheel–rail) on reference/contact_wheelrail/ (CONTACT's public decks,
//! verbatim): the reader of its printed results (`contact_output::wheelrail`) on every `.ref_out`
//! (case and patch counts, values by hand with their printed resolution) and the reader of its
//! decks (`import::contact::wheelrail_deck`) on every `.inp` (case counts, values read and kept
//! between cases, unsupported features named, errors at their line and column), the two checked
//! against each other case by case.

use crate::common::root;
use creepbench::comparison::references::contact_output::printed::Printed;
use creepbench::comparison::references::contact_output::wheelrail::{
    self, Along, Forward, NormalMeasure, PatchHistory, Ratio, Support, WheelRailCase, WheelSide,
};
use creepbench::import::contact::features::WheelRailFeature;
use creepbench::import::contact::wheelrail_deck::{
    self, FrictionValues, FrictionVariation, PitchInput, ProfileFormat, RailPlacement, Side, TrackFourth, Vertical,
};
use std::path::PathBuf;

fn dir() -> PathBuf {
    root().join("reference/contact_wheelrail")
}

fn output(rel: &str) -> Vec<WheelRailCase> {
    wheelrail::read(&dir().join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

fn deck(rel: &str) -> Vec<wheelrail_deck::WheelRailCase> {
    wheelrail_deck::read(&dir().join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"))
}

/// A printed value and its resolution, against the text.
fn printed(p: Printed, value: f64, half_unit: f64) {
    assert!((p.value - value).abs() <= 1e-12 * value.abs().max(1.0), "{p:?} != {value}");
    assert!((p.half_unit - half_unit).abs() <= 1e-9 * half_unit, "{p:?}: half unit != {half_unit}");
}

/// Per `.ref_out`: the module-1 cases printed (case number: patches).
const OUTPUTS: [(&str, &[(u32, usize)]); 8] = [
    ("examples/mbench_a22_kpec.ref_out", &[(1, 1), (2, 1), (3, 1), (4, 1), (5, 1), (6, 1), (7, 1), (8, 1), (9, 1)]),
    ("examples/mbench_a22_left.ref_out", &[]),
    ("examples/mbench_a22_right.ref_out", &[]),
    ("examples/mbench_a22_varfric.ref_out", &[(1, 1), (2, 1), (3, 2), (4, 1), (5, 1), (6, 1), (7, 1)]),
    ("testbank/contact_mbench.ref_out", &[]),
    ("testbank/examples_trans/force_site_b.ref_out", &[(1, 1), (2, 2), (3, 2), (4, 2)]),
    (
        "testbank/examples_trans/iestim_site_b.ref_out",
        &[
            (1, 1),
            (2, 1),
            (3, 2),
            (4, 2),
            (5, 3),
            (6, 3),
            (7, 3),
            (8, 3),
            (9, 3),
            (10, 2),
            (11, 2),
            (12, 2),
            (13, 3),
            (14, 3),
            (15, 3),
            (16, 3),
            (17, 3),
            (18, 2),
            (19, 2),
            (20, 1),
            (21, 1),
        ],
    ),
    (
        "testbank/testbank.ref_out",
        &[
            (18, 1),
            (19, 1),
            (20, 1),
            (21, 1),
            (22, 1),
            (23, 1),
            (27, 1),
            (28, 1),
            (29, 1),
            (30, 1),
            (31, 2),
            (32, 1),
            (33, 3),
            (34, 2),
            (35, 1),
            (36, 1),
            (37, 1),
            (38, 2),
            (39, 3),
        ],
    ),
];

#[test]
fn every_printed_module1_case_and_patch_is_read() {
    for (rel, expected) in OUTPUTS {
        let cases = output(rel);
        let got: Vec<(u32, usize)> = cases.iter().map(|c| (c.case, c.patches.len())).collect();
        let expected: Vec<(u32, usize)> = match (rel, expected.is_empty()) {
            (r, true) if r.contains("contact_mbench") => (1..=21).flat_map(|c| [(c, 1), (c, 1)]).collect(),
            (_, true) => (1..=21).map(|c| (c, 1)).collect(),
            _ => expected.to_vec(),
        };
        assert_eq!(got, expected, "{rel}");
        for c in &cases {
            let h = c.heading.unwrap_or_else(|| panic!("{rel} case {}: no heading", c.case));
            assert_eq!(h.patches as usize, c.patches.len(), "{rel} case {}", c.case);
            assert!(c.forces.is_some(), "{rel} case {}", c.case);
            for (k, p) in c.patches.iter().enumerate() {
                assert_eq!(p.index as usize, k + 1, "{rel} case {}", c.case);
                assert!(p.totals.is_some() && p.statistics.is_some() && p.reference.is_some(), "{rel} case {}", c.case);
            }
        }
    }
}

#[test]
fn sides_supports_and_result_elements_as_printed() {
    let side = |rel: &str| output(rel).iter().map(|c| c.side().unwrap()).collect::<Vec<_>>();
    assert!(side("examples/mbench_a22_left.ref_out").iter().all(|&s| s == WheelSide::Left));
    assert!(side("examples/mbench_a22_right.ref_out").iter().all(|&s| s == WheelSide::Right));
    let lib = output("testbank/contact_mbench.ref_out");
    for c in &lib {
        let (re, s) = (c.result_element.unwrap(), c.side().unwrap());
        assert_eq!(s, if re == 1 { WheelSide::Left } else { WheelSide::Right }, "case {} element {re}", c.case);
    }
    let tb = output("testbank/testbank.ref_out");
    let roller: Vec<u32> =
        tb.iter().filter(|c| c.heading.unwrap().support == Support::Roller).map(|c| c.case).collect();
    assert_eq!(roller, [20, 21]);
    assert!(matches!(tb[2].position.unwrap().along, Along::RollerXMm(_)));
    assert!(matches!(tb[2].velocity.unwrap().forward, Forward::RollerPitchRadS(_)));
    // Case 36: the massless rail prints its deflections.
    let c36 = tb.iter().find(|c| c.case == 36).unwrap();
    assert!(c36.rail_deflection.is_some());
    // Case 35 uses the conformal approach (D = 4): BAR_FN, TILDE_FN.
    let c35 = tb.iter().find(|c| c.case == 35).unwrap().patches[0].totals.unwrap();
    assert!(c35.conformal && matches!(c35.normal, NormalMeasure::TildeFnN(_)));
    // Case 39 continues case 38's patches (P = 0): its patch 2 splits off patch 1, patch 3 is 2.
    let c39: Vec<PatchHistory> = tb.last().unwrap().patches.iter().map(|p| p.history.clone()).collect();
    assert_eq!(
        c39,
        [PatchHistory::Previous(vec![1]), PatchHistory::Previous(vec![1]), PatchHistory::Previous(vec![2])]
    );
    assert!(tb[0].patches.iter().all(|p| p.history == PatchHistory::NotPrinted));
}

#[test]
fn mbench_a22_left_case_1_by_hand() {
    let cases = output("examples/mbench_a22_left.ref_out");
    let c = &cases[0];
    assert_eq!((c.case, c.line, c.result_element), (1, 10, None));
    let f = c.forces.unwrap();
    printed(f.fx_tr_n, 0.2783, 5e-5);
    printed(f.fy_tr_n, -36.24, 5e-3);
    printed(f.fz_tr_n, 10000.0, 0.5);
    printed(f.fz_ws_n, 10000.0, 0.5);
    let pos = c.position.unwrap();
    printed(pos.z_mm, 0.1981, 5e-5);
    printed(c.velocity.unwrap().vpitch_rad_s, -4.3481181, 5e-8);
    let p = &c.patches[0];
    assert_eq!((p.index, p.line, &p.history), (1, 73, &PatchHistory::NotPrinted));
    let r = p.reference.unwrap();
    printed(r.ycp_tr_mm, -751.8726, 5e-5);
    printed(r.deltcp_tr_rad, 0.0290, 5e-5);
    printed(r.ycp_r_mm, 8.66, 5e-5);
    printed(p.wheel_reference.unwrap().ycp_w_mm, -1.8726, 5e-5);
    let k = p.kinematics.unwrap();
    printed(k.cksi, -5.665e-5, 5e-9);
    printed(k.veloc_mm_s, 2000.0, 0.5);
    printed(k.cphi_per_mm, -6.302e-5, 5e-9);
    let t = p.totals.unwrap();
    printed(t.fn_n, 9997.0, 0.5);
    printed(t.fx_n, 0.2783, 5e-5);
    printed(t.fs_n, 253.6, 5e-2);
    printed(t.mn_nmm, 4605.0, 0.5);
    printed(t.fric_power_nmm_s, -0.4677, 5e-5);
    assert!(matches!(t.normal, NormalMeasure::FnOverGMm2(g) if g.value == 0.1219));
    assert!(matches!(t.fs_ratio, Ratio::OverFstatFn(r) if r.value == 8.458e-2));
    printed(t.approach_mm, 1.596e-2, 5e-6);
    printed(t.pmax_mpa.unwrap(), 338.3, 5e-2);
    let s = p.statistics.unwrap();
    assert_eq!((s.npot, s.ncon, s.nadh, s.nslip, s.inorm, s.itang), (3999, 1291, 943, 348, 1, 1));
}

#[test]
fn the_right_wheel_prints_its_lateral_values_as_computed() {
    // mbench_a22_right case 1 is mbench_a22_left case 1 mirrored: FY, FS, MN change sign.
    let (l, r) = (output("examples/mbench_a22_left.ref_out"), output("examples/mbench_a22_right.ref_out"));
    let (fl, fr) = (l[0].forces.unwrap(), r[0].forces.unwrap());
    assert_eq!((fl.fy_tr_n.value, fr.fy_tr_n.value), (-36.24, 36.24));
    let (tl, tr) = (l[0].patches[0].totals.unwrap(), r[0].patches[0].totals.unwrap());
    assert_eq!((tl.fs_n.value, tr.fs_n.value, tl.mn_nmm.value, tr.mn_nmm.value), (253.6, -253.6, 4605.0, -4605.0));
    assert_eq!(tl.fn_n, tr.fn_n);
}

/// Per deck: its module-1 case numbers are those of its `.ref_out`.
const DECKS: [&str; 14] = [
    "examples/mbench_a22_kpec",
    "examples/mbench_a22_left",
    "examples/mbench_a22_right",
    "examples/mbench_a22_varfric",
    "testbank/examples_trans/force_site_b",
    "testbank/examples_trans/iestim_site_b",
    "testbank/testbank",
    "testbank/examples_conformal/groove_li",
    "testbank/examples_conformal/mbench_conf",
    "testbank/examples_conformal/test-rollers2",
    "testbank/examples_conformal/test-rollers3",
    "testbank/generated_blanco_variants/groove_li_var1",
    "testbank/generated_blanco_variants/groove_li_var2",
    "testbank/generated_blanco_variants/groove_li_var4",
];

#[test]
fn every_deck_reads_the_cases_its_output_prints() {
    for stem in DECKS {
        let (d, o) = (deck(&format!("{stem}.inp")), output(&format!("{stem}.ref_out")));
        let numbers = |v: Vec<u32>| v;
        assert_eq!(
            numbers(d.iter().map(|c| c.number as u32).collect()),
            numbers(o.iter().map(|c| c.case).collect()),
            "{stem}"
        );
        for (c, p) in d.iter().zip(&o) {
            let side = if c.digits.side() == Side::Left { WheelSide::Left } else { WheelSide::Right };
            assert_eq!(Some(side), p.side(), "{stem} case {}", c.number);
            assert_eq!(
                c.digits.roller_rig(),
                p.heading.unwrap().support == Support::Roller,
                "{stem} case {}",
                c.number
            );
            // The position the deck gives is the one printed (to its printed digits), where
            // printed (E >= 1).
            let (given, Some(shown)) = (c.state.position.unwrap(), p.position) else { continue };
            let near = |x: f64, q: Printed| (x - q.value).abs() <= q.half_unit * (1.0 + 1e-9);
            assert!(near(given.y_mm, shown.y_mm), "{stem} case {}: Y {} vs {:?}", c.number, given.y_mm, shown.y_mm);
            assert!(near(given.yaw_rad, shown.yaw_rad), "{stem} case {}: YAW", c.number);
            // With the massless rail (F = 3) CONTACT prints the height it found for the
            // deflected rail (testbank case 36: 2.0855 for the given 2.0884).
            if let (Vertical::ZMm(z), false) = (given.vertical, c.digits.f == 3) {
                assert!(near(z, shown.z_mm), "{stem} case {}: Z {z} vs {:?}", c.number, shown.z_mm);
            }
            if let Vertical::FzN(fz) = given.vertical {
                // CONTACT's total-force iteration stops near FZ (KPEC's approximate normal
                // problem 0.2 % off).
                let fz_tr = p.forces.unwrap().fz_tr_n.value;
                assert!((fz_tr - fz).abs() <= 5e-3 * fz, "{stem} case {}: FZ {fz} vs {fz_tr}", c.number);
            }
        }
    }
}

#[test]
fn mbench_a22_left_case_2_by_hand_with_what_case_1_left_in_force() {
    let cases = deck("examples/mbench_a22_left.inp");
    assert_eq!(cases.len(), 21);
    let c = &cases[1];
    assert_eq!((c.number, c.line, c.digits.l, c.digits.d, c.digits.z, c.digits.e, c.digits.g), (2, 30, 1, 1, 0, 2, 1));
    let s = &c.state;
    let pos = s.position.unwrap();
    assert_eq!((pos.along, pos.y_mm, pos.vertical), (wheelrail_deck::Along::SMm(0.0), 0.5, Vertical::FzN(10000.0)));
    assert_eq!((pos.roll_rad, pos.yaw_rad, pos.pitch_rad), (-0.00002304, 0.0012, 0.0));
    let v = s.velocity.unwrap();
    assert_eq!(
        (v.forward, v.sixth, v.per_step),
        (wheelrail_deck::Forward::VsMmS(2000.0), PitchInput::VpitchRadS(-4.34741340), false)
    );
    // Kept from case 1.
    let d = s.discretisation.as_ref().unwrap();
    assert_eq!((d.method, d.dx_mm, d.ds_mm, d.dqrel, d.d_sep_mm, d.d_comb_mm), (2, 0.2, 0.2, 1.0, 8.0, 4.0));
    assert_eq!(d.a_sep_rad, std::f64::consts::FRAC_PI_2);
    let t = s.track.unwrap();
    assert_eq!(t.placement, RailPlacement::Gauge { gaught_mm: 14.0, gaugsq: 0, gaugwd_mm: 1435.0 });
    assert_eq!((t.fourth, t.curv_per_mm), (TrackFourth::CantRad(0.0), 0.0));
    let w = s.wheelset.unwrap();
    assert_eq!((w.fbdist_mm, w.fbpos_mm, w.nomrad_mm, w.ytape_mm), (1360.0, -70.0, 460.0, None));
    let (rail, wheel) = (s.rail_profile.as_ref().unwrap(), s.wheel_profile.as_ref().unwrap());
    assert_eq!(
        (rail.file.as_str(), rail.place.line, rail.format()),
        ("MBench_UIC60_v3.prr", 21, ProfileFormat::Simpack)
    );
    assert_eq!((wheel.file.as_str(), wheel.mirror_y, wheel.scale, wheel.smooth), ("MBench_S1002_v3.prw", 0, 1.0, 0.0));
    let f = s.friction.as_ref().unwrap();
    assert_eq!(
        (f.law, f.variation, f.sets[0].values),
        (0, FrictionVariation::Uniform, FrictionValues::Coulomb { fstat: 0.3, fkin: 0.3 })
    );
    let m = s.material.as_ref().unwrap();
    assert_eq!((m.influence, m.poiss, m.gg_mpa), (2, [0.28, 0.28], [82000.0, 82000.0]));
    assert_eq!(s.solver.as_ref().unwrap().eps, 1e-5);
    assert!(c.unsupported().is_empty(), "{:?}", c.unsupported());
    // The first case's P and I are CONTACT's (P = 2: a new sequence).
    assert_eq!((cases[0].digits.p, cases[0].digits.i), (2, 0));
}

#[test]
fn friction_varying_across_the_rail_or_along_the_track_is_read_and_named() {
    let cases = deck("examples/mbench_a22_varfric.inp");
    assert_eq!(cases.len(), 7);
    // Cases 1-5: two sets across the rail (ALPHA in degrees); 6, 7: along the track (SVF [mm]).
    let f = cases[4].state.friction.as_ref().unwrap();
    assert_eq!((f.law, f.variation, f.sets.len()), (0, FrictionVariation::AcrossRail, 2));
    assert_eq!(f.sets[0].at, Some((-20f64).to_radians()));
    assert_eq!(f.sets[1].values, FrictionValues::Coulomb { fstat: 0.3, fkin: 0.3 });
    let f = cases[6].state.friction.as_ref().unwrap();
    assert_eq!((f.variation, f.sets[0].at, f.sets[1].at), (FrictionVariation::AlongTrack, Some(0.0), Some(100.0)));
    assert_eq!(f.sets[0].values, FrictionValues::Coulomb { fstat: 0.2, fkin: 0.2 });
    // Carried (a note): the planar contact takes one mu per patch, the conformal one (cases 5
    // and 7, D = 4) one per grid row.
    for c in &cases {
        let used: Vec<(WheelRailFeature, bool)> = c.features().iter().map(|u| (u.feature, u.supported)).collect();
        assert!(used.contains(&(WheelRailFeature::VaryingFriction, true)), "case {}: {used:?}", c.number);
        let conformal = used.contains(&(WheelRailFeature::ContactApproach, true));
        assert_eq!(conformal, [5, 7].contains(&c.number), "case {}", c.number);
        assert!(
            c.unsupported().is_empty(),
            "case {}: {:?}",
            c.number,
            c.unsupported().iter().map(|u| u.name).collect::<Vec<_>>()
        );
    }
    assert_eq!((cases[0].digits.s, cases[0].state.subsurface_points), (3, true));
}

#[test]
fn the_testbank_module1_cases_by_hand() {
    let cases = deck("testbank/testbank.inp");
    let numbers: Vec<usize> = cases.iter().map(|c| c.number).collect();
    assert_eq!(numbers, [18, 19, 20, 21, 22, 23, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39]);
    let case = |n: usize| cases.iter().find(|c| c.number == n).unwrap();
    let unsupported = |n: usize| case(n).unsupported().iter().map(|u| u.feature).collect::<Vec<_>>();
    // 19: absolute rail placement, a circular wheel.
    let t = case(19).state.track.unwrap();
    assert_eq!(t.placement, RailPlacement::Absolute { gaught_mm: -1.0, raily0_mm: 750.0, railz0_mm: 0.0 });
    // 20: a roller rig, NOMRADR in the track line, RPITCH first in the velocity line.
    assert_eq!(case(20).state.track.unwrap().fourth, TrackFourth::RollerRadiusMm(22.7020));
    // The roller rig with the grid search (D = 5) is carried, and case 21's (frictionless, T = 0).
    assert!(!unsupported(20).contains(&WheelRailFeature::RollerRig));
    assert!(unsupported(21).is_empty());
    // 21: a compressible sheet, FLXZ after the material.
    assert_eq!(case(21).state.material.as_ref().unwrap().flxz, Some(0.00007429));
    // 22: friction across the rail, ALPHA given in radians (-0.5236, -0.3491).
    assert_eq!(case(22).state.friction.as_ref().unwrap().sets[1].at, Some(-0.3491));
    // 30: profile options (PRFOPT = 1) and MIRRORZ = 1.
    let rail = case(30).state.rail_profile.as_ref().unwrap();
    assert_eq!((rail.format(), rail.mirror_z, rail.prfopt), (ProfileFormat::Miniprof, 1, 1));
    assert_eq!(rail.curation.unwrap().kinkhigh_rad, 30f64.to_radians());
    // 34: D_TURN given; 33: its default.
    assert_eq!(case(33).state.discretisation.as_ref().unwrap().d_turn_mm(), 9.0);
    assert_eq!(case(34).state.discretisation.as_ref().unwrap().d_turn_given_mm, Some(14.0));
    // 36, 37: the massless rail, DYSTEP0 given and defaulted.
    let (m36, m37) = (case(36).state.massless_rail.unwrap(), case(37).state.massless_rail.unwrap());
    assert_eq!(
        (m36.ky_n_mm, m36.fy_n, m36.dystep0_mm, m37.fy_n, m37.dystep0_mm),
        (10000.0, -68230.0, 0.75, -68130.0, 1.0)
    );
    // The massless rail itself is carried ([massless_rail]); under the conformal approach it is not.
    assert!(!unsupported(36).contains(&WheelRailFeature::MasslessRail));
    // 38: a backslash kept in the file name; 39: shifts per step (T = 1) keeping case 38's profiles.
    assert_eq!(case(38).state.rail_profile.as_ref().unwrap().file, "profiles\\site_b_hr.prr");
    let v = case(39).state.velocity.unwrap();
    assert_eq!((v.per_step, v.sixth), (true, PitchInput::VpitchRadS(-0.0000086667)));
    assert_eq!(case(39).state.wheel_profile, case(38).state.wheel_profile);
    // 39 continues case 38's shift (P = 0): supported (a sequence of shifts), nothing unsupported.
    assert!(!unsupported(39).contains(&WheelRailFeature::TransientContact));
    let supported = case(39).features().into_iter().filter(|u| u.supported).map(|u| u.feature).collect::<Vec<_>>();
    assert!(supported.contains(&WheelRailFeature::TransientContact), "{supported:?}");
}

#[test]
fn approximate_normal_problems_are_named_per_case() {
    let cases = deck("examples/mbench_a22_kpec.inp");
    let named: Vec<bool> = cases
        .iter()
        .map(|c| c.features().iter().any(|u| u.feature == WheelRailFeature::ApproximateNormalProblem && u.supported))
        .collect();
    assert_eq!(named, [true, true, true, true, true, true, false, false, false]);
    assert!(cases.iter().all(|c| c.unsupported().is_empty()));
    let message = cases[0]
        .features()
        .iter()
        .find(|u| u.feature == WheelRailFeature::ApproximateNormalProblem)
        .unwrap()
        .to_string();
    assert!(message.starts_with("B = 5, M = 3: approximate normal problems (KPEC, ANALYN) with FASTSIM"), "{message}");
    // Without FASTSIM (case 2 with M = 0) KPEC is refused.
    let text = std::fs::read_to_string(dir().join("examples/mbench_a22_kpec.inp")).unwrap();
    let elastic = wheelrail_deck::parse("kpec.inp", &text.replacen(" 0111302 ", " 0111002 ", 1)).unwrap();
    let message = elastic[1].unsupported().iter().map(|u| u.to_string()).collect::<Vec<_>>().join("; ");
    assert!(
        message.starts_with("B = 5, M = 0: approximate normal problems (KPEC, ANALYN) without FASTSIM"),
        "{message}"
    );
}

#[test]
fn a_malformed_deck_names_file_line_and_column() {
    let text = std::fs::read_to_string(dir().join("examples/mbench_a22_left.inp")).unwrap();
    let bad = text.replacen("  1360.0  -70.0   460.0", "  1360.0  -7x.0   460.0", 1);
    let e = wheelrail_deck::parse("mbench_a22_left.inp", &bad).unwrap_err();
    let input: creepbench::error::InputError = e.into();
    let message = input.to_string();
    assert!(message.contains("mbench_a22_left.inp:23:11"), "{message}");
    assert!(message.contains("-7x.0"), "{message}");
    let err = creepbench::error::Error::Input(input);
    assert_eq!(err.exit_code(), 2);
}
