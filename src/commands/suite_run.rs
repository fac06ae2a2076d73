//! Running a suite for `run`, `check` and `bless`: its files split and checked before anything
//! runs, its module-3 and wheel–rail scenes run, the re-timing, the empty shard.

use super::*;

/// A suite's results: its module-3 scenes as stored, its wheel–rail scenes with their runs.
#[derive(Default)]
pub(super) struct SuiteRun {
    pub(super) scenes: Vec<StoredScene>,
    pub(super) wheelrail: Vec<(WheelRailScene, SceneRun)>,
}

/// A suite's scene files (or one shard's), split and checked before anything runs: its module-3
/// scenes and its wheel–rail scenes (read, profiles and models checked).
pub(super) struct SuiteFiles {
    pub(super) plain: Vec<suite::SceneSource>,
    pub(super) wheelrail: Vec<WheelRailScene>,
    /// The shard holds none of the suites' scenes (noted; nothing runs).
    pub(super) empty: bool,
}

impl SuiteFiles {
    pub(super) fn read(suite_dir: &[PathBuf], shard: Option<Shard>) -> Result<Self, Error> {
        let files = suite::scene_files(suite_dir, shard)?;
        if files.is_empty() {
            empty_shard(suite_dir, shard)?;
            return Ok(SuiteFiles { plain: Vec::new(), wheelrail: Vec::new(), empty: true });
        }
        let (plain, wheelrail) = suite::wheelrail::split(files)?;
        Ok(SuiteFiles { plain, wheelrail, empty: false })
    }
}

/// Run a suite (or one shard): its module-3 scenes, then, `with_wheelrail`, its wheel–rail
/// scenes (`bless` leaves them out: they are gated against CONTACT, never against golden/).
pub(super) fn run_suite(files: SuiteFiles, runner: Runner, with_wheelrail: bool) -> Result<SuiteRun, Error> {
    let Runner { progress, in_process, timing_repeats, .. } = runner;
    let SuiteFiles { plain: files, wheelrail, empty } = files;
    if empty {
        return Ok(SuiteRun::default());
    }
    let start = Instant::now();
    let results = if files.is_empty() { Vec::new() } else { suite::run_with(&files, progress, in_process)? };
    let wheelrail = if with_wheelrail {
        let runs = suite::wheelrail::run_all(&wheelrail)?;
        wheelrail.into_iter().zip(runs).collect()
    } else {
        if !wheelrail.is_empty() {
            errln!("note: {} wheel-rail scene(s) left out: they are gated against CONTACT only", wheelrail.len());
        }
        Vec::new()
    };
    errln!("ran {} scene(s) in {:.2} s", results.len() + wheelrail.len(), start.elapsed().as_secs_f64());
    let mut scenes: Vec<StoredScene> = results.iter().map(StoredScene::from_result).collect();
    retime(&results, &mut scenes, timing_repeats)?;
    Ok(SuiteRun { scenes, wheelrail })
}

/// The wheel–rail scenes' comparisons with CONTACT's printed module-1 results (the set
/// "CONTACT wheel-rail", judged by the defaults as every reference set's).
pub(super) fn wheelrail_findings(refs: &References, runs: &[(WheelRailScene, SceneRun)]) -> Vec<Finding> {
    let Some(set) = refs.get::<WheelRailCases>(wheelrail_cases::AGAINST) else { return Vec::new() };
    runs.iter().flat_map(|(s, r)| set.compare_run(r, s.origin.as_ref(), tolerances::defaults())).collect()
}

/// Attach each wheel–rail run's worst comparison per case to the set (the report's list).
pub(super) fn attach_wheelrail(refs: &mut References, runs: &[(WheelRailScene, SceneRun)]) {
    if let Some(set) = refs.get_mut::<WheelRailCases>(wheelrail_cases::AGAINST) {
        for (s, r) in runs {
            if let Some(o) = &s.origin {
                set.attach_run(r, o, tolerances::defaults());
            }
        }
    }
}

/// The models of the scenes whose timings the report draws ([`report::timed::wants_isolated`])
/// re-timed alone, one after another on this thread, `repeats` times each (none for 0).
pub(super) fn retime(
    results: &[pipeline::SceneResult],
    stored: &mut [StoredScene],
    repeats: usize,
) -> Result<(), Error> {
    let wanted: Vec<usize> = (0..stored.len()).filter(|&i| report::timed::wants_isolated(&stored[i])).collect();
    if repeats == 0 || wanted.is_empty() {
        return Ok(());
    }
    let start = Instant::now();
    errln!("re-timing the models of {} scene(s) alone, {repeats} repeats each ...", wanted.len());
    for i in wanted {
        stored[i].repeats = suite::timing::retime(&results[i].problem, repeats)?;
    }
    errln!("re-timed in {:.2} s", start.elapsed().as_secs_f64());
    Ok(())
}

/// A shard that holds none of the suites' scenes is a success with a one-line note (a CI matrix
/// is sized before the suite is); suites without any scene are an input error.
pub(super) fn empty_shard(suite_dir: &[PathBuf], shard: Option<Shard>) -> Result<(), Error> {
    let dirs: Vec<String> = suite_dir.iter().map(|d| d.display().to_string()).collect();
    let all = match shard {
        Some(_) => suite::scene_files(suite_dir, None)?.len(),
        None => 0,
    };
    match shard {
        Some(Shard { index, count }) if all > 0 => {
            errln!(
                "note: shard {index}/{count} holds none of the {all} scene(s) of {}: nothing to run",
                dirs.join(", ")
            );
            Ok(())
        }
        _ => Err(InputError::new("--suite", dirs.join(", "), "folders with at least one scene (*.toml)").into()),
    }
}
