//! Issue 45, shifts from rest (CONTACT's T = 1 with P = 2) over profiles: the grid anchored in the
//! rail's material as CONTACT anchors it, checked against the anchor CONTACT prints per patch
//! (SPINXO, SPINYO: the reference seen from the grid's origin `mpot`), and the bad input a shift
//! refuses. The forces, references, shifts and element counts are the gate's
//! (`scenes/wheelrail/t1_*`, `testbank_38`: `wheelrail_mbench`).

use crate::common::root;
use creepbench::pipeline::wheelrail_scene::run_scene;
use creepbench::scene::wheelrail::WheelRailScene;

fn scene(name: &str) -> WheelRailScene {
    let path = root().join("scenes/wheelrail").join(format!("{name}.toml"));
    let text = std::fs::read_to_string(&path).unwrap();
    WheelRailScene::from_toml(&text, path.parent().unwrap()).unwrap()
}

/// CONTACT's printed (SPINXO, SPINYO) of every patch of every case of a `.ref_out`, in order.
fn printed_spin_centres(deck: &str) -> Vec<Vec<[f64; 2]>> {
    let path = root().join("reference/contact_wheelrail/testbank/examples_trans").join(deck);
    let text = std::fs::read_to_string(path).unwrap();
    let mut cases: Vec<Vec<[f64; 2]>> = Vec::new();
    let mut lines = text.lines();
    while let Some(line) = lines.next() {
        if line.trim_start().starts_with("Case ") {
            cases.push(Vec::new());
        } else if line.split_whitespace().eq(["SPINXO", "SPINYO"]) {
            let v: Vec<f64> = lines.next().unwrap().split_whitespace().map(|x| x.parse().unwrap()).collect();
            cases.last_mut().unwrap().push([v[0], v[1]]);
        }
    }
    cases
}

/// Half a unit of the last digit of CONTACT's 4-significant-digit print of `v`.
fn half_unit(v: f64) -> f64 {
    0.5 * 10f64.powi(v.abs().log10().floor() as i32 - 3)
}

#[test]
fn the_grid_is_anchored_where_contact_anchors_it() {
    // t1_zws: S_WS = 0 (case 1) and 0.4 mm (cases 2-5), two and three patches.
    let printed = printed_spin_centres("t1_zws.ref_out");
    let mut checked = 0;
    for name in ["t1_zws_1", "t1_zws_2"] {
        let run = run_scene(&scene(name)).unwrap();
        for (case, result) in &run.cases {
            let theirs = &printed[*case as usize - 1];
            assert_eq!(theirs.len(), result.normal.patches.len(), "case {case}");
            for (p, [sx, sy]) in result.normal.patches.iter().zip(theirs) {
                let [ax, as_] = p.geometry.grid.anchor_mm;
                assert!((-ax - sx).abs() <= half_unit(*sx), "case {case}: SPINXO {} vs {sx}", -ax);
                assert!((-as_ - sy).abs() <= half_unit(*sy), "case {case}: SPINYO {} vs {sy}", -as_);
                // The grid's element centres lie on the anchor's lattice.
                let g = &p.geometry.grid;
                let (i, j) = ((g.x0_mm + 0.5 * g.dx_mm - ax) / g.dx_mm, (g.s0_mm + 0.5 * g.ds_mm - as_) / g.ds_mm);
                assert!((i - i.round()).abs() < 1e-9 && (j - j.round()).abs() < 1e-9, "case {case}: {i}, {j}");
                assert_eq!([i.round() as i64, j.round() as i64], g.first_index);
                checked += 1;
            }
        }
    }
    assert_eq!(checked, 11);
}

#[test]
fn a_shift_refuses_what_it_does_not_solve() {
    let dir = root().join("scenes/wheelrail");
    let text = std::fs::read_to_string(dir.join("t1_zws_1.toml")).unwrap();
    let read = |t: &str| WheelRailScene::from_toml(t, &dir);
    assert!(read(&text).is_ok());
    // FASTSIM and the UBA follow a shift with their own tractions; a model without a history of
    // one is refused, named with the motion.
    assert!(read(&text.replace("solvers = [\"contact\"]", "solvers = [\"contact\", \"fastsim\", \"uba\"]")).is_ok());
    let e = read(&text.replace("solvers = [\"contact\"]", "solvers = [\"contact\", \"linear\"]")).unwrap_err();
    assert!(e.field == "solvers" && e.value.contains("linear") && e.allowed.contains("motion = \"shift\""), "{e:?}");
    let e = read(&text.replace("motion = \"shift\"", "motion = \"shift\"\nfrictionless = true")).unwrap_err();
    assert!(e.field.contains("motion") && e.allowed.contains("not frictionless"), "{e:?}");
    let e = read(&text.replace("motion = \"shift\"", "motion = \"slide\"")).unwrap_err();
    assert!(e.field.contains("motion"), "{e:?}");
}

/// Runs the shipped scene `name` and checks each transient step's grid anchor against the
/// (SPINXO, SPINYO) CONTACT printed in `ref_out` (a steady first case: the grid on the
/// reference); the run and the number of patches checked.
fn anchors_against_contact(name: &str, ref_out: &str) -> (creepbench::pipeline::wheelrail_scene::SceneRun, usize) {
    let printed = printed_spin_centres(ref_out);
    let run = run_scene(&scene(name)).unwrap();
    let mut checked = 0;
    for (case, result) in &run.cases {
        let theirs = &printed[*case as usize - 1];
        for (k, p) in result.normal.patches.iter().enumerate() {
            let [ax, as_] = p.geometry.grid.anchor_mm;
            if *case == 1 {
                assert!(theirs.is_empty() && [ax, as_] == [0.0, 0.0], "steady: the grid on the reference");
                continue;
            }
            let [sx, sy] = theirs[k];
            assert!((-ax - sx).abs() <= half_unit(sx), "case {case}: SPINXO {} vs {sx}", -ax);
            assert!((-as_ - sy).abs() <= half_unit(sy), "case {case}: SPINYO {} vs {sy}", -as_);
            checked += 1;
        }
    }
    (run, checked)
}

/// Transient rolling after a steady case (CONTACT's T = 3 then T = 2, P = 0; `t3_t2_force`): the
/// steady case's grid lies on its reference, each transient step's on CONTACT's super-grid (x from
/// the wheelset, s the rail profile's arc length), whose anchor CONTACT prints as (SPINXO, SPINYO);
/// the step carries the previous tractions (the forces move off the steady ones by many printed
/// digits, as CONTACT's: the gate compares them, `scenes/wheelrail/t3_t2_force_1`).
#[test]
fn transient_rolling_is_anchored_where_contact_anchors_it() {
    let (run, checked) = anchors_against_contact("t3_t2_force_1", "t3_t2_force.ref_out");
    assert_eq!(run.cases.len(), 6);
    assert_eq!(checked, 15);
    // Patch 1's FX: steady −40455 N (CONTACT −4.045e4), after one step −40070 N (−4.007e4).
    let fx = |case: usize| run.cases[case].1.models[0].1[0].fx_n;
    assert!((fx(0) - fx(1)).abs() > 300.0, "{} vs {}", fx(0), fx(1));
}

/// The same on the conformal approach (`t3_t2_conformal`, D = 4): each transient step's grid on
/// the super-grid, its rows at the rail profile's arc length, the anchor CONTACT prints as
/// (SPINXO, SPINYO) in every patch of the five steps, case 3's three too.
#[test]
fn conformal_transient_rolling_is_anchored_where_contact_anchors_it() {
    let (_, checked) = anchors_against_contact("t3_t2_conformal_1", "t3_t2_conformal.ref_out");
    assert_eq!(checked, 11);
}

#[test]
fn transient_rolling_refuses_what_it_does_not_solve() {
    let dir = root().join("scenes/wheelrail");
    let text = std::fs::read_to_string(dir.join("t3_t2_force_1.toml")).unwrap();
    let read = |t: &str| WheelRailScene::from_toml(t, &dir);
    assert!(read(&text).is_ok());
    // The UBA follows transient rolling with its own tractions; FASTSIM has no memory in rolling.
    assert!(read(&text.replace("solvers = [\"contact\"]", "solvers = [\"contact\", \"uba\"]")).is_ok());
    let e = read(&text.replace("solvers = [\"contact\"]", "solvers = [\"contact\", \"fastsim\"]")).unwrap_err();
    assert!(e.field == "solvers" && e.value.contains("fastsim") && e.allowed.contains("no memory"), "{e:?}");
    assert!(e.allowed.contains("rolling_sequence"), "{e:?}");
    let e = read(&text.replace("dq_rel = 1.0", "dq_rel = 1.0\nfrictionless = true")).unwrap_err();
    assert!(e.field.contains("motion") && e.allowed.contains("not frictionless"), "{e:?}");
    let e = read(&text.replace("motion = \"rolling_sequence\"", "motion = \"rolling\"")).unwrap_err();
    assert!(e.field.contains("dq_rel") && e.allowed.contains("rolling_sequence"), "{e:?}");
    let e = read(&text.replace("dq_rel = 1.0", "dq_rel = 0.0")).unwrap_err();
    assert!(e.field.contains("dq_rel"), "{e:?}");
    let e = read(&text.replace("dq_rel = 1.0", "dq_rel = 1.0\nstart = \"now\"")).unwrap_err();
    assert!(e.field.contains("start") && e.allowed.contains("rest"), "{e:?}");
    let shift = std::fs::read_to_string(dir.join("t1_zws_1.toml")).unwrap();
    let e = read(&shift.replace("motion = \"shift\"", "motion = \"shift\"\nstart = \"rest\"")).unwrap_err();
    assert!(e.field.contains("start") && e.allowed.contains("rolling_sequence"), "{e:?}");
}

/// A shift continuing a steady case (CONTACT's T = 3 then T = 1, P = 0; `t3_t1_force`): the
/// shift's grid on CONTACT's material-fixed super-grid (its anchor CONTACT's SPINXO, SPINYO), and
/// its forces those of the steady tractions carried over and shifted (the gate compares them with
/// CONTACT's digits, `scenes/wheelrail/t3_t1_force_1`): the same shift from rest is far off.
#[test]
fn a_shift_continues_the_steady_case_before_it() {
    let printed = printed_spin_centres("t3_t1_force.ref_out");
    let continued = scene("t3_t1_force_1");
    let run = run_scene(&continued).unwrap();
    assert_eq!(run.cases.len(), 2);
    let (case, result) = &run.cases[1];
    let theirs = &printed[*case as usize - 1];
    assert_eq!(theirs.len(), result.normal.patches.len());
    for (p, [sx, sy]) in result.normal.patches.iter().zip(theirs) {
        let [ax, as_] = p.geometry.grid.anchor_mm;
        assert!((-ax - sx).abs() <= half_unit(*sx), "SPINXO {} vs {sx}", -ax);
        assert!((-as_ - sy).abs() <= half_unit(*sy), "SPINYO {} vs {sy}", -as_);
    }
    // The shift alone, from rest at the same position (T = 1, P = 2).
    let text = std::fs::read_to_string(root().join("scenes/wheelrail/t3_t1_force_1.toml")).unwrap();
    let alone =
        text.replace("motion = \"shift_sequence\"\nstart = \"steady\"\ns_mm = 0.0", "motion = \"shift\"\ns_mm = 0.4");
    let mut alone = WheelRailScene::from_toml(&alone, &root().join("scenes/wheelrail")).unwrap();
    alone.cases.remove(0);
    let from_rest = run_scene(&alone).unwrap();
    let fx = |r: &creepbench::pipeline::wheelrail::CaseResult| r.models[0].1[0].fx_n;
    // Patch 1's FX: continued −4.0e4 N (CONTACT's case 2), from rest a fraction of it.
    let (continued_n, rest_n) = (fx(result), fx(&from_rest.cases[0].1));
    assert!((continued_n - rest_n).abs() > 0.1 * continued_n.abs(), "{continued_n} vs {rest_n}");
}

/// A trial height of the height search may give a candidate patch whose material-fixed grid
/// misses its tiny overlap (no element interpenetrates): that patch carries nothing and is left
/// out, as CONTACT's `wr_solve_cp` ("no actual contact in patch", ncon = 0) gives it zero force,
/// instead of ending the case. `d3_shift_site_b` (D = 3, FZ prescribed) met one on its first
/// trial height after the yaw changes (case 3); the cases end with CONTACT's numbers of patches
/// (2, 2, 3, 3: `examples/d3_shift_site_b.ref_out`).
#[test]
fn a_trial_height_whose_grid_misses_a_tiny_overlap_leaves_that_patch_out() {
    let run = run_scene(&scene("d3_shift_site_b")).unwrap();
    let path = root().join("reference/contact_wheelrail/examples/d3_shift_site_b.ref_out");
    let text = std::fs::read_to_string(path).unwrap();
    let printed: Vec<usize> = text
        .lines()
        .filter_map(|l| l.split_once("RIGHT WHEEL,").and_then(|(_, r)| r.split_whitespace().next()))
        .map(|n| n.parse().unwrap())
        .collect();
    let ours: Vec<usize> = run.cases.iter().map(|(_, r)| r.normal.patches.len()).collect();
    assert_eq!(printed, [2, 2, 3, 3]);
    assert_eq!(ours, printed);
    assert!(run.cases.iter().all(|(_, r)| r.normal.patches.iter().all(|p| p.fn_n > 0.0)));
}
