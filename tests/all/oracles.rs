//! Snapshots of what users and CI read (issue 47 item 5): the console of `run` and `check`, the
//! report's Markdown, the JUnit, JSON and summary files of a drifted check, and the messages of
//! bad input. Any change to them shows in review as a snapshot diff. Only what differs run to run
//! is redacted: the temporary folder's path, wall-clock times (console "in … s", the report's
//! timing columns).

use crate::common::{root, tempdir};
use std::path::Path;
use std::process::Command;

/// `creepbench args` run in the repository's folder: (exit code, stdout, stderr), redacted.
fn creepbench(args: &[&str], tmp: &Path) -> (i32, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench")).current_dir(root()).args(args).output().unwrap();
    let text = |b: &[u8]| redact(&String::from_utf8_lossy(b), tmp);
    (o.status.code().unwrap_or(-1), text(&o.stdout), text(&o.stderr))
}

/// The temporary folder as `<tmp>` and wall-clock times as `<t>`.
fn redact(text: &str, tmp: &Path) -> String {
    let text = text.replace(&tmp.display().to_string(), "<tmp>");
    text.lines().map(redact_times).collect::<Vec<_>>().join("\n") + if text.ends_with('\n') { "\n" } else { "" }
}

/// A number followed by a unit of time ("in 0.57 s", "wall times 0.00 s.") as `<t>`.
fn redact_times(line: &str) -> String {
    let words: Vec<&str> = line.split(' ').collect();
    let is_unit = |w: &str| matches!(w.trim_end_matches(['.', ',', ')', ';']), "s" | "ms" | "µs");
    let mut out: Vec<&str> = Vec::with_capacity(words.len());
    for (i, w) in words.iter().enumerate() {
        let timed = words.get(i + 1).is_some_and(|u| is_unit(u)) && w.parse::<f64>().is_ok();
        out.push(if timed { "<t>" } else { w });
    }
    out.join(" ")
}

/// The report's Markdown with the cells of its timing columns (a header naming seconds or
/// microseconds) as `<t>`: the only numbers that differ run to run.
fn redact_report(md: &str, tmp: &Path) -> String {
    let is_time = |h: &str| {
        let h = h.trim();
        h.ends_with(" s") || h.contains("µs") || h.contains("ms per") || h.contains("wall")
    };
    let mut timing: Vec<bool> = Vec::new();
    let mut out = String::new();
    for line in md.replace(&tmp.display().to_string(), "<tmp>").lines() {
        if !line.starts_with('|') {
            timing.clear();
            out.push_str(&redact_times(line));
        } else if timing.is_empty() {
            timing = line.trim_matches('|').split(" | ").map(is_time).collect();
            out.push_str(line);
        } else if line.starts_with("|---") {
            out.push_str(line);
        } else {
            let cells: Vec<&str> = line.trim_matches('|').split(" | ").collect();
            let cells: Vec<String> = cells
                .iter()
                .enumerate()
                .map(|(i, c)| if timing.get(i) == Some(&true) { "<t>".to_string() } else { c.trim().to_string() })
                .collect();
            out.push_str(&format!("| {} |", cells.join(" | ")));
        }
        out.push('\n');
    }
    out
}

/// A one-scene suite: the thesis's step in cx, with UBA and FASTSIM.
fn tiny_suite(tmp: &Path) -> String {
    let suite = tmp.join("suite");
    std::fs::create_dir_all(&suite).unwrap();
    let text = std::fs::read_to_string(root().join("scenes/thesis/step_cx001.toml")).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let at = lines.iter().position(|l| l.starts_with("solvers = ")).unwrap();
    lines[at] = r#"solvers = ["uba", "fastsim"]"#.into();
    std::fs::write(suite.join("step_cx001.toml"), lines.join("\n") + "\n").unwrap();
    suite.display().to_string()
}

#[test]
fn the_console_and_report_of_run() {
    let tmp = tempdir("oracle_run");
    let suite = tiny_suite(&tmp);
    let (results, report, none) = (tmp.join("res"), tmp.join("rep"), tmp.join("no_golden"));
    let (code, out, err) = creepbench(
        &[
            "run",
            "--suite",
            &suite,
            "--results",
            &results.display().to_string(),
            "--report",
            &report.display().to_string(),
            "--golden",
            &none.display().to_string(),
        ],
        &tmp,
    );
    insta::assert_snapshot!("run_console", format!("exit {code}\n--- stdout\n{out}--- stderr\n{err}"));
    let md = std::fs::read_to_string(report.join("validation.md")).unwrap();
    insta::assert_snapshot!("run_report", redact_report(&md, &tmp));
}

#[test]
fn the_console_and_ci_files_of_a_check_that_drifts() {
    let tmp = tempdir("oracle_check");
    let suite = tiny_suite(&tmp);
    let base = tmp.join("base");
    let p = |p: &Path| p.display().to_string();
    let (code, _, err) = creepbench(
        &["run", "--suite", &suite, "--results", &p(&base), "--report", &p(&tmp.join("rep")), "--quiet"],
        &tmp,
    );
    assert_eq!(code, 0, "{err}");
    // One value of FASTSIM's baseline moved by 1e-3: a drift of one gated quantity.
    let csv = base.join("step_cx001/fastsim.csv");
    crate::common::nudge_csv(&csv, 5, 6, 1e-3);
    let (junit, json, summary) = (tmp.join("j.xml"), tmp.join("c.json"), tmp.join("s.md"));
    let (code, out, err) = creepbench(
        &[
            "check",
            "--suite",
            &suite,
            "--against",
            &p(&base),
            "--quiet",
            "--junit",
            &p(&junit),
            "--json",
            &p(&json),
            "--summary",
            &p(&summary),
        ],
        &tmp,
    );
    insta::assert_snapshot!("check_drift_console", format!("exit {code}\n--- stdout\n{out}--- stderr\n{err}"));
    let read = |f: &Path| redact(&std::fs::read_to_string(f).unwrap(), &tmp);
    insta::assert_snapshot!("check_drift_junit", read(&junit));
    insta::assert_snapshot!("check_drift_json", read(&json));
    insta::assert_snapshot!("check_drift_summary", read(&summary));
}

/// A scene of the thesis with one line replaced (`None`: the line `with` appended).
fn scene_with(tmp: &Path, name: &str, find: Option<&str>, with: &str) -> String {
    let text = std::fs::read_to_string(root().join("scenes/thesis/step_cx001.toml")).unwrap();
    let text = match find {
        Some(f) => {
            assert!(text.contains(f), "{f} not in the scene");
            text.replacen(f, with, 1)
        }
        None => format!("{text}{with}\n"),
    };
    let path = tmp.join(format!("{name}.toml"));
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

#[test]
fn the_messages_of_bad_input() {
    let tmp = tempdir("oracle_errors");
    let out = tmp.join("out").display().to_string();
    let cases: Vec<(&str, Vec<String>)> = vec![
        ("a negative friction coefficient", vec![scene_with(&tmp, "mu", Some("mu = 0.4"), "mu = -0.4")]),
        ("malformed TOML", vec![scene_with(&tmp, "toml", Some("mu = 0.4"), "mu = = 0.4")]),
        ("an unknown key", vec![scene_with(&tmp, "key", None, "[contact_solver]\ntolerence = 1e-7")]),
        ("an unknown model", vec![scene_with(&tmp, "model", Some(r#"solvers = ["uba""#), r#"solvers = ["ubaa""#)]),
        ("a missing scene file", vec![tmp.join("missing.toml").display().to_string()]),
    ];
    let mut all = String::new();
    for (what, files) in cases {
        let mut args = vec!["simulate".to_string()];
        args.extend(files);
        args.extend(["--out".to_string(), out.clone()]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (code, stdout, stderr) = creepbench(&args, &tmp);
        assert!(!tmp.join("out").exists(), "{what}: written after an error");
        all.push_str(&format!("## {what}: simulate, exit {code}\n{stdout}{stderr}\n"));
    }
    for (what, args) in [
        ("a shard beyond the count", vec!["check", "--shard", "3/2"]),
        ("a suite that does not exist", vec!["check", "--suite", "scenes/nope"]),
    ] {
        let (code, stdout, stderr) = creepbench(&args, &tmp);
        all.push_str(&format!("## {what}: {}, exit {code}\n{stdout}{stderr}\n", args.join(" ")));
    }
    insta::assert_snapshot!("bad_input_messages", all);
}
