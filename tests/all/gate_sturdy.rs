//! The gate keeps its promises, round two (issue 48): a closed console, interrupted blesses'
//! leftovers, merges that fail on drift and on what a scene is owed, empty shards, huge numbers
//! in drift lines, `--strict` before any scene runs. Every case in a temporary folder.

use crate::common;
use common::*;
use creepbench::suite::Shard;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn command(dir: &Path, args: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_creepbench"));
    c.current_dir(dir).args(args).env_remove("GITHUB_STEP_SUMMARY");
    c
}

fn creepbench(dir: &Path, args: &[&str]) -> Output {
    command(dir, args).output().expect("runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).to_string()
}

/// The reference data, as an argument.
fn refs() -> String {
    root().join("reference").display().to_string()
}

/// A quick scene called `name` (the UBA on an 8x8 grid, four steps) as `dir/<name>.toml`.
fn write_scene(dir: &Path, name: &str) {
    std::fs::create_dir_all(dir).unwrap();
    let text = scene_text(name, "[\"uba\"]", 0.4, 8, "kind = \"step\"\nc = 0.005\nsteps = 4", "");
    std::fs::write(dir.join(format!("{name}.toml")), text).unwrap();
}

/// A work folder with suite/ holding `names`, blessed into golden/ when `bless`.
fn workspace(names: &[&str], bless: bool) -> tempfile::TempDir {
    let w = tempfile::tempdir().unwrap();
    for n in names {
        write_scene(&w.path().join("suite"), n);
    }
    if bless {
        let o = creepbench(w.path(), &["bless", "--quiet", "--suite", "suite"]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    }
    w
}

/// Set the `column`-th field of data row `row` of a CSV file to `value`.
fn set_csv_field(path: &Path, row: usize, column: usize, value: &str) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let mut fields: Vec<String> = lines[row].split(',').map(str::to_string).collect();
    fields[column] = value.into();
    lines[row] = fields.join(",");
    std::fs::write(path, lines.join("\n") + "\n").unwrap();
}

/// A drift in golden/: a_one's UBA fx_over_fn at its first step set to `value`.
fn drift_golden(w: &Path, value: &str) {
    set_csv_field(&w.join("golden/a_one/uba.csv"), 1, 6, value);
}

/// Standard output whose reader is already gone: every write fails with a broken pipe.
fn closed_stdout() -> Stdio {
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    Stdio::from(writer)
}

// ---------------------------------------------------------------------------------------------
// Item 1: a closed console

#[test]
fn a_closed_console_costs_neither_the_gate_files_nor_the_exit_status() {
    let w = workspace(&["a_one", "a_two"], true);
    let refs = refs();
    let check = |tag: &str| {
        let files = [format!("{tag}.xml"), format!("{tag}.json"), format!("{tag}.md")];
        let args = ["check", "--quiet", "--verbose", "--suite", "suite", "--reference", &refs];
        let o = command(w.path(), &args)
            .args(["--junit", &files[0], "--json", &files[1], "--summary", &files[2]])
            .stdout(closed_stdout())
            .output()
            .unwrap();
        for f in &files {
            let written = std::fs::read_to_string(w.path().join(f)).unwrap_or_default();
            assert!(!written.is_empty(), "{tag}: {f} not written: {}", stderr(&o));
        }
        o
    };
    let o = check("pass");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!stderr(&o).contains("panicked"), "{}", stderr(&o));
    // A closed pipe is no failure worth a warning: the reader chose to stop.
    assert!(!stderr(&o).contains("standard output"), "{}", stderr(&o));
    drift_golden(w.path(), "0.2");
    let o = check("fail");
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let json = std::fs::read_to_string(w.path().join("fail.json")).unwrap();
    assert!(json.contains("\"passed\": false"), "{json}");
    // run, simulate and merge print their paths and verdicts: a closed console costs them nothing.
    let cases: [&[&str]; 3] = [
        &["run", "--quiet", "--suite", "suite", "--reference", &refs, "--results", "res", "--report", "rep"],
        &["simulate", "suite/a_one.toml", "--out", "sim"],
        &["merge", "res", "--suite", "suite", "--reference", &refs, "--report", "merged", "--golden", "none"],
    ];
    for args in cases {
        let o = command(w.path(), args).stdout(closed_stdout()).output().unwrap();
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
    }
    assert!(w.path().join("rep/validation.md").is_file() && w.path().join("sim/a_one/uba.csv").is_file());
    assert!(w.path().join("merged/validation.md").is_file());
    // A full standard error (`2> /dev/full`): the warnings and notes are dropped, no panic.
    let full = || std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
    drift_golden(w.path(), "0.2");
    let args = ["check", "--suite", "suite", "--reference", &refs, "--json", "full.json"];
    let o = command(w.path(), &args).stderr(full()).stdout(Stdio::null()).output().unwrap();
    assert_eq!(o.status.code(), Some(1));
    assert!(std::fs::read_to_string(w.path().join("full.json")).unwrap().contains("\"passed\": false"));
    let args = ["run", "--suite", "suite", "--reference", &refs, "--results", "res2", "--report", "rep2"];
    let o = command(w.path(), &args).stderr(full()).stdout(Stdio::null()).output().unwrap();
    assert_eq!(o.status.code(), Some(0));
    assert!(w.path().join("rep2/validation.md").is_file());
}

// ---------------------------------------------------------------------------------------------
// Item 3: leftovers of interrupted blesses

/// The id of a process that has ended.
fn dead_pid() -> u32 {
    let mut child = Command::new("true").spawn().unwrap();
    let pid = child.id();
    child.wait().unwrap();
    pid
}

/// The entries of `dir`, sorted.
fn listing(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> =
        std::fs::read_dir(dir).unwrap().flatten().map(|e| e.file_name().to_string_lossy().into()).collect();
    v.sort();
    v
}

/// A leftover as an interrupted cleanup leaves it: scene files, no marker.
fn plant_leftover(dir: &Path) -> PathBuf {
    std::fs::create_dir_all(dir.join("a_one")).unwrap();
    std::fs::write(dir.join("a_one/uba.csv"), "half").unwrap();
    std::fs::write(dir.join("metrics.csv"), "x").unwrap();
    dir.to_path_buf()
}

#[test]
fn leftovers_whose_owner_no_longer_runs_are_removed_by_the_next_run_that_takes_the_lock() {
    let w = workspace(&["a_one", "a_two"], true);
    let dead = dead_pid();
    let gone = plant_leftover(&w.path().join(format!(".golden.creepbench-new-{dead}-0")));
    // A live owner's folder (this test process) and a look-alike of no run's are left alone.
    let live = plant_leftover(&w.path().join(format!(".golden.creepbench-new-{}-7", std::process::id())));
    let foreign = plant_leftover(&w.path().join(".golden.creepbench-new-x-0"));
    let o = creepbench(w.path(), &["bless", "--quiet", "--suite", "suite"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!gone.exists(), "{:?}", listing(w.path()));
    assert!(live.join("a_one/uba.csv").is_file() && foreign.join("a_one/uba.csv").is_file());
    // In a results folder: the leftover of a scene this run does not write goes too.
    let res = w.path().join("res");
    std::fs::create_dir_all(&res).unwrap();
    let gone = plant_leftover(&res.join(format!(".renamed_scene.creepbench-new-{dead}-3")));
    let refs = refs();
    let args = ["run", "--quiet", "--suite", "suite", "--reference", &refs, "--results", "res", "--report", "rep"];
    let o = creepbench(w.path(), &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!gone.exists(), "{:?}", listing(&res));
}

#[test]
fn blesses_interrupted_by_signals_leave_nothing_the_next_bless_does_not_remove() {
    let names: Vec<String> = (0..40).map(|i| format!("s_{i:02}")).collect();
    let refs: Vec<&str> = names.iter().map(String::as_str).collect();
    let w = workspace(&refs, true);
    let start = Instant::now();
    let o = creepbench(w.path(), &["bless", "--quiet", "--suite", "suite"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let full = start.elapsed().as_secs_f64();
    let signals = [rustix::process::Signal::INT, rustix::process::Signal::TERM, rustix::process::Signal::HUP];
    let (mut rng, mut leftovers, mut trials) = (0x2545_f491_4f6c_dd1du64, 0, 0);
    while trials < 30 && start.elapsed() < Duration::from_secs(30) {
        trials += 1;
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        let mut child = command(w.path(), &["bless", "--quiet", "--suite", "suite"])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(Duration::from_secs_f64(full * (rng % 1000) as f64 / 1000.0));
        let pid = rustix::process::Pid::from_raw(child.id() as i32).unwrap();
        let _ = rustix::process::kill_process(pid, signals[trials % 3]);
        child.wait().unwrap();
        if listing(w.path()).len() > 2 {
            leftovers += 1;
        }
        let o = creepbench(w.path(), &["bless", "--quiet", "--suite", "suite"]);
        assert_eq!(o.status.code(), Some(0), "trial {trials}: {}", stderr(&o));
        assert_eq!(listing(w.path()), ["golden", "suite"], "trial {trials}");
    }
    eprintln!("{trials} interrupted blesses, {leftovers} left leftovers, all removed by the next bless");
}

// ---------------------------------------------------------------------------------------------
// Item 5: merge fails on drift and on what a scene is owed

#[test]
fn merge_exits_with_the_verdict_and_a_result_short_of_its_scene_fails() {
    let w = workspace(&["a_one", "a_two"], true);
    let refs = refs();
    let args = ["run", "--quiet", "--suite", "suite", "--reference", &refs, "--results", "res", "--golden", "none"];
    let o = creepbench(w.path(), &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let merge = |report: &str, golden: &str| {
        let args = ["merge", "res", "--suite", "suite", "--reference", &refs, "--report", report, "--golden", golden];
        creepbench(w.path(), &args)
    };
    let o = merge("rep0", "golden");
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // A drift fails the merge as it fails `check`.
    drift_golden(w.path(), "0.2");
    let o = merge("rep1", "golden");
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("gates: FAIL"));
    // Without golden data: an edited scene.json and a history cut to half its rows each fail.
    let json = w.path().join("res/a_one/scene.json");
    let original = std::fs::read_to_string(&json).unwrap();
    let mut scene: serde_json::Value = serde_json::from_str(&original).unwrap();
    scene["freq_hz"] = serde_json::json!(0.0);
    std::fs::write(&json, serde_json::to_string_pretty(&scene).unwrap()).unwrap();
    let o = merge("rep2", "none");
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("SHORT scene a_one") && stderr(&o).contains("freq_hz"), "{}", stderr(&o));
    let md = std::fs::read_to_string(w.path().join("rep2/validation.md")).unwrap();
    assert!(md.contains("GATES FAIL") && !md.contains("All gates pass"));
    // scene.json records the loading as declared (issue 48 item 6): an edited step level fails too.
    let mut scene: serde_json::Value = serde_json::from_str(&original).unwrap();
    scene["loading"]["creepage"]["c"] = serde_json::json!(0.01);
    std::fs::write(&json, serde_json::to_string_pretty(&scene).unwrap()).unwrap();
    let o = merge("rep2b", "none");
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("SHORT scene a_one") && stderr(&o).contains("\"loading\""), "{}", stderr(&o));
    std::fs::write(&json, original).unwrap();
    let csv = w.path().join("res/a_two/uba.csv");
    let text = std::fs::read_to_string(&csv).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    std::fs::write(&csv, lines[..1 + (lines.len() - 1) / 2].join("\n") + "\n").unwrap();
    let o = merge("rep3", "none");
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("SHORT scene a_two uba: rows (") && stderr(&o).contains("owes 4"), "{}", stderr(&o));
    // A scene of a suite not given is named, not checked.
    let o = creepbench(w.path(), &["merge", "res", "--reference", &refs, "--report", "rep4", "--golden", "none"]);
    assert!(stderr(&o).contains("not checked against their scene files: a_one, a_two"), "{}", stderr(&o));
}

// ---------------------------------------------------------------------------------------------
// Item 8: an empty shard, huge numbers, --strict first

#[test]
fn an_empty_shard_is_a_success_with_a_one_line_note() {
    let w = workspace(&["a_one", "a_two"], true);
    let before = std::fs::read_dir(w.path().join("golden")).unwrap().count();
    let empty = (1..=4).find(|&i| ["a_one", "a_two"].iter().all(|n| !Shard { index: i, count: 4 }.takes(n))).unwrap();
    let shard = format!("{empty}/4");
    let refs = refs();
    for args in [
        vec!["check", "--quiet", "--suite", "suite", "--reference", &refs, "--shard", &shard, "--junit", "j.xml"],
        vec!["run", "--quiet", "--suite", "suite", "--reference", &refs, "--shard", &shard, "--results", "res"],
        vec!["bless", "--quiet", "--suite", "suite", "--shard", &shard],
    ] {
        let o = creepbench(w.path(), &args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        let err = stderr(&o);
        let notes: Vec<&str> = err.lines().filter(|l| l.contains("holds none of")).collect();
        assert_eq!(notes, [format!("note: shard {shard} holds none of the 2 scene(s) of suite: nothing to run")]);
    }
    let junit = std::fs::read_to_string(w.path().join("j.xml")).unwrap();
    assert!(junit.contains("tests=\"0\" failures=\"0\""), "{junit}");
    assert_eq!(std::fs::read_dir(w.path().join("golden")).unwrap().count(), before);
    // A suite without any scene stays an input error.
    std::fs::create_dir_all(w.path().join("empty")).unwrap();
    let o = creepbench(w.path(), &["check", "--quiet", "--suite", "empty", "--reference", &refs, "--shard", "1/4"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}

#[test]
fn drift_lines_print_huge_numbers_with_an_exponent() {
    let w = workspace(&["a_one", "a_two"], true);
    drift_golden(w.path(), "1.7e308");
    let refs = refs();
    let o = creepbench(w.path(), &["check", "--quiet", "--suite", "suite", "--reference", &refs, "--summary", "s.md"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let summary = std::fs::read_to_string(w.path().join("s.md")).unwrap();
    for text in [stderr(&o), summary] {
        assert!(text.contains("1.7e308"), "{text}");
        assert!(!text.contains("0000000000000000000000000"), "{text}");
    }
}

#[test]
fn strict_refuses_a_loosening_rule_before_any_scene_runs() {
    let w = workspace(&["a_one", "a_two"], true);
    let rule = "[[rule]]\nagainst = \"golden\"\nscene = \"a_one\"\nsolver = \"uba\"\nquantity = \"fx_over_fn\"\n\
                abs = 0.01\nwhy = \"the test's reason\"\n";
    std::fs::write(w.path().join("t.toml"), rule).unwrap();
    let refs = refs();
    let args = ["check", "--quiet", "--suite", "suite", "--reference", &refs, "--tolerances", "t.toml", "--strict"];
    let o = creepbench(w.path(), &args);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("t.toml rule[0]") && stderr(&o).contains("--strict"), "{}", stderr(&o));
    assert!(!stderr(&o).contains("ran 2 scene(s)"), "a scene ran before the refusal: {}", stderr(&o));
}

// ---------------------------------------------------------------------------------------------
// Item 7: a foreign file in a suite is never quoted

#[test]
fn a_foreign_file_in_a_suite_is_named_by_path_and_position_only() {
    let w = workspace(&["a_one"], false);
    std::fs::create_dir(w.path().join("golden")).unwrap();
    let passwd = "root:x:0:0:root:/root:/bin/bash\ndaemon:x:1:1:daemon:/usr/sbin:/usr/sbin/nologin\n";
    std::fs::write(w.path().join("passwd"), passwd).unwrap();
    std::os::unix::fs::symlink(w.path().join("passwd"), w.path().join("suite/passwd.toml")).unwrap();
    let refs = refs();
    for args in [
        vec!["check", "--quiet", "--suite", "suite", "--reference", &refs],
        vec!["simulate", "suite/passwd.toml", "--out", "out"],
        vec!["check", "--quiet", "--suite", "suite", "--reference", &refs, "--tolerances", "passwd"],
    ] {
        let o = creepbench(w.path(), &args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains("passwd") && err.contains("line 1, column"), "{args:?}: {err}");
        for secret in ["x:0:0", "/bin/bash", "nologin", "daemon"] {
            assert!(!err.contains(secret), "{args:?} quotes {secret:?}: {err}");
        }
    }
    // A line of the tool's own files is still quoted (a typo is found by its text).
    use creepbench::scene::reader::looks_like_own_toml;
    for own in ["mu = 0.4 0.3", "abs = 1e-9 x", "[contact", "scene = \"sine_*\" x", "\"contact.mu\" = [0.3, 0.4"] {
        assert!(looks_like_own_toml(own), "{own}");
    }
    for foreign in ["root:x:0:0:root:/root:/bin/bash", "KEY=abc/def+g", "user@host:~$ ls", "-----BEGIN KEY-----"] {
        assert!(!looks_like_own_toml(foreign), "{foreign}");
    }
}

// ---------------------------------------------------------------------------------------------
// Item 2: outputs through links

/// Every file under `dir` with its contents.
fn tree(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        if e.file_type().unwrap().is_dir() {
            out.extend(tree(&e.path()));
        } else {
            out.push((e.path(), std::fs::read(e.path()).unwrap()));
        }
    }
    out.sort();
    out
}

#[test]
fn outputs_through_links_are_written_through_and_a_protected_file_is_known_by_its_identity() {
    use std::os::unix::fs::symlink;
    let w = workspace(&["a_one", "a_two"], true);
    let d = w.path();
    let golden = tree(&d.join("golden"));
    std::fs::create_dir(d.join("real")).unwrap();
    std::fs::write(d.join("real/j.xml"), "old").unwrap();
    symlink("real/j.xml", d.join("j.xml")).unwrap();
    symlink(d.join("real/new.json"), d.join("c.json")).unwrap();
    symlink("real/s.md", d.join("s.md")).unwrap();
    let refs = refs();
    let check = ["check", "--quiet", "--suite", "suite", "--reference", &refs];
    let o = command(d, &check).args(["--junit", "j.xml", "--json", "c.json", "--summary", "s.md"]).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    for (link, target, says) in [
        ("j.xml", "real/j.xml", "<testsuites"),
        ("c.json", "real/new.json", "\"passed\""),
        ("s.md", "real/s.md", "## "),
    ] {
        assert!(std::fs::symlink_metadata(d.join(link)).unwrap().file_type().is_symlink(), "{link} was replaced");
        assert!(std::fs::read_to_string(d.join(target)).unwrap().contains(says), "{target}");
    }
    // A link that names a file not yet there inside golden/: refused before any work.
    symlink("golden/new.json", d.join("g.json")).unwrap();
    let o = command(d, &check).args(["--json", "g.json"]).output().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("refusing") && !stderr(&o).contains("ran 2 scene(s)"), "{}", stderr(&o));
    // $GITHUB_STEP_SUMMARY or --junit that is a hard link of a golden file: refused by identity.
    std::fs::hard_link(d.join("golden/a_one/metrics.csv"), d.join("summary.md")).unwrap();
    let o = command(d, &check).env("GITHUB_STEP_SUMMARY", "summary.md").output().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("hard link") && stderr(&o).contains("metrics.csv"), "{}", stderr(&o));
    let o = command(d, &check).args(["--junit", "summary.md"]).output().unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    // A report file that is a link into golden/ is never written through.
    std::fs::create_dir(d.join("rep")).unwrap();
    symlink("../golden/a_one/notes.md", d.join("rep/validation.md")).unwrap();
    let args = ["run", "--quiet", "--suite", "suite", "--reference", &refs, "--results", "res", "--report", "rep"];
    let o = creepbench(d, &args);
    assert_ne!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(std::fs::symlink_metadata(d.join("rep/validation.md")).unwrap().file_type().is_symlink());
    assert_eq!(tree(&d.join("golden")), golden);
}

#[test]
fn every_report_output_is_checked_before_any_work() {
    use std::os::unix::fs::symlink;
    let w = workspace(&["a_one"], true);
    let d = w.path();
    let golden = tree(&d.join("golden"));
    let refs = refs();
    let args = ["run", "--quiet", "--suite", "suite", "--reference", &refs, "--results", "res", "--report", "rep"];
    // figures/ a link into golden/, tables/ a folder this tool did not write: each refused
    // before any scene runs, and the results folder never made.
    std::fs::create_dir(d.join("rep")).unwrap();
    symlink("../golden/a_one", d.join("rep/figures")).unwrap();
    let o = creepbench(d, &args);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("figures") && stderr(&o).contains("bless"), "{}", stderr(&o));
    assert!(!d.join("res").exists(), "results written despite the refusal");
    std::fs::remove_file(d.join("rep/figures")).unwrap();
    std::fs::create_dir_all(d.join("rep/tables")).unwrap();
    std::fs::write(d.join("rep/tables/mine.md"), "my notes").unwrap();
    let o = creepbench(d, &args);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("tables"), "{}", stderr(&o));
    assert!(!d.join("res").exists(), "results written despite the refusal");
    assert_eq!(std::fs::read_to_string(d.join("rep/tables/mine.md")).unwrap(), "my notes");
    // merge: the same check before reading anything.
    std::fs::remove_dir_all(d.join("rep/tables")).unwrap();
    let o = creepbench(
        d,
        &["run", "--quiet", "--suite", "suite", "--reference", &refs, "--results", "res", "--report", "ok"],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    symlink("../golden/a_one", d.join("rep/figures")).unwrap();
    let o = creepbench(d, &["merge", "res", "--reference", &refs, "--report", "rep"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert_eq!(tree(&d.join("golden")), golden);
}

#[test]
fn a_suites_own_tolerance_file_covers_only_that_suites_scenes() {
    // Two suites, one scene each, blessed together; both drift by the same amount in golden/.
    let w = tempfile::tempdir().unwrap();
    let d = w.path();
    write_scene(&d.join("one"), "a_one");
    write_scene(&d.join("two"), "b_two");
    let both = ["--suite", "one", "--suite", "two"];
    let o = command(d, &["bless", "--quiet"]).args(both).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    drift_golden(d, "0.2");
    set_csv_field(&d.join("golden/b_two/uba.csv"), 1, 6, "0.2");
    // Suite one's own file loosens every scene's UBA fx: it decides a_one, never b_two.
    let rule = "[[rule]]\nagainst = \"golden\"\nscene = \"*\"\nsolver = \"uba\"\nquantity = \"fx_over_fn\"\n\
                abs = 1.0\nwhy = \"suite one's own reason\"\n";
    std::fs::write(d.join("one/tolerances.toml"), rule).unwrap();
    let refs = refs();
    let o = command(d, &["check", "--quiet", "--reference", &refs, "--json", "c.json"]).args(both).output().unwrap();
    assert_eq!(o.status.code(), Some(1), "b_two's drift must still fail: {}", stderr(&o));
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(d.join("c.json")).unwrap()).unwrap();
    let failed: Vec<&str> = json["findings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|f| f["gated"] == true && f["passed"] == false)
        .map(|f| f["scene"].as_str().unwrap())
        .collect();
    assert!(!failed.is_empty() && failed.iter().all(|s| *s == "b_two"), "{failed:?}");
}
