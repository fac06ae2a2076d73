//! Issue 47 item 1, the report shows this run and only this run: `run` into a result folder that
//! holds another run's scenes (and fit records) reports, judges and tabulates its own scenes
//! only, names the others once on the console and ends with the verdict and the report's path;
//! `merge` still reads every scene folder it is given.

use crate::common::{root, scene_text, tempdir};
use std::path::Path;
use std::process::{Command, Output};

/// A quick scene called `name` (the UBA on an 8x8 grid, four steps) in the suite folder `suite`.
fn write_scene(suite: &Path, name: &str) {
    std::fs::create_dir_all(suite).unwrap();
    let text = scene_text(name, "[\"uba\"]", 0.4, 8, "kind = \"step\"\nc = 0.005\nsteps = 4", "");
    std::fs::write(suite.join(format!("{name}.toml")), text).unwrap();
}

/// `creepbench ARGS` from the project folder (its reference data and golden/).
fn creepbench(args: &[&std::ffi::OsStr]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_creepbench")).current_dir(root()).args(args).output().unwrap()
}

/// `creepbench run --quiet --suite SUITE --results RES --report REP`; it must succeed. Returns
/// its stdout and stderr.
fn run(suite: &Path, res: &Path, rep: &Path) -> (String, String) {
    let (run, quiet) = ("run".as_ref(), "--quiet".as_ref());
    let (s, r, p) = ("--suite".as_ref(), "--results".as_ref(), "--report".as_ref());
    let o = creepbench(&[run, quiet, s, suite.as_os_str(), r, res.as_os_str(), p, rep.as_os_str()]);
    let (out, err) = (String::from_utf8_lossy(&o.stdout).into_owned(), String::from_utf8_lossy(&o.stderr).into_owned());
    assert!(o.status.success(), "{err}");
    (out, err)
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

#[test]
fn a_second_suite_into_the_same_results_folder_reports_only_itself() {
    let dir = tempdir("report_scope_two_suites");
    let (first, second) = (dir.join("first"), dir.join("second"));
    write_scene(&first, "a_one");
    write_scene(&first, "a_two");
    write_scene(&second, "b_one");
    let (res, rep) = (dir.join("res"), dir.join("rep"));
    run(&first, &res, &rep);
    // A fit record an earlier run left (not even a valid one): this run neither reads nor shows it.
    std::fs::create_dir_all(res.join("fits")).unwrap();
    std::fs::write(res.join("fits/old_fit.json"), "{}").unwrap();
    let (out, err) = run(&second, &res, &rep);
    let md = read(&rep.join("validation.md"));
    assert!(md.contains("from 1 scene(s)"), "{md}");
    assert!(!md.contains("a_one") && !md.contains("a_two") && !md.contains("Calibration"), "{md}");
    let csv = read(&rep.join("results.csv"));
    assert!(csv.lines().skip(1).all(|l| l.starts_with("b_one,")) && csv.lines().count() > 1, "{csv}");
    // The verdict and the table are those of the second suite alone.
    let (alone_res, alone_rep) = (dir.join("alone_res"), dir.join("alone_rep"));
    let (alone_out, _) = run(&second, &alone_res, &alone_rep);
    let gates = |o: &str| o.lines().find(|l| l.starts_with("gates: ")).unwrap().to_string();
    assert_eq!(gates(&out), gates(&alone_out));
    assert_eq!(csv, read(&alone_rep.join("results.csv")));
    // The left-out folders and fit record are named once each, on one warning line each.
    for name in ["a_one", "a_two", "old_fit"] {
        assert_eq!(err.matches(name).count(), 1, "{name}: {err}");
    }
    assert!(err.contains("2 scene folder(s) this run did not write, left out of this run's report"), "{err}");
    // The console ends with the verdict and the report's path.
    let last: Vec<&str> = out.lines().rev().take(2).collect();
    assert_eq!(last[0], format!("report: {}", rep.join("validation.md").display()), "{out}");
    assert!(last[1].starts_with("gates: "), "{out}");
    // `merge` reads every scene folder of the folders it is given, on purpose.
    std::fs::remove_file(res.join("fits/old_fit.json")).unwrap();
    let merged = dir.join("merged");
    let o = creepbench(&["merge".as_ref(), res.as_os_str(), "--report".as_ref(), merged.as_os_str()]);
    // Its three scenes have no golden data: the verdict fails, and merge exits 1 as check would
    // (issue 48); the report is written all the same.
    assert_eq!(o.status.code(), Some(1), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(read(&merged.join("validation.md")).contains("from 3 scene(s)"));
}
