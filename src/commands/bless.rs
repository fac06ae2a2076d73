//! `creepbench bless`: the only writer of golden/.

use super::*;

/// `creepbench bless`: write the suite's results as the new golden data (the only writer of
/// golden/). All or nothing: the new tree is built beside the old one — this run's scenes plus
/// the blessed scenes of other suites and shards — and swapped in with one atomic exchange.
pub fn bless(suite_dir: &[PathBuf], golden: &Path, shard: Option<Shard>, progress: bool) -> Result<(), Error> {
    let SuiteRun { scenes, .. } = run_suite(SuiteFiles::read(suite_dir, shard)?, Runner::cli(shard, progress), false)?;
    if scenes.is_empty() {
        // An empty shard (noted by `run_suite`): golden/ stays as it is.
        return Ok(());
    }
    let suites = suite_names(suite_dir);
    // One writer of golden/ at a time; what it keeps is read under the lock, so that concurrent
    // blesses of other suites or shards all land.
    let _lock = lock::lock_protected(golden, lock::DEFAULT_LOCK_WAIT)?;
    let mut kept = Vec::new();
    for name in results::scene_names(golden) {
        let old = results::read_resolved(golden, &name)?;
        let rerun = shard.is_none_or(|s| s.takes(&name)) && suites.contains(&old.suite);
        if !rerun && !scenes.iter().any(|s| s.name == name) {
            kept.push(name);
        }
    }
    folder::replace_tree_atomically(golden, |new: &Path| -> Result<(), Error> {
        for name in &kept {
            results::copy_scene(golden, new, name)?;
        }
        results::write_scenes(new, &scenes, false)?;
        Ok(())
    })?;
    errln!(
        "blessed {} scene(s) into {} ({} kept from other suites or shards)",
        scenes.len(),
        golden.display(),
        kept.len()
    );
    Ok(())
}
