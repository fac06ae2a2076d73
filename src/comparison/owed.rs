//! What a merged result owes its scene (issue 48 item 5). `merge` judges result folders another
//! process wrote: without golden data nothing else would notice a scene.json edited (a sine's
//! `freq_hz` set to 0 drops its delay comparison) or a history cut short (fewer rows compare
//! fewer points, and pass). What a scene owes is known from its scene file: scene.json as the
//! file resolves, every solver it names, each with one history row per step of its loading. A
//! shortfall is a gated failure against the [`Against::SceneFile`], which no rule file can name.

use crate::comparison::finding::{Against, Finding};
use crate::error::Error;
use crate::problem::ResolvedScene;
use crate::suite::results::StoredScene;
use crate::suite::SceneSource;
use std::collections::BTreeMap;
use std::path::PathBuf;

/// The keys of scene.json that are not owed: the warnings a run adds as it goes, and where the
/// report shows the scene (not a result; results written before it existed lack it).
const NOT_OWED: [&str; 2] = ["warnings", "report_group"];

/// The shortfalls of merged results, and the scenes that could not be checked.
#[derive(Debug, Default)]
pub struct Owed {
    /// One gated failure per shortfall.
    pub shortfalls: Vec<Finding>,
    /// Scenes whose suite folder was not given (`--suite`): named, not checked.
    pub unchecked: Vec<String>,
}

/// Check each of `scenes` against its scene file in `suites` (the folder named as its scene.json
/// records its suite). A scene whose suite is not among them is [`Owed::unchecked`]; one its suite
/// no longer holds, or a scene file that no longer loads, is a shortfall.
pub fn check(scenes: &[StoredScene], suites: &[PathBuf]) -> Result<Owed, Error> {
    let given: Vec<&PathBuf> = suites.iter().filter(|d| d.is_dir()).collect();
    let suite_of =
        |s: &StoredScene| given.iter().copied().find(|d| d.file_name().is_some_and(|n| *n == *s.scene.suite));
    let mut owed = Owed::default();
    let mut sources: BTreeMap<PathBuf, Vec<SceneSource>> = BTreeMap::new();
    for s in scenes {
        let Some(dir) = suite_of(s) else {
            owed.unchecked.push(s.name.clone());
            continue;
        };
        if !sources.contains_key(dir) {
            sources.insert(dir.clone(), crate::suite::scene_files(std::slice::from_ref(dir), None)?);
        }
        match sources[dir].iter().find(|src| src.name == s.name) {
            Some(src) => owed.shortfalls.extend(shortfalls(s, src)),
            None => owed.shortfalls.push(shortfall(
                s,
                "-",
                "scene",
                format!("its suite {} holds no scene of this name", dir.display()),
            )),
        }
    }
    Ok(owed)
}

/// What `stored` lacks against the scene `source` gives: a scene.json that differs, a solver
/// without a history, a history whose steps are not the loading's.
fn shortfalls(stored: &StoredScene, source: &SceneSource) -> Vec<Finding> {
    let problem = match crate::pipeline::load_source(source, &[]) {
        Ok(p) => p,
        Err(e) => {
            let note = format!("its scene file {} does not load: {e}", source.path.display());
            return vec![shortfall(stored, "-", "scene", note)];
        }
    };
    let mut out = Vec::new();
    let expected = ResolvedScene::of(&problem, &problem.solvers);
    let differ = differing_keys(&expected, &stored.scene);
    if !differ.is_empty() {
        let note = format!("differs from what its scene file {} gives in {differ:?}", source.path.display());
        out.push(shortfall(stored, "-", "scene.json", note));
    }
    let owed_steps: Vec<usize> = problem.loading.rows().map(|r| r.step).collect();
    for solver in &problem.solvers {
        let Some(h) = stored.histories.get(solver) else {
            out.push(shortfall(stored, solver, "history", format!("the scene runs {solver}; no {solver}.csv")));
            continue;
        };
        if !h.rows.iter().map(|r| r.sample.step).eq(owed_steps.iter().copied()) {
            let note = format!(
                "{} rows, the scene owes {} (one per step of its loading{})",
                h.rows.len(),
                owed_steps.len(),
                steps_range(&owed_steps)
            );
            out.push(shortfall(stored, solver, "rows", note));
        }
    }
    out
}

/// The top-level keys of scene.json whose values differ ([`NOT_OWED`] aside).
fn differing_keys(expected: &ResolvedScene, stored: &ResolvedScene) -> Vec<String> {
    let (Ok(serde_json::Value::Object(a)), Ok(serde_json::Value::Object(b))) =
        (serde_json::to_value(expected), serde_json::to_value(stored))
    else {
        return vec!["(not an object)".into()];
    };
    a.keys()
        .chain(b.keys().filter(|k| !a.contains_key(*k)))
        .filter(|k| !NOT_OWED.contains(&k.as_str()) && a.get(*k) != b.get(*k))
        .cloned()
        .collect()
}

/// `, steps a to b` for a non-empty list of steps.
fn steps_range(steps: &[usize]) -> String {
    match (steps.first(), steps.last()) {
        (Some(a), Some(b)) => format!(", steps {a} to {b}"),
        _ => String::new(),
    }
}

/// A gated failure of `stored` (a comparison that cannot be made: never passes).
fn shortfall(stored: &StoredScene, solver: &str, quantity: &str, note: String) -> Finding {
    Finding {
        scene: stored.name.clone(),
        solver: solver.into(),
        against: Against::SceneFile,
        quantity: quantity.into(),
        step: None,
        ours: f64::NAN,
        theirs: f64::NAN,
        diff: f64::NAN,
        allowed: 0.0,
        gated: true,
        note: format!("the merged result owes its scene: {note}"),
    }
}
