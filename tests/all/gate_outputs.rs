//! Issue 15, the gate in CI: `check --junit/--json/--summary` on a suite with a drifted golden
//! value — the JUnit file checked against the common JUnit schema (the elements and attributes
//! Jenkins' junit-4 XSD requires, and counts that add up), the JSON and the summary agreeing with
//! it, `$GITHUB_STEP_SUMMARY` appended; and no verdict file inside golden/.

use crate::common;
use common::{root, tempdir};
use quick_xml::events::Event;
use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command;

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let e = e.unwrap();
        std::fs::copy(e.path(), to.join(e.file_name())).unwrap();
    }
}

/// Every element: name, attributes, parent element.
type Elements = Vec<(String, BTreeMap<String, String>, Option<String>)>;

/// Elements with their parent, tracking Start/End nesting exactly.
fn parse_tree(xml: &str) -> Elements {
    let mut reader = quick_xml::Reader::from_str(xml);
    let mut stack: Vec<String> = Vec::new();
    let mut out = Vec::new();
    loop {
        let ev = reader.read_event().expect("well-formed XML");
        let (e, opens) = match &ev {
            Event::Start(e) => (e.clone(), true),
            Event::Empty(e) => (e.clone(), false),
            Event::End(_) => {
                stack.pop();
                continue;
            }
            Event::Eof => break,
            _ => continue,
        };
        let name = String::from_utf8(e.name().as_ref().to_vec()).unwrap();
        let attrs = e
            .attributes()
            .map(|a| {
                let a = a.unwrap();
                (String::from_utf8(a.key.as_ref().to_vec()).unwrap(), a.unescape_value().unwrap().to_string())
            })
            .collect();
        out.push((name.clone(), attrs, stack.last().cloned()));
        if opens {
            stack.push(name);
        }
    }
    assert!(stack.is_empty(), "unclosed elements {stack:?}");
    out
}

#[test]
fn check_writes_junit_json_and_summary() {
    let dir = tempdir("gate_outputs");
    // A golden folder with one scene whose exact-solver result drifted.
    let golden = dir.join("golden");
    copy_dir(&root().join("golden/nh_flat_sweep_cx"), &golden.join("nh_flat_sweep_cx"));
    let csv = golden.join("nh_flat_sweep_cx/contact.csv");
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let mut cells: Vec<String> = lines[5].split(',').map(String::from).collect();
    let v: f64 = cells[6].parse().unwrap();
    cells[6] = format!("{}", v + 1e-3);
    lines[5] = cells.join(",");
    std::fs::write(&csv, lines.join("\n") + "\n").unwrap();
    let step_summary = dir.join("step_summary.md");
    std::fs::write(&step_summary, "earlier content\n").unwrap();
    let (junit, json, summary) = (dir.join("out/junit.xml"), dir.join("out/check.json"), dir.join("out/summary.md"));
    std::fs::create_dir_all(dir.join("out")).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(root())
        .env("GITHUB_STEP_SUMMARY", &step_summary)
        .args(["check", "--quiet", "--suite", "scenes/nonhertz", "--golden"])
        .arg(&golden)
        .arg("--junit")
        .arg(&junit)
        .arg("--json")
        .arg(&json)
        .arg("--summary")
        .arg(&summary)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(1), "drift fails the gate: {}", String::from_utf8_lossy(&o.stderr));

    // JUnit: the schema's structure and required attributes; counts add up.
    let xml = std::fs::read_to_string(&junit).unwrap();
    let el = parse_tree(&xml);
    assert_eq!(el[0].0, "testsuites");
    let (mut cases, mut failures) = (0usize, 0usize);
    for (name, attrs, parent) in &el {
        let need = |keys: &[&str]| {
            for k in keys {
                assert!(attrs.contains_key(*k), "<{name}> lacks {k}: {attrs:?}");
            }
        };
        match name.as_str() {
            "testsuites" => assert!(parent.is_none()),
            "testsuite" => {
                assert_eq!(parent.as_deref(), Some("testsuites"));
                need(&["name", "tests", "failures", "errors", "time"]);
            }
            "testcase" => {
                assert_eq!(parent.as_deref(), Some("testsuite"));
                need(&["name", "classname", "time"]);
                cases += 1;
            }
            "failure" => {
                assert_eq!(parent.as_deref(), Some("testcase"));
                need(&["message", "type"]);
                failures += 1;
            }
            "system-out" => assert_eq!(parent.as_deref(), Some("testcase")),
            other => panic!("element <{other}> is not in the JUnit schema"),
        }
    }
    let top = &el[0].1;
    assert_eq!(top["tests"].parse::<usize>().unwrap(), cases);
    assert_eq!(top["failures"].parse::<usize>().unwrap(), failures);
    let suite_sum: usize =
        el.iter().filter(|e| e.0 == "testsuite").map(|e| e.1["failures"].parse::<usize>().unwrap()).sum();
    assert_eq!(suite_sum, failures);
    // The drifted value's test case fails and names the worst point.
    let drifted = el
        .iter()
        .position(|e| {
            e.0 == "testcase" && e.1["name"] == "nh_flat_sweep_cx contact" && e.1["classname"] == "creepbench.golden"
        })
        .unwrap();
    assert_eq!(el[drifted + 1].0, "failure");
    assert!(el[drifted + 1].1["message"].contains("fx_over_fn step 5"), "{:?}", el[drifted + 1].1);
    // Scenes without golden data fail too (four scenes x four solvers), CONTACT's gate passes.
    assert!(failures >= 17, "{failures}");

    // JSON: complete, and the same verdict.
    let j: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(j["passed"], false);
    let findings = j["findings"].as_array().unwrap();
    let failed = findings.iter().filter(|f| f["gated"] == true && f["passed"] == false).count();
    assert_eq!(j["failed"].as_u64().unwrap() as usize, failed);
    assert!(findings.iter().any(|f| f["scene"] == "nh_flat_sweep_cx"
        && f["quantity"] == "fx_over_fn"
        && f["step"] == 5
        && f["passed"] == false));

    // The summary, and the same appended to $GITHUB_STEP_SUMMARY after what was there.
    let md = std::fs::read_to_string(&summary).unwrap();
    assert!(md.starts_with("## creepbench check: FAILED"), "{md}");
    assert!(md.contains(&format!("{failed} failed")), "{md}");
    let appended = std::fs::read_to_string(&step_summary).unwrap();
    assert_eq!(appended, format!("earlier content\n{md}"));

    // No verdict file inside golden/.
    let o = Command::new(env!("CARGO_BIN_EXE_creepbench"))
        .current_dir(root())
        .args(["check", "--quiet", "--suite", "scenes/nonhertz", "--golden"])
        .arg(&golden)
        .arg("--junit")
        .arg(golden.join("junit.xml"))
        .output()
        .unwrap();
    assert_ne!(o.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&o.stderr).contains("only `creepbench bless` writes"));
    assert!(!golden.join("junit.xml").exists());
}

/// The CI examples are at least syntactically valid: the YAML files parse (and hold the jobs the
/// README names), the Slurm script passes `bash -n`, and each calls `check` with `--shard`.
#[test]
fn ci_examples_are_valid() {
    let dir = root().join("ci-examples");
    for (file, jobs) in [("github-actions.yml", ["gate", "report"]), ("gitlab-ci.yml", ["gate", "report"])] {
        let text = std::fs::read_to_string(dir.join(file)).unwrap();
        let docs = yaml_rust2::YamlLoader::load_from_str(&text).unwrap_or_else(|e| panic!("{file}: {e}"));
        let doc = &docs[0];
        let root_jobs = if file.starts_with("github") { &doc["jobs"] } else { doc };
        for job in jobs {
            assert!(!root_jobs[job].is_badvalue(), "{file}: no job {job}");
        }
        assert!(text.contains("creepbench check") && text.contains("--shard") && text.contains("--junit"), "{file}");
        assert!(text.contains("creepbench merge"), "{file}");
    }
    let o = Command::new("bash").arg("-n").arg(dir.join("slurm-array.sh")).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let script = std::fs::read_to_string(dir.join("slurm-array.sh")).unwrap();
    assert!(script.contains("--shard \"$i/$n\"") && script.contains("SLURM_ARRAY_TASK_COUNT"));
}
