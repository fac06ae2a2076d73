//! The subcommands behind the CLI, one file per command (simulate, expand, fit, run, check,
//! bless, merge, manifest, CONTACT's import and export), and what several of them share: the
//! reference sets, how a suite runs (`suite_run`), the report of stored scenes (`reporting`).

use crate::calibration::fit::record::FitRecord;
use crate::calibration::fit::spec::FitSpec;
use crate::calibration::section as calibration;
use crate::comparison::compare::{self, Against, Finding};
use crate::comparison::console::{self, Verdict};
use crate::comparison::owed;
use crate::comparison::references::contact_output::wheelrail::WheelRailCase as PrintedCase;
use crate::comparison::references::wheelrail_cases::{self, WheelRailCases};
use crate::comparison::references::References;
use crate::comparison::tolerance_file::{self, Loosening, Rule};
use crate::comparison::tolerances;
use crate::error::{Error, InputError};
use crate::pipeline;
use crate::pipeline::wheelrail_scene::SceneRun;
use crate::report::section::Section;
use crate::report::table;
use crate::report::{self, ReportInput};
use crate::report::{contact_wheelrail, ladder, registry, sections};
use crate::safety::stdout::{errln, out, outln};
use crate::safety::{folder, guard, lock};
use crate::scene::wheelrail::WheelRailScene;
use crate::suite::results::{self, StoredScene};
use crate::suite::{self, Shard};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

mod bless;
mod check;
mod contact;
mod expand;
mod fit;
mod manifest;
mod merge;
mod reporting;
mod run;
mod simulate;
mod suite_run;

pub use bless::bless;
pub use check::{check, gate, Baseline, Gate, GateFiles};
pub use contact::{export_contact, import_contact, import_contact_output, ImportOptions};
pub use expand::expand;
pub use fit::fit;
pub use manifest::manifest;
pub use merge::merge;
pub use reporting::build_report;
pub use run::{run, run_with, RunOutcome, RunOutputs};
pub use simulate::{narrow, simulate, simulate_report};
// What the commands share, for their files (`use super::*`).
use fit::{fit_record_paths, load_fit_specs, read_fit_records, read_run_fits, run_fits, FITS_SUBDIR};
use reporting::{report_with_findings, Drawn, Judging};
use simulate::{read_printed, wheelrail_section};
use suite_run::{attach_wheelrail, run_suite, wheelrail_findings, SuiteFiles, SuiteRun};

/// The importer's verdict on every case of CONTACT's public decks, attached to the sets
/// `contact_public` and `contact_wheelrail` for the report's lists of them (the import stage sits
/// above comparison and report, so the survey is made here and passed down). Only a command that
/// writes a report asks for it, and only for the lists its report shows: it imports every deck.
fn survey_decks(refs: &mut References, lists: DeckLists) {
    use crate::comparison::references::contact_public::{CaseSurvey, PublicCases, Survey, AGAINST};
    let survey = |inp: &Path, modules: &[u8]| match crate::import::contact::survey(inp) {
        Ok(cases) => Survey::Cases(
            cases
                .into_iter()
                .filter(|c| modules.contains(&c.module))
                .map(|c| (c.case, CaseSurvey { module: c.module, refused: c.refused }))
                .collect(),
        ),
        Err(e) => Survey::Unread(e.to_string()),
    };
    if let (true, Some(public)) = (lists.public, refs.get_mut::<PublicCases>(AGAINST)) {
        public.attach_survey(|inp| survey(inp, &[1, 3]));
    }
    // The module-1 decks: their module-1 cases only.
    if let (true, Some(wr)) = (lists.wheelrail, refs.get_mut::<WheelRailCases>(wheelrail_cases::AGAINST)) {
        wr.attach_survey(|inp| survey(inp, &[1]));
    }
}

/// Which lists of CONTACT's decks a report shows: each only when the run holds a scene imported
/// from a deck of its kind (`report::contact_public::applies`, `report::contact_wheelrail::applies`);
/// the public list's module-1 rows read the wheel–rail survey, so that list needs both.
#[derive(Clone, Copy)]
struct DeckLists {
    public: bool,
    wheelrail: bool,
}

impl DeckLists {
    /// The lists of a report of `stored` module-3 scenes and `wheelrail` scenes.
    fn of(stored: &[StoredScene], wheelrail: &[(WheelRailScene, SceneRun)]) -> Self {
        let public = report::contact_public::applies(stored);
        DeckLists { public, wheelrail: public || wheelrail.iter().any(|(s, _)| s.origin.is_some()) }
    }
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

/// Write `text` to `path` whole: a temporary file beside it, then one rename.
/// The reference sets of the tree `dir`, a note on the console for each set it does not hold
/// (a tree of one's own references may hold only some: their comparisons are not made).
fn load_references(dir: &Path) -> Result<References, Error> {
    let refs = References::load(dir)?;
    for (folder, against) in refs.absent() {
        errln!("note: {} holds no {folder}: no comparisons with \"{}\"", dir.display(), against.label());
    }
    Ok(refs)
}

fn write_whole(path: &Path, text: &str) -> Result<(), Error> {
    crate::safety::whole::write(path, text.as_bytes()).map_err(Error::io(path))
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

/// Each scene's suite (its folder's name), by scene name: the module-3 scenes' and the wheel–rail
/// scenes' (a suite's own tolerance rules cover its scenes only).
fn suite_of(scenes: &[StoredScene], wheelrail: &[(WheelRailScene, SceneRun)]) -> BTreeMap<String, String> {
    let module3 = scenes.iter().map(|s| (s.name.clone(), s.scene.suite.clone()));
    module3.chain(wheelrail.iter().map(|(s, _)| (s.name.clone(), suite::wheelrail::suite_of(s)))).collect()
}

/// The folder names of the suites (a blessed scene records its suite's).
fn suite_names(suite_dir: &[PathBuf]) -> Vec<String> {
    suite_dir.iter().filter_map(|d| d.file_name().map(|n| n.to_string_lossy().to_string())).collect()
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

/// The folders a report writes beside validation.md.
const REPORT_SUBDIRS: [&str; 2] = ["figures", "tables"];

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
