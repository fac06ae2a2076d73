//! External models end to end (docs/models.md, "Bring your own model"), and `check` / `bless` / `run` /
//! `merge` on a small suite: gating, drift between two result sets, shards.

use crate::common;
use common::*;
use std::path::Path;
use std::process::Command;

fn creepbench(args: &[&str], dir: &Path, env: &[(&str, &str)]) -> std::process::Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_creepbench"));
    c.args(args).current_dir(dir);
    for (k, v) in env {
        c.env(k, v);
    }
    c.output().expect("runs")
}

/// A tiny suite in a temp folder: a step scene with an external model, a sine scene, and the
/// references of the project.
fn suite(dir: &Path) {
    let suite = dir.join("suite");
    std::fs::create_dir_all(&suite).unwrap();
    let script = root().join("scripts/example_model.py");
    let ext = format!("[external.example]\ncommand = [\"python3\", \"{}\"]\n", script.display());
    let step = scene_text(
        "step_mu04",
        "[\"uba\", \"fastsim\", \"example\"]",
        0.4,
        22,
        "kind = \"step\"\nc = 0.005\nsteps = 44",
        &ext,
    );
    std::fs::write(suite.join("step_mu04.toml"), step).unwrap();
    let sine = scene_text(
        "sine_f30_mu10",
        "[\"uba\", \"fastsim\"]",
        1.0,
        22,
        "kind = \"sine\"\nc0 = 0.005\ncp = 0.005\nfreq_hz = 30.0\nperiods = 3.0",
        "[init]\nkind = \"steady\"",
    );
    std::fs::write(suite.join("sine_f30_mu10.toml"), sine).unwrap();
}

#[test]
fn external_model_is_run_compared_and_gated() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path();
    suite(d);
    let refs = root().join("reference");
    let refs = refs.to_str().unwrap();
    // simulate: the external model's CSV is written like the built-in ones.
    let o = creepbench(&["simulate", "suite/step_mu04.toml", "--out", "sim"], d, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let ext = creepbench::history::History::from_csv(
        "example",
        &std::fs::read_to_string(d.join("sim/step_mu04/example.csv")).unwrap(),
    )
    .unwrap();
    let fs = creepbench::history::History::from_csv(
        "fastsim",
        &std::fs::read_to_string(d.join("sim/step_mu04/fastsim.csv")).unwrap(),
    )
    .unwrap();
    assert_eq!(ext.rows.len(), 44);
    // The cubic saturation law and FASTSIM agree on the steady value within a few per cent of μ.
    let (a, b) = (ext.rows[43].fx_over_fn, fs.rows[43].fx_over_fn);
    assert!((a - b).abs() < 0.03, "example {a} vs fastsim {b}");
    let metrics = std::fs::read_to_string(d.join("sim/step_mu04/metrics.csv")).unwrap();
    assert!(metrics.contains("example,steady_value"), "{metrics}");

    // No golden yet: check fails and says so.
    std::fs::create_dir_all(d.join("golden")).unwrap();
    let o = creepbench(&["check", "--suite", "suite", "--reference", refs, "--quiet"], d, &[]);
    assert_eq!(o.status.code(), Some(1), "{}", String::from_utf8_lossy(&o.stdout));
    assert!(String::from_utf8_lossy(&o.stdout).contains("bless"));
    // Bless, then check passes and prints (with --verbose) the worst-point table with the CONTACT rows.
    let o = creepbench(&["bless", "--suite", "suite", "--quiet"], d, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(d.join("golden/step_mu04/example.csv").exists());
    let o = creepbench(&["check", "--suite", "suite", "--reference", refs, "--quiet", "--verbose"], d, &[]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{out}\n{}", String::from_utf8_lossy(&o.stderr));
    assert!(out.contains("step_mu04") && out.contains("example") && out.contains("CONTACT"), "{out}");
    // The model drifts by 1 %: check fails, naming scene, solver, metric, step and both values.
    let o = creepbench(
        &["check", "--suite", "suite", "--reference", refs, "--quiet"],
        d,
        &[("EXAMPLE_MODEL_SCALE", "1.01")],
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1));
    assert!(err.contains("DRIFT scene step_mu04 solver example against golden metric fx_over_fn step"), "{err}");
    // Drift between two model versions: run once, then check --against that result set.
    let o = creepbench(
        &["run", "--suite", "suite", "--reference", refs, "--results", "before", "--report", "rep", "--quiet"],
        d,
        &[],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(d.join("rep/validation.md").exists());
    let o = creepbench(
        &["check", "--suite", "suite", "--reference", refs, "--against", "before", "--quiet"],
        d,
        &[("EXAMPLE_MODEL_SCALE", "0.98")],
    );
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1));
    assert!(out.contains("moved against") && out.contains("step_mu04 example fx_over_fn"), "{out}");
    // A golden file is never touched by check or run.
    let golden = std::fs::read(d.join("golden/step_mu04/example.csv")).unwrap();
    assert_eq!(golden, std::fs::read(d.join("golden/step_mu04/example.csv")).unwrap());
}

#[test]
fn shards_merge_into_one_report() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path();
    suite(d);
    let refs = root().join("reference");
    let refs = refs.to_str().unwrap();
    for i in 1..=2 {
        let shard = format!("{i}/2");
        let res = format!("shard{i}");
        let o = creepbench(
            &["run", "--suite", "suite", "--reference", refs, "--shard", &shard, "--results", &res, "--quiet"],
            d,
            &[],
        );
        // A shard may be empty for a two-scene suite: that is an input error (exit 2), not a crash.
        assert!(o.status.success() || o.status.code() == Some(2), "{}", String::from_utf8_lossy(&o.stderr));
    }
    let mut dirs = vec![];
    for i in 1..=2 {
        if d.join(format!("shard{i}")).exists() {
            dirs.push(format!("shard{i}"));
        }
    }
    let n: usize = dirs.iter().map(|s| creepbench::suite::results::scene_names(&d.join(s)).len()).sum();
    assert_eq!(n, 2, "each scene in exactly one shard");
    let mut args = vec!["merge"];
    args.extend(dirs.iter().map(String::as_str));
    args.extend(["--reference", refs, "--report", "merged"]);
    let o = creepbench(&args, d, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let md = std::fs::read_to_string(d.join("merged/validation.md")).unwrap();
    assert!(md.contains("step_mu04") && md.contains("sine_f30_mu10"));
}

/// A step scene `s.toml` in `dir` run by the external model `m` = `sh model.sh SCENE OUT`, where
/// model.sh prints to stdout and stderr, then runs `body`.
fn printing_model(dir: &Path, body: &str) {
    let script = root().join("scripts/example_model.py");
    let model = format!("echo \"model: starting\"\necho 'model: a warning' >&2\n{body}\n");
    std::fs::write(dir.join("model.sh"), model.replace("EXAMPLE", &script.display().to_string())).unwrap();
    let ext = "[external.m]\ncommand = [\"sh\", \"model.sh\"]\n";
    let text = scene_text("s", "[\"fastsim\", \"m\"]", 0.4, 10, "kind = \"step\"\nc = 0.005\nsteps = 6", ext);
    std::fs::write(dir.join("s.toml"), text).unwrap();
}

#[test]
fn a_failing_model_leaves_its_folder_with_its_output_and_stderr_named_in_the_message() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path();
    for (body, says) in [
        ("echo 'Traceback: boom' >&2; exit 3", "exit status: 3"),
        ("echo 'step,t_s' > \"$2\"", "header must start with"),
    ] {
        printing_model(d, body);
        let o = creepbench(&["simulate", "s.toml", "--out", "out"], d, &[]);
        let err = String::from_utf8_lossy(&o.stderr).to_string();
        assert_eq!(o.status.code(), Some(1), "{err}");
        assert!(err.contains(says) && err.contains("model `m`"), "{err}");
        assert!(!d.join("out/s").exists(), "no partial result folder");
        // Every path the message names exists after the command ended, until removed here.
        let (folder, files, stdout, stderr) = take_kept_folder(&err);
        assert!(folder.starts_with(std::env::temp_dir()) && err.contains(&folder.display().to_string()), "{err}");
        assert_eq!(stdout, "model: starting\n");
        let wrote_csv = body.contains("$2");
        let expected_stderr = if wrote_csv { "model: a warning\n" } else { "model: a warning\nTraceback: boom\n" };
        assert_eq!(stderr, expected_stderr);
        let mut expected_files = vec!["loading.csv", "scene.json", "stderr.txt", "stdout.txt"];
        if wrote_csv {
            expected_files.insert(1, "m.csv");
            assert!(err.contains(&folder.join("m.csv").display().to_string()), "{err}");
        }
        assert_eq!(files, expected_files);
    }
}

#[test]
fn a_succeeding_model_s_stdout_and_stderr_are_kept_in_the_result_folder() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path();
    printing_model(d, "exec python3 EXAMPLE \"$@\"");
    let o = creepbench(&["simulate", "s.toml", "--out", "out"], d, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let read = |f: &str| std::fs::read_to_string(d.join("out/s").join(f)).unwrap();
    assert_eq!(read("m.stdout.txt"), "model: starting\n");
    assert_eq!(read("m.stderr.txt"), "model: a warning\n");
    // A built-in model prints nothing and gets no log file.
    let mut files: Vec<String> =
        std::fs::read_dir(d.join("out/s")).unwrap().flatten().map(|e| e.file_name().to_string_lossy().into()).collect();
    files.sort();
    assert_eq!(
        files,
        [".creepbench-result", "fastsim.csv", "m.csv", "m.stderr.txt", "m.stdout.txt", "metrics.csv", "scene.json"]
    );
    // A model that prints nothing leaves no log file.
    printing_model(d, "exec python3 EXAMPLE \"$@\"");
    let quiet = std::fs::read_to_string(d.join("model.sh")).unwrap().lines().skip(2).collect::<Vec<_>>().join("\n");
    std::fs::write(d.join("model.sh"), quiet).unwrap();
    let o = creepbench(&["simulate", "s.toml", "--out", "out"], d, &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(d.join("out/s/m.csv").exists() && !d.join("out/s/m.stdout.txt").exists());
    assert!(!d.join("out/s/m.stderr.txt").exists());
}
