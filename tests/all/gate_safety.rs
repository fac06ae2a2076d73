//! Issue 11 through the public API: hostile inputs against the bounded reader, the external
//! solver and the result folders; processes killed on timeout, interrupt and kill -9; and a
//! fault-injection test that kills a bless-style replacement at random points.
//!
//! Some tests re-run this test binary as a child (`child_entry`, selected by an environment
//! variable) to have a creepbench-like process to interrupt or kill.

use crate::common;
use common::{scene_text, take_kept_folder};
use creepbench::problem::Problem;
use creepbench::safety::excerpt::excerpt;
use creepbench::safety::folder::{self, FolderError, MARKER};
use creepbench::safety::guard::{guard_not_under, GuardError};
use creepbench::safety::lock::{lock_folder, LockError};
use creepbench::safety::manifest::{self, ManifestError, MANIFEST};
use creepbench::safety::process::{self, ProcessError, CAPTURE_LIMIT_BYTES};
use creepbench::safety::read::{self, read_text, FileKind, ReadError};
use creepbench::scene::Scene;
use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

const CHILD_ENV: &str = "GATE_SAFETY_CHILD";
const DIR_ENV: &str = "GATE_SAFETY_DIR";
const VERSION_ENV: &str = "GATE_SAFETY_VERSION";

// ---------------------------------------------------------------------------------------------
// Processes: helpers

/// The state letter of /proc/PID/stat, `None` when there is no such process.
fn proc_state(pid: i32) -> Option<(char, i32)> {
    let stat = fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    let mut fields = stat[stat.rfind(')')? + 2..].split(' ');
    let state = fields.next()?.chars().next()?;
    let pgrp = fields.nth(1)?.parse().ok()?;
    Some((state, pgrp))
}

/// Running (not a zombie waiting for a reaper).
fn alive(pid: i32) -> bool {
    proc_state(pid).is_some_and(|(s, _)| s != 'Z' && s != 'X')
}

/// Live processes of the group `pgid`.
fn group_members(pgid: i32) -> Vec<i32> {
    fs::read_dir("/proc")
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().to_str()?.parse::<i32>().ok())
        .filter(|&pid| proc_state(pid).is_some_and(|(s, g)| g == pgid && s != 'Z' && s != 'X'))
        .collect()
}

/// Wait up to `limit` for `file` to hold a pid.
fn wait_for_pid(file: &Path, limit: Duration) -> i32 {
    let start = Instant::now();
    loop {
        if let Some(pid) = fs::read_to_string(file).ok().and_then(|s| s.trim().parse().ok()) {
            return pid;
        }
        assert!(start.elapsed() < limit, "{} never appeared", file.display());
        std::thread::sleep(Duration::from_millis(5));
    }
}

fn wait_until(limit: Duration, mut done: impl FnMut() -> bool) -> bool {
    let start = Instant::now();
    while start.elapsed() < limit {
        if done() {
            return true;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    done()
}

fn kill_pid(pid: i32, signal: rustix::process::Signal) {
    if let Some(pid) = rustix::process::Pid::from_raw(pid) {
        let _ = rustix::process::kill_process(pid, signal);
    }
}

/// Wait for a child with a deadline; killed and failed past it.
fn wait_child(child: &mut Child, limit: Duration) -> std::process::ExitStatus {
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("child did not exit within {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

fn sh(script: &str) -> Command {
    let mut c = Command::new("sh");
    c.arg("-c").arg(script);
    c
}

/// This test binary as a child in `mode`.
fn spawn_self(mode: &str, dir: &Path, version: u64) -> Command {
    // The test's path in this binary: its module path without the crate's name.
    let test = format!("{}::child_entry", module_path!().split_once("::").map_or("", |(_, m)| m));
    let mut c = Command::new(std::env::current_exe().unwrap());
    c.args([test.as_str(), "--exact", "--nocapture", "--test-threads=1", "-q"])
        .env(CHILD_ENV, mode)
        .env(DIR_ENV, dir)
        .env(VERSION_ENV, version.to_string())
        .stdout(Stdio::null())
        .stderr(Stdio::null());
    c
}

/// Does nothing in a normal run; as a child started by another test, plays its part.
#[test]
fn child_entry() {
    let Ok(mode) = std::env::var(CHILD_ENV) else { return };
    let dir = PathBuf::from(std::env::var(DIR_ENV).unwrap());
    let version: u64 = std::env::var(VERSION_ENV).unwrap().parse().unwrap();
    match mode.as_str() {
        // Blesses in a row: replace dir/golden with the trees of `version`, `version + 1`, …
        "bless" => {
            for v in version..version + BLESSES_PER_CHILD {
                folder::replace_tree_atomically(&dir.join("golden"), |tree| write_version(tree, v)).unwrap();
            }
        }
        // A model run interrupted or killed by the parent test; a registered temp folder.
        "model" => {
            fs::create_dir_all(dir.join("work")).unwrap();
            fs::write(dir.join("work/big.bin"), "x").unwrap();
            let _cleanup = creepbench::safety::interrupt::register_folder(dir.join("work"));
            // The direct child records itself and a grandchild, then sleeps.
            let d = dir.display();
            let script = format!(
                "sleep 1000 & echo $! > {d}/gc.tmp; mv {d}/gc.tmp {d}/gc; echo $$ > {d}/pid.tmp; mv {d}/pid.tmp {d}/pid; exec sleep 1000"
            );
            let _ = process::run(sh(&script), Duration::from_secs(60), 1 << 20);
        }
        // Whether a program reading stdin gets end-of-file although our own stdin stays open.
        "stdin" => {
            let out = process::run(sh("cat; echo eof"), Duration::from_secs(5), 1 << 20);
            let verdict = match out {
                Ok(o) if o.stdout.tail() == b"eof\n" => "stdin-eof-ok".to_string(),
                other => format!("{other:?}"),
            };
            fs::write(dir.join("verdict"), verdict).unwrap();
        }
        other => panic!("unknown child mode {other}"),
    }
}

// ---------------------------------------------------------------------------------------------
// Bounded, non-blocking reads

fn fifo(path: &Path) {
    use rustix::fs::{mknodat, FileType, Mode, CWD};
    mknodat(CWD, path, FileType::Fifo, Mode::RUSR | Mode::WUSR, 0).unwrap();
}

/// A hostile file: what it is, its path, the size limit it is read with, the error expected.
type ReadCase = (&'static str, PathBuf, u64, fn(&ReadError) -> bool);

#[test]
fn hostile_files_are_refused_quickly_naming_the_file_and_never_quoting_it() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path();
    let start = Instant::now();
    let path = |name: &str| d.join(name);

    fifo(&path("scene.toml"));
    let socket = std::os::unix::net::UnixListener::bind(path("table.sock")).unwrap();
    std::os::unix::fs::symlink("/dev/zero", path("zero_link.toml")).unwrap();
    std::os::unix::fs::symlink(path("loop_b"), path("loop_a")).unwrap();
    std::os::unix::fs::symlink(path("loop_a"), path("loop_b")).unwrap();
    let secret = "SECRET_TOKEN_abc123";
    fs::write(path("ten_mb.toml"), format!("name = \"{secret}\"\n{}", "#".repeat(10 << 20))).unwrap();
    let sparse = fs::File::create(path("three_gb.csv")).unwrap();
    sparse.set_len(3 << 30).unwrap();
    fs::write(path("latin1.csv"), b"t_s,cx\n0,\xff\xfe\n").unwrap();
    fs::write(path("nul.csv"), format!("t_s,cx\n0,{secret}\0\n")).unwrap();
    fs::write(path("at_limit.toml"), "a".repeat(1000)).unwrap();
    fs::write(path("over_limit.toml"), format!("{secret}{}", "a".repeat(1000))).unwrap();

    let mib = 1 << 20;
    let cases: Vec<ReadCase> = vec![
        ("FIFO as scene file", path("scene.toml"), mib, |e| {
            matches!(e, ReadError::NotRegular { kind: FileKind::Fifo, .. })
        }),
        ("/dev/zero", PathBuf::from("/dev/zero"), mib, |e| {
            matches!(e, ReadError::NotRegular { kind: FileKind::CharacterDevice, .. })
        }),
        ("/dev/null", PathBuf::from("/dev/null"), mib, |e| matches!(e, ReadError::NotRegular { .. })),
        ("a symbolic link to /dev/zero", path("zero_link.toml"), mib, |e| {
            matches!(e, ReadError::NotRegular { kind: FileKind::CharacterDevice, .. })
        }),
        ("a directory", d.to_path_buf(), mib, |e| matches!(e, ReadError::NotRegular { kind: FileKind::Directory, .. })),
        ("a socket", path("table.sock"), mib, |e| matches!(e, ReadError::NotRegular { kind: FileKind::Socket, .. })),
        ("a symbolic link loop", path("loop_a"), mib, |e| matches!(e, ReadError::Io { .. })),
        ("a missing file", path("missing.toml"), mib, |e| matches!(e, ReadError::Io { .. })),
        (
            "10 MB with a 1 MB limit",
            path("ten_mb.toml"),
            mib,
            |e| matches!(e, ReadError::TooLarge { limit_bytes, .. } if *limit_bytes == 1 << 20),
        ),
        ("a 3 GB sparse model output", path("three_gb.csv"), read::MODEL_OUTPUT_LIMIT_BYTES, |e| {
            matches!(e, ReadError::TooLarge { .. })
        }),
        ("/proc/self/environ as table file", PathBuf::from("/proc/self/environ"), read::TABLE_LIMIT_BYTES, |e| {
            matches!(e, ReadError::Binary { .. })
        }),
        ("/proc/self/maps past a small limit", PathBuf::from("/proc/self/maps"), 64, |e| {
            matches!(e, ReadError::TooLarge { .. })
        }),
        ("invalid UTF-8", path("latin1.csv"), mib, |e| matches!(e, ReadError::NotUtf8 { offset_bytes: 9, .. })),
        ("a NUL byte", path("nul.csv"), mib, |e| matches!(e, ReadError::Binary { .. })),
        ("one byte over the limit", path("over_limit.toml"), 1000 + secret.len() as u64 - 1, |e| {
            matches!(e, ReadError::TooLarge { .. })
        }),
    ];
    for (name, p, limit, expected) in &cases {
        let e = read_text(p, *limit, "scene file").expect_err(name);
        let m = e.to_string();
        assert!(expected(&e), "{name}: {m}");
        assert!(m.contains(&p.display().to_string()) && m.contains("scene file"), "{name}: {m}");
        assert!(!m.contains(secret) && !m.contains("PATH=") && m.len() < 400, "{name}: {m}");
        if let ReadError::TooLarge { .. } = e {
            assert!(m.contains(&format!("{limit} bytes")), "{name}: {m}");
        }
    }
    assert_eq!(read_text(&path("at_limit.toml"), 1000, "scene file").unwrap().len(), 1000);
    // The 3 GB file was neither read nor allocated: all of this takes well under a second.
    assert!(start.elapsed() < Duration::from_secs(5), "{:?}", start.elapsed());
    drop(socket);
}

#[test]
fn excerpts_of_hostile_values_are_short_and_inert() {
    for (value, must_not_contain) in [
        ("x".repeat(10 << 20), "xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx"),
        ("\u{1b}]0;pwned\u{7}\u{1b}[2J".to_string(), "\u{1b}"),
        ("line1\nline2\r".to_string(), "\n"),
        ("abc\u{202e}cba".to_string(), "\u{202e}"),
        ("\0".repeat(100), "\0"),
    ] {
        let e = excerpt(&value);
        assert!(e.chars().count() <= 90 && !e.contains(must_not_contain), "{e}");
    }
}

// ---------------------------------------------------------------------------------------------
// External models

/// First line of every model script: log the model's temporary folder in `dir/tempdirs`.
const LOG_TEMP_DIR: &str = "echo \"$(dirname \"$2\")\" >> \"$(dirname \"$0\")/tempdirs\"\n";

/// A step scene of six steps run by the external model `m` = `sh dir/model.sh SCENE OUT`.
fn problem_with_model(dir: &Path, script: &str) -> Problem {
    fs::write(dir.join("model.sh"), format!("{LOG_TEMP_DIR}{script}")).unwrap();
    let ext = format!("[external.m]\ncommand = [\"sh\", \"{}\"]\n", dir.join("model.sh").display());
    let text = scene_text("ext", "[\"m\"]", 0.4, 10, "kind = \"step\"\nc = 0.005\nsteps = 6", &ext);
    creepbench::pipeline::resolve(&Scene::from_toml(&text, dir).unwrap()).unwrap()
}

/// Every temporary folder a model ran in is gone (those kept on failure removed by the test).
fn assert_no_temp_dirs(dir: &Path) {
    let log = fs::read_to_string(dir.join("tempdirs")).unwrap();
    assert!(log.lines().count() > 0);
    let left: Vec<&str> = log.lines().filter(|d| Path::new(d).exists()).collect();
    assert!(left.is_empty(), "left behind: {left:?}");
}

fn run_model(problem: &Problem) -> Result<creepbench::history::History, String> {
    let ran = creepbench::history::external::External::new(problem.external[0].clone()).run(problem);
    ran.map(|r| r.history).map_err(|e| e.to_string())
}

/// The rows a correct model writes: the scene's loading, traction 0.1, 0.
fn good_rows(p: &Problem) -> Vec<Vec<String>> {
    p.loading
        .samples
        .iter()
        .map(|s| {
            [s.step.to_string(), s.t_s.to_string(), s.cx.to_string(), s.cy.to_string(), s.cs.to_string()]
                .into_iter()
                .chain([s.fn_n.to_string(), "0.1".into(), "0".into()])
                .collect()
        })
        .collect()
}

const HEADER: &str = "step,t_s,cx,cy,cs,fn_n,fx_over_fn,fy_over_fn";

fn csv(header: &str, rows: &[Vec<String>]) -> String {
    let mut out = format!("{header}\n");
    for r in rows {
        out.push_str(&r.join(","));
        out.push('\n');
    }
    out
}

/// A model that copies `dir/out.csv` to its output.
const COPY_MODEL: &str = "cp \"$(dirname \"$0\")/out.csv\" \"$2\"\n";

#[test]
fn a_correct_model_passes_and_its_output_is_kept() {
    let tmp = tempfile::tempdir().unwrap();
    let p = problem_with_model(tmp.path(), COPY_MODEL);
    fs::write(tmp.path().join("out.csv"), csv(HEADER, &good_rows(&p))).unwrap();
    let h = run_model(&p).unwrap();
    assert_eq!(h.rows.len(), 6);
    // Loading within the relative tolerance (last digit of t_s off) is accepted.
    let mut rows = good_rows(&p);
    rows[2][1] = (p.loading.samples[2].t_s * (1.0 + 1e-12)).to_string();
    fs::write(tmp.path().join("out.csv"), csv(HEADER, &rows)).unwrap();
    run_model(&p).unwrap();
}

#[test]
fn hostile_model_output_is_refused_naming_model_file_step_and_column() {
    let tmp = tempfile::tempdir().unwrap();
    let p = problem_with_model(tmp.path(), COPY_MODEL);
    let good = good_rows(&p);
    let set = |row: usize, col: usize, v: &str| {
        let mut rows = good.clone();
        rows[row][col] = v.into();
        csv(HEADER, &rows)
    };
    let with_extra = |name: &str, v: &str| {
        let rows: Vec<Vec<String>> = good.iter().map(|r| r.iter().cloned().chain([v.to_string()]).collect()).collect();
        csv(&format!("{HEADER},{name}"), &rows)
    };
    let huge = "9".repeat(10 << 20);
    let cases: Vec<(&str, String, &str)> = vec![
        ("NaN traction", set(2, 6, "NaN"), "step 3 column \"fx_over_fn\": \"NaN\" is not a finite number"),
        ("inf time", set(0, 1, "inf"), "step 1 column \"t_s\": \"inf\" is not a finite number"),
        ("-inf creepage", set(4, 2, "-inf"), "step 5 column \"cx\": \"-inf\" is not a finite number"),
        ("overflowing literal", set(1, 3, "1e999"), "step 2 column \"cy\": \"inf\" is not a finite number"),
        ("NaN in an extra column", with_extra("slip_area", "NaN"), "column \"slip_area\": \"NaN\""),
        (
            "a shadowing fx_over_fn",
            with_extra("fx_over_fn", "0.9"),
            "extra column \"fx_over_fn\" repeats a leading column",
        ),
        ("a shadowing t_s", with_extra("t_s", "0.9"), "extra column \"t_s\" repeats a leading column"),
        (
            "duplicate extra columns",
            csv(
                &format!("{HEADER},a,a"),
                &good.iter().map(|r| [r.clone(), vec!["1".into(), "2".into()]].concat()).collect::<Vec<_>>(),
            ),
            "column \"a\" appears twice",
        ),
        ("cx differs from the scene", set(3, 2, "0.5"), "step 4 column \"cx\": \"0.5\" differs from the scene's 0.005"),
        (
            "fn_n off by 1e-6",
            set(0, 5, &(p.loading.samples[0].fn_n * (1.0 + 1e-6)).to_string()),
            "step 1 column \"fn_n\"",
        ),
        ("cy not zero", set(5, 3, "0.001"), "step 6 column \"cy\""),
        ("cs not zero", set(5, 4, "1e-30"), "step 6 column \"cs\""),
        ("t_s shifted", set(1, 1, &(p.loading.samples[1].t_s * 2.0).to_string()), "step 2 column \"t_s\""),
        (
            "steps shifted by one",
            {
                let rows: Vec<Vec<String>> = good
                    .iter()
                    .map(|r| {
                        let mut r = r.clone();
                        r[0] = (r[0].parse::<usize>().unwrap() + 1).to_string();
                        r
                    })
                    .collect();
                csv(HEADER, &rows)
            },
            "has 6 rows (steps 2..7); the scene has 6 steps (steps 1..6)",
        ),
        ("a row missing", csv(HEADER, &good[..5]), "has 5 rows"),
        ("a row twice", csv(HEADER, &[good.clone(), vec![good[5].clone()]].concat()), "has 7 rows"),
        ("header only", csv(HEADER, &[]), "has 0 rows (no steps)"),
        ("an empty file", String::new(), "header must start with"),
        ("a header without fy_over_fn", csv("step,t_s,cx,cy,cs,fn_n,fx_over_fn", &[]), "header must start with"),
        ("a 10 MB value", set(0, 6, &format!("x{huge}")), "line 2 column fx_over_fn: \"x999"),
        ("a terminal escape as value", set(0, 6, "\u{1b}[2J"), "is not a number"),
        ("a negative step", set(0, 0, "-1"), "is not a step index"),
        ("a NUL byte", set(0, 6, "0\u{0}"), "not a text file"),
    ];
    for (name, text, expected) in &cases {
        fs::write(tmp.path().join("out.csv"), text).unwrap();
        let m = run_model(&p).expect_err(name);
        assert!(m.contains(expected), "{name}: {m}");
        assert!(m.contains("model `m`") && m.contains("m.csv"), "{name}: names model and file: {m}");
        assert!(m.len() < 1000 && !m.contains('\u{1b}'), "{name}: {} bytes", m.len());
        // The output file the message names is still there, in the kept folder.
        let (folder, files, _, _) = take_kept_folder(&m);
        assert!(m.contains(&folder.join("m.csv").display().to_string()), "{name}: {m}");
        assert_eq!(files, ["loading.csv", "m.csv", "scene.json", "stderr.txt", "stdout.txt"], "{name}");
    }
    fs::write(tmp.path().join("out.csv"), b"step,t_s\n\xff\n").unwrap();
    let m = run_model(&p).unwrap_err();
    assert!(m.contains("not UTF-8"), "{m}");
    take_kept_folder(&m);
    assert_no_temp_dirs(tmp.path());
}

#[test]
fn hostile_model_behaviour_is_bounded_and_cleaned_up() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path();
    let good = |p: &Problem| fs::write(d.join("out.csv"), csv(HEADER, &good_rows(p))).unwrap();
    let start = Instant::now();
    let cases: Vec<(&str, String, &str)> = vec![
        ("writes a FIFO as output", "mkfifo \"$2\"".into(), "FIFO"),
        ("writes a directory as output", "mkdir \"$2\"".into(), "directory, not a regular file"),
        ("links its output to /dev/zero", "ln -s /dev/zero \"$2\"".into(), "symbolic link"),
        ("links its output to /proc/self/environ", "ln -s /proc/self/environ \"$2\"".into(), "symbolic link"),
        ("writes 3 GB", "truncate -s 3G \"$2\"".into(), "exited with"),
        ("writes no output", "exit 0".into(), "wrote no output file"),
        (
            "exits 3",
            "echo 'model: bad input' >&2; exit 3".into(),
            "exit status: 3; the end of its stderr:\nmodel: bad input",
        ),
        (
            "floods stderr and fails",
            "head -c 10000000 /dev/zero | tr '\\0' 'e' >&2; exit 1".into(),
            "exited with exit status: 1",
        ),
        ("prints terminal escapes", "printf '\\033]0;pwned\\007\\033[2J' >&2; exit 1".into(), "\\u{1b}"),
        ("is not a shell script", "\u{1}\u{2}garbage(((".into(), "exited with"),
    ];
    for (name, script, expected) in &cases {
        let p = problem_with_model(d, &format!("{script}\n"));
        good(&p);
        let m = run_model(&p).expect_err(name);
        assert!(m.contains(expected), "{name}: {m}");
        assert!(m.len() < 6000 && !m.contains('\u{1b}'), "{name}: {} bytes", m.len());
        // Kept with what the model printed (its tail), inert, whatever the failure.
        let (_, _, _, stderr) = take_kept_folder(&m);
        // At most the tail's bytes, each escaped to at most `\u{NN}` (6 bytes).
        assert!(stderr.len() <= 6 * CAPTURE_LIMIT_BYTES + 4 && !stderr.contains('\u{1b}'), "{name}: {stderr:?}");
        if *name == "exits 3" {
            assert_eq!(stderr, "model: bad input\n");
        }
    }
    // A model that reads stdin, floods stdout, and leaves a sleeper behind still succeeds, fast;
    // the sleeper is killed with its group.
    let script =
        format!("cat; head -c 20000000 /dev/zero; sleep 1000 & echo $! > {}/sleeper; {COPY_MODEL}", d.display());
    let p = problem_with_model(d, &script);
    good(&p);
    run_model(&p).unwrap();
    let sleeper = wait_for_pid(&d.join("sleeper"), Duration::from_secs(1));
    assert!(wait_until(Duration::from_secs(2), || !alive(sleeper)), "sleeper {sleeper} survived");
    assert!(start.elapsed() < Duration::from_secs(20), "{:?}", start.elapsed());
    assert_no_temp_dirs(d);
}

#[test]
fn a_model_that_never_exits_is_killed_with_its_whole_group_at_the_timeout() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path().display();
    let start = Instant::now();
    let script = format!("echo $$ > {d}/leader; sleep 1000 & echo $! > {d}/grandchild; while :; do sleep 1; done");
    let e = process::run(sh(&script), Duration::from_millis(500), 1 << 20).unwrap_err();
    assert!(matches!(e, ProcessError::Timeout { .. }), "{e}");
    assert!(e.to_string().contains("0.5 s") && e.to_string().contains("killed"), "{e}");
    assert!(start.elapsed() < Duration::from_secs(4), "{:?}", start.elapsed());
    let leader = wait_for_pid(&tmp.path().join("leader"), Duration::ZERO);
    let grandchild = wait_for_pid(&tmp.path().join("grandchild"), Duration::ZERO);
    // A killed process lingers until its parent (or init, for the grandchild) reaps it.
    let gone = || !alive(leader) && !alive(grandchild) && group_members(leader).is_empty();
    assert!(
        wait_until(Duration::from_secs(2), gone),
        "leader {leader} or grandchild {grandchild} alive: {:?}",
        group_members(leader)
    );
    let e = process::run(Command::new("/nonexistent/model"), Duration::from_secs(1), 1 << 20).unwrap_err();
    assert!(matches!(e, ProcessError::Spawn { .. }), "{e}");
}

#[test]
fn a_model_reading_stdin_gets_end_of_file_at_once() {
    // The child's own stdin is a pipe this test keeps open: only a closed stdin ends `cat`.
    let tmp = tempfile::tempdir().unwrap();
    let mut child = spawn_self("stdin", tmp.path(), 0).stdin(Stdio::piped()).spawn().unwrap();
    let status = wait_child(&mut child, Duration::from_secs(30));
    assert!(status.success());
    assert_eq!(fs::read_to_string(tmp.path().join("verdict")).unwrap(), "stdin-eof-ok");
}

#[test]
fn an_interrupted_creepbench_kills_its_models_removes_their_folders_and_exits_130() {
    for signal in [rustix::process::Signal::INT, rustix::process::Signal::TERM] {
        let tmp = tempfile::tempdir().unwrap();
        let d = tmp.path();
        let mut child = spawn_self("model", d, 0).spawn().unwrap();
        let model = wait_for_pid(&d.join("pid"), Duration::from_secs(20));
        let grandchild = wait_for_pid(&d.join("gc"), Duration::from_secs(20));
        assert!(d.join("work").exists());
        kill_pid(child.id() as i32, signal);
        let status = wait_child(&mut child, Duration::from_secs(20));
        assert_eq!(status.code(), Some(130), "{signal:?}");
        assert!(wait_until(Duration::from_secs(2), || !alive(model) && !alive(grandchild)), "{signal:?}: orphans");
        assert!(!d.join("work").exists(), "{signal:?}: temp folder left");
    }
}

#[test]
fn a_model_dies_with_a_killed_creepbench() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path();
    let mut child = spawn_self("model", d, 0).spawn().unwrap();
    let model = wait_for_pid(&d.join("pid"), Duration::from_secs(20));
    let grandchild = wait_for_pid(&d.join("gc"), Duration::from_secs(20));
    child.kill().unwrap();
    child.wait().unwrap();
    // The direct child dies by its parent-death signal. A grandchild is out of reach of
    // that signal (it would need a cgroup); clean it up here.
    let died = wait_until(Duration::from_secs(5), || !alive(model));
    kill_pid(model, rustix::process::Signal::KILL);
    kill_pid(grandchild, rustix::process::Signal::KILL);
    assert!(died, "model {model} outlived creepbench");
}

// ---------------------------------------------------------------------------------------------
// Result folders

fn listing(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> =
        fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

#[test]
fn hostile_result_folder_targets_are_refused_and_left_intact() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path();
    fs::create_dir_all(d.join("golden/step")).unwrap();
    fs::write(d.join("golden/step/uba.csv"), "gold").unwrap();
    fs::create_dir_all(d.join("src")).unwrap();
    fs::write(d.join("src/main.rs"), "fn main() {}").unwrap();
    fs::write(d.join("notes"), "a file").unwrap();
    fs::create_dir_all(d.join("other")).unwrap();
    std::os::unix::fs::symlink(d.join("other"), d.join("linked")).unwrap();
    fs::create_dir_all(d.join("empty")).unwrap();
    let files = [("uba.csv", "1")];
    let long = "n".repeat(300);
    for (name, expected) in [
        ("golden", "no .creepbench-result file"),
        ("src", "no .creepbench-result file"),
        ("notes", "is not a directory"),
        ("linked", "is not a directory"),
    ] {
        let e = folder::write_result_folder(d, name, files).unwrap_err();
        assert!(e.to_string().contains(expected) && e.to_string().contains(name), "{name}: {e}");
    }
    // An empty directory holds nothing to lose: it is replaced (a golden/ made for a first bless).
    folder::write_result_folder(d, "empty", files).unwrap();
    assert_eq!(fs::read_to_string(d.join("empty/uba.csv")).unwrap(), "1");
    for name in ["", ".", "..", "../golden", "a/b", "/tmp", ".golden.creepbench-new-1-1", long.as_str()] {
        let e = folder::write_result_folder(d, name, files).unwrap_err();
        assert!(matches!(e, FolderError::BadName { .. }), "{name}: {e}");
        assert!(e.to_string().len() < 300, "{e}");
    }
    for file in ["../escape.csv", "/etc/passwd", MARKER, "", "sub/x.csv"] {
        let e = folder::write_result_folder(d, "scene", [(file, "x")]).unwrap_err();
        assert!(matches!(e, FolderError::BadName { .. }), "{file}: {e}");
    }
    assert_eq!(listing(d), ["empty", "golden", "linked", "notes", "other", "src"]);
    assert_eq!(fs::read_to_string(d.join("golden/step/uba.csv")).unwrap(), "gold");
    assert_eq!(fs::read_to_string(d.join("notes")).unwrap(), "a file");
}

#[test]
fn golden_is_guarded_whatever_the_spelling() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path();
    let golden = d.join("golden");
    fs::create_dir_all(golden.join("step")).unwrap();
    fs::create_dir_all(d.join("out")).unwrap();
    std::os::unix::fs::symlink(&golden, d.join("out/sneaky")).unwrap();
    for p in [
        golden.clone(),
        golden.join("new_scene"),
        d.join("out/../golden"),
        d.join("out/sneaky"),
        d.join("out/sneaky/x/y"),
        d.join("./golden/./step"),
    ] {
        let e = guard_not_under(&p, &golden).unwrap_err();
        assert!(matches!(e, GuardError::Inside { .. }) && e.to_string().contains("bless"), "{}: {e}", p.display());
    }
    guard_not_under(&d.join("out/results"), &golden).unwrap();
    guard_not_under(&d.join("golden_old"), &golden).unwrap();
}

#[test]
fn concurrent_writers_of_one_folder_all_succeed_and_leave_one_whole_result() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path().to_path_buf();
    let writers: Vec<_> = (0..8)
        .map(|k| {
            let d = d.clone();
            std::thread::spawn(move || {
                for round in 0..5 {
                    let files: Vec<(String, String)> =
                        (0..10).map(|i| (format!("f{i}.csv"), format!("writer {k} round {round}"))).collect();
                    folder::write_result_folder(&d, "scene", files).unwrap();
                }
            })
        })
        .collect();
    for w in writers {
        w.join().unwrap();
    }
    assert_eq!(listing(&d), ["scene"]);
    let contents: Vec<String> =
        (0..10).map(|i| fs::read_to_string(d.join(format!("scene/f{i}.csv"))).unwrap()).collect();
    assert!(contents.iter().all(|c| c == &contents[0]), "mixed: {contents:?}");
    // A folder lock: a second writer waits, or stops with a clear message.
    let held = lock_folder(&d, Duration::ZERO).unwrap();
    let e = lock_folder(&d, Duration::from_millis(30)).unwrap_err();
    assert!(matches!(e, LockError::Busy { .. }) && e.to_string().contains("another creepbench run"), "{e}");
    drop(held);
    lock_folder(&d, Duration::ZERO).unwrap();
}

#[test]
fn reference_manifests_catch_every_change_and_agree_with_sha256sum() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path();
    fs::create_dir_all(d.join("contact")).unwrap();
    fs::write(d.join("cases.csv"), "case\nstep_mu04\n").unwrap();
    fs::write(d.join("contact/step_mu04.csv"), "t_s,fx\n0,0.1\n").unwrap();
    assert!(matches!(manifest::verify(d), Err(ManifestError::Missing { .. })));
    manifest::write(d).unwrap();
    let ok = Command::new("sha256sum").arg("-c").arg("--quiet").arg(MANIFEST).current_dir(d).status().unwrap();
    assert!(ok.success());
    manifest::verify(d).unwrap();
    fs::write(d.join("cases.csv"), "case\n").unwrap();
    let e = manifest::verify(d).unwrap_err().to_string();
    assert!(e.contains("changed: cases.csv") && e.contains("reviewed commit"), "{e}");
}

// ---------------------------------------------------------------------------------------------
// Fault injection: bless killed at random points

/// The files of golden tree `version`: the count, names and contents differ between versions.
fn version_files(version: u64) -> BTreeMap<String, String> {
    (0..20 + version % 7)
        .map(|i| (format!("scene{}/f{i}.csv", i % 3), format!("version {version} file {i}\n").repeat(40)))
        .collect()
}

fn write_version(dir: &Path, version: u64) -> Result<(), FolderError> {
    for (name, text) in version_files(version) {
        let path = dir.join(&name);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(&path, text).unwrap();
    }
    Ok(())
}

/// The tree's files (marker apart, which must be there), by relative path.
fn read_tree(dir: &Path) -> BTreeMap<String, String> {
    assert!(dir.join(MARKER).is_file(), "{} has no marker", dir.display());
    let mut files = BTreeMap::new();
    let mut pending = vec![(dir.to_path_buf(), String::new())];
    while let Some((d, prefix)) = pending.pop() {
        for e in fs::read_dir(&d).unwrap() {
            let e = e.unwrap();
            let name = format!("{prefix}{}", e.file_name().to_string_lossy());
            if e.file_type().unwrap().is_dir() {
                pending.push((e.path(), format!("{name}/")));
            } else if name != MARKER {
                files.insert(name, fs::read_to_string(e.path()).unwrap());
            }
        }
    }
    files
}

/// Blesses one child makes in a row: the time of a process start is shared by many swaps, so
/// that random kills land often inside a bless, in each of its steps.
const BLESSES_PER_CHILD: u64 = 10;

#[test]
fn bless_killed_at_random_points_leaves_golden_old_or_new_and_the_next_run_cleans_up() {
    let tmp = tempfile::tempdir().unwrap();
    let d = tmp.path();
    let golden = d.join("golden");
    let mut current = 0;
    folder::replace_tree_atomically(&golden, |t| write_version(t, current)).unwrap();
    // How long one uninterrupted child takes: kills are spread over that time.
    let t0 = Instant::now();
    assert!(spawn_self("bless", d, 1).status().unwrap().success());
    current = BLESSES_PER_CHILD;
    assert_eq!(read_tree(&golden), version_files(current));
    let full = t0.elapsed().as_secs_f64();
    let mut rng: u64 = 0x9e37_79b9_7f4a_7c15;
    let (mut untouched, mut inside, mut finished, mut leftovers) = (0, 0, 0, 0);
    let start = Instant::now();
    let mut iterations = 0;
    while iterations < 60 && start.elapsed() < Duration::from_secs(15) {
        iterations += 1;
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        let delay = Duration::from_secs_f64(full * 1.1 * (rng % 1000) as f64 / 1000.0);
        let first = current + 1;
        let mut child = spawn_self("bless", d, first).spawn().unwrap();
        std::thread::sleep(delay);
        child.kill().unwrap();
        child.wait().unwrap();
        // golden is exactly one of the versions, whole: the one before, or one blessed since.
        let state = read_tree(&golden);
        let Some(v) = (current..first + BLESSES_PER_CHILD).find(|&v| state == version_files(v)) else {
            panic!(
                "iteration {iterations}: golden is no version in {current}..{}: {:?}",
                first + BLESSES_PER_CHILD,
                state.keys()
            );
        };
        match v - current {
            0 => untouched += 1,
            n if n == BLESSES_PER_CHILD => finished += 1,
            _ => inside += 1,
        }
        if listing(d).len() > 1 {
            leftovers += 1;
        }
        // The next bless runs to completion and leaves nothing behind.
        current = first + BLESSES_PER_CHILD;
        folder::replace_tree_atomically(&golden, |t| write_version(t, current)).unwrap();
        assert_eq!(listing(d), ["golden"], "iteration {iterations}");
        assert_eq!(read_tree(&golden), version_files(current));
    }
    eprintln!("{iterations} kills: {untouched} before any swap, {inside} between swaps, {finished} after all; {leftovers} left leftovers");
    assert!(iterations >= 20, "only {iterations} iterations");
    assert!(inside > 0 && leftovers > 0, "kills did not land inside the blesses");
}

#[test]
fn golden_never_goes_missing_while_blesses_follow_each_other() {
    // A watcher checks golden's marker as fast as it can while blesses swap trees: a
    // replacement that is not one atomic exchange leaves a moment without golden.
    let tmp = tempfile::tempdir().unwrap();
    let golden = tmp.path().join("golden");
    folder::replace_tree_atomically(&golden, |t| write_version(t, 0)).unwrap();
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let watcher = {
        let (stop, marker) = (stop.clone(), golden.join(MARKER));
        std::thread::spawn(move || {
            let (mut looks, mut missing) = (0u64, 0u64);
            while !stop.load(std::sync::atomic::Ordering::Relaxed) {
                looks += 1;
                if fs::symlink_metadata(&marker).is_err() {
                    missing += 1;
                }
            }
            (looks, missing)
        })
    };
    for v in 1..=200 {
        folder::replace_tree_atomically(&golden, |t| write_version(t, v)).unwrap();
    }
    stop.store(true, std::sync::atomic::Ordering::Relaxed);
    let (looks, missing) = watcher.join().unwrap();
    assert_eq!(missing, 0, "golden was missing {missing} times of {looks} looks");
    assert_eq!(read_tree(&golden), version_files(200));
}

/// `simulate --out DIR` writes under DIR's folder lock, as `run` does (issue 30: every run into a
/// shared results folder takes the lock): while another writer holds it, nothing is written; once
/// it is released, the scene lands.
#[test]
fn simulate_waits_for_the_results_folder_lock() {
    let tmp = tempfile::tempdir().unwrap();
    let (scene, out) = (tmp.path().join("s.toml"), tmp.path().join("out"));
    fs::write(&scene, scene_text("locked", r#"["fastsim"]"#, 0.3, 11, "kind = \"step\"\nc = 0.001\nsteps = 5", ""))
        .unwrap();
    let held = lock_folder(&out, Duration::ZERO).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .arg("simulate")
        .arg(&scene)
        .arg("--out")
        .arg(&out)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(Duration::from_millis(1500));
    assert!(child.try_wait().unwrap().is_none(), "simulate finished while the folder was locked");
    assert!(!out.join("locked").exists(), "simulate wrote while the folder was locked");
    drop(held);
    assert!(child.wait().unwrap().success());
    assert!(out.join("locked").join("fastsim.csv").is_file());
}
