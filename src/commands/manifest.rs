//! `creepbench manifest`: a folder's MANIFEST.sha256.

use super::*;

/// `creepbench manifest DIR`: write DIR/MANIFEST.sha256 (reviewed with the data it lists).
pub fn manifest(dir: &Path) -> Result<(), Error> {
    // Blessed data are bless's alone.
    guard::guard_manifest_dir(dir)?;
    let n = crate::safety::manifest::write(dir).map_err(|source| Error::Manifest { dir: dir.to_path_buf(), source })?;
    errln!("{n} file(s) listed in {}", dir.join(crate::safety::manifest::MANIFEST).display());
    Ok(())
}
