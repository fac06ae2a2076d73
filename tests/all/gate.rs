//! The CI gate: the default suites run once, compared with golden/ and with every reference that
//! applies exactly as `creepbench check` does, and one insta snapshot per scene of its rounded
//! metrics and row counts. Iteration counts and terminations have one regression oracle, golden/
//! (gated at 5 % + 2 iterations, the slack floating-point differences between CPUs need; an exact
//! snapshot would fail on another CPU for no model change).

use crate::common;
use common::*;
use creepbench::comparison::compare::{self, Against};
use creepbench::comparison::references::References;
use creepbench::suite;
use creepbench::suite::results::StoredScene;

/// 6 significant digits (round-off-sized values as 0): stable across machines, still sensitive to
/// any real model change.
fn round6(v: f64) -> String {
    if v.abs() < 1e-12 || !v.is_finite() {
        return if v.is_finite() { "0 (round-off)".into() } else { format!("{v}") };
    }
    format!("{:.*e}", 5, v)
}

fn snapshot(s: &StoredScene) -> String {
    let mut out = String::new();
    for ((solver, metric, step), v) in &s.metrics {
        let step = step.map(|k| format!("[{k}]")).unwrap_or_default();
        out.push_str(&format!("{solver} {metric}{step} = {}\n", round6(*v)));
    }
    for (solver, h) in &s.histories {
        out.push_str(&format!("{solver} rows = {}\n", h.rows.len()));
    }
    out
}

#[test]
fn suite_matches_golden_references_and_snapshots() {
    let dirs: Vec<_> = suite::DEFAULT_SUITES.iter().map(|d| root().join(d)).collect();
    // The module-3 scenes (the wheel–rail suite is gated against CONTACT alone: wheelrail_mbench).
    let (files, _) = suite::wheelrail::split(suite::scene_files(&dirs, None).unwrap()).unwrap();
    let results = suite::run(&files, false).unwrap();
    let scenes: Vec<StoredScene> = results.iter().map(StoredScene::from_result).collect();
    let refs = References::load(&root().join("reference")).unwrap();
    let golden = root().join("golden");
    let all = compare::evaluate(&scenes, &refs, Some((&golden, Against::Golden))).unwrap();
    let worst = compare::worst_per_group(&all);
    println!("{}", compare::table(&worst));
    let fails = compare::failures(&all);
    let gated = all.iter().filter(|f| f.gated).count();
    println!("{gated} gated comparisons, {} failed", fails.len());
    assert!(gated > 300, "the gate must cover every scene and solver ({gated})");
    assert!(fails.is_empty(), "gated drift:\n{}", fails.join("\n"));
    for s in &scenes {
        insta::assert_snapshot!(s.name.clone(), snapshot(s));
    }
}
