//! The CI gate: the default suites (scenes/thesis and scenes/stability) run once, compared with
//! golden/ and with every reference that applies exactly as `creepbench check` does, and one insta
//! snapshot per scene of its rounded metrics and iteration counts.

mod common;
use common::*;
use creepbench::harness::compare::{self, Against};
use creepbench::harness::reference::References;
use creepbench::harness::results::StoredScene;
use creepbench::harness::suite;

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
        if let Some(it) = h.column("iterations") {
            out.push_str(&format!(
                "{solver} iterations total = {} max = {}\n",
                it.iter().sum::<f64>(),
                it.iter().fold(0.0f64, |a, &b| a.max(b))
            ));
        }
        if let Some(c) = h.column("converged") {
            out.push_str(&format!("{solver} unconverged steps = {}\n", c.iter().filter(|&&x| x < 0.5).count()));
        }
    }
    out
}

#[test]
fn suite_matches_golden_references_and_snapshots() {
    let dirs = vec![root().join("scenes/thesis"), root().join("scenes/stability")];
    let files = suite::scene_files(&dirs, None).unwrap();
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
