//! CONTACT's own test table (issue 14, item 5): the study scenes/table/study_test_table.toml
//! writes its 3220 steady cases (140 sweeps of 23 magnitudes), the reference reader reads CONTACT's
//! verbatim output under the same names, and the exact solver reproduces every case; the sweep's
//! `at` list and the study axis's `x_values` that the study needs.

use crate::common;
use common::*;
use creepbench::comparison::references::envelope::EnvelopeCases;
use creepbench::comparison::references::{table, References};
use creepbench::history::MZ;
use creepbench::suite;

/// The study's 140 points, named as the reference, x the direction in degrees.
#[test]
fn the_study_writes_every_case_of_the_table() {
    let sources = suite::scene_files(&[root().join("scenes/table")], None).unwrap();
    assert_eq!(sources.len(), 140);
    let refs = References::load(&root().join("reference")).unwrap();
    let table = refs.get::<EnvelopeCases>(table::TABLE).unwrap();
    assert_eq!(table.histories.len(), 140);
    for s in &sources {
        let h = table.histories.get(&s.name).unwrap_or_else(|| panic!("no reference for {}", s.name));
        assert_eq!(h.rows.len(), 23, "{}", s.name);
        let (_, points) = s.study.as_ref().unwrap();
        assert_eq!(points[0].x_key, "angle");
        assert!([-90.0, -60.0, -30.0, 0.0, 30.0, 60.0, 90.0].contains(&points[0].x));
    }
    // CONTACT's second line of cases (a/b 0.2, spin 0, -90 degrees, magnitude 0.1):
    // Fy = 0.111744 on body 1 over mu FN, Mz = -0.021818 over mu FN cp.
    let h = &table.histories["tt_ab0p2_sp0_m90"];
    assert_eq!(h.rows[1].fy_over_fn, -0.3 * 0.111744);
    let mz = h.column(MZ).unwrap()[1];
    assert!((mz - 0.3 * 82000.0 * 80f64.sqrt() * 0.021818).abs() < 1e-9, "{mz}");
}

/// The exact solver on all 3220 cases against CONTACT: fx/FN, fy/FN and mz/(FN a) within 1e-6
/// (the table prints F/(mu FN) to 6 decimals, 1.5e-7 in f/FN; measured 3.5e-7 at worst).
#[test]
fn the_exact_solver_reproduces_contacts_test_table() {
    let refs = References::load(&root().join("reference")).unwrap();
    let table = refs.get::<EnvelopeCases>(table::TABLE).unwrap();
    let mut worst = (0.0f64, String::new());
    let mut cases = 0;
    for s in suite::scene_files(&[root().join("scenes/table")], None).unwrap() {
        let problem = creepbench::pipeline::load_source(&s, &["contact".to_string()]).unwrap();
        let a_mm = problem.hertz().a_mm;
        let result = creepbench::pipeline::run(problem).unwrap();
        let ours = &result.histories[0];
        let theirs = &table.histories[&s.name];
        let (om, tm) = (ours.column(MZ).unwrap(), theirs.column(MZ).unwrap());
        for (k, (o, t)) in ours.rows.iter().zip(&theirs.rows).enumerate() {
            assert_eq!(o.sample.step, t.sample.step);
            let d =
                [o.fx_over_fn - t.fx_over_fn, o.fy_over_fn - t.fy_over_fn, (om[k] - tm[k]) / (o.sample.fn_n * a_mm)]
                    .iter()
                    .fold(0.0f64, |m, x| m.max(x.abs()));
            if d > worst.0 {
                worst = (d, format!("{} point {}", s.name, o.sample.step));
            }
            cases += 1;
        }
    }
    println!("{cases} cases, worst difference {:.2e} at {}", worst.0, worst.1);
    assert_eq!(cases, 3220);
    assert!(worst.0 < 1e-6, "{:?}", worst);
}

fn sweep_scene(creepage: &str) -> String {
    scene_text("sweep_at", "[\"linear\"]", 0.4, 8, creepage, "")
}

/// `creepage.at`: the sweep points at the listed t, in order; with from/to/points, empty, or a
/// point outside the creepage range it is an input error naming the entry.
#[test]
fn sweep_at_a_list() {
    let p = problem(&sweep_scene("kind = \"sweep\"\nover = \"cy\"\nat = [0.0, 0.002, 0.001]\ncs = 0.0001"));
    let cy: Vec<f64> = p.loading.samples.iter().map(|s| s.cy).collect();
    let cs: Vec<f64> = p.loading.samples.iter().map(|s| s.cs).collect();
    assert_eq!(cy, [0.0, 0.002, 0.001]);
    assert_eq!(cs, [0.0001; 3]);
    let dir = std::path::Path::new(".");
    let err = |c: &str| creepbench::scene::Scene::from_toml(&sweep_scene(c), dir).unwrap_err();
    let e = err("kind = \"sweep\"\nat = [0.001]\nfrom = 0.0");
    assert!(e.field.ends_with("creepage.from") && e.allowed.contains("creepage.at"), "{e}");
    let e = err("kind = \"sweep\"\nat = []");
    assert!(e.field.ends_with("creepage.at"), "{e}");
    let e = err("kind = \"sweep\"\nat = [0.001, 5.0]");
    assert!(e.field.ends_with("creepage.at[1]") && e.value.contains("cx = 5"), "{e}");
}

/// `x_values`: an axis whose values are not numbers gives the curves' x; the wrong count is an
/// input error naming it.
#[test]
fn axis_x_values() {
    let text = std::fs::read_to_string(root().join("scenes/table/study_test_table.toml")).unwrap();
    let doc: toml::Table = text.parse().unwrap();
    let points = creepbench::pipeline::expand_study(&doc).unwrap();
    assert_eq!(points.len(), 140);
    assert_eq!((points[0].name.as_str(), points[0].point.x), ("tt_ab0p2_sp0_m90", -90.0));
    assert_eq!(points[0].point.series, "case ab0p2_sp0");
    let bad = text.replace("x_values = [-90.0, -60.0,", "x_values = [-60.0,");
    let e = creepbench::pipeline::expand_study(&bad.parse().unwrap()).unwrap_err();
    assert!(e.field.ends_with("x_values") && e.allowed.contains("7 numbers"), "{e}");
}
