//! The subcommands behind the CLI: simulate, run, check, bless, merge.

use crate::calibration::fit::record::FitRecord;
use crate::calibration::fit::spec::FitSpec;
use crate::calibration::section as calibration;
use crate::comparison::compare::{self, Against, Finding};
use crate::comparison::console::{self, Verdict};
use crate::comparison::owed;
use crate::comparison::references::wheelrail_cases::{self, WheelRailCases};
use crate::comparison::references::References;
use crate::comparison::tolerance_file::{self, Loosening, Rule};
use crate::comparison::tolerances;
use crate::error::{Error, InputError};
use crate::pipeline;
use crate::pipeline::wheelrail_scene::SceneRun;
use crate::report::table;
use crate::report::{self, ReportInput};
use crate::report::{ladder, registry, sections};
use crate::safety::stdout::{errln, out, outln};
use crate::safety::{folder, guard, lock};
use crate::scene::wheelrail::WheelRailScene;
use crate::suite::results::{self, StoredScene};
use crate::suite::{self, Shard};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// `creepbench simulate`: one scene into `out/<name>/` (a study file: each of its scenes).
pub fn simulate(scene: &Path, solvers: &[String], out: &Path, golden: &Path) -> Result<Vec<PathBuf>, Error> {
    if let Some(wr) = crate::scene::wheelrail::read_if_wheelrail(scene)? {
        return simulate_wheelrail(wr, solvers, out, golden);
    }
    let sources = suite::sources_of_file(scene)?;
    // Every scene validated (and its folder checked) before any runs: bad input writes nothing.
    let problems = sources.iter().map(|s| pipeline::load_source(s, solvers)).collect::<Result<Vec<_>, _>>()?;
    guard::guard_output_dir(out, golden)?;
    for problem in &problems {
        // The folder written is out/<name>: a scene named after a protected folder cannot reach it.
        guard::guard_not_under(&out.join(&problem.name), golden)?;
    }
    let mut dirs = Vec::new();
    for problem in problems {
        let before = problem.warnings.len();
        for w in &problem.warnings {
            errln!("warning: {w}");
        }
        let result = pipeline::run(problem)?;
        for w in &result.problem.warnings[before..] {
            errln!("warning: {w}");
        }
        let stored = StoredScene::from_result(&result);
        // Writers into one folder take turns (as `run` does), so two simulations both land.
        let _lock = lock::lock_folder(out, lock::DEFAULT_LOCK_WAIT)?;
        dirs.push(results::write_scenes(out, std::slice::from_ref(&stored), false)?.remove(0));
        for (h, t) in result.histories.iter().zip(&result.timing) {
            errln!("{}: {} rows in {:.3} s", h.solver, h.rows.len(), t.wall_s);
        }
    }
    Ok(dirs)
}

/// `creepbench simulate` of a wheel–rail scene: its cases into `out/<name>/` (`<model>.csv`,
/// `<model>_patches.csv`); `solvers` narrows its models.
fn simulate_wheelrail(
    mut scene: crate::scene::wheelrail::WheelRailScene,
    solvers: &[String],
    out: &Path,
    golden: &Path,
) -> Result<Vec<PathBuf>, Error> {
    narrow(&mut scene, solvers)?;
    guard::guard_output_dir(out, golden)?;
    guard::guard_not_under(&out.join(&scene.name), golden)?;
    let run = run_wheelrail(&scene)?;
    // Writers into one folder take turns.
    let _lock = lock::lock_folder(out, lock::DEFAULT_LOCK_WAIT)?;
    Ok(vec![suite::wheelrail::write(out, &run)?])
}

/// `creepbench simulate SCENE... --report DIR` of wheel–rail scenes: each into `out/<name>/`
/// as [`simulate`] writes it, then `DIR/validation.md` with the section "Wheel–rail contact" of
/// the scenes that declare `[report] group = "wheelrail"` (`report::wheelrail`). Every scene, its
/// profiles and its CONTACT output are read and checked before any runs.
pub fn simulate_report(
    scenes: &[PathBuf],
    solvers: &[String],
    out: &Path,
    report_dir: &Path,
    golden: &Path,
) -> Result<Vec<PathBuf>, Error> {
    use crate::comparison::references::contact_output::wheelrail as printed;
    use crate::scene::wheelrail::{read_if_wheelrail, WheelRailScene};
    let mut read: Vec<(WheelRailScene, Vec<printed::WheelRailCase>)> = Vec::new();
    for path in scenes {
        let Some(mut scene) = read_if_wheelrail(path)? else {
            return Err(InputError::new(
                "--report",
                path.display(),
                "wheel–rail scenes (a [wheelrail] table); the report of other scenes is `creepbench run`'s",
            )
            .into());
        };
        narrow(&mut scene, solvers)?;
        pipeline::wheelrail_scene::prepare(&scene)?;
        let contact = match &scene.report.contact_output {
            Some(file) => printed::read(file).map_err(|e| {
                InputError::new(
                    format!("{}: report.contact_output", path.display()),
                    file.display(),
                    format!("CONTACT's printed module-1 output ({e})"),
                )
            })?,
            None => Vec::new(),
        };
        read.push((scene, contact));
    }
    if !read.iter().any(|(s, _)| s.report.in_section) {
        return Err(InputError::new(
            "--report",
            scenes.iter().map(|p| p.display().to_string()).collect::<Vec<_>>().join(", "),
            "at least one scene with [report] group = \"wheelrail\" (the section draws the scenes that declare it)",
        )
        .into());
    }
    guard::guard_output_dir(out, golden)?;
    guard::guard_output_dir(report_dir, golden)?;
    report::check_outputs(report_dir, golden)?;
    for (s, _) in &read {
        guard::guard_not_under(&out.join(&s.name), golden)?;
    }
    let (mut dirs, mut views) = (Vec::new(), Vec::new());
    for (scene, _) in &read {
        let run = run_wheelrail(scene)?;
        let lock = lock::lock_folder(out, lock::DEFAULT_LOCK_WAIT)?;
        dirs.push(suite::wheelrail::write(out, &run)?);
        drop(lock);
        views.push(pipeline::wheelrail_view::view(scene, run)?);
    }
    let wheels: Vec<report::wheelrail::Wheel> =
        views.iter().zip(&read).map(|(view, (_, contact))| report::wheelrail::Wheel { view, contact }).collect();
    let section = report::wheelrail::section(&wheels).expect("a scene declares the group (checked above)");
    let markdown = format!(
        "# creepbench wheel–rail report\n\nGenerated by `creepbench simulate --report` from {} wheel–rail scene(s).\n\n## {}\n\n{}\n",
        read.len(),
        section.title,
        section.body
    );
    let report = report::Report { markdown, figures: section.figures, tables: section.tables };
    std::fs::create_dir_all(report_dir).map_err(Error::io(report_dir))?;
    report.write(report_dir)?;
    dirs.push(report_dir.join("validation.md"));
    Ok(dirs)
}

/// `--solver` narrows a wheel–rail scene's models (to none of them: an input error).
fn narrow(scene: &mut crate::scene::wheelrail::WheelRailScene, solvers: &[String]) -> Result<(), Error> {
    if !solvers.is_empty() {
        scene.solvers.retain(|m| solvers.contains(m));
        if scene.solvers.is_empty() {
            return Err(InputError::new("--solvers", solvers.join(","), "models the scene names").into());
        }
    }
    Ok(())
}

/// Run a wheel–rail scene, with its time on the console.
fn run_wheelrail(
    scene: &crate::scene::wheelrail::WheelRailScene,
) -> Result<pipeline::wheelrail_scene::SceneRun, Error> {
    let start = Instant::now();
    let run = pipeline::wheelrail_scene::run_scene(scene)?;
    errln!(
        "{}: {} cases, {} models in {:.3} s",
        run.name,
        run.cases.len(),
        run.models.len(),
        start.elapsed().as_secs_f64()
    );
    Ok(run)
}

/// `creepbench expand`: a study's scenes as scene files `out/<name>.toml` (none is replaced).
pub fn expand(study_file: &Path, out: &Path, golden: &Path) -> Result<Vec<PathBuf>, Error> {
    let sources = suite::sources_of_file(study_file)?;
    if sources.iter().all(|s| s.study.is_none()) {
        return Err(InputError::new("STUDY", study_file.display(), "a study file (with a [study] table)").into());
    }
    guard::guard_output_dir(out, golden)?;
    let mut files = Vec::new();
    for s in &sources {
        pipeline::load_source(s, &[])?;
        let path = out.join(format!("{}.toml", s.name));
        if path.exists() {
            return Err(InputError::new(
                "--out",
                path.display(),
                "a folder without these scene files (expand replaces nothing)",
            )
            .into());
        }
        let header =
            format!("# Expanded by `creepbench expand` from {} (study point {}).\n", study_file.display(), s.name);
        files.push((path, header + &s.text()?));
    }
    std::fs::create_dir_all(out).map_err(|source| Error::Io { path: out.to_path_buf(), source })?;
    for (path, text) in &files {
        write_whole(path, text)?;
    }
    Ok(files.into_iter().map(|(p, _)| p).collect())
}

/// `creepbench fit`: fit a model's parameters (calibration::fit), print the before/after table and
/// write the fitted block to `out` (default `out/fits/<name>.toml`), which must not exist yet.
pub fn fit(file: &Path, out: Option<&Path>, reference: &Path, golden: &Path) -> Result<PathBuf, Error> {
    use crate::calibration::fit;
    let spec = FitSpec::from_file(file)?;
    let out = out.map_or_else(|| Path::new("out/fits").join(format!("{}.toml", spec.name)), Path::to_path_buf);
    guard::guard_output_file(&out, golden)?;
    if out.exists() {
        return Err(
            InputError::new("--out", out.display(), "a file that does not exist yet (fit replaces nothing)").into()
        );
    }
    let refs = References::load(reference)?;
    let outcome = fit::fit(&spec, &refs)?;
    out!("{}", fit::record::FitRecord::of(&outcome).table());
    let text = fit::render(&outcome)?;
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(Error::io(dir))?;
    }
    write_whole(&out, &text)?;
    Ok(out)
}

/// The reference sets, with the importer's verdict on every case of CONTACT's public decks
/// attached to the set `contact_public` (its report section lists them; the import stage sits
/// above comparison and report, so the survey is made here and passed down).
fn load_references(reference: &Path) -> Result<References, Error> {
    use crate::comparison::references::contact_public::{PublicCases, Survey, AGAINST};
    let mut refs = References::load(reference)?;
    if let Some(public) = refs.get_mut::<PublicCases>(AGAINST) {
        public.attach_survey(|inp| match crate::import::contact::survey(inp) {
            Ok(cases) => Survey::Cases(cases.into_iter().map(|c| (c.case, c.refused)).collect()),
            Err(e) => Survey::Unread(e.to_string()),
        });
    }
    // The module-1 decks: their module-1 cases only.
    if let Some(wr) = refs.get_mut::<WheelRailCases>(wheelrail_cases::AGAINST) {
        wr.attach_survey(|inp| match crate::import::contact::survey(inp) {
            Ok(cases) => {
                Survey::Cases(cases.into_iter().filter(|c| c.module == 1).map(|c| (c.case, c.refused)).collect())
            }
            Err(e) => Survey::Unread(e.to_string()),
        });
    }
    Ok(refs)
}

/// How a command runs a suite's scenes: one shard (none: all), with a progress bar or not, and
/// the models its caller runs in this process beside the built-in and external ones
/// ([`pipeline::InProcess`]: the Python package's callables; none from the command line).
/// `timing_repeats`: after the suite, the models of the scenes whose timings the report draws
/// are re-timed alone, this many times each ([`suite::timing`]; 0: not re-timed, as `check` and
/// `bless`, which write no timings, run).
#[derive(Clone, Copy, Default)]
pub struct Runner<'a> {
    pub shard: Option<Shard>,
    pub progress: bool,
    pub in_process: &'a [pipeline::InProcess<'a>],
    pub timing_repeats: usize,
}

impl Runner<'_> {
    /// The command line's runner: no in-process model, no re-timing.
    pub fn cli(shard: Option<Shard>, progress: bool) -> Self {
        Runner { shard, progress, in_process: &[], timing_repeats: 0 }
    }
}

/// A suite's results: its module-3 scenes as stored, its wheel–rail scenes with their runs.
#[derive(Default)]
struct SuiteRun {
    scenes: Vec<StoredScene>,
    wheelrail: Vec<(WheelRailScene, SceneRun)>,
}

/// Run a suite (or one shard): its module-3 scenes, then, `with_wheelrail`, its wheel–rail
/// scenes (`bless` leaves them out: they are gated against CONTACT, never against golden/).
fn run_suite(suite_dir: &[PathBuf], runner: Runner, with_wheelrail: bool) -> Result<SuiteRun, Error> {
    let Runner { shard, progress, in_process, timing_repeats } = runner;
    let files = suite::scene_files(suite_dir, shard)?;
    if files.is_empty() {
        return empty_shard(suite_dir, shard).map(|()| SuiteRun::default());
    }
    let (files, wheelrail) = suite::wheelrail::split(files)?;
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
fn wheelrail_findings(refs: &References, runs: &[(WheelRailScene, SceneRun)]) -> Vec<Finding> {
    let Some(set) = refs.get::<WheelRailCases>(wheelrail_cases::AGAINST) else { return Vec::new() };
    runs.iter().flat_map(|(s, r)| set.compare_run(r, s.origin.as_ref(), tolerances::defaults())).collect()
}

/// Attach each wheel–rail run's worst comparison per case to the set (the report's list).
fn attach_wheelrail(refs: &mut References, runs: &[(WheelRailScene, SceneRun)]) {
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
fn retime(results: &[pipeline::SceneResult], stored: &mut [StoredScene], repeats: usize) -> Result<(), Error> {
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
fn empty_shard(suite_dir: &[PathBuf], shard: Option<Shard>) -> Result<(), Error> {
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

/// Build the report from stored scenes and reference data (it runs no model).
pub fn build_report(
    scenes: &[StoredScene],
    refs: &References,
    out: &Path,
    golden: Option<&Path>,
    rules: &[Rule],
    fits: &[FitRecord],
    missing: Vec<Finding>,
) -> Result<PathBuf, Error> {
    report_with_findings(scenes, refs, out, (golden, rules), fits, (missing, &suite_of(scenes, &[]))).map(|(md, ..)| md)
}

/// [`build_report`], also returning the report's findings (the run's tolerance files applied)
/// and the rules that loosened a default gate.
fn report_with_findings(
    scenes: &[StoredScene],
    refs: &References,
    out: &Path,
    (golden, rules): (Option<&Path>, &[Rule]),
    fits: &[FitRecord],
    (missing, suites): (Vec<Finding>, &BTreeMap<String, String>),
) -> Result<(PathBuf, Vec<Finding>, Vec<Loosening>), Error> {
    let mut findings = compare::evaluate(scenes, refs, golden.filter(|g| g.exists()).map(|g| (g, Against::Golden)))?;
    findings.extend(missing);
    let loosened = tolerance_file::apply(rules, &mut findings, suites, |_| false)?;
    for l in &loosened {
        errln!("loosened: {l}");
    }
    let mut all = registry::all(scenes, refs);
    if let Some(s) = sections::loosened(&loosened) {
        all.insert(0, s);
    }
    // Calibration right after the model ladder (or last, without one).
    if let Some(c) = calibration::section(fits) {
        registry::insert_after(&mut all, ladder::ID, c);
    }
    let input = ReportInput { scenes, refs, findings: &findings, sections: all };
    let report = report::build(&input);
    std::fs::create_dir_all(out).map_err(Error::io(out))?;
    report.write(out)?;
    table::write(out, &table::rows(scenes, &findings)).map_err(Error::io(out.join(table::FILE)))?;
    Ok((out.join("validation.md"), findings, loosened))
}

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
    let SuiteRun { scenes, wheelrail } = run_suite(suite_dir, runner, true)?;
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
    let records = read_run_fits(results_dir, &fitted)?;
    let rules = file_rules(&[], suite_dir)?;
    let wheelrail_found = wheelrail_findings(&refs, &wheelrail);
    attach_wheelrail(&mut refs, &wheelrail);
    let (md, findings, loosened) = report_with_findings(
        &stored,
        &refs,
        report_dir,
        (Some(golden), &rules),
        &records,
        (wheelrail_found, &suite_of(&stored, &wheelrail)),
    )?;
    outcome.report = Some(md);
    outcome.findings = findings;
    outcome.loosened = loosened;
    outcome.oscillating = console::oscillating(&stored, false);
    Ok(outcome)
}

/// The records of the fits `fitted` this run stored in `results_dir`, sorted by name.
fn read_run_fits(results_dir: &Path, fitted: &[String]) -> Result<Vec<FitRecord>, Error> {
    let mut records = fitted
        .iter()
        .map(|name| read_fit_record(&fit_record_path(results_dir, name)))
        .collect::<Result<Vec<_>, _>>()?;
    records.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(records)
}

/// The scene folders of `results_dir` that are not among `ran` (written by other runs), named
/// once on the console: left out of this run's report, or (`shard`) read by `merge` of the folder.
fn other_runs_scenes(results_dir: &Path, ran: &[String], shard: bool) -> Vec<String> {
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
fn other_runs_fits(results_dir: &Path, fitted: &[String]) -> Vec<String> {
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

/// The folders a report writes beside validation.md.
const REPORT_SUBDIRS: [&str; 2] = ["figures", "tables"];

/// An error if a scene of `names` would have its result folder where `flag`'s output goes.
fn refuse_taken(names: &[String], taken: &[&str], results: &Path, flag: &str) -> Result<(), Error> {
    match names.iter().find(|n| taken.contains(&n.as_str())) {
        Some(n) => Err(InputError::new(
            "name",
            format!("scene {n:?} in {}", results.display()),
            format!("a scene name other than {} where {flag} writes into the same folder", taken.join(", ")),
        )
        .into()),
        None => Ok(()),
    }
}

/// Every scene folder of the result folders `dirs` (each scene in one folder only).
fn read_results(dirs: &[PathBuf]) -> Result<Vec<StoredScene>, Error> {
    let mut scenes: Vec<StoredScene> = Vec::new();
    for d in dirs {
        for name in results::scene_names(d) {
            if scenes.iter().any(|s| s.name == name) {
                return Err(InputError::new("merge", d.join(&name).display(), "each scene in one shard only").into());
            }
            scenes.push(results::read_scene(d, &name)?);
        }
    }
    scenes.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(scenes)
}

/// Where a result folder keeps the fits' outcomes.
const FITS_SUBDIR: &str = "fits";

/// Every fit file of `dir` (sorted), read and validated.
fn load_fit_specs(dir: &Path) -> Result<Vec<FitSpec>, Error> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| InputError::new("--fits", dir.display(), format!("a folder of fit files ({e})")))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    files.iter().map(|f| FitSpec::from_file(f)).collect()
}

/// Each fit run and stored as `<results>/fits/<name>.json` with its fitted block `<name>.toml`
/// beside (replaced on each run, as the scenes' results are); the record carries the fitted
/// variant beside the published model over the suites just run.
fn run_fits(
    specs: &[FitSpec],
    refs: &References,
    results_dir: &Path,
    (stored, sources): (&[StoredScene], &[suite::SceneSource]),
) -> Result<(), Error> {
    use crate::calibration::fit;
    let out = results_dir.join(FITS_SUBDIR);
    std::fs::create_dir_all(&out).map_err(Error::io(&out))?;
    for spec in specs {
        let start = Instant::now();
        let outcome = fit::fit(spec, refs)?;
        let mut record = fit::record::FitRecord::of(&outcome);
        // Beside the published model on every suite scene that runs it with the exact theory.
        record.suites = fit::across_suites(&outcome, stored, sources)?;
        let json = serde_json::to_string_pretty(&record)
            .map_err(|e| Error::Fit { fit: spec.name.clone(), source: e.into() })?;
        write_whole(&fit_record_path(results_dir, &spec.name), &json)?;
        write_whole(&out.join(format!("{}.toml", spec.name)), &fit::render(&outcome)?)?;
        errln!("fit {}: {} evaluations in {:.1} s", spec.name, outcome.evaluations, start.elapsed().as_secs_f64());
    }
    Ok(())
}

/// The fit outcomes stored in result folders (none where there are none), sorted by name.
fn read_fit_records(dirs: &[PathBuf]) -> Result<Vec<FitRecord>, Error> {
    let mut records = Vec::new();
    for d in dirs {
        for p in fit_record_paths(d) {
            records.push(read_fit_record(&p)?);
        }
    }
    records.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(records)
}

/// The fit records of a result folder (`<dir>/fits/*.json`; none without that folder), sorted.
fn fit_record_paths(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir.join(FITS_SUBDIR)) else { return Vec::new() };
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    paths.sort();
    paths
}

/// Where `run` stores the outcome of the fit `name` in the result folder `dir`.
fn fit_record_path(dir: &Path, name: &str) -> PathBuf {
    dir.join(FITS_SUBDIR).join(format!("{name}.json"))
}

/// One fit record, as `run` wrote it.
fn read_fit_record(path: &Path) -> Result<FitRecord, Error> {
    let text = crate::safety::read::read_text(path, crate::safety::read::SCENE_LIMIT_BYTES, "fit record")?;
    let record = serde_json::from_str(&text).map_err(|e| {
        InputError::new(
            path.display().to_string(),
            "not a fit record",
            format!("JSON written by `creepbench run` ({e})"),
        )
    })?;
    Ok(record)
}

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
    let refs = load_references(reference)?;
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
    let fits = read_fit_records(dirs)?;
    let (md, findings, _) = report_with_findings(
        &scenes,
        &refs,
        report_dir,
        (Some(golden), &rules),
        &fits,
        (extra, &suite_of(&scenes, &[])),
    )?;
    let verdict = Verdict::of(&findings);
    outln!("gates: {verdict}");
    outln!("report: {}", md.display());
    // The exit status is the verdict's, as `check`'s: a drift fails the CI job that merges.
    match verdict.failed {
        0 => Ok(()),
        count => Err(Error::Drift { count }),
    }
}

/// What the merged `scenes` owe their scene files in `suites` ([`owed::check`]): each
/// shortfall named on stderr and returned as a gated failure; the scenes of suites not given
/// named once.
fn owed_by_scenes(scenes: &[StoredScene], suites: &[PathBuf]) -> Result<Vec<Finding>, Error> {
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

/// The tolerance files of a run (`--tolerances`, then each suite's `tolerances.toml`), read and
/// checked against the comparison labels this project has.
pub fn file_rules(given: &[PathBuf], suite_dir: &[PathBuf]) -> Result<Vec<Rule>, Error> {
    let labels = tolerances::labels();
    let mut rules = Vec::new();
    for (path, suite) in tolerance_file::sources(given, suite_dir) {
        rules.extend(tolerance_file::load(&path, &labels)?.into_iter().map(|r| Rule { suite: suite.clone(), ..r }));
    }
    Ok(rules)
}

/// The files `check` reads and writes besides the suite (issue 15): tolerance rules in, the
/// verdict out.
#[derive(Debug, Clone, Default)]
pub struct GateFiles {
    /// Tolerance rule files (`--tolerances`), before each suite's `tolerances.toml`.
    pub tolerances: Vec<PathBuf>,
    /// JUnit XML.
    pub junit: Option<PathBuf>,
    /// Every finding as JSON.
    pub json: Option<PathBuf>,
    /// A Markdown summary; `$GITHUB_STEP_SUMMARY`, when set, gets it appended too.
    pub summary: Option<PathBuf>,
    /// Refuse every rule that loosens a comparison the defaults gate (CI).
    pub strict: bool,
    /// Print the full worst-point table and every drift (the console shows one screen otherwise).
    pub verbose: bool,
}

impl GateFiles {
    /// Every output file the user named, none of them inside golden/.
    fn check_paths(&self, golden: &Path) -> Result<(), Error> {
        for p in [&self.junit, &self.json, &self.summary].into_iter().flatten() {
            guard::guard_output_file(p, golden)?;
        }
        if let Some(step_summary) = step_summary() {
            guard::guard_output_file(&step_summary, golden)?;
        }
        Ok(())
    }

    /// Write each output whole (a temporary file in the same folder, renamed over the target).
    fn write(&self, all: &[Finding], loosened: &[Loosening]) -> Result<(), Error> {
        use crate::comparison::gate_output;
        let outputs = [
            (&self.junit, gate_output::junit as fn(&[Finding], &[Loosening]) -> String),
            (&self.json, gate_output::json),
            (&self.summary, gate_output::summary),
        ];
        for (path, make) in outputs {
            if let Some(path) = path {
                write_whole(path, &make(all, loosened))?;
            }
        }
        if let Some(path) = step_summary() {
            let io = |source| Error::Io { path: path.clone(), source };
            let mut f = std::fs::OpenOptions::new().append(true).create(true).open(&path).map_err(io)?;
            std::io::Write::write_all(&mut f, gate_output::summary(all, loosened).as_bytes()).map_err(io)?;
        }
        Ok(())
    }
}

/// `$GITHUB_STEP_SUMMARY`, when set.
fn step_summary() -> Option<PathBuf> {
    std::env::var_os("GITHUB_STEP_SUMMARY").filter(|v| !v.is_empty()).map(PathBuf::from)
}

/// Write `text` to `path` whole: a temporary file beside it, then one rename.
fn write_whole(path: &Path, text: &str) -> Result<(), Error> {
    crate::safety::whole::write(path, text.as_bytes()).map_err(Error::io(path))
}

/// The gate's findings over a suite (or one shard): every comparison with the references and
/// the baseline (golden/, or `against`), the baseline's missing scenes, the run's tolerance files
/// applied (what `check` prints and writes).
#[derive(Debug, Clone)]
pub struct Gate {
    pub findings: Vec<Finding>,
    /// The rules of the run's files that loosen a default gate.
    pub loosened: Vec<Loosening>,
    /// Each scene's suite.
    pub suite_of: BTreeMap<String, String>,
    /// The histories flagged as oscillating (one line each; all of them with `verbose`).
    pub oscillating: Vec<String>,
}

/// Run the suite and gate it ([`Gate`]); `check` prints the result.
pub fn gate(
    suite_dir: &[PathBuf],
    reference: &Path,
    golden: &Path,
    against: Option<&Path>,
    shard: Option<Shard>,
    progress: bool,
    files: &GateFiles,
) -> Result<Gate, Error> {
    gate_with(suite_dir, reference, (golden, against), Runner::cli(shard, progress), files)
}

/// [`gate`], `runner` also giving the models run in this process; `against` (a folder of
/// earlier results) replaces `golden` as the baseline when given.
pub fn gate_with(
    suite_dir: &[PathBuf],
    reference: &Path,
    (golden, against): (&Path, Option<&Path>),
    runner: Runner,
    files: &GateFiles,
) -> Result<Gate, Error> {
    let shard = runner.shard;
    files.check_paths(golden)?;
    let refs = load_references(reference)?;
    let rules = file_rules(&files.tolerances, suite_dir)?;
    if files.strict {
        // Refused before any scene runs; the verdict's own check below covers what this cannot.
        crate::comparison::strict::refuse_loosening(&rules, tolerances::defaults())?;
    }
    let (dir, key, what, kind) = match against {
        Some(dir) => {
            (dir, "--against", "a folder of results written by `creepbench run` (--results)", Against::Previous)
        }
        None => (golden, "--golden", "the golden folder (create it with `creepbench bless`)", Against::Golden),
    };
    if !dir.is_dir() {
        return Err(InputError::new(key, dir.display(), what).into());
    }
    let baseline = (dir, kind);
    let SuiteRun { scenes, wheelrail } = run_suite(suite_dir, runner, true)?;
    let mut all = compare::evaluate(&scenes, &refs, Some(baseline))?;
    all.extend(wheelrail_findings(&refs, &wheelrail));
    let suites = suite_names(suite_dir);
    let expected = |name: &str, suite: &str| shard.is_none_or(|s| s.takes(name)) && suites.iter().any(|x| x == suite);
    all.extend(compare::missing_scenes(dir, &scenes, kind, expected)?);
    // On a shard, a rule may be meant for scenes of other shards: it must cover some scene of the
    // suites; `merge` then checks it against every comparison.
    let other_shards: Vec<String> = match shard {
        Some(s) => suite::scene_names(suite_dir)?.into_iter().filter(|n| !s.takes(n)).collect(),
        None => Vec::new(),
    };
    let suite_of = suite_of(&scenes, &wheelrail);
    let loosened = tolerance_file::apply(&rules, &mut all, &suite_of, |r| {
        other_shards.iter().any(|n| tolerance_file::glob(&r.scene, n))
    })?;
    if files.strict {
        if let Some(l) = loosened.first() {
            return Err(InputError::new(&l.origin, l.to_string(), "no loosening of a default gate (--strict)").into());
        }
    }
    let oscillating = console::oscillating(&scenes, files.verbose);
    Ok(Gate { findings: all, loosened, suite_of, oscillating })
}

/// `creepbench check`: run the suite, compare with golden/ (or `against`) and the references;
/// print the verdict first, then one screen (console: per suite and model, scenes without data,
/// the worst drifts; everything with `verbose`); write the verdict files asked for; fail on gated
/// drift.
pub fn check(
    suite_dir: &[PathBuf],
    reference: &Path,
    golden: &Path,
    against: Option<&Path>,
    shard: Option<Shard>,
    progress: bool,
    files: &GateFiles,
) -> Result<(), Error> {
    let Gate { findings: all, loosened, suite_of, oscillating } =
        gate(suite_dir, reference, golden, against, shard, progress, files)?;
    let verdict = Verdict::of(&all);
    outln!("{verdict}\n");
    out!("{}", console::per_model(&all, &suite_of));
    if files.verbose {
        outln!();
        out!("{}", compare::table(&compare::worst_per_group(&all)));
    }
    print_list("", &console::no_baseline(&all, files.verbose));
    print_list("", &oscillating);
    if !loosened.is_empty() {
        outln!("\n{} rule(s) of the run's files loosen what the defaults gate:", loosened.len());
        for l in &loosened {
            outln!("  {l}");
        }
    }
    if against.is_some() {
        let (n, lines) = console::moved(&all, files.verbose);
        let head = format!(
            "{n} quantities moved against {} (worst first, |diff| / allowed):",
            against.unwrap_or(golden).display()
        );
        print_list(&head, &lines);
    }
    files.write(&all, &loosened)?;
    if verdict.failed == 0 {
        Ok(())
    } else {
        for line in console::drifts(&all, files.verbose) {
            errln!("{line}");
        }
        Err(Error::Drift { count: verdict.failed })
    }
}

/// A list on stdout after a blank line, under its heading (nothing for no heading and no lines).
fn print_list(head: &str, lines: &[String]) {
    if head.is_empty() && lines.is_empty() {
        return;
    }
    outln!();
    if !head.is_empty() {
        outln!("{head}");
    }
    for l in lines {
        outln!("  {l}");
    }
}

/// `creepbench bless`: write the suite's results as the new golden data (the only writer of
/// golden/). All or nothing: the new tree is built beside the old one — this run's scenes plus
/// the blessed scenes of other suites and shards — and swapped in with one atomic exchange.
pub fn bless(suite_dir: &[PathBuf], golden: &Path, shard: Option<Shard>, progress: bool) -> Result<(), Error> {
    let SuiteRun { scenes, .. } = run_suite(suite_dir, Runner::cli(shard, progress), false)?;
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

/// The folder names of the suites (a blessed scene records its suite's).
/// Each scene's suite (its folder's name), by scene name: the module-3 scenes' and the wheel–rail
/// scenes' (a suite's own tolerance rules cover its scenes only).
fn suite_of(scenes: &[StoredScene], wheelrail: &[(WheelRailScene, SceneRun)]) -> BTreeMap<String, String> {
    let module3 = scenes.iter().map(|s| (s.name.clone(), s.scene.suite.clone()));
    module3.chain(wheelrail.iter().map(|(s, _)| (s.name.clone(), suite::wheelrail::suite_of(s)))).collect()
}

fn suite_names(suite_dir: &[PathBuf]) -> Vec<String> {
    suite_dir.iter().filter_map(|d| d.file_name().map(|n| n.to_string_lossy().to_string())).collect()
}

/// `creepbench manifest DIR`: write DIR/MANIFEST.sha256 (reviewed with the data it lists).
pub fn manifest(dir: &Path) -> Result<(), Error> {
    // Blessed data are bless's alone.
    guard::guard_manifest_dir(dir)?;
    let n = crate::safety::manifest::write(dir).map_err(|source| Error::Manifest { dir: dir.to_path_buf(), source })?;
    errln!("{n} file(s) listed in {}", dir.join(crate::safety::manifest::MANIFEST).display());
    Ok(())
}

/// `creepbench export contact SCENE --out DIR`: the CONTACT module-3 input that computes the scene
/// (`DIR/<name>.inp`, written whole; never inside golden/); a study file: one per point; a
/// wheel–rail scene: its module-1 input.
pub fn export_contact(scene_path: &Path, out: &Path, golden: &Path) -> Result<Vec<PathBuf>, Error> {
    if let Some(scene) = crate::scene::wheelrail::read_if_wheelrail(scene_path)? {
        return export_contact_wheelrail(scene_path, &scene, out, golden);
    }
    // A scene file, or a study file: every point, all validated before anything is written.
    // CONTACT's own input check refuses what the deck would give it out of its ranges.
    let export_ready = |s: &suite::SceneSource| -> Result<_, Error> {
        let problem = pipeline::load_source(s, &[])?;
        crate::export::contact::check(&problem).map_err(|e| pipeline::in_source(s, e))?;
        Ok(problem)
    };
    let problems = suite::sources_of_file(scene_path)?.iter().map(export_ready).collect::<Result<Vec<_>, _>>()?;
    let paths: Vec<PathBuf> = problems.iter().map(|p| out.join(format!("{}.inp", p.name))).collect();
    guard::guard_output_dir(out, golden)?;
    for path in &paths {
        guard::guard_output_file(path, golden)?;
        if path.exists() {
            return Err(InputError::new(
                "--out",
                path.display(),
                "a folder without these input files (export replaces nothing)",
            )
            .into());
        }
    }
    std::fs::create_dir_all(out).map_err(Error::io(out))?;
    for (problem, path) in problems.iter().zip(&paths) {
        write_whole(path, &crate::export::contact::module3_input(problem))?;
    }
    Ok(paths)
}

/// `export contact` of a wheel–rail scene: CONTACT's module-1 input `DIR/<name>.inp`, one case per
/// row, its profiles named from DIR (written whole, replacing nothing; never inside golden/).
fn export_contact_wheelrail(
    scene_path: &Path,
    scene: &crate::scene::wheelrail::WheelRailScene,
    out: &Path,
    golden: &Path,
) -> Result<Vec<PathBuf>, Error> {
    use crate::export::wheelrail;
    let in_file = |mut e: InputError| {
        e.field = format!("{}: {}", scene_path.display(), e.field);
        e
    };
    wheelrail::check(scene).map_err(in_file)?;
    let text = wheelrail::module1_input(scene, out).map_err(in_file)?;
    let path = out.join(format!("{}.inp", scene.name));
    guard::guard_output_dir(out, golden)?;
    guard::guard_output_file(&path, golden)?;
    if path.exists() {
        let allowed = "a folder without this input file (export replaces nothing)";
        return Err(InputError::new("--out", path.display(), allowed).into());
    }
    std::fs::create_dir_all(out).map_err(Error::io(out))?;
    write_whole(&path, &text)?;
    Ok(vec![path])
}

/// `creepbench import contact DECK [--out DIR] [--supported-only] [--overwrite]`: CONTACT's
/// module-3 input as scenes, one per history, its module-1 input as wheel–rail scenes (profiles by
/// their path from DIR) (`DIR/<name>.toml` and its tables; DIR defaults to a folder named after
/// the deck). A deck with a case that is not supported is refused whole (exit
/// 2, every such case listed, nothing written) unless `supported_only`, which writes the supported
/// scenes and lists the cases skipped. Existing files are replaced only with `overwrite`.
pub fn import_contact(
    deck: &Path,
    out: Option<&Path>,
    options: ImportOptions,
    golden: &Path,
) -> Result<Vec<PathBuf>, Error> {
    let stem = deck
        .file_stem()
        .map(|s| PathBuf::from(s.to_string_lossy().to_string()))
        .unwrap_or_else(|| PathBuf::from("imported"));
    let out = out.map(Path::to_path_buf).unwrap_or(stem);
    let imported = crate::import::contact::import_into(deck, &out)?;
    let skipped: Vec<_> = imported.statuses.iter().filter(|s| !s.supported()).collect();
    for s in &skipped {
        errln!(
            "{} case {} (line {}): not supported: {}",
            if options.supported_only { "skipped" } else { "refused" },
            s.case,
            s.line,
            s.refused.join("; ")
        );
    }
    let total = imported.statuses.len();
    if !skipped.is_empty() && !options.supported_only {
        return Err(InputError::new(
            deck.display().to_string(),
            format!("{} of {total} case(s) not supported (listed above)", skipped.len()),
            "a deck whose every case is supported; --supported-only writes the supported scenes",
        )
        .into());
    }
    if imported.scenes.is_empty() {
        return Err(InputError::new(
            deck.display().to_string(),
            format!("none of {total} case(s) supported"),
            "at least one supported case",
        )
        .into());
    }
    guard::guard_output_dir(&out, golden)?;
    let files: Vec<(PathBuf, &String)> =
        imported.scenes.iter().flat_map(|s| s.files.iter().map(|(name, text)| (out.join(name), text))).collect();
    for (path, _) in &files {
        guard::guard_output_file(path, golden)?;
        if path.exists() && !options.overwrite {
            return Err(InputError::new(
                "--out",
                path.display(),
                "a folder without these files (--overwrite replaces them)",
            )
            .into());
        }
    }
    std::fs::create_dir_all(&out).map_err(Error::io(&out))?;
    for (path, text) in &files {
        write_whole(path, text)?;
    }
    Ok(imported.scenes.iter().map(|s| out.join(&s.files[0].0)).collect())
}

/// The choices of `import contact`.
#[derive(Debug, Clone, Copy, Default)]
pub struct ImportOptions {
    /// Write the supported scenes and list the skipped cases instead of refusing the deck.
    pub supported_only: bool,
    /// Replace existing files of the same names.
    pub overwrite: bool,
}

/// `creepbench import contact-output FILE [--out CSV] [--cases A-B]`: the totals CONTACT printed
/// for each module-3 case as a reference CSV (`comparison::references::contact_output::reference_csv`), written
/// whole to `out` (never inside golden/) or to standard output; a count of the cases on stderr.
pub fn import_contact_output(file: &Path, out: Option<&Path>, cases: Option<&str>, golden: &Path) -> Result<(), Error> {
    use crate::comparison::references::contact_output::{self, reference_csv, CaseBody};
    let range = cases.map(str::parse::<reference_csv::CaseRange>).transpose()?;
    if let Some(path) = out {
        guard::guard_output_file(path, golden)?;
    }
    let all = contact_output::read(file)?;
    let (csv, rows) = reference_csv::write(&all, range);
    let count = |f: fn(&CaseBody) -> bool| all.iter().filter(|c| f(&c.body)).count();
    let module1 = count(|b| matches!(b, CaseBody::Module1));
    if rows == 0 && range.is_none() {
        let source = Box::new(contact_output::ContactOutputError::NoTotals { cases: all.len(), module1 });
        return Err(Error::Import { path: file.to_path_buf(), source });
    }
    if rows == 0 {
        let allowed = "a range holding a module-3 case with printed totals (see the file's `Case n` lines)";
        return Err(InputError::new("--cases", cases.unwrap_or("(all)"), allowed).into());
    }
    match out {
        Some(path) => write_whole(path, &csv)?,
        None => crate::safety::stdout::write_data(csv.as_bytes()).map_err(Error::io("standard output"))?,
    }
    errln!(
        "{}: {} case(s): {rows} row(s) written; {module1} module-1 case(s) not read, {} without totals",
        file.display(),
        all.len(),
        count(|b| matches!(b, CaseBody::Nothing)),
    );
    Ok(())
}
