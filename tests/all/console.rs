//! Issue 31 item 3, a console that answers first: `check` prints the verdict, one line per suite
//! and model and the worst drifts by |diff| / allowed (at most 20 unless `--verbose`); a scene
//! without golden data is named once, never as NaN; `run` ends with the verdict and the report.

use crate::common::{root, scene_text, tempdir};
use creepbench::comparison::compare::{self, Against, Finding};
use creepbench::comparison::console::{self, Verdict, CONSOLE_LINES};
use std::collections::BTreeMap;
use std::path::Path;
use std::process::{Command, Output};

fn finding(scene: &str, solver: &str, quantity: &str, diff: f64, allowed: f64) -> Finding {
    Finding {
        scene: scene.into(),
        solver: solver.into(),
        against: Against::Golden,
        quantity: quantity.into(),
        step: Some(3),
        ours: 1.0 + diff,
        theirs: 1.0,
        diff,
        allowed,
        gated: true,
        note: String::new(),
    }
}

/// A scene and solver without golden data, as the baseline comparison reports it.
fn no_golden(scene: &str, solver: &str) -> Finding {
    let mut f = finding(scene, solver, "fx_over_fn", f64::NAN, 1e-7);
    (f.ours, f.theirs, f.step, f.note) = (f64::NAN, f64::NAN, None, compare::no_baseline_note(Against::Golden));
    f
}

#[test]
fn drifts_ranked_by_diff_over_tolerance_and_capped() {
    // A moment 10 N mm off with 5 allowed (2x) ranks below a coefficient 0.01 off with 0.001 (10x).
    let all = vec![finding("s1", "uba", "mz_nmm", 10.0, 5.0), finding("s2", "uba", "fx_over_fn", 0.01, 0.001)];
    let lines = console::drifts(&all, false);
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(lines[0].starts_with("DRIFT scene s2 solver uba against golden metric fx_over_fn step 3"), "{lines:?}");
    assert!(lines[1].contains("metric mz_nmm"), "{lines:?}");
    // 25 drifts: 20 on the console and a count of the rest; all 25 with --verbose.
    let many: Vec<Finding> = (0..25).map(|i| finding(&format!("s{i:02}"), "uba", "cx", 2.0 + i as f64, 1.0)).collect();
    let lines = console::drifts(&many, false);
    assert_eq!(lines.len(), CONSOLE_LINES + 1);
    assert_eq!(CONSOLE_LINES, 20);
    assert!(lines[0].contains("scene s24 "), "worst (26x) first: {}", lines[0]);
    assert_eq!(lines[20], "... and 5 more (see --verbose / --json)");
    assert_eq!(console::drifts(&many, true).len(), 25);
    assert_eq!(Verdict::of(&many), Verdict { gated: 25, failed: 25 });
    assert_eq!(Verdict::of(&many).to_string(), "FAIL: 25 gated comparisons, 25 failed");
}

#[test]
fn a_scene_without_golden_data_is_named_once_not_as_nan() {
    let all =
        vec![no_golden("new_scene", "uba"), no_golden("new_scene", "fastsim"), finding("old", "uba", "cx", 0.0, 1.0)];
    let lines = console::no_baseline(&all, false);
    assert_eq!(
        lines,
        ["new_scene: no golden data (models uba, fastsim): run `creepbench bless` to accept its results"]
    );
    // Not listed again as drifts, though counted as failed.
    assert!(console::drifts(&all, false).is_empty());
    assert_eq!(Verdict::of(&all), Verdict { gated: 3, failed: 2 });
    // Other unmatched comparisons say why rather than "NaN vs NaN".
    let mut f = no_golden("s", "uba");
    f.note = "steps differ: 3 rows here, 4 there, 3 matched".into();
    let line = compare::drift_line(&f);
    assert!(
        line.ends_with("unmatched: steps differ: 3 rows here, 4 there, 3 matched") && !line.contains("NaN"),
        "{line}"
    );
}

#[test]
fn one_line_per_suite_and_model_with_its_worst_ratio() {
    let all = vec![
        finding("a", "uba", "cx", 0.5, 1.0),
        finding("b", "uba", "fx_over_fn", 3.0, 1.0),
        finding("a", "fastsim", "cx", 0.0, 1.0),
        no_golden("c", "uba"),
    ];
    let suite_of: BTreeMap<String, String> =
        [("a", "thesis"), ("b", "thesis"), ("c", "thesis")].map(|(s, t)| (s.to_string(), t.to_string())).into();
    let text = console::per_model(&all, &suite_of);
    let lines: Vec<Vec<&str>> = text.lines().map(|l| l.split_whitespace().collect()).collect();
    assert_eq!(lines.len(), 3, "{text}");
    assert_eq!(lines[1], ["thesis", "fastsim", "1", "0", "0", "no", "difference"], "{text}");
    assert_eq!(lines[2], ["thesis", "uba", "3", "2", "3.000", "b", "golden", "fx_over_fn", "step", "3"], "{text}");
}

/// nonhertz's golden data with nh_flat_sweep_cx only, one CONTACT value drifted by 1e-3.
fn drifted_golden(dir: &Path) -> std::path::PathBuf {
    let golden = dir.join("golden");
    let to = golden.join("nh_flat_sweep_cx");
    std::fs::create_dir_all(&to).unwrap();
    for e in std::fs::read_dir(root().join("golden/nh_flat_sweep_cx")).unwrap() {
        let e = e.unwrap();
        std::fs::copy(e.path(), to.join(e.file_name())).unwrap();
    }
    let csv = to.join("contact.csv");
    crate::common::nudge_csv(&csv, 5, 6, 1e-3);
    golden
}

fn creepbench(args: &[&str], golden: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(root())
        .args(args)
        .arg("--golden")
        .arg(golden)
        .output()
        .unwrap()
}

#[test]
fn check_answers_first_and_run_ends_with_the_verdict() {
    let dir = tempdir("console");
    let golden = drifted_golden(&dir);
    let o = creepbench(&["check", "--quiet", "--suite", "scenes/nonhertz"], &golden);
    let (out, err) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert_eq!(o.status.code(), Some(1), "{err}");
    let first = out.lines().next().unwrap();
    assert!(first.starts_with("FAIL: ") && first.ends_with(" failed"), "verdict first: {out}");
    assert!(out.lines().count() < 40, "one screen: {out}");
    assert!(!out.contains("NaN") && !err.contains("NaN"), "{out}\n{err}");
    let per_model = out.lines().find(|l| l.starts_with("nonhertz") && l.contains(" contact ")).expect(&out);
    assert!(per_model.contains("nh_flat_sweep_cx golden fx_over_fn"), "{per_model}");
    // Every other nonhertz scene lacks golden data: named once each.
    let scenes: Vec<String> = std::fs::read_dir(root().join("scenes/nonhertz"))
        .unwrap()
        .filter_map(|e| e.unwrap().file_name().to_str().unwrap().strip_suffix(".toml").map(String::from))
        .filter(|n| n != "nh_flat_sweep_cx")
        .collect();
    assert!(!scenes.is_empty());
    for s in &scenes {
        let n = out.lines().filter(|l| l.trim_start().starts_with(&format!("{s}: no golden data"))).count();
        assert_eq!(n, 1, "{s}: {out}");
    }
    assert!(err.contains("DRIFT scene nh_flat_sweep_cx solver contact against golden metric fx_over_fn step"), "{err}");
    // --verbose adds the full worst-point table.
    let o = creepbench(&["check", "--quiet", "--verbose", "--suite", "scenes/nonhertz"], &golden);
    let verbose = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1));
    assert!(verbose.lines().next() == Some(first) && verbose.contains("against         quantity"), "{verbose}");
    assert!(verbose.lines().count() > out.lines().count(), "{verbose}");
    // run: the gates' verdict and the report's path, last.
    let (_, rep, out) =
        run_into(&dir, &["--suite".as_ref(), "scenes/nonhertz".as_ref(), "--golden".as_ref(), golden.as_os_str()]);
    let last: Vec<&str> = out.lines().rev().take(2).collect();
    assert_eq!(last[0], format!("report: {}", rep.join("validation.md").display()), "{out}");
    assert!(last[1].starts_with("gates: FAIL: ") && last[1].ends_with(" failed"), "{out}");
}

/// A report of a suite of one's own (issue 31): that suite and the sections that apply to it —
/// no shipped fits run, no thesis table, no CONTACT error table or grid refinement without their
/// scenes, and a scene without golden data named as such, never with NaN values.
#[test]
fn a_report_of_ones_own_suite_shows_that_suite() {
    let dir = tempdir("console_own_suite");
    let suite = dir.join("suite");
    std::fs::create_dir_all(&suite).unwrap();
    let text = scene_text("my_step", r#"["uba", "fastsim"]"#, 0.4, 22, "kind = \"step\"\nc = 0.005\nsteps = 10", "");
    std::fs::write(suite.join("my_step.toml"), text).unwrap();
    let (res, rep, out) = run_into(&dir, &["--suite".as_ref(), suite.as_os_str()]);
    assert!(!out.contains("fit ") && !res.join("fits").exists(), "the shipped fits ran: {out}");
    assert!(out.contains("gates: FAIL: 2 gated comparisons, 2 failed"), "{out}");
    let md = std::fs::read_to_string(rep.join("validation.md")).unwrap();
    for absent in [
        "The thesis's figures beside ours",
        "Error against CONTACT",
        "Convergence under grid refinement",
        "Calibration",
        "NaN",
    ] {
        assert!(!md.contains(absent), "the report of one's own suite shows {absent:?}:\n{md}");
    }
    assert!(md.contains("no golden data for this scene and solver"), "{md}");
    // The models it ran are introduced, not every built-in one.
    assert!(md.contains("`uba` (") && md.contains("`fastsim` (") && !md.contains("`polach` ("), "{md}");
}

/// `creepbench run --quiet ARGS` from the project folder, results and report in `dir/res` and
/// `dir/rep`; it must succeed. Returns both folders and its stdout.
fn run_into(dir: &Path, args: &[&std::ffi::OsStr]) -> (std::path::PathBuf, std::path::PathBuf, String) {
    let (res, rep) = (dir.join("res"), dir.join("rep"));
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(root())
        .args(["run", "--quiet"])
        .args(args)
        .arg("--results")
        .arg(&res)
        .arg("--report")
        .arg(&rep)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    (res, rep, String::from_utf8_lossy(&o.stdout).into_owned())
}
