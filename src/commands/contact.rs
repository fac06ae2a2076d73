//! `creepbench import contact`, `import contact-output` and `export contact`: CONTACT's decks
//! and printed output in and out.

use super::*;

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
pub(super) fn export_contact_wheelrail(
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
