//! `creepbench fit` and the fits `run` runs after its suites: fit files, their records.

use super::*;

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
    let refs = load_references(reference)?;
    let outcome = fit::fit(&spec, &refs)?;
    out!("{}", fit::record::FitRecord::of(&outcome).table());
    let text = fit::render(&outcome)?;
    if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(Error::io(dir))?;
    }
    write_whole(&out, &text)?;
    Ok(out)
}

/// Where a result folder keeps the fits' outcomes.
pub(super) const FITS_SUBDIR: &str = "fits";

/// Every fit file of `dir` (sorted), read and validated.
pub(super) fn load_fit_specs(dir: &Path) -> Result<Vec<FitSpec>, Error> {
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
pub(super) fn run_fits(
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
pub(super) fn read_fit_records(dirs: &[PathBuf]) -> Result<Vec<FitRecord>, Error> {
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
pub(super) fn fit_record_paths(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir.join(FITS_SUBDIR)) else { return Vec::new() };
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    paths.sort();
    paths
}

/// Where `run` stores the outcome of the fit `name` in the result folder `dir`.
pub(super) fn fit_record_path(dir: &Path, name: &str) -> PathBuf {
    dir.join(FITS_SUBDIR).join(format!("{name}.json"))
}

/// One fit record, as `run` wrote it.
pub(super) fn read_fit_record(path: &Path) -> Result<FitRecord, Error> {
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

/// The records of the fits `fitted` this run stored in `results_dir`, sorted by name.
pub(super) fn read_run_fits(results_dir: &Path, fitted: &[String]) -> Result<Vec<FitRecord>, Error> {
    let mut records = fitted
        .iter()
        .map(|name| read_fit_record(&fit_record_path(results_dir, name)))
        .collect::<Result<Vec<_>, _>>()?;
    records.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(records)
}
