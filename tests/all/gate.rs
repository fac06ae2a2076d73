//! The CI gate: the default suites run once, compared with golden/ and with every reference that
//! applies exactly as `creepbench check` does. golden/ is the one regression oracle of the
//! numbers (iteration counts and terminations gated at 5 % + 2 iterations, the slack
//! floating-point differences between CPUs need); what users read is snapshotted in `oracles`.

use crate::common;
use common::*;
use creepbench::comparison::compare::{self, Against};
use creepbench::comparison::references::References;
use creepbench::suite;
use creepbench::suite::results::StoredScene;

#[test]
fn suite_matches_golden_and_references() {
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
}
