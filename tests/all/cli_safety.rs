//! The gate protects its own data, through the command line (issue 11): no command but `bless`
//! writes golden/, a result folder (and a report's figures/ and tables/) never replaces a
//! directory creepbench did not write, special files are refused without blocking, changed
//! reference data fail the gate, and bless keeps the blessed scenes of the suites it does not run.

use crate::common;
use common::*;
use std::path::Path;
use std::process::{Command, Output};

fn creepbench(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_creepbench")).current_dir(dir).args(args).output().expect("runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).to_string()
}

/// A work folder with a small golden/ (marker and one scene folder) and a scene named `name`.
fn workspace(name: &str) -> tempfile::TempDir {
    let w = tempfile::tempdir().unwrap();
    let g = w.path().join("golden/step_mu04");
    std::fs::create_dir_all(&g).unwrap();
    std::fs::write(w.path().join("golden/.creepbench-result"), "marker").unwrap();
    std::fs::write(g.join("scene.json"), "{}").unwrap();
    let text = scene_text(name, "[\"uba\"]", 0.4, 8, "kind = \"step\"\nc = 0.005\nsteps = 4", "");
    std::fs::write(w.path().join("s.toml"), text).unwrap();
    w
}

fn golden_intact(w: &Path) -> bool {
    std::fs::read_to_string(w.join("golden/step_mu04/scene.json")).is_ok_and(|t| t == "{}")
}

#[test]
fn no_command_but_bless_writes_golden() {
    let w = workspace("golden");
    // A scene named "golden" simulated into the folder that holds golden/.
    let o = creepbench(w.path(), &["simulate", "s.toml", "--out", "."]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("only `creepbench bless` writes"), "{}", stderr(&o));
    assert!(golden_intact(w.path()));
    for args in [
        vec!["simulate", "s.toml", "--out", "golden"],
        vec!["simulate", "s.toml", "--out", "golden/sub"],
        vec!["simulate", "s.toml", "--out", "out/../golden"],
        vec!["run", "--suite", ".", "--results", "golden", "--quiet"],
        vec!["run", "--suite", ".", "--report", "golden/r", "--quiet"],
        vec!["merge", "golden", "--report", "golden"],
    ] {
        let o = creepbench(w.path(), &args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(golden_intact(w.path()), "{args:?}");
    }
}

#[test]
fn a_folder_creepbench_did_not_write_is_never_replaced() {
    let w = workspace("src");
    std::fs::create_dir_all(w.path().join("src")).unwrap();
    std::fs::write(w.path().join("src/main.rs"), "fn main() {}").unwrap();
    let o = creepbench(w.path(), &["simulate", "s.toml", "--out", "."]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("did not write"), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(w.path().join("src/main.rs")).unwrap(), "fn main() {}");
    // A file where the folder would go is left alone too, and nothing is hidden beside it.
    std::fs::remove_dir_all(w.path().join("src")).unwrap();
    std::fs::write(w.path().join("src"), "a file").unwrap();
    let o = creepbench(w.path(), &["simulate", "s.toml", "--out", "."]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(w.path().join("src")).unwrap(), "a file");
    let hidden: Vec<_> = std::fs::read_dir(w.path())
        .unwrap()
        .flatten()
        .filter(|e| e.file_name().to_string_lossy().starts_with('.'))
        .collect();
    assert!(hidden.is_empty(), "{hidden:?}");
    // Its own earlier result is replaced.
    let w = workspace("mine");
    for _ in 0..2 {
        let o = creepbench(w.path(), &["simulate", "s.toml", "--out", "out"]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    }
}

/// A report's figures/ and tables/ folders are replaced whole, and only when creepbench wrote
/// them: a foreign figures/ is refused and left intact, and no validation.md is written beside it.
#[test]
fn report_folders_are_replaced_only_when_creepbench_wrote_them() {
    let w = workspace("rep_scene");
    std::fs::create_dir_all(w.path().join("suite")).unwrap();
    std::fs::rename(w.path().join("s.toml"), w.path().join("suite/s.toml")).unwrap();
    let refs = root().join("reference");
    let run = |report: &str| {
        let args = ["run", "--quiet", "--suite", "suite", "--results", "res", "--report", report, "--reference"];
        let mut c = Command::new(env!("CARGO_BIN_EXE_creepbench"));
        c.current_dir(w.path()).args(args).arg(&refs).output().expect("runs")
    };
    for _ in 0..2 {
        let o = run("rep");
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    }
    for sub in ["figures", "tables"] {
        assert!(w.path().join("rep").join(sub).join(".creepbench-result").is_file(), "{sub}");
    }
    assert!(std::fs::read_to_string(w.path().join("rep/validation.md")).unwrap().contains("rep_scene"));
    std::fs::create_dir_all(w.path().join("rep2/figures")).unwrap();
    std::fs::write(w.path().join("rep2/figures/mine.svg"), "<svg/>").unwrap();
    // Refused before any scene runs (issue 48 item 4): an input error.
    let o = run("rep2");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("did not write"), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(w.path().join("rep2/figures/mine.svg")).unwrap(), "<svg/>");
    assert!(!w.path().join("rep2/validation.md").exists());
}

#[test]
fn special_files_are_refused_at_once() {
    let w = workspace("x");
    let fifo = w.path().join("fifo.toml");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    for scene in [fifo.to_str().unwrap(), "/dev/zero", "/proc/self/environ", "."] {
        let start = std::time::Instant::now();
        let o = creepbench(w.path(), &["simulate", scene]);
        assert_eq!(o.status.code(), Some(2), "{scene}: {}", stderr(&o));
        assert!(start.elapsed().as_secs() < 10, "{scene} blocked");
        assert!(!stderr(&o).contains("PATH="), "{scene}: file contents echoed");
    }
}

#[test]
fn a_file_that_is_no_table_is_never_quoted() {
    let w = tempfile::tempdir().unwrap();
    std::fs::write(w.path().join("secret.csv"), "root:x:0:0:root:/root:/bin/bash\nTOKEN=abc123\n").unwrap();
    let text = scene_text("t", "[\"uba\"]", 0.4, 8, "kind = \"table\"\nfile = \"secret.csv\"", "");
    std::fs::write(w.path().join("s.toml"), text).unwrap();
    let o = creepbench(w.path(), &["simulate", "s.toml"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(!stderr(&o).contains("root:x") && !stderr(&o).contains("abc123"), "{}", stderr(&o));
    assert!(stderr(&o).contains("header column 1"), "{}", stderr(&o));
}

#[test]
fn a_changed_reference_file_fails_until_its_manifest_is_updated() {
    let w = tempfile::tempdir().unwrap();
    let r = w.path().join("reference");
    Command::new("cp").arg("-r").arg(root().join("reference")).arg(&r).status().unwrap();
    std::fs::create_dir_all(w.path().join("suite")).unwrap();
    let text = scene_text("tiny", "[\"uba\"]", 0.4, 8, "kind = \"step\"\nc = 0.005\nsteps = 4", "");
    std::fs::write(w.path().join("suite/tiny.toml"), text).unwrap();
    let run = |w: &Path| creepbench(w, &["run", "--suite", "suite", "--quiet", "--results", "res", "--report", "rep"]);
    assert_eq!(run(w.path()).status.code(), Some(0), "{}", stderr(&run(w.path())));
    let t42 = r.join("thesis/table_4_2_delay.csv");
    let text = std::fs::read_to_string(&t42).unwrap();
    std::fs::write(&t42, text.replace("0.040", "0.041")).unwrap();
    let o = run(w.path());
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("changed: thesis/table_4_2_delay.csv"), "{}", stderr(&o));
    std::fs::remove_file(r.join("contact/step_mu04.csv")).unwrap();
    assert!(stderr(&run(w.path())).contains("missing: contact/step_mu04.csv"), "{}", stderr(&run(w.path())));
    std::fs::copy(root().join("reference/contact/step_mu04.csv"), r.join("contact/step_mu04.csv")).unwrap();
    assert_eq!(creepbench(w.path(), &["manifest", "reference"]).status.code(), Some(0));
    assert_eq!(run(w.path()).status.code(), Some(0), "a reviewed manifest update accepts the change");
    // A reference folder that is not there is bad input (exit 2), not a changed reference.
    let args =
        ["run", "--suite", "suite", "--quiet", "--results", "res2", "--report", "rep2", "--reference", "nowhere"];
    let o = creepbench(w.path(), &args);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("`--reference` = nowhere"), "{}", stderr(&o));
    assert!(!w.path().join("res2").exists() && !w.path().join("rep2").exists());
}

#[test]
fn bless_keeps_the_blessed_scenes_of_other_suites_and_replaces_its_own() {
    let w = workspace("x");
    let g = w.path().join("golden");
    // An old scene of this suite (gone from it now) and one of another suite.
    for (name, suite) in [("gone", "suite"), ("other", "elsewhere")] {
        let d = g.join(name);
        std::fs::create_dir_all(&d).unwrap();
        std::fs::copy(root().join("golden/step_mu04/uba.csv"), d.join("uba.csv")).unwrap();
        std::fs::copy(root().join("golden/step_mu04/metrics.csv"), d.join("metrics.csv")).unwrap();
        let json = std::fs::read_to_string(root().join("golden/step_mu04/scene.json")).unwrap();
        let mut scene = creepbench::problem::ResolvedScene::from_json(&json).unwrap();
        (scene.suite, scene.solvers) = (suite.into(), vec!["uba".into()]);
        std::fs::write(d.join("scene.json"), scene.to_json()).unwrap();
    }
    std::fs::remove_dir_all(g.join("step_mu04")).unwrap();
    std::fs::create_dir_all(w.path().join("suite")).unwrap();
    std::fs::copy(w.path().join("s.toml"), w.path().join("suite/x.toml")).unwrap();
    let o = creepbench(w.path(), &["bless", "--suite", "suite", "--quiet"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let mut names: Vec<String> =
        std::fs::read_dir(&g).unwrap().flatten().map(|e| e.file_name().to_string_lossy().to_string()).collect();
    names.sort();
    assert_eq!(names, [".creepbench-result", "other", "x"], "this suite's scenes replaced, the other suite's kept");
    let leftovers: Vec<_> = std::fs::read_dir(w.path())
        .unwrap()
        .flatten()
        .filter(|e| e.file_name().to_string_lossy().contains("creepbench"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
}

#[test]
fn an_external_model_that_never_exits_is_stopped_at_its_scene_timeout() {
    let w = tempfile::tempdir().unwrap();
    std::fs::write(w.path().join("hang.sh"), "#!/bin/sh\nsleep 1000\n").unwrap();
    let text = scene_text(
        "hang",
        "[\"hang\"]",
        0.4,
        8,
        "kind = \"step\"\nc = 0.005\nsteps = 4",
        "[external.hang]\ncommand = [\"sh\", \"hang.sh\"]\ntimeout_s = 0.5",
    );
    std::fs::write(w.path().join("s.toml"), text).unwrap();
    let start = std::time::Instant::now();
    let o = creepbench(w.path(), &["simulate", "s.toml", "--out", "out"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(start.elapsed().as_secs() < 10, "{:?}", start.elapsed());
    assert!(stderr(&o).contains("hang") && stderr(&o).contains("0.5 s"), "{}", stderr(&o));
    assert!(!w.path().join("out/hang").exists(), "no partial output");
    // The model's folder is kept for inspection and named; the test removes it.
    let (_, files, _, _) = take_kept_folder(&stderr(&o));
    assert_eq!(files, ["loading.csv", "scene.json", "stderr.txt", "stdout.txt"]);
    let bad = std::fs::read_to_string(w.path().join("s.toml")).unwrap().replace("timeout_s = 0.5", "timeout_s = -1");
    std::fs::write(w.path().join("s.toml"), bad).unwrap();
    assert_eq!(creepbench(w.path(), &["simulate", "s.toml"]).status.code(), Some(2));
}
