//! The report of stored scenes (`run`, `merge`): sections, calibration, the wheel–rail section.

use super::*;

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
    let judging = Judging { golden, rules, extra: missing, suites: &suite_of(scenes, &[]) };
    report_with_findings(scenes, refs, out, judging, Drawn { fits, wheelrail: None }).map(|(md, ..)| md)
}

/// How a report judges its scenes: against golden/ (when it exists), with the run's tolerance
/// rules, each scene's suite known (a suite's rules cover its own scenes), and the comparisons
/// made elsewhere (scenes missing or owed, the wheel–rail runs against CONTACT).
pub(super) struct Judging<'a> {
    pub(super) golden: Option<&'a Path>,
    pub(super) rules: &'a [Rule],
    pub(super) extra: Vec<Finding>,
    pub(super) suites: &'a BTreeMap<String, String>,
}

/// What a report draws besides its stored scenes: the fits' records and the section of the
/// run's wheel–rail scenes.
pub(super) struct Drawn<'a> {
    pub(super) fits: &'a [FitRecord],
    pub(super) wheelrail: Option<Section>,
}

/// [`build_report`], also returning the report's findings (the run's tolerance files applied)
/// and the rules that loosened a default gate.
pub(super) fn report_with_findings(
    scenes: &[StoredScene],
    refs: &References,
    out: &Path,
    judging: Judging,
    drawn: Drawn,
) -> Result<(PathBuf, Vec<Finding>, Vec<Loosening>), Error> {
    let Judging { golden, rules, extra: missing, suites } = judging;
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
    if let Some(c) = calibration::section(drawn.fits) {
        registry::insert_after(&mut all, ladder::ID, c);
    }
    // The run's wheel–rail scenes drawn right after the list of CONTACT's wheel–rail decks.
    if let Some(w) = drawn.wheelrail {
        let after = if all.iter().any(|s| s.id == contact_wheelrail::ID) { contact_wheelrail::ID } else { ladder::ID };
        registry::insert_after(&mut all, after, Section { id: report::wheelrail::ID, ..w });
    }
    let input = ReportInput { scenes, refs, findings: &findings, suites, sections: all };
    let report = report::build(&input);
    std::fs::create_dir_all(out).map_err(Error::io(out))?;
    report.write(out)?;
    table::write(out, &table::rows(scenes, &findings)).map_err(Error::io(out.join(table::FILE)))?;
    Ok((out.join("validation.md"), findings, loosened))
}
