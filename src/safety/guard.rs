//! Protected folders: no command but `bless` may write under golden/, whatever its flags say
//! (`--out golden`, `--results golden/x`, a symbolic link into it, `a/../golden`), and none
//! writes under reference data. Both are recognised by what they are as well as by the path
//! given: a blessed tree (a folder with the result marker holding scene folders) and a
//! checksummed tree (a folder with a `MANIFEST.sha256`), whatever the working folder (issue 30).
//! Outputs are regular files or new ones, never a FIFO, a device or a folder.

use std::io;
use std::path::{Component, Path, PathBuf};

/// A write that would land in a protected folder, or a path that could not be resolved.
#[derive(Debug, thiserror::Error)]
pub enum GuardError {
    #[error("refusing to write {}: it is inside {}, which only `creepbench bless` writes", path.display(), protected.display())]
    Inside { path: PathBuf, protected: PathBuf },
    #[error("refusing to write {}: it is inside {}, reference data checksummed in its {}", path.display(), protected.display(), super::manifest::MANIFEST)]
    Reference { path: PathBuf, protected: PathBuf },
    #[error("refusing to write {}: it is another name (a hard link) of {}, inside {}, which only `creepbench bless` writes", path.display(), file.display(), protected.display())]
    Alias { path: PathBuf, file: PathBuf, protected: PathBuf },
    #[error("refusing to write {}: it exists and is not a regular file (a folder, FIFO or device)", path.display())]
    NotAFile { path: PathBuf },
    #[error("refusing to write into {}: it exists and is not a folder", path.display())]
    NotAFolder { path: PathBuf },
    #[error("cannot resolve {}: {source}", path.display())]
    Io {
        path: PathBuf,
        #[source]
        source: io::Error,
    },
}

/// An error if `path` is `protected` or lies inside it, both resolved as far as they exist
/// (symbolic links followed, `.` and `..` applied), so that no spelling gets around the guard.
pub fn guard_not_under(path: &Path, protected: &Path) -> Result<(), GuardError> {
    let resolved = resolve(path)?;
    if resolved.starts_with(resolve(protected)?) {
        return Err(GuardError::Inside { path: path.into(), protected: protected.into() });
    }
    for dir in resolved.ancestors() {
        if is_blessed_tree(dir) {
            return Err(GuardError::Inside { path: path.into(), protected: dir.into() });
        }
        if dir.join(super::manifest::MANIFEST).is_file() {
            return Err(GuardError::Reference { path: path.into(), protected: dir.into() });
        }
    }
    Ok(())
}

/// A blessed tree by what it is: a folder creepbench replaces whole (its marker) holding scene
/// result folders (a `scene.json` each).
pub fn is_blessed_tree(dir: &Path) -> bool {
    dir.join(super::folder::MARKER).is_file()
        && std::fs::read_dir(dir).is_ok_and(|entries| {
            entries.flatten().any(|e| e.file_type().is_ok_and(|t| t.is_dir()) && e.path().join("scene.json").is_file())
        })
}

/// An output file: outside the protected trees — where its name leads, through a symbolic link
/// that names a file not yet there too — and a regular file or none yet (never a FIFO, a device
/// or a folder: writing one would block or fail after the work), nor another name (a hard link)
/// of a file in `protected`: a protected file is known by its device and inode, whatever its name.
pub fn guard_output_file(path: &Path, protected: &Path) -> Result<(), GuardError> {
    guard_not_under(path, protected)?;
    let target = super::link::write_target(path).map_err(|source| GuardError::Io { path: path.into(), source })?;
    guard_not_under(&target, protected)?;
    match std::fs::metadata(path) {
        Ok(m) if !m.is_file() => Err(GuardError::NotAFile { path: path.into() }),
        Ok(m) => guard_not_alias(path, &m, protected),
        Err(_) => Ok(()),
    }
}

/// Where a write through a symbolic link lands must not be inside a tree recognised as protected
/// by what it is (a blessed tree, a checksummed one): [`super::whole::write`] asks this of every
/// link it writes through, whoever its caller (a report's `validation.md` that is a link).
pub fn guard_link_target(target: &Path) -> Result<(), GuardError> {
    for dir in resolve(target)?.ancestors() {
        if is_blessed_tree(dir) {
            return Err(GuardError::Inside { path: target.into(), protected: dir.into() });
        }
        if dir.join(super::manifest::MANIFEST).is_file() {
            return Err(GuardError::Reference { path: target.into(), protected: dir.into() });
        }
    }
    Ok(())
}

/// An error if the existing file `path` (metadata `meta`) is a hard link of a file in `protected`.
fn guard_not_alias(path: &Path, meta: &std::fs::Metadata, protected: &Path) -> Result<(), GuardError> {
    use std::os::unix::fs::MetadataExt;
    if meta.nlink() < 2 {
        return Ok(());
    }
    match find_file(protected, (meta.dev(), meta.ino()), ALIAS_SEARCH_DEPTH) {
        Some(file) => Err(GuardError::Alias { path: path.into(), file, protected: protected.into() }),
        None => Ok(()),
    }
}

/// Folder levels of a protected tree searched for another name of an output file (golden/ has
/// two: scene folders and their files).
const ALIAS_SEARCH_DEPTH: usize = 4;

/// A regular file under `dir` (`depth` levels at most, links not followed) with this identity.
fn find_file(dir: &Path, (dev, ino): (u64, u64), depth: usize) -> Option<PathBuf> {
    use std::os::unix::fs::MetadataExt;
    if depth == 0 {
        return None;
    }
    for entry in std::fs::read_dir(dir).ok()?.flatten() {
        let Ok(m) = std::fs::symlink_metadata(entry.path()) else { continue };
        if m.is_file() && m.dev() == dev && m.ino() == ino {
            return Some(entry.path());
        }
        if m.is_dir() {
            if let Some(found) = find_file(&entry.path(), (dev, ino), depth - 1) {
                return Some(found);
            }
        }
    }
    None
}

/// An output folder: outside the protected trees, and a folder or none yet.
pub fn guard_output_dir(path: &Path, protected: &Path) -> Result<(), GuardError> {
    guard_not_under(path, protected)?;
    match std::fs::metadata(path) {
        Ok(m) if !m.is_dir() => Err(GuardError::NotAFolder { path: path.into() }),
        _ => Ok(()),
    }
}

/// A folder `creepbench manifest` may write into: no blessed tree, nor inside one.
pub fn guard_manifest_dir(dir: &Path) -> Result<(), GuardError> {
    match resolve(dir)?.ancestors().find(|d| is_blessed_tree(d)) {
        Some(tree) => Err(GuardError::Inside { path: dir.into(), protected: tree.into() }),
        None => Ok(()),
    }
}

/// Whether two paths name one folder once resolved (symbolic links, `..`).
pub fn same_place(a: &Path, b: &Path) -> Result<bool, GuardError> {
    Ok(resolve(a)? == resolve(b)?)
}

/// `path` made absolute: its longest existing ancestor canonicalised, the rest applied lexically.
pub fn resolve(path: &Path) -> Result<PathBuf, GuardError> {
    let io_err = |source| GuardError::Io { path: path.into(), source };
    let absolute = std::path::absolute(path).map_err(io_err)?;
    let mut existing = absolute.as_path();
    let mut rest = Vec::new();
    let mut resolved = loop {
        match existing.canonicalize() {
            Ok(p) => break p,
            Err(e) if e.kind() == io::ErrorKind::NotFound || e.kind() == io::ErrorKind::NotADirectory => {
                match (existing.parent(), existing.file_name()) {
                    (Some(parent), Some(name)) => {
                        rest.push(Component::Normal(name));
                        existing = parent;
                    }
                    // `..` as last component, or the root: apply lexically below.
                    _ => match existing.parent() {
                        Some(parent) => {
                            rest.push(Component::ParentDir);
                            existing = parent;
                        }
                        None => break existing.to_path_buf(),
                    },
                }
            }
            Err(e) => return Err(io_err(e)),
        }
    };
    for c in rest.into_iter().rev() {
        match c {
            Component::ParentDir => {
                resolved.pop();
            }
            Component::Normal(n) => resolved.push(n),
            _ => {}
        }
    }
    Ok(resolved)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_spelling_of_a_path_inside_is_refused() {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path();
        std::fs::create_dir_all(root.join("golden/step")).unwrap();
        std::fs::create_dir_all(root.join("out")).unwrap();
        std::os::unix::fs::symlink(root.join("golden"), root.join("out/link")).unwrap();
        let golden = root.join("golden");
        for inside in [
            root.join("golden"),
            root.join("golden/step"),
            root.join("golden/new/deeper"),
            root.join("out/../golden/x"),
            root.join("out/link"),
            root.join("out/link/new"),
            root.join("./golden/."),
            root.join("missing/../golden/x"),
        ] {
            let e = guard_not_under(&inside, &golden).unwrap_err();
            assert!(matches!(e, GuardError::Inside { .. }), "{}: {e}", inside.display());
        }
        for outside in [root.join("out"), root.join("golden2"), root.join("out/golden"), root.to_path_buf()] {
            guard_not_under(&outside, &golden).unwrap_or_else(|e| panic!("{}: {e}", outside.display()));
        }
    }

    #[test]
    fn a_relative_path_is_resolved_against_the_working_folder() {
        let here = std::env::current_dir().unwrap();
        assert!(guard_not_under(Path::new("golden/x"), &here.join("golden")).is_err());
        assert!(guard_not_under(Path::new("results"), &here.join("golden")).is_ok());
    }
}
