//! `creepbench run`: the suites → result folders, then the report of this run only.

use super::*;

/// Where `creepbench run` writes: the result folders, the report, and the fits it runs.
pub struct RunOutputs<'a> {
    pub results_dir: &'a Path,
    pub report_dir: &'a Path,
    /// The folder of fit files run after the suites (none: no fits).
    pub fits: Option<&'a Path>,
}

/// What [`run_with`] made: the result folder, the report (none for a shard), the report's
/// findings with the rules of the run's files that loosened a default gate, the histories
/// flagged as oscillating, and what the result folder holds from other runs (left out).
#[derive(Debug, Clone)]
pub struct RunOutcome {
    pub results_dir: PathBuf,
    /// validation.md.
    pub report: Option<PathBuf>,
    pub findings: Vec<Finding>,
    pub loosened: Vec<Loosening>,
    pub oscillating: Vec<String>,
    /// The scene folders of the result folder this run did not write: left out of its report
    /// and results.csv (named once on the console).
    pub ignored_scenes: Vec<String>,
    /// The fit records of `<results>/fits/` this run did not write: left out of its report.
    pub ignored_fits: Vec<String>,
    /// The wheel–rail scenes this run solved, with their runs (what its result folders and its
    /// gate against CONTACT were made from; empty for a shard).
    pub wheelrail: Vec<(WheelRailScene, SceneRun)>,
}

/// `creepbench run`: the suites → result folders, then the report from this run's results;
/// the console ends with the gates' verdict and the report's path, after any warnings.
pub fn run(
    suite_dir: &[PathBuf],
    reference: &Path,
    outputs: RunOutputs,
    runner: Runner,
    golden: &Path,
) -> Result<(), Error> {
    let outcome = run_with(suite_dir, reference, outputs, runner, golden)?;
    let Some(md) = outcome.report else {
        errln!("shard done; build the report with `creepbench merge {} ...`", outcome.results_dir.display());
        return Ok(());
    };
    for line in &outcome.oscillating {
        outln!("{line}");
    }
    outln!("gates: {}", Verdict::of(&outcome.findings));
    outln!("report: {}", md.display());
    Ok(())
}

/// [`run`] without printing its outcome; `runner` also gives the models run in this process.
/// The report, its verdict and results.csv cover exactly the scenes (and fits) this run wrote:
/// the result folder's other scene folders and fit records are named once and left out.
pub fn run_with(
    suite_dir: &[PathBuf],
    reference: &Path,
    outputs: RunOutputs,
    runner: Runner,
    golden: &Path,
) -> Result<RunOutcome, Error> {
    let RunOutputs { results_dir, report_dir, fits } = outputs;
    let shard = runner.shard;
    guard::guard_output_dir(results_dir, golden)?;
    guard::guard_output_dir(report_dir, golden)?;
    if shard.is_none() {
        report::check_outputs(report_dir, golden)?;
    }
    // No scene's result folder may be another output's folder: refused before anything runs.
    let names = suite::scene_files(suite_dir, shard)?.into_iter().map(|s| s.name).collect::<Vec<_>>();
    if fits.is_some() {
        refuse_taken(&names, &[FITS_SUBDIR], results_dir, "--fits")?;
    }
    if guard::same_place(results_dir, report_dir)? && shard.is_none() {
        refuse_taken(&names, &REPORT_SUBDIRS, results_dir, "--report")?;
    }
    let mut refs = load_references(reference)?;
    // Fit files validated before any scene runs: a bad --fits writes nothing.
    let fit_specs = fits.map(load_fit_specs).transpose()?;
    let files = SuiteFiles::read(suite_dir, shard)?;
    let printed = if shard.is_none() { read_printed(&files.wheelrail)? } else { Vec::new() };
    let SuiteRun { scenes, wheelrail } = run_suite(files, runner, true)?;
    std::fs::create_dir_all(results_dir).map_err(Error::io(results_dir))?;
    // Runs into one folder take turns rather than fail on each other's half-written scenes.
    let _lock = lock::lock_folder(results_dir, lock::DEFAULT_LOCK_WAIT)?;
    results::write_scenes(results_dir, &scenes, true)?;
    for (_, run) in &wheelrail {
        suite::wheelrail::write(results_dir, run)?;
    }
    errln!("results in {}", results_dir.display());
    let mut ran: Vec<String> = scenes.iter().map(|s| s.name.clone()).collect();
    ran.sort();
    let mut outcome = RunOutcome {
        results_dir: results_dir.to_path_buf(),
        report: None,
        findings: Vec::new(),
        loosened: Vec::new(),
        oscillating: Vec::new(),
        ignored_scenes: other_runs_scenes(results_dir, &ran, shard.is_some()),
        ignored_fits: Vec::new(),
        wheelrail: Vec::new(),
    };
    if shard.is_some() {
        return Ok(outcome);
    }
    let fitted = match fit_specs {
        Some(specs) => {
            run_fits(&specs, &refs, results_dir, (&scenes, &suite::scene_files(suite_dir, None)?))?;
            specs.into_iter().map(|s| s.name).collect()
        }
        None => Vec::new(),
    };
    outcome.ignored_fits = other_runs_fits(results_dir, &fitted);
    // This run's scenes read back as stored (the numbers `merge` would show), and only those.
    let stored = ran.iter().map(|name| results::read_scene(results_dir, name)).collect::<Result<Vec<_>, _>>()?;
    survey_decks(&mut refs, DeckLists::of(&stored, &wheelrail));
    let records = read_run_fits(results_dir, &fitted)?;
    let rules = file_rules(&[], suite_dir)?;
    let wheelrail_found = wheelrail_findings(&refs, &wheelrail);
    attach_wheelrail(&mut refs, &wheelrail);
    let suites = suite_of(&stored, &wheelrail);
    let drawn = Drawn { fits: &records, wheelrail: wheelrail_section(&wheelrail, &printed)? };
    let judging = Judging { golden: Some(golden), rules: &rules, extra: wheelrail_found, suites: &suites };
    let (md, findings, loosened) = report_with_findings(&stored, &refs, report_dir, judging, drawn)?;
    outcome.report = Some(md);
    outcome.findings = findings;
    outcome.loosened = loosened;
    outcome.oscillating = console::oscillating(&stored, false);
    outcome.wheelrail = wheelrail;
    Ok(outcome)
}

/// The scene folders of `results_dir` that are not among `ran` (written by other runs), named
/// once on the console: left out of this run's report, or (`shard`) read by `merge` of the folder.
pub(super) fn other_runs_scenes(results_dir: &Path, ran: &[String], shard: bool) -> Vec<String> {
    let others: Vec<String> = results::scene_names(results_dir).into_iter().filter(|n| !ran.contains(n)).collect();
    if !others.is_empty() {
        let what = match shard {
            true => "; `merge` reads every scene folder of the folders it is given",
            false => ", left out of this run's report and results.csv",
        };
        errln!(
            "warning: {} holds {} scene folder(s) this run did not write{what}: {}",
            results_dir.display(),
            others.len(),
            others.join(", ")
        );
    }
    others
}

/// The fit records of `<results_dir>/fits/` other than this run's `fitted`, named once on the
/// console and left out of this run's report.
pub(super) fn other_runs_fits(results_dir: &Path, fitted: &[String]) -> Vec<String> {
    let others: Vec<String> = fit_record_paths(results_dir)
        .iter()
        .filter_map(|p| p.file_stem().map(|s| s.to_string_lossy().to_string()))
        .filter(|n| !fitted.contains(n))
        .collect();
    if !others.is_empty() {
        errln!(
            "warning: {} holds {} fit record(s) this run did not write, left out of this run's report: {}",
            results_dir.join(FITS_SUBDIR).display(),
            others.len(),
            others.join(", ")
        );
    }
    others
}
