//! Issue 15, tolerances as data: a user's rule file gates what the defaults only report (and
//! loosens nothing else), suite folders' `tolerances.toml` are picked up, a bad file — unknown
//! key, unknown comparison, a rule that matches nothing — is an input error (exit 2) naming the
//! file and the rule; every default rule (`tolerances.toml`) decides comparisons of the shipped
//! suites; shards merged with a rule file give the unsharded verdict.

use crate::common;
use common::{root, tempdir};
use creepbench::comparison::compare::{self, Against};
use creepbench::comparison::references::References;
use creepbench::comparison::{tolerance_file, tolerances};
use creepbench::suite::{self, results};
use std::path::{Path, PathBuf};
use std::process::Command;

fn check(rules: &Path, json: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(root())
        .args(["check", "--quiet", "--suite", "scenes/nonhertz", "--tolerances"])
        .arg(rules)
        .arg("--json")
        .arg(json)
        .output()
        .unwrap()
}

fn rule(abs: f64, scene: &str) -> String {
    format!("[[rule]]\nagainst = \"CONTACT non-Hertzian\"\nscene = \"{scene}\"\nsolver = \"uba\"\nquantity = \"fx_over_fn\"\nabs = {abs}\nwhy = \"the UBA's accepted gap\"\n")
}

#[test]
fn a_rule_file_gates_what_the_defaults_report() {
    let dir = tempdir("tolerance_files");
    let (rules, json) = (dir.join("t.toml"), dir.join("c.json"));
    let gated = |path: &Path| -> (u64, u64) {
        let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
        (j["gated"].as_u64().unwrap(), j["failed"].as_u64().unwrap())
    };
    // The UBA's fx against CONTACT on the five cases is reported by default (worst 0.101, kink):
    // gated at 0.2 it passes, five more gated comparisons.
    std::fs::write(&rules, rule(0.2, "nh_*")).unwrap();
    let o = check(&rules, &json);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    let (n_loose, failed) = gated(&json);
    assert_eq!(failed, 0);
    // Gated at 0.05 the asymmetric step (0.079) and the kinked sine (0.101) fail.
    std::fs::write(&rules, rule(0.05, "nh_*")).unwrap();
    let o = check(&rules, &json);
    assert_eq!(o.status.code(), Some(1));
    let (n_tight, failed) = gated(&json);
    assert_eq!((n_tight, failed), (n_loose, 2));
    // Without the file: the defaults (648 gated comparisons on this suite, none failing).
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(root())
        .args(["check", "--quiet", "--suite", "scenes/nonhertz", "--json"])
        .arg(&json)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(gated(&json), (n_loose - 5, 0));

    // Bad files: exit 2, the file and the rule named, no verdict file written.
    for (text, expect) in [
        (rule(0.2, "nh_*") + "colour = \"red\"\n", "rule[0].colour"),
        (rule(0.2, "nh_*").replace("CONTACT non-Hertzian", "CONTAKT"), "rule[0].against"),
        (rule(0.2, "no_such_scene_*"), "rule[0]"),
        ("[[rule]]\nagainst = \"golden\"\nwhy = \"x\"\n".to_string(), "rule[0].abs"),
    ] {
        std::fs::write(&rules, &text).unwrap();
        let _ = std::fs::remove_file(&json);
        let o = check(&rules, &json);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{text}: {err}");
        assert!(err.contains("t.toml") && err.contains(expect), "{text}: {err}");
        assert!(!json.exists());
    }
}

#[test]
fn suite_folders_tolerance_files_are_sources() {
    let dir = tempdir("tolerance_sources");
    let (a, b) = (dir.join("a"), dir.join("b"));
    std::fs::create_dir_all(&a).unwrap();
    std::fs::create_dir_all(&b).unwrap();
    std::fs::write(b.join("tolerances.toml"), "").unwrap();
    let given = vec![dir.join("mine.toml")];
    assert_eq!(
        tolerance_file::sources(&given, &[a, b.clone()]),
        vec![(dir.join("mine.toml"), None), (b.join("tolerances.toml"), Some("b".to_string()))]
    );
}

/// Every rule of the project's defaults decides at least one comparison of the shipped suites, or
/// is the catch-all of its label. The shipped suites' results are their blessed ones (golden/
/// holds exactly their scenes): compared with golden/ and every reference set, as `check` does.
#[test]
fn every_default_rule_decides_a_comparison_of_the_shipped_suites_or_is_a_catch_all() {
    let golden = root().join("golden");
    let names = results::scene_names(&golden);
    let suites: Vec<PathBuf> = suite::DEFAULT_SUITES.iter().map(|s| root().join(s)).collect();
    let (module3, _) = suite::wheelrail::split(suite::scene_files(&suites, None).unwrap()).unwrap();
    let mut shipped: Vec<String> = module3.into_iter().map(|s| s.name).collect();
    shipped.sort();
    assert_eq!(names, shipped, "golden/ holds exactly the shipped suites' scenes");
    let scenes: Vec<_> = names.iter().map(|n| results::read_scene(&golden, n).unwrap()).collect();
    let refs = References::load(&root().join("reference")).unwrap();
    let findings = compare::evaluate(&scenes, &refs, Some((&golden, Against::Golden))).unwrap();
    let rules = tolerances::defaults();
    let mut decided = vec![0usize; rules.len()];
    for f in &findings {
        let i = rules.iter().position(|r| r.covers(f.against, &f.scene, &f.solver, &f.quantity));
        decided[i.unwrap_or_else(|| panic!("no default rule for {f:?}"))] += 1;
    }
    for (r, n) in rules.iter().zip(&decided) {
        // The wheel–rail gate's rules judge wheel–rail runs, which golden/ never holds: the test
        // wheelrail_mbench checks that each decides a comparison of scenes/wheelrail.
        if r.against == creepbench::comparison::references::wheelrail_cases::AGAINST {
            continue;
        }
        println!("{:>6} comparisons: {} {:?} {} {} {}", n, r.origin, r.against.label(), r.scene, r.solver, r.quantity);
        assert!(*n > 0 || r.is_catch_all(), "{} decides nothing on the shipped suites: {r:?}", r.origin);
    }
}

/// (gated, failed) of the verdict line of a report ("**…**: N gated comparisons, M failed.").
fn report_verdict(md: &Path) -> (u64, u64) {
    let text = std::fs::read_to_string(md).unwrap();
    let line = text.lines().find(|l| l.starts_with("**") && l.contains("gated comparisons")).expect("a verdict");
    let nums: Vec<u64> =
        line.split(|c: char| !c.is_ascii_digit()).filter(|w| !w.is_empty()).map(|w| w.parse().unwrap()).collect();
    (nums[0], nums[1])
}

fn json_verdict(path: &Path) -> (u64, u64) {
    let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    (j["gated"].as_u64().unwrap(), j["failed"].as_u64().unwrap())
}

fn creepbench(dir: &Path, args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_creepbench")).current_dir(dir).args(args).output().unwrap()
}

/// A sharded CI: each shard runs its scenes, `merge --tolerances FILE` builds the report; its
/// verdict is the unsharded `check --tolerances FILE`'s. Each shard's own check accepts a rule
/// whose scenes all ran in the other shard, and still refuses one that matches no scene at all.
#[test]
fn shards_merged_with_a_rule_file_give_the_unsharded_verdict() {
    let dir = tempdir("tolerance_merge");
    let (rules, json) = (dir.join("t.toml"), dir.join("c.json"));
    // Gated at 0.05 the UBA fails on two of the five non-Hertzian cases (0.079, 0.101).
    std::fs::write(&rules, rule(0.05, "nh_*")).unwrap();
    let o = check(&rules, &json);
    assert_eq!(o.status.code(), Some(1), "{}", String::from_utf8_lossy(&o.stderr));
    let unsharded = json_verdict(&json);
    assert_eq!(unsharded.1, 2);

    let r = root();
    let (rules_s, suite_s) = (rules.to_str().unwrap(), r.join("scenes/nonhertz"));
    let suite_s = suite_s.to_str().unwrap();
    let mut shards = Vec::new();
    for i in 1..=2 {
        let res = dir.join(format!("shard{i}"));
        let shard = format!("{i}/2");
        let o = creepbench(
            &r,
            &["run", "--quiet", "--suite", suite_s, "--shard", &shard, "--results", res.to_str().unwrap()],
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        shards.push(res);
    }
    let in_shard: Vec<Vec<String>> = shards.iter().map(|d| results::scene_names(d)).collect();
    assert!(
        in_shard.iter().all(|s| !s.is_empty()) && in_shard.iter().map(Vec::len).sum::<usize>() == 5,
        "{in_shard:?}"
    );

    let merge = |extra: &[&str], report: &str| {
        let mut args = vec!["merge", shards[0].to_str().unwrap(), shards[1].to_str().unwrap()];
        args.extend(["--report", report]);
        args.extend(extra);
        let o = creepbench(&r, &args);
        let verdict = report_verdict(&Path::new(report).join("validation.md"));
        // merge exits with its verdict, as check does (issue 48).
        assert_eq!(o.status.code(), Some(i32::from(verdict.1 > 0)), "{}", String::from_utf8_lossy(&o.stderr));
        verdict
    };
    let report = dir.join("merged");
    assert_eq!(merge(&["--tolerances", rules_s], report.to_str().unwrap()), unsharded);
    // Without the file the merged report has the defaults' verdict: five comparisons fewer gated.
    let plain = merge(&[], dir.join("plain").to_str().unwrap());
    assert_eq!(plain, (unsharded.0 - 5, 0));

    // A shard's check: a rule for one scene of the other shard is no error there; a typo is.
    let other = &in_shard[1][0];
    std::fs::write(&rules, rule(0.2, other)).unwrap();
    let o = creepbench(&r, &["check", "--quiet", "--suite", suite_s, "--shard", "1/2", "--tolerances", rules_s]);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    std::fs::write(&rules, rule(0.2, "nh_no_such_*")).unwrap();
    let o = creepbench(&r, &["check", "--quiet", "--suite", suite_s, "--shard", "1/2", "--tolerances", rules_s]);
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
    // merge refuses the typo as check does.
    let o = creepbench(
        &r,
        &[
            "merge",
            shards[0].to_str().unwrap(),
            shards[1].to_str().unwrap(),
            "--report",
            dir.join("bad").to_str().unwrap(),
            "--tolerances",
            rules_s,
        ],
    );
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
}

/// `merge` applies the tolerances.toml of the suites its scenes came from (by the suite folder
/// name each scene records), as `check` does: a suite file gating the UBA makes the same verdict.
#[test]
fn merge_applies_the_merged_suites_tolerance_files() {
    let dir = tempdir("tolerance_merge_suite");
    // The scenes read their profiles from ../../reference: the copy sits at the same depth.
    let suite_dir = dir.join("scenes/nonhertz");
    std::fs::create_dir_all(&suite_dir).unwrap();
    std::os::unix::fs::symlink(root().join("reference"), dir.join("reference")).unwrap();
    for e in std::fs::read_dir(root().join("scenes/nonhertz")).unwrap() {
        let p = e.unwrap().path();
        std::fs::copy(&p, suite_dir.join(p.file_name().unwrap())).unwrap();
    }
    std::fs::write(suite_dir.join("tolerances.toml"), rule(0.05, "nh_*")).unwrap();
    let r = root();
    let suite_s = suite_dir.to_str().unwrap();
    let json = dir.join("c.json");
    let o = creepbench(&r, &["check", "--quiet", "--suite", suite_s, "--json", json.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "{}", String::from_utf8_lossy(&o.stderr));
    let checked = json_verdict(&json);
    assert_eq!(checked.1, 2);
    let res = dir.join("results");
    let o =
        creepbench(&r, &["run", "--quiet", "--suite", suite_s, "--shard", "1/1", "--results", res.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let report = dir.join("merged");
    let o = creepbench(&r, &["merge", res.to_str().unwrap(), "--suite", suite_s, "--report", report.to_str().unwrap()]);
    // Two failures: merge exits 1, as check did (issue 48).
    assert_eq!(o.status.code(), Some(1), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(report_verdict(&report.join("validation.md")), checked);
}
