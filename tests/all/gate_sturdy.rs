//! The gate keeps its promises, round two (issue 48): a closed console, interrupted blesses'
//! leftovers, merges that fail on drift and on what a scene is owed, empty shards, huge numbers
//! in drift lines, `--strict` before any scene runs. Every case in a temporary folder.

use crate::common;
use common::*;
use std::path::Path;
use std::process::{Command, Output, Stdio};

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
}
