//! Parameter studies (issue 14): a study file expands into scenes with deterministic names, its
//! points are sharded one by one, the thesis's studies reproduce CONTACT's case names and
//! problems, bad study files are input errors naming the field, and the report draws them.

use crate::common;
use common::*;
use creepbench::scene::study;
use creepbench::suite::{self, Shard};
use std::path::PathBuf;

const TEMPLATE: &str = r#"
[scene]
solvers = ["linear"]
[scene.contact]
a_mm = 8.56
b_mm = 4.08
fn_n = 100000.0
mu = 0.4
[scene.material]
g_mpa = 82000.0
poisson = 0.28
[scene.grid]
mx = 8
my = 8
[scene.rolling]
v_mm_s = 1000.0
courant = 1.0
[scene.creepage]
kind = "step"
c = 0.001
steps = 3
[scene.init]
kind = "zero"
"#;

fn study_text(head: &str) -> String {
    format!("{head}\n{TEMPLATE}")
}

fn expand(text: &str) -> Result<Vec<study::Expanded>, creepbench::error::InputError> {
    creepbench::pipeline::expand_study(&text.parse::<toml::Table>().unwrap())
}

const TWO_AXES: &str = r#"
[study]
name = "demo"
title = "Demo"
x = "c"
metrics = ["steady_value"]
[[study.axis]]
name = "mu"
"contact.mu" = [0.3, 0.5]
[[study.axis]]
name = "c"
"creepage.c" = [0.001, 0.002, 0.004]
"#;

/// Axes crossed, the first outermost; default names `<study>_<axis><value>` with `.` → `p`;
/// the values set in the scene; x and the series recorded.
#[test]
fn expansion_order_names_and_values() {
    let points = expand(&study_text(TWO_AXES)).unwrap();
    let names: Vec<&str> = points.iter().map(|p| p.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "demo_mu0p3_c0p001",
            "demo_mu0p3_c0p002",
            "demo_mu0p3_c0p004",
            "demo_mu0p5_c0p001",
            "demo_mu0p5_c0p002",
            "demo_mu0p5_c0p004"
        ]
    );
    let p = &points[4];
    assert_eq!(p.doc["contact"]["mu"].as_float(), Some(0.5));
    assert_eq!(p.doc["creepage"]["c"].as_float(), Some(0.002));
    assert_eq!(p.doc["name"].as_str(), Some("demo_mu0p5_c0p002"));
    assert_eq!((p.point.x_key.as_str(), p.point.x, p.point.series.as_str()), ("creepage.c", 0.002, "mu 0p5"));
    assert_eq!(p.point.metrics, ["steady_value"]);
    // Each point is a valid scene with its values.
    for e in &points {
        let sc = creepbench::scene::Scene::from_table(&e.doc, std::path::Path::new(".")).unwrap();
        assert_eq!(sc.name, e.name);
    }
}

/// Keys of one axis vary together (a load with its semi-axes); labels name the scenes.
#[test]
fn zipped_keys_and_labels() {
    let head = r#"
[study]
name = "load"
scene_name = "load_fn{fn}"
[[study.axis]]
name = "fn"
"contact.fn_n" = [50000.0, 100000.0]
"contact.a_mm" = [6.794076502, 8.56]
"contact.b_mm" = [3.238298146, 4.08]
labels = ["050", "100"]
"#;
    let points = expand(&study_text(head)).unwrap();
    assert_eq!(points.iter().map(|p| p.name.as_str()).collect::<Vec<_>>(), ["load_fn050", "load_fn100"]);
    assert_eq!(points[0].doc["contact"]["a_mm"].as_float(), Some(6.794076502));
    assert_eq!(points[0].doc["contact"]["fn_n"].as_float(), Some(50000.0));
    assert_eq!(points[0].point.series, "");
}

/// Every malformed study is an input error naming the field and what is allowed.
#[test]
fn study_errors_name_the_field() {
    let cases: [(&str, &str); 9] = [
        ("[study]\nname = \"s\"\nfoo = 1\n[[study.axis]]\nname = \"mu\"\n\"contact.mu\" = [0.3]", "study.foo"),
        ("[study]\nname = \"s\"", "study.axis"),
        ("[study]\nname = \"s\"\n[[study.axis]]\nname = \"mu\"", "study.axis[0]"),
        ("[study]\nname = \"s\"\n[[study.axis]]\nname = \"mu\"\n\"contact.mu\" = [0.3, 0.4]\n\"contact.fn_n\" = [1e5]", "study.axis[0].\"contact."),
        ("[study]\nname = \"s\"\n[[study.axis]]\nname = \"mu\"\n\"contact.mu\" = [0.3, 0.4]\nlabels = [\"a\"]", "study.axis[0].labels"),
        ("[study]\nname = \"s\"\nx = \"c\"\n[[study.axis]]\nname = \"mu\"\n\"contact.mu\" = [0.3]", "study.x"),
        ("[study]\nname = \"s\"\nmetrics = [\"nope\"]\n[[study.axis]]\nname = \"mu\"\n\"contact.mu\" = [0.3]", "study.metrics"),
        ("[study]\nname = \"s\"\nscene_name = \"fixed\"\n[[study.axis]]\nname = \"mu\"\n\"contact.mu\" = [0.3]", "study.scene_name"),
        ("[study]\nname = \"s\"\n[[study.axis]]\nname = \"mu\"\n\"contact.mu\" = [0.3, 0.4]\nlabels = [\"a\", \"a\"]", "study.scene_name"),
    ];
    for (head, field) in cases {
        let e = expand(&study_text(head)).unwrap_err();
        assert!(e.field.contains(field), "{head}: field {:?}, expected {field}", e.field);
        assert!(!e.allowed.is_empty());
    }
    let named = format!(
        "[study]\nname = \"s\"\n[[study.axis]]\nname = \"mu\"\n\"contact.mu\" = [0.3]\n{}",
        TEMPLATE.replace("[scene]\n", "[scene]\nname = \"x\"\n")
    );
    assert_eq!(expand(&named).unwrap_err().field, "scene.name");
    // A point whose scene is invalid fails at load, naming the file and the point; nothing runs.
    let dir = tempfile::tempdir().unwrap();
    let bad =
        study_text(TWO_AXES).replace("\"creepage.c\" = [0.001, 0.002, 0.004]", "\"creepage.c\" = [0.001, 5.0, 0.004]");
    let file = dir.path().join("demo.toml");
    std::fs::write(&file, bad).unwrap();
    let out = dir.path().join("out");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .args(["simulate", file.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("demo.toml") && stderr.contains("demo_mu0p3_c5") && stderr.contains("creepage.c"),
        "{stderr}"
    );
    assert!(!out.exists(), "nothing written");
}

/// A study's points are sharded one by one: the shards are disjoint and together the whole.
#[test]
fn points_are_sharded_one_by_one() {
    let dirs = [root().join("scenes/thesis")];
    let all: Vec<String> = suite::scene_files(&dirs, None).unwrap().into_iter().map(|s| s.name).collect();
    let mut parts = Vec::new();
    for i in 1..=3 {
        let shard = Shard { index: i, count: 3 };
        parts.extend(suite::scene_files(&dirs, Some(shard)).unwrap().into_iter().map(|s| s.name));
    }
    parts.sort();
    assert_eq!(parts, all);
    let mut unique = all.clone();
    unique.dedup();
    assert_eq!(unique.len(), all.len(), "one source per name");
}

/// The thesis suite: every CONTACT case of the thesis family is a scene of it (a file or a study
/// point), and a point two studies share runs once, in both.
#[test]
fn thesis_studies_hold_contacts_cases() {
    let dirs = [root().join("scenes/thesis")];
    let sources = suite::scene_files(&dirs, None).unwrap();
    let mut cases = csv::Reader::from_path(root().join("reference/contact/cases.csv")).unwrap();
    for r in cases.records().map(Result::unwrap).filter(|r| &r[18] == "x") {
        assert!(sources.iter().any(|s| s.name == r[0]), "CONTACT case {} is no thesis scene", &r[0]);
    }
    let shared = sources.iter().find(|s| s.name == "sine_f10_mu10").unwrap();
    let studies: Vec<&str> = shared.study.as_ref().unwrap().1.iter().map(|p| p.study.as_str()).collect();
    assert_eq!(studies, ["sine_freq", "sine_mu"]);
    let p = creepbench::pipeline::load_source(shared, &[]).unwrap();
    assert_eq!((p.nominal.mu, p.loading.freq_hz), (1.0, Some(10.0)));
}

/// `expand` writes the points as scene files that resolve to the same problems, and replaces none.
#[test]
fn expand_writes_scene_files() {
    let dir = tempfile::tempdir().unwrap();
    let out: PathBuf = dir.path().join("scenes");
    let run = || {
        std::process::Command::new(env!("CARGO_BIN_EXE_creepbench"))
            .args(["expand", root().join("scenes/thesis/study_step_mu.toml").to_str().unwrap()])
            .args(["--out", out.to_str().unwrap()])
            .output()
            .unwrap()
    };
    let o = run();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let written = std::fs::read_dir(&out).unwrap().count();
    assert_eq!(written, 6);
    let from_file = creepbench::pipeline::load(&out.join("step_mu03.toml"), &[]).unwrap();
    let from_study = suite_problem("thesis", "step_mu03", &[]);
    assert_eq!(from_file.loading.samples, from_study.loading.samples);
    assert_eq!(from_file.nominal, from_study.nominal);
    let again = run();
    assert_eq!(again.status.code(), Some(2), "an existing file is not replaced");
}

/// The report's studies section, from the blessed results only: the frequency study (thesis Fig.
/// 4.9) has a table row per point with CONTACT's delay ratio where CONTACT ran the scene (the
/// same value the gate compares, within its 0.005), and one figure per metric.
#[test]
fn report_draws_the_frequency_study_with_contacts_points() {
    use creepbench::suite::results::read_scene;
    let golden = root().join("golden");
    let names = ["sine_f2_mu10", "sine_f10_mu10", "sine_f30_mu10", "sine_f60_mu10", "sine_f100_mu10"];
    let scenes: Vec<_> = names.iter().map(|n| read_scene(&golden, n).unwrap()).collect();
    let refs = creepbench::comparison::references::References::load(&root().join("reference")).unwrap();
    let s = creepbench::report::studies::section(&scenes, &refs).expect("a studies section");
    assert!(s.body.contains("### Frequency at mu = 1 and 0.6 (thesis Fig. 4.9)"), "{}", s.body);
    let figures: Vec<&str> = s.figures.iter().map(|(f, _)| f.as_str()).collect();
    assert!(figures.contains(&"study_sine_freq_delay_ratio.svg") && figures.contains(&"study_sine_freq_loop_area.svg"));
    // Each metric's table is headed by its name.
    assert!(s.body.contains("**delay_ratio**\n\n| creepage.freq_hz |"), "{}", s.body);
    // The 10 Hz row: CONTACT's delay ratio beside ours.
    let ours = scenes[1].metric("contact", "delay_ratio").unwrap();
    let row = s.body.lines().find(|l| l.starts_with("| 10 | mu 10 |")).expect("the 10 Hz row");
    let theirs: f64 =
        row.split("CONTACT ").nth(1).unwrap().split_whitespace().next().unwrap().trim_end_matches(',').parse().unwrap();
    assert!((ours - theirs).abs() <= 0.005, "{ours} vs CONTACT {theirs}");
    // 2 Hz: no CONTACT case, no marker.
    let row2 = s.body.lines().find(|l| l.starts_with("| 2 | mu 10 |")).expect("the 2 Hz row");
    assert!(row2.ends_with("| — |"), "{row2}");
}
