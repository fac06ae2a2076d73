//! Checksum manifests of reference data: `MANIFEST.sha256` in `sha256sum` format (so that
//! `sha256sum -c MANIFEST.sha256` verifies it too) lists every file of the tree, so that a
//! changed, removed, renamed or added reference file fails until the manifest is updated in a
//! reviewed commit.

use super::read::{open_regular, read_text, FileKind, ReadError};
use sha2::{Digest, Sha256};
use std::collections::BTreeMap;
use std::io::{self, Read};
use std::path::{Path, PathBuf};

/// The manifest's file name, at the top of the tree it lists.
pub const MANIFEST: &str = "MANIFEST.sha256";
/// One line of about a hundred bytes a file: a mebibyte lists ten thousand files.
pub const MANIFEST_LIMIT_BYTES: u64 = 1 << 20;
/// Names listed at most per kind of mismatch in a message (the count says how many more).
const NAMES_SHOWN: usize = 10;

/// Why a tree does not match its manifest, or could not be listed.
#[derive(Debug, thiserror::Error)]
pub enum ManifestError {
    #[error("{} has no {MANIFEST}: its files cannot be verified (write one with `creepbench manifest` and commit it)", dir.display())]
    Missing { dir: PathBuf },
    #[error(transparent)]
    Read(#[from] ReadError),
    #[error("{} line {line}: {reason}", manifest.display())]
    Malformed { manifest: PathBuf, line: u64, reason: &'static str },
    #[error("{} cannot be listed in a manifest: {reason}", path.display())]
    Unlistable { path: PathBuf, reason: String },
    #[error("cannot list {}: {source}", path.display())]
    Io {
        path: PathBuf,
        #[source]
        source: io::Error,
    },
    #[error("{} does not match its {MANIFEST}:{}{}{} (a change that is meant needs the manifest updated in a reviewed commit)",
        dir.display(), names("changed", changed), names("missing", missing), names("not listed", extra))]
    Mismatch { dir: PathBuf, changed: Vec<String>, missing: Vec<String>, extra: Vec<String> },
}

fn names(label: &str, list: &[String]) -> String {
    if list.is_empty() {
        return String::new();
    }
    let shown: Vec<&str> = list.iter().take(NAMES_SHOWN).map(String::as_str).collect();
    let more = list.len().saturating_sub(NAMES_SHOWN);
    let more = if more > 0 { format!(" and {more} more") } else { String::new() };
    format!(" {label}: {}{more};", shown.join(", "))
}

/// Write `dir/MANIFEST.sha256` listing every other file of the tree; returns how many.
pub fn write(dir: &Path) -> Result<usize, ManifestError> {
    let files = hash_tree(dir)?;
    let text: String = files.iter().map(|(name, hash)| format!("{hash}  {name}\n")).collect();
    let path = dir.join(MANIFEST);
    // Written whole; its temporary file is removed on any error (a full disk leaves nothing).
    super::whole::write(&path, text.as_bytes()).map_err(|source| ManifestError::Io { path: path.clone(), source })?;
    Ok(files.len())
}

/// Check the tree `dir` against its manifest: every listed file present with its checksum, no
/// other file. Returns how many files were verified.
pub fn verify(dir: &Path) -> Result<usize, ManifestError> {
    let path = dir.join(MANIFEST);
    if std::fs::symlink_metadata(&path).is_err_and(|e| e.kind() == io::ErrorKind::NotFound) {
        return Err(ManifestError::Missing { dir: dir.into() });
    }
    let listed = parse(&read_text(&path, MANIFEST_LIMIT_BYTES, "manifest")?, &path)?;
    let found = hash_tree(dir)?;
    let (mut changed, mut missing) = (Vec::new(), Vec::new());
    for (name, hash) in &listed {
        match found.get(name) {
            None => missing.push(name.clone()),
            Some(h) if h != hash => changed.push(name.clone()),
            Some(_) => {}
        }
    }
    let extra: Vec<String> = found.keys().filter(|n| !listed.contains_key(*n)).cloned().collect();
    if changed.is_empty() && missing.is_empty() && extra.is_empty() {
        Ok(found.len())
    } else {
        Err(ManifestError::Mismatch { dir: dir.into(), changed, missing, extra })
    }
}

/// Manifest lines `HASH  NAME` (or `HASH *NAME`, sha256sum's binary mode), by name.
fn parse(text: &str, manifest: &Path) -> Result<BTreeMap<String, String>, ManifestError> {
    let mut listed = BTreeMap::new();
    for (n, line) in text.lines().enumerate() {
        let bad = |reason| ManifestError::Malformed { manifest: manifest.into(), line: n as u64 + 1, reason };
        let (hash, rest) =
            line.split_at_checked(64).ok_or_else(|| bad("expected a SHA-256 checksum and a file name"))?;
        if !hash.bytes().all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(&b)) {
            return Err(bad("the checksum is not 64 lower-case hexadecimal digits"));
        }
        let name = rest
            .strip_prefix("  ")
            .or_else(|| rest.strip_prefix(" *"))
            .ok_or_else(|| bad("expected two spaces between checksum and file name"))?;
        if !is_listable(name) {
            return Err(bad("the file name is not a relative path inside the folder"));
        }
        if listed.insert(name.to_string(), hash.to_string()).is_some() {
            return Err(bad("the file is listed twice"));
        }
    }
    Ok(listed)
}

/// A relative path with `/` separators, no empty, `.` or `..` part, nothing sha256sum escapes.
fn is_listable(name: &str) -> bool {
    !name.is_empty()
        && !name.contains(['\\', '\n', '\r', '\0'])
        && name.split('/').all(|part| !part.is_empty() && part != "." && part != "..")
}

/// SHA-256 of every file of the tree but the manifest, by relative path. Symbolic links and
/// special files are refused: the manifest vouches for the bytes of this tree only.
fn hash_tree(dir: &Path) -> Result<BTreeMap<String, String>, ManifestError> {
    let mut files = BTreeMap::new();
    let mut pending = vec![(dir.to_path_buf(), String::new())];
    while let Some((folder, prefix)) = pending.pop() {
        let io_err = |source| ManifestError::Io { path: folder.clone(), source };
        for entry in std::fs::read_dir(&folder).map_err(io_err)? {
            let entry = entry.map_err(io_err)?;
            let path = entry.path();
            let unlistable = |reason: String| ManifestError::Unlistable { path: path.clone(), reason };
            let name = entry.file_name().into_string().map_err(|_| unlistable("the name is not UTF-8".into()))?;
            let relative = format!("{prefix}{name}");
            if relative == MANIFEST {
                continue;
            }
            if !is_listable(&relative) {
                return Err(unlistable("the name holds a backslash or a line break".into()));
            }
            let meta = entry.metadata().map_err(io_err)?;
            if meta.is_dir() {
                pending.push((path, format!("{relative}/")));
            } else if meta.is_file() {
                files.insert(relative, sha256_hex(&path)?);
            } else {
                return Err(unlistable(format!("it is a {}", FileKind::of(&meta))));
            }
        }
    }
    Ok(files)
}

fn sha256_hex(path: &Path) -> Result<String, ManifestError> {
    let (mut file, _) = open_regular(path, "reference file")?;
    let mut hasher = Sha256::new();
    let mut buf = vec![0u8; 64 << 10];
    loop {
        let n = file.read(&mut buf).map_err(|source| ManifestError::Io { path: path.into(), source })?;
        if n == 0 {
            break;
        }
        hasher.update(&buf[..n]);
    }
    Ok(hasher.finalize().iter().map(|b| format!("{b:02x}")).collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs;

    fn tree() -> tempfile::TempDir {
        let tmp = tempfile::tempdir().unwrap();
        fs::create_dir_all(tmp.path().join("contact")).unwrap();
        fs::write(tmp.path().join("cases.csv"), "case,mu\nstep,0.4\n").unwrap();
        fs::write(tmp.path().join("contact/step.csv"), "t_s,fx\n0,0.1\n").unwrap();
        assert_eq!(write(tmp.path()).unwrap(), 2);
        tmp
    }

    fn mismatch(dir: &Path) -> (Vec<String>, Vec<String>, Vec<String>, String) {
        match verify(dir).unwrap_err() {
            e @ ManifestError::Mismatch { .. } => {
                let m = e.to_string();
                let ManifestError::Mismatch { changed, missing, extra, .. } = e else { unreachable!() };
                (changed, missing, extra, m)
            }
            e => panic!("{e}"),
        }
    }

    #[test]
    fn a_written_manifest_verifies_and_has_the_sha256sum_format() {
        let t = tree();
        assert_eq!(verify(t.path()).unwrap(), 2);
        let text = fs::read_to_string(t.path().join(MANIFEST)).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 2);
        assert!(lines[0].ends_with("  cases.csv") && lines[1].ends_with("  contact/step.csv"), "{text}");
        // sha256sum of "case,mu\nstep,0.4\n"
        assert!(lines[0].starts_with("6ed7a866630859"), "{text}");
    }

    #[test]
    fn a_changed_byte_fails_naming_the_file() {
        let t = tree();
        fs::write(t.path().join("contact/step.csv"), "t_s,fx\n0,0.2\n").unwrap();
        let (changed, missing, extra, m) = mismatch(t.path());
        assert_eq!((changed, missing, extra), (vec!["contact/step.csv".to_string()], vec![], vec![]));
        assert!(m.contains("changed: contact/step.csv"), "{m}");
    }

    #[test]
    fn a_removed_added_or_renamed_file_fails_naming_it() {
        let t = tree();
        fs::remove_file(t.path().join("cases.csv")).unwrap();
        let (_, missing, _, m) = mismatch(t.path());
        assert_eq!(missing, ["cases.csv"]);
        assert!(m.contains("missing: cases.csv"), "{m}");
        let t = tree();
        fs::write(t.path().join("contact/new.csv"), "x").unwrap();
        let (_, _, extra, m) = mismatch(t.path());
        assert_eq!(extra, ["contact/new.csv"]);
        assert!(m.contains("not listed: contact/new.csv"), "{m}");
        let t = tree();
        fs::rename(t.path().join("contact/step.csv"), t.path().join("contact/steps.csv")).unwrap();
        let (changed, missing, extra, _) = mismatch(t.path());
        assert!(changed.is_empty());
        assert_eq!((missing, extra), (vec!["contact/step.csv".to_string()], vec!["contact/steps.csv".to_string()]));
    }

    #[test]
    fn a_missing_or_malformed_manifest_fails() {
        let t = tree();
        fs::remove_file(t.path().join(MANIFEST)).unwrap();
        assert!(matches!(verify(t.path()), Err(ManifestError::Missing { .. })));
        for (bad, reason) in [
            ("xyz  cases.csv\n", "checksum and a file name"),
            (&format!("{}  ../etc/passwd\n", "0".repeat(64)), "relative path"),
            (&format!("{} cases.csv\n", "0".repeat(64)), "two spaces"),
            (&format!("{}  a\n{}  a\n", "0".repeat(64), "0".repeat(64)), "twice"),
            (&format!("{}  a\n", "G".repeat(64)), "hexadecimal"),
        ] {
            fs::write(t.path().join(MANIFEST), bad).unwrap();
            let e = verify(t.path()).unwrap_err();
            assert!(matches!(e, ManifestError::Malformed { .. }) && e.to_string().contains(reason), "{bad}: {e}");
        }
    }

    #[test]
    fn links_and_special_files_are_refused() {
        let t = tree();
        std::os::unix::fs::symlink("/etc/hostname", t.path().join("link.csv")).unwrap();
        let e = verify(t.path()).unwrap_err();
        assert!(matches!(e, ManifestError::Unlistable { .. }) && e.to_string().contains("link.csv"), "{e}");
    }
}
