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
