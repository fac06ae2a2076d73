//! Writing a folder of files atomically: into a temporary folder, renamed at the end, so that a
//! failure leaves no partial output.

use std::path::{Path, PathBuf};

/// Write `files` (name, contents) as the folder `dir/name`, atomically replacing an old one.
pub fn write_folder_atomically(dir: &Path, name: &str, files: &[(String, String)]) -> std::io::Result<PathBuf> {
    std::fs::create_dir_all(dir)?;
    let target = dir.join(name);
    let tmp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
    if tmp.exists() {
        std::fs::remove_dir_all(&tmp)?;
    }
    std::fs::create_dir_all(&tmp)?;
    let result = (|| {
        for (file, text) in files {
            std::fs::write(tmp.join(file), text)?;
        }
        if target.exists() {
            let old = dir.join(format!(".{name}.old-{}", std::process::id()));
            std::fs::rename(&target, &old)?;
            std::fs::rename(&tmp, &target)?;
            std::fs::remove_dir_all(&old)?;
        } else {
            std::fs::rename(&tmp, &target)?;
        }
        Ok(target.clone())
    })();
    if result.is_err() {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    result
}
