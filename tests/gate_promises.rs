//! The gate keeps its promises under concurrency, shards, odd paths and loosened rules (issue 30).

mod common;
use common::*;
use creepbench::harness::suite::Shard;
use std::path::Path;
use std::process::{Command, Output};

fn creepbench(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_creepbench")).current_dir(dir).args(args).output().expect("runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).to_string()
}

/// A quick scene called `name` (the UBA on an 8x8 grid, four steps) written as `dir/file`.
fn write_scene(dir: &Path, file: &str, name: &str) {
    std::fs::create_dir_all(dir).unwrap();
    let text = scene_text(name, "[\"uba\"]", 0.4, 8, "kind = \"step\"\nc = 0.005\nsteps = 4", "");
    std::fs::write(dir.join(file), text).unwrap();
}

/// The scene folders of a blessed tree, sorted.
fn blessed(golden: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(golden)
        .map(|d| d.flatten().filter(|e| e.path().is_dir()).map(|e| e.file_name().to_string_lossy().into()).collect())
        .unwrap_or_default();
    names.sort();
    names
}

#[test]
fn concurrent_blesses_of_two_suites_both_land() {
    let w = tempfile::tempdir().unwrap();
    for (suite, names) in [("sa", ["a_one", "a_two"]), ("sb", ["b_one", "b_two"])] {
        for n in names {
            write_scene(&w.path().join(suite), &format!("{n}.toml"), n);
        }
    }
    for round in 0..20 {
        let _ = std::fs::remove_dir_all(w.path().join("golden"));
        let spawn = |suite: &str| {
            Command::new(env!("CARGO_BIN_EXE_creepbench"))
                .current_dir(w.path())
                .args(["bless", "--quiet", "--suite", suite])
                .stdout(std::process::Stdio::null())
                .stderr(std::process::Stdio::piped())
                .spawn()
                .unwrap()
        };
        let (a, b) = (spawn("sa"), spawn("sb"));
        for child in [a, b] {
            let o = child.wait_with_output().unwrap();
            assert_eq!(o.status.code(), Some(0), "round {round}: {}", stderr(&o));
        }
        assert_eq!(blessed(&w.path().join("golden")), ["a_one", "a_two", "b_one", "b_two"], "round {round}");
    }
}

#[test]
fn shards_and_bless_select_and_keep_scenes_by_their_name() {
    let w = tempfile::tempdir().unwrap();
    let names = ["n_alpha", "n_beta", "n_gamma", "n_delta", "n_eps", "n_zeta"];
    let stems = ["f1", "f2", "f3", "f4", "f5", "f6"];
    for (stem, name) in stems.iter().zip(names) {
        write_scene(&w.path().join("suite"), &format!("{stem}.toml"), name);
    }
    // The files' stems and the scenes' names fall into different shards for some scene.
    let s1 = Shard { index: 1, count: 2 };
    assert!(stems.iter().zip(names).any(|(st, n)| s1.takes(st) != s1.takes(n)));
    for shard in ["1/2", "2/2"] {
        let o = creepbench(w.path(), &["bless", "--quiet", "--suite", "suite", "--shard", shard]);
        assert_eq!(o.status.code(), Some(0), "{shard}: {}", stderr(&o));
    }
    let mut want: Vec<String> = names.iter().map(|s| s.to_string()).collect();
    want.sort();
    assert_eq!(blessed(&w.path().join("golden")), want);
    // Blessed twice more, shard by shard: nothing goes missing.
    for shard in ["2/2", "1/2"] {
        let o = creepbench(w.path(), &["bless", "--quiet", "--suite", "suite", "--shard", shard]);
        assert_eq!(o.status.code(), Some(0), "{shard}: {}", stderr(&o));
        assert_eq!(blessed(&w.path().join("golden")), want);
    }
    // Two files of one name remain an error, sharded or not.
    write_scene(&w.path().join("suite"), "f7.toml", "n_alpha");
    for args in
        [vec!["bless", "--quiet", "--suite", "suite"], vec!["bless", "--quiet", "--suite", "suite", "--shard", "2/2"]]
    {
        let o = creepbench(w.path(), &args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("n_alpha") && stderr(&o).contains("f7.toml"), "{}", stderr(&o));
    }
}

/// A work folder with suite/ (two quick scenes), golden/ blessed from it, and a drift put into
/// golden/: a_one's UBA fx_over_fn at step 1 moved by about 5e-3.
fn drifted_workspace() -> tempfile::TempDir {
    let w = tempfile::tempdir().unwrap();
    for n in ["a_one", "a_two"] {
        write_scene(&w.path().join("suite"), &format!("{n}.toml"), n);
    }
    let o = creepbench(w.path(), &["bless", "--quiet", "--suite", "suite"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let csv = w.path().join("golden/a_one/uba.csv");
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let mut row: Vec<String> = lines[1].split(',').map(str::to_string).collect();
    row[6] = "0.2".into();
    lines[1] = row.join(",");
    std::fs::write(&csv, lines.join("\n") + "\n").unwrap();
    w
}

fn rule(body: &str) -> String {
    format!("[[rule]]\nagainst = \"golden\"\n{body}\nwhy = \"the test's reason\"\n")
}

#[test]
fn no_gate_is_disabled_in_silence() {
    let w = drifted_workspace();
    let check = |extra: &[&str]| {
        let mut args = vec!["check", "--quiet", "--suite", "suite", "--reference"];
        let refs = root().join("reference");
        args.push(refs.to_str().unwrap());
        args.extend_from_slice(extra);
        creepbench(w.path(), &args)
    };
    // Without a file the drift fails the gate.
    let o = check(&[]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    // Rules that make a gate unable to fail are refused unless they say so.
    let one = "scene = \"a_one\"\nsolver = \"uba\"\nquantity = \"fx_over_fn\"";
    for (body, field) in [
        (format!("{one}\nabs = 1e9"), "abs"),
        (format!("{one}\nabs = 1.7e308"), "abs"),
        (format!("{one}\nabs = 0.0\nrel = 1e12"), "rel"),
        (format!("{one}\ngated = false"), "gated = false"),
        ("abs = 0.5".to_string(), "\"*\""),
        ("scene = \"*\"\nabs = 0.5".to_string(), "\"*\""),
    ] {
        std::fs::write(w.path().join("t.toml"), rule(&body)).unwrap();
        let o = check(&["--tolerances", "t.toml"]);
        assert_eq!(o.status.code(), Some(2), "{body}: {}", stderr(&o));
        assert!(stderr(&o).contains("t.toml rule[0]") && stderr(&o).contains(field), "{body}: {}", stderr(&o));
        assert!(stderr(&o).contains("disable = true"), "{body}: {}", stderr(&o));
    }
    // Beyond f64, the file does not even parse.
    std::fs::write(w.path().join("t.toml"), rule(&format!("{one}\nabs = 1.8e308"))).unwrap();
    assert_eq!(check(&["--tolerances", "t.toml"]).status.code(), Some(2));
    // A suite's tolerances.toml is read the same way.
    std::fs::write(w.path().join("suite/tolerances.toml"), rule(&format!("{one}\nabs = 1e300"))).unwrap();
    let o = check(&[]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("tolerances.toml rule[0]"), "{}", stderr(&o));
    std::fs::remove_file(w.path().join("suite/tolerances.toml")).unwrap();
    // A loosening that passes the drift is listed in every verdict, with file, rule, why, count.
    for (body, decided) in [(format!("{one}\nabs = 0.01"), 1), (format!("{one}\ngated = false\ndisable = true"), 1)] {
        std::fs::write(w.path().join("t.toml"), rule(&body)).unwrap();
        let o = check(&["--tolerances", "t.toml", "--json", "v.json", "--junit", "v.xml", "--summary", "v.md"]);
        assert_eq!(o.status.code(), Some(0), "{body}: {}", stderr(&o));
        let out = String::from_utf8_lossy(&o.stdout).to_string();
        let line =
            format!("decided {decided} comparison(s), loosened {decided} the defaults gate; why: the test's reason");
        assert!(out.contains("t.toml rule[0]: against golden") && out.contains(&line), "{body}: {out}");
        let j: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(w.path().join("v.json")).unwrap()).unwrap();
        let l = &j["loosened"][0];
        assert_eq!(
            (l["origin"].as_str(), l["decided"].as_u64(), l["why"].as_str()),
            (Some("t.toml rule[0]"), Some(decided), Some("the test's reason")),
            "{j}"
        );
        let xml = std::fs::read_to_string(w.path().join("v.xml")).unwrap();
        assert!(xml.contains("<property name=\"loosened\" value=\"t.toml rule[0]: against golden"), "{xml}");
        let md = std::fs::read_to_string(w.path().join("v.md")).unwrap();
        assert!(md.contains("t.toml rule[0]") && md.contains(&line), "{md}");
        // --strict refuses every loosening.
        let o = check(&["--tolerances", "t.toml", "--strict"]);
        assert_eq!(o.status.code(), Some(2), "{body}: {}", stderr(&o));
        assert!(stderr(&o).contains("--strict") && stderr(&o).contains("t.toml rule[0]"), "{}", stderr(&o));
    }
    // A tightening is no loosening: --strict takes it, and nothing is listed.
    std::fs::write(
        w.path().join("t.toml"),
        rule("scene = \"a_two\"\nsolver = \"uba\"\nquantity = \"fx_over_fn\"\nabs = 0.0"),
    )
    .unwrap();
    let o = check(&["--tolerances", "t.toml", "--strict"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(!String::from_utf8_lossy(&o.stdout).contains("loosen"));
    // The report lists it too (merge of a run's results with the file).
    let refs = root().join("reference");
    let refs = refs.to_str().unwrap();
    let o = creepbench(
        w.path(),
        &["run", "--quiet", "--suite", "suite", "--results", "res", "--report", "rep", "--reference", refs],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    std::fs::write(w.path().join("t.toml"), rule(&format!("{one}\nabs = 0.01"))).unwrap();
    let o = creepbench(
        w.path(),
        &["merge", "res", "--suite", "suite", "--report", "rep2", "--tolerances", "t.toml", "--reference", refs],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let md = std::fs::read_to_string(w.path().join("rep2/validation.md")).unwrap();
    assert!(md.contains("Loosened gates") && md.contains("t.toml rule[0]") && md.contains("the test's reason"), "{md}");
    assert!(stderr(&o).contains("loosened: t.toml rule[0]"), "{}", stderr(&o));
}
