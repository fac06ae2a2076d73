//! A baseline cannot vanish or change unnoticed (issue 11): each mutation of a blessed folder
//! below makes the gate fail, naming what changed.

use crate::common;
use common::*;
use creepbench::comparison::compare::{self, Against, Finding};
use creepbench::comparison::references::References;
use creepbench::suite;
use creepbench::suite::results::StoredScene;
use std::path::Path;

const SCENES: [&str; 2] = ["step_mu04", "steady_fastsim_g22"];

fn ours() -> Vec<StoredScene> {
    let files: Vec<_> = SCENES.iter().map(|n| suite_scene("thesis", n)).collect();
    suite::run(&files, false).unwrap().iter().map(StoredScene::from_result).collect()
}

/// The gate's failures against a copy of golden/ (these scenes only) mutated by `mutate`.
fn failures_after(scenes: &[StoredScene], mutate: impl Fn(&Path)) -> Vec<Finding> {
    let dir = tempfile::tempdir().unwrap();
    for n in SCENES {
        let to = dir.path().join(n);
        std::fs::create_dir_all(&to).unwrap();
        for f in std::fs::read_dir(root().join("golden").join(n)).unwrap() {
            let f = f.unwrap().path();
            std::fs::copy(&f, to.join(f.file_name().unwrap())).unwrap();
        }
    }
    mutate(dir.path());
    let refs = References::load(&root().join("reference")).unwrap();
    let mut all = match compare::evaluate(scenes, &refs, Some((dir.path(), Against::Golden))) {
        Ok(f) => f,
        Err(e) => {
            // An unreadable baseline is an error of its own: report it as one failure.
            let mut f = compare::Ctx { scene: "-", solver: "-", against: Against::Golden, rules: &[] }
                .unmatched("folder", e.to_string());
            f.gated = true;
            vec![f]
        }
    };
    all.extend(compare::missing_scenes(dir.path(), scenes, Against::Golden, |_, suite| suite == "thesis").unwrap());
    all.into_iter().filter(|f| f.gated && !f.passed()).collect()
}

/// The CSV text with field `col` of line `line` (0-based) replaced.
fn set_field(text: &str, line: usize, col: usize, value: &str) -> String {
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let mut fields: Vec<&str> = lines[line].split(',').collect();
    fields[col] = value;
    lines[line] = fields.join(",");
    lines.join("\n") + "\n"
}

/// A named mutation of the baseline and the text a failure must name.
type Case = (&'static str, Box<dyn Fn(&Path)>, &'static str);

fn edit(path: &Path, f: impl Fn(String) -> String) {
    let text = std::fs::read_to_string(path).unwrap();
    std::fs::write(path, f(text)).unwrap();
}

#[test]
fn every_mutation_of_a_baseline_fails_the_gate() {
    let scenes = ours();
    assert!(failures_after(&scenes, |_| {}).is_empty(), "the untouched baseline passes");
    let cases: Vec<Case> = vec![
        (
            "scene folder removed",
            Box::new(|d: &Path| std::fs::remove_dir_all(d.join("step_mu04")).unwrap()),
            "fx_over_fn|no golden data",
        ),
        (
            "loading column edited",
            Box::new(|d: &Path| edit(&d.join("step_mu04/uba.csv"), |t| t.replacen(",0.005,", ",0.5,", 1))),
            "cx|",
        ),
        (
            "mu column edited",
            Box::new(|d: &Path| edit(&d.join("step_mu04/uba.csv"), |t| set_field(&t, 2, 8, "0.5"))),
            "mu|",
        ),
        (
            "metric value added",
            Box::new(|d: &Path| edit(&d.join("step_mu04/metrics.csv"), |t| t + "uba,loop_area,1,\n")),
            "loop_area|",
        ),
        (
            "metric value removed",
            Box::new(|d: &Path| {
                edit(&d.join("step_mu04/metrics.csv"), |t| {
                    t.lines().filter(|l| !l.starts_with("uba,steady_value")).map(|l| format!("{l}\n")).collect()
                })
            }),
            "steady_value|",
        ),
        (
            "scene.json edited",
            Box::new(|d: &Path| {
                edit(&d.join("step_mu04/scene.json"), |t| t.replace("\"courant\": 1.0", "\"courant\": 0.9"))
            }),
            "scene.json|",
        ),
        (
            "header-only history",
            Box::new(|d: &Path| {
                edit(&d.join("step_mu04/contact.csv"), |t| t.lines().next().unwrap().to_string() + "\n")
            }),
            "steps differ",
        ),
        (
            "history column removed",
            Box::new(|d: &Path| {
                edit(&d.join("step_mu04/contact.csv"), |t| {
                    t.lines().map(|l| l.rsplit_once(',').unwrap().0.to_string() + "\n").collect()
                })
            }),
            "columns differ",
        ),
        (
            "extra history file",
            Box::new(|d: &Path| {
                std::fs::copy(d.join("step_mu04/uba.csv"), d.join("step_mu04/other.csv")).map(|_| ()).unwrap()
            }),
            "other.csv",
        ),
        (
            "solver history added to scene.json",
            Box::new(|d: &Path| {
                std::fs::copy(d.join("steady_fastsim_g22/uba.csv"), d.join("steady_fastsim_g22/contact.csv")).unwrap();
                edit(&d.join("steady_fastsim_g22/scene.json"), |t| {
                    t.replace("\"fastsim\"\n  ]", "\"fastsim\",\n    \"contact\"\n  ]")
                });
            }),
            "solvers|",
        ),
    ];
    for (what, mutate, needle) in cases {
        let fails = failures_after(&scenes, mutate);
        let text: Vec<String> = fails.iter().map(|f| format!("{}|{}", f.quantity, f.note)).collect();
        assert!(!fails.is_empty(), "{what}: the gate did not fail");
        assert!(text.iter().any(|t| t.contains(needle)), "{what}: no failure names {needle:?}: {text:?}");
    }
    // A blessed scene whose suite file is gone (renamed, deleted) is missing from the run.
    let fewer: Vec<StoredScene> = scenes.iter().filter(|s| s.name != "step_mu04").cloned().collect();
    let fails = failures_after(&fewer, |_| {});
    assert!(fails.iter().any(|f| f.scene == "step_mu04" && f.quantity == "scene"), "{fails:?}");
}
