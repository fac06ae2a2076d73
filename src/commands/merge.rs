//! `creepbench merge`: one report from the result folders of several shards.

use super::*;

/// `creepbench merge`: one report from the result folders of several shards, judged by the same
/// tolerance rules as `check` and `run`: the `--tolerances` files, then the `tolerances.toml` of
/// each suite folder in `suites` that the merged scenes came from (each scene records its suite's
/// folder name), then the defaults.
pub fn merge(
    dirs: &[PathBuf],
    reference: &Path,
    report_dir: &Path,
    golden: &Path,
    suites: &[PathBuf],
    tolerances: &[PathBuf],
) -> Result<(), Error> {
    guard::guard_output_dir(report_dir, golden)?;
    report::check_outputs(report_dir, golden)?;
    for (i, d) in dirs.iter().enumerate() {
        for e in &dirs[..i] {
            if guard::same_place(d, e)? {
                return Err(InputError::new("merge", d.display(), "each result folder once").into());
            }
        }
    }
    let mut refs = load_references(reference)?;
    let scenes = read_results(dirs)?;
    for d in dirs {
        if guard::same_place(d, report_dir)? {
            let names: Vec<String> = results::scene_names(d);
            refuse_taken(&names, &REPORT_SUBDIRS, d, "--report")?;
        }
    }
    if scenes.is_empty() {
        let given: Vec<String> = dirs.iter().map(|d| d.display().to_string()).collect();
        return Err(InputError::new(
            "merge",
            given.join(", "),
            "result folders written by `creepbench run --results DIR`, holding at least one scene",
        )
        .into());
    }
    let suites_given = suites;
    let merged_suites: Vec<PathBuf> = suites
        .iter()
        .filter(|d| d.file_name().is_some_and(|n| scenes.iter().any(|s| *s.scene.suite == *n.to_string_lossy())))
        .cloned()
        .collect();
    let rules = file_rules(tolerances, &merged_suites)?;
    // The blessed scenes of the merged suites that no shard produced fail, as in `check`.
    let suites: Vec<&str> = scenes.iter().map(|s| s.scene.suite.as_str()).collect();
    let missing = match golden.is_dir() {
        true => compare::missing_scenes(golden, &scenes, Against::Golden, |_, suite| suites.contains(&suite))?,
        false => Vec::new(),
    };
    for f in &missing {
        errln!("MISSING scene {}: {}", f.scene, crate::comparison::gate_output::describe(f));
    }
    let mut extra = missing;
    extra.extend(owed_by_scenes(&scenes, &merged_suites)?);
    note_wheelrail_not_merged(suites_given)?;
    let fits = read_fit_records(dirs)?;
    survey_decks(&mut refs, DeckLists::of(&scenes, &[]));
    let judging = Judging { golden: Some(golden), rules: &rules, extra, suites: &suite_of(&scenes, &[]) };
    let (md, findings, _) =
        report_with_findings(&scenes, &refs, report_dir, judging, Drawn { fits: &fits, wheelrail: None })?;
    let verdict = Verdict::of(&findings);
    outln!("gates: {verdict}");
    outln!("report: {}", md.display());
    // The exit status is the verdict's, as `check`'s: a drift fails the CI job that merges.
    match verdict.failed {
        0 => Ok(()),
        count => Err(Error::Drift { count }),
    }
}

/// `merge` reads module-3 result folders only: the wheel–rail scenes of `suites` are gated
/// against CONTACT by each shard's `check`, and are named once so that nobody takes the merged
/// verdict for theirs.
pub(super) fn note_wheelrail_not_merged(suites: &[PathBuf]) -> Result<(), Error> {
    let given: Vec<PathBuf> = suites.iter().filter(|d| d.is_dir()).cloned().collect();
    let files = suite::scene_files(&given, None)?;
    let names: Vec<&str> =
        files.iter().filter(|f| suite::wheelrail::is_wheelrail(f)).map(|f| f.name.as_str()).collect();
    if !names.is_empty() {
        errln!(
            "note: {} wheel-rail scene(s) are not in a merge (each shard's `check` gates them against CONTACT): {}",
            names.len(),
            names.join(", ")
        );
    }
    Ok(())
}

/// What the merged `scenes` owe their scene files in `suites` ([`owed::check`]): each
/// shortfall named on stderr and returned as a gated failure; the scenes of suites not given
/// named once.
pub(super) fn owed_by_scenes(scenes: &[StoredScene], suites: &[PathBuf]) -> Result<Vec<Finding>, Error> {
    let owed = owed::check(scenes, suites)?;
    for f in &owed.shortfalls {
        errln!("SHORT scene {} {}: {} ({})", f.scene, f.solver, f.quantity, f.note);
    }
    if !owed.unchecked.is_empty() {
        errln!(
            "warning: {} merged scene(s) of suites not given with --suite, not checked against their scene files: {}",
            owed.unchecked.len(),
            owed.unchecked.join(", ")
        );
    }
    Ok(owed.shortfalls)
}
