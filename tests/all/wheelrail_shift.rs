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
    let e = read(&text.replace("solvers = [\"contact\"]", "solvers = [\"contact\", \"fastsim\"]")).unwrap_err();
    assert!(e.field == "solvers" && e.allowed.contains("exact theory alone"), "{e:?}");
    let e = read(&text.replace("motion = \"shift\"", "motion = \"shift\"\nfrictionless = true")).unwrap_err();
    assert!(e.field.contains("motion") && e.allowed.contains("not frictionless"), "{e:?}");
    let e = read(&text.replace("motion = \"shift\"", "motion = \"slide\"")).unwrap_err();
    assert!(e.field.contains("motion"), "{e:?}");
}
