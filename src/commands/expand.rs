//! `creepbench expand`: a study's scenes as scene files.

use super::*;

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
