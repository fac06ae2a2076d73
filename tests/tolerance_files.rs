//! Issue 15, tolerances as data: a user's rule file gates what the compiled defaults only report
//! (and loosens nothing else), suite folders' `tolerances.toml` are picked up, and a bad file —
//! unknown key, unknown comparison, a rule that matches nothing — is an input error (exit 2)
//! naming the file and the rule.

mod common;
use common::{root, tempdir};
use creepbench::harness::tolerance_file;
use std::path::Path;
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
    // Without the file: the defaults (452 gated comparisons on this suite, none failing).
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
        vec![dir.join("mine.toml"), b.join("tolerances.toml")]
    );
}
