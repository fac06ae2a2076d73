//! scene.json records the loading as the scene declared it (issue 48 item 6): its rows, sampled
//! back from that declaration by the one sampling the models' runs use, are the run's rows bit
//! for bit, for every scene of every suite; and equal the `history` a result folder listed before.

use crate::common::{problem, root, scene_text};
use creepbench::problem::{ResolvedScene, Sample};

/// A row's every value as bits (NaN-safe, -0 ≠ 0).
fn bits(rows: &[Sample]) -> Vec<Vec<u64>> {
    let opt = |f: Option<f64>| f.map_or(u64::MAX, f64::to_bits);
    rows.iter()
        .map(|s| {
            let mut v = vec![s.step as u64, s.t_s.to_bits(), s.cx.to_bits(), s.cy.to_bits(), s.cs.to_bits()];
            v.extend([s.fn_n.to_bits(), s.mu.to_bits(), opt(s.v_mm_s), opt(s.courant), opt(s.fx_target)]);
            v.extend([opt(s.fy_target), opt(s.pen_mm), opt(s.chi_deg)]);
            v.extend(s.h_coefficients.map_or([u64::MAX; 6], |b| b.map(f64::to_bits)));
            v
        })
        .collect()
}

#[test]
fn every_suite_scene_samples_back_from_its_scene_json_bit_for_bit() {
    let suites: Vec<_> = std::fs::read_dir(root().join("scenes")).unwrap().map(|e| e.unwrap().path()).collect();
    let sources = creepbench::suite::scene_files(&suites, None).unwrap();
    let mut checked = 0;
    for src in &sources {
        let Ok(p) = creepbench::pipeline::load_source(src, &[]) else { continue };
        let ran: Vec<Sample> = p.loading.initial.iter().chain(&p.loading.samples).copied().collect();
        let json = ResolvedScene::of(&p, &p.solvers).to_json();
        assert!(!json.contains("\"history\""), "{}: scene.json lists no rows", src.name);
        let back = ResolvedScene::from_json(&json).unwrap().loading_rows().unwrap();
        assert_eq!(bits(&back), bits(&ran), "{}", src.name);
        checked += 1;
    }
    assert!(checked > 300, "{checked} scenes checked");
}

/// golden/step_mu01's scene.json as written at f95dd0c (tests/fixtures), which listed every row.
#[test]
fn the_declared_loading_samples_the_rows_a_folder_listed_before() {
    let text = std::fs::read_to_string(root().join("tests/fixtures/scene_v1_step.json")).unwrap();
    let old = ResolvedScene::from_json(&text).unwrap();
    assert!(old.loading.is_none() && old.legacy_history.len() == 45);
    let p = crate::common::suite_problem("thesis", "step_mu01", &[]);
    let new = ResolvedScene::from_json(&ResolvedScene::of(&p, &p.solvers).to_json()).unwrap();
    assert_eq!(bits(&new.loading_rows().unwrap()), bits(&old.loading_rows().unwrap()));
}

/// A long step is a few hundred bytes of scene.json, whatever its steps.
#[test]
fn a_long_step_is_recorded_by_its_parameters() {
    let p = problem(&scene_text("long", "[\"fastsim\"]", 0.4, 4, "kind = \"step\"\nc = 0.001\nsteps = 200000", ""));
    let json = ResolvedScene::of(&p, &p.solvers).to_json();
    assert!(json.len() < 5000, "{} bytes", json.len());
    let rows = ResolvedScene::from_json(&json).unwrap().loading_rows().unwrap();
    assert_eq!((rows.len(), rows[200000].step, rows[200000].cx), (200001, 200000, 0.001));
}

/// A table in scene.json is its rows; a row edited out of range is refused when read back,
/// naming scene.json's table, the line and the column.
#[test]
fn a_table_is_recorded_by_its_rows_and_checked_when_read() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("t.csv"), "t_s,cx,fn_n\n0,0,100000\n0.01,0.002,110000\n0.02,0.003,90000\n").unwrap();
    let text = scene_text("tab", "[\"fastsim\"]", 0.4, 4, "kind = \"table\"\nfile = \"t.csv\"", "");
    let scene = dir.path().join("tab.toml");
    std::fs::write(&scene, text).unwrap();
    let p = creepbench::pipeline::load(&scene, &[]).unwrap();
    let json = ResolvedScene::of(&p, &p.solvers).to_json();
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    let table = &v["loading"]["creepage"]["table"];
    assert_eq!(table["columns"], serde_json::json!(["t_s", "cx", "fn_n"]));
    assert_eq!(table["rows"][1], serde_json::json!([0.01, 0.002, 110000.0]));
    let edited = json.replacen("110000.0", "-5.0", 1);
    let e = ResolvedScene::from_json(&edited).unwrap_err().to_string();
    assert!(e.contains("scene.json loading.creepage.table line 3 column fn_n") && e.contains("-5"), "{e}");
}
