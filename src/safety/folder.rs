//! Result folders are replaced whole and atomically, and only when creepbench wrote them: the new
//! tree is built in a sibling folder and swapped in with one atomic exchange, so that after a
//! kill at any moment the target is the old tree or the new one, never a mix, and never a folder
//! of someone else's. Leftovers of a killed run are recognised by name and marker and removed by
//! the next. (Atomic against crashes of creepbench; durability against power loss is the
//! file system's.)

use super::excerpt::excerpt;
use super::interrupt::{self, Registration};
use std::borrow::Cow;
use std::ffi::OsStr;
use std::fs::{self, File, TryLockError};
use std::io::{self, BufWriter, Write};
use std::path::{Component, Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// The file that marks a folder as written by creepbench: only such folders are ever replaced.
pub const MARKER: &str = ".creepbench-result";
const MARKER_TEXT: &str =
    "creepbench wrote this folder and may replace it whole; it replaces no folder without this file.\n";
/// Sibling folders are named `.{name}.creepbench-{new|old}-{pid}-{n}`.
const TAG: &str = ".creepbench-";

/// Why a result folder was not written.
#[derive(Debug, thiserror::Error)]
pub enum FolderError {
    #[error("refusing to replace {}: a directory that creepbench did not write (no {MARKER} file in it)", path.display())]
    NotOurs { path: PathBuf },
    #[error("refusing to replace {}: it exists and is not a directory", path.display())]
    NotADirectory { path: PathBuf },
    #[error("{} is not a plain file or folder name (in {})", excerpt(name), parent.display())]
    BadName { parent: PathBuf, name: String },
    #[error("{action} {}: {source}", path.display())]
    Io {
        action: &'static str,
        path: PathBuf,
        #[source]
        source: io::Error,
    },
}

fn io_error(action: &'static str, path: &Path) -> impl FnOnce(io::Error) -> FolderError {
    let path = path.to_path_buf();
    move |source| FolderError::Io { action, path, source }
}

/// A file's contents: its bytes, or a function that writes them into the (buffered) file as it
/// produces them, so that a large file (a long history, its scene.json) is never held whole.
pub enum Contents<'a> {
    Bytes(Cow<'a, [u8]>),
    Written(Box<WriteFn<'a>>),
}

/// What writes a file's contents into it.
pub type WriteFn<'a> = dyn FnOnce(&mut dyn Write) -> io::Result<()> + 'a;

impl<'a> Contents<'a> {
    /// Contents written by `write` into the file.
    pub fn written(write: impl FnOnce(&mut dyn Write) -> io::Result<()> + 'a) -> Contents<'a> {
        Contents::Written(Box::new(write))
    }

    /// The whole contents in memory.
    pub fn into_bytes(self) -> Vec<u8> {
        match self {
            Contents::Bytes(b) => b.into_owned(),
            written => {
                let mut out = Vec::new();
                written.write_into(&mut out).expect("writing into memory does not fail");
                out
            }
        }
    }

    fn write_into(self, out: &mut dyn Write) -> io::Result<()> {
        match self {
            Contents::Bytes(b) => out.write_all(&b),
            Contents::Written(write) => write(out),
        }
    }
}

impl<'a> From<&'a str> for Contents<'a> {
    fn from(s: &'a str) -> Self {
        Contents::Bytes(Cow::Borrowed(s.as_bytes()))
    }
}

impl From<String> for Contents<'_> {
    fn from(s: String) -> Self {
        Contents::Bytes(Cow::Owned(s.into_bytes()))
    }
}

impl From<Vec<u8>> for Contents<'_> {
    fn from(b: Vec<u8>) -> Self {
        Contents::Bytes(Cow::Owned(b))
    }
}

/// Write `files` (plain file name, contents) as the folder `parent/name`, replacing an earlier
/// result folder of that name atomically. Refused: a `name` or file name that is not a plain,
/// visible name; an existing directory without the marker; anything else that is not a directory.
/// Leftovers of killed runs for `name` are removed first, which lists `parent`.
pub fn write_result_folder<'a, N: AsRef<str>, C: Into<Contents<'a>>>(
    parent: &Path,
    name: &str,
    files: impl IntoIterator<Item = (N, C)>,
) -> Result<PathBuf, FolderError> {
    write_folder(parent, name, files, Leftovers::Clean)
}

/// [`write_result_folder`] for a writer that holds `parent`'s lock ([`super::lock::lock_folder`],
/// whose taking removed every leftover of killed runs in it) or is building `parent` itself (a
/// staging tree): no leftover can be there, so `parent` is not listed. The time of a write then
/// does not grow with the folder's size (a listing per write made N folders written into a
/// folder of M cost N·M).
pub fn write_result_folder_cleaned<'a, N: AsRef<str>, C: Into<Contents<'a>>>(
    parent: &Path,
    name: &str,
    files: impl IntoIterator<Item = (N, C)>,
) -> Result<PathBuf, FolderError> {
    write_folder(parent, name, files, Leftovers::Cleaned)
}

/// Whether the leftovers of killed runs beside a target are still to be removed.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Leftovers {
    /// Remove them first (lists the parent folder).
    Clean,
    /// The caller's lock removed them (or the parent is its own staging tree).
    Cleaned,
}

fn write_folder<'a, N: AsRef<str>, C: Into<Contents<'a>>>(
    parent: &Path,
    name: &str,
    files: impl IntoIterator<Item = (N, C)>,
    leftovers: Leftovers,
) -> Result<PathBuf, FolderError> {
    check_plain_name(parent, name)?;
    let target = parent.join(name);
    replace_tree(&target, leftovers, |dir| {
        for (file, contents) in files {
            check_plain_name(&target, file.as_ref())?;
            let path = dir.join(file.as_ref());
            let file =
                fs::OpenOptions::new().write(true).create_new(true).open(&path).map_err(io_error("creating", &path))?;
            let mut out = BufWriter::with_capacity(WRITE_BUFFER_BYTES, file);
            contents.into().write_into(&mut out).and_then(|()| out.flush()).map_err(io_error("writing", &path))?;
        }
        Ok::<_, FolderError>(())
    })?;
    Ok(target)
}

/// The buffer between a file's writer and the file.
const WRITE_BUFFER_BYTES: usize = 1 << 16;

/// Build a complete new tree with `build` (given the empty folder, marker already in it) beside
/// `target`, then swap it into place with one atomic exchange and remove the old tree. An
/// existing `target` must be a directory holding the marker. Leftovers of earlier killed runs
/// are cleaned up first; if `build` fails or panics, its folder is removed.
pub fn replace_tree_atomically<T, E: From<FolderError>>(
    target: &Path,
    build: impl FnOnce(&Path) -> Result<T, E>,
) -> Result<T, E> {
    replace_tree(target, Leftovers::Clean, build)
}

fn replace_tree<T, E: From<FolderError>>(
    target: &Path,
    leftovers: Leftovers,
    build: impl FnOnce(&Path) -> Result<T, E>,
) -> Result<T, E> {
    let (parent, name) = split(target)?;
    fs::create_dir_all(parent).map_err(io_error("creating", parent))?;
    if leftovers == Leftovers::Clean {
        clean_stale(parent, name, target);
    }
    check_replaceable(target, target)?;
    let mut staging = Staging::create(parent, name)?;
    let value = build(&staging.path)?;
    staging.install(parent, name, target)?;
    Ok(value)
}

/// An error if [`replace_tree_atomically`] would refuse `target` (it exists and is not a folder
/// this tool wrote): asked before any work, so a refusal comes before anything is written.
pub fn check_tree_replaceable(target: &Path) -> Result<(), FolderError> {
    check_replaceable(target, target).map(|_| ())
}

/// A plain, visible name: one path component, no leading dot (those are creepbench's siblings).
fn check_plain_name(parent: &Path, name: &str) -> Result<(), FolderError> {
    let mut components = Path::new(name).components();
    let plain = matches!(components.next(), Some(Component::Normal(_)))
        && components.next().is_none()
        && !name.starts_with('.')
        && !name.contains(['/', '\\', '\0'])
        && name.len() <= 200;
    if plain {
        Ok(())
    } else {
        Err(FolderError::BadName { parent: parent.into(), name: name.into() })
    }
}

fn split(target: &Path) -> Result<(&Path, &str), FolderError> {
    let bad = || FolderError::BadName { parent: target.into(), name: target.display().to_string() };
    let name = match target.components().next_back() {
        Some(Component::Normal(n)) => n.to_str().ok_or_else(bad)?,
        _ => return Err(bad()),
    };
    let parent = target.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    Ok((parent, name))
}

/// `found` (the thing at `target`, or what was swapped out of it) may be replaced: absent, or a
/// directory with the marker. Returns whether it exists.
fn check_replaceable(found: &Path, target: &Path) -> Result<bool, FolderError> {
    use std::os::unix::fs::MetadataExt;
    // Another writer may swap the folder between the looks at it and at its marker: a folder
    // that changed identity meanwhile is looked at again.
    for _ in 0..SWAP_RETRIES {
        let m = match fs::symlink_metadata(found) {
            Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(false),
            Err(e) => return Err(io_error("inspecting", target)(e)),
            Ok(m) if !m.is_dir() => return Err(FolderError::NotADirectory { path: target.into() }),
            Ok(m) => m,
        };
        match fs::symlink_metadata(found.join(MARKER)) {
            Ok(marker) if marker.is_file() => return Ok(true),
            // An empty directory holds nothing to lose (e.g. a golden/ made for a first bless).
            _ if fs::read_dir(found).is_ok_and(|mut d| d.next().is_none()) => return Ok(true),
            _ => {}
        }
        let same = fs::symlink_metadata(found).is_ok_and(|now| (now.dev(), now.ino()) == (m.dev(), m.ino()));
        if same {
            return Err(FolderError::NotOurs { path: target.into() });
        }
    }
    Err(FolderError::NotOurs { path: target.into() })
}

/// How often a folder swapped by another writer while being inspected is looked at again.
const SWAP_RETRIES: usize = 100;

#[derive(Debug, Clone, Copy, PartialEq)]
enum Sibling {
    New,
    Old,
}

fn sibling_path(parent: &Path, name: &str, kind: Sibling) -> PathBuf {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let kind = if kind == Sibling::New { "new" } else { "old" };
    parent.join(format!(".{name}{TAG}{kind}-{}-{n}", std::process::id()))
}

/// A folder of this tool's name pattern `.{name}.creepbench-{new|old}-{pid}-{n}`: the target
/// `name` it was built for, its kind and the process that made it.
#[derive(Debug, Clone, PartialEq)]
struct Leftover {
    name: String,
    kind: Sibling,
    pid: u32,
}

/// The leftover a file name describes, `None` for anything else.
fn parse_leftover(file_name: &OsStr) -> Option<Leftover> {
    let rest = file_name.to_str()?.strip_prefix('.')?;
    let (name, rest) = rest.rsplit_once(TAG)?;
    let (kind, rest) = rest.split_once('-')?;
    let (pid, n) = rest.split_once('-')?;
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    if name.is_empty() || !digits(pid) || !digits(n) {
        return None;
    }
    let kind = match kind {
        "new" => Sibling::New,
        "old" => Sibling::Old,
        _ => return None,
    };
    Some(Leftover { name: name.into(), kind, pid: pid.parse().ok()? })
}

/// The kind of a sibling of `name` from its file name, `None` for anything else.
#[cfg(test)]
fn parse_sibling(file_name: &OsStr, name: &str) -> Option<Sibling> {
    parse_leftover(file_name).filter(|l| l.name == name).map(|l| l.kind)
}

/// Whether the process `pid` that made a leftover no longer runs (this process always runs; a
/// process of another user that cannot be signalled runs too).
fn owner_gone(pid: u32) -> bool {
    if pid == std::process::id() {
        return false;
    }
    let Some(pid) = i32::try_from(pid).ok().and_then(rustix::process::Pid::from_raw) else { return false };
    rustix::process::test_kill_process(pid) == Err(rustix::io::Errno::SRCH)
}

/// Open `dir`'s marker (creating it when `create`) and lock it exclusively without waiting: a
/// locked marker is a tree some live run is working on. `NotFound` when it is gone (or was
/// unlinked by a cleaner before the lock was taken), `WouldBlock` when someone else holds it.
fn lock_marker(dir: &Path, create: bool) -> io::Result<File> {
    let path = dir.join(MARKER);
    let mut file = fs::OpenOptions::new().read(true).write(create).create(create).open(&path)?;
    match file.try_lock() {
        Ok(()) => {}
        Err(TryLockError::WouldBlock) => return Err(io::ErrorKind::WouldBlock.into()),
        Err(TryLockError::Error(e)) => return Err(e),
    }
    let meta = file.metadata()?;
    if std::os::unix::fs::MetadataExt::nlink(&meta) == 0 {
        return Err(io::ErrorKind::NotFound.into());
    }
    if create && meta.len() == 0 {
        file.write_all(MARKER_TEXT.as_bytes())?;
    }
    Ok(file)
}

/// Remove the leftovers of killed runs for `target` (see [`clean_leftover`]).
fn clean_stale(parent: &Path, name: &str, target: &Path) {
    let Ok(entries) = fs::read_dir(parent) else { return };
    for entry in entries.flatten() {
        match parse_leftover(&entry.file_name()) {
            Some(l) if l.name == name => clean_leftover(&entry, &l, target),
            _ => {}
        }
    }
}

/// Remove every leftover of killed runs in `dir`, whatever target it was built for (see
/// [`clean_leftover`]): what the run that takes `dir`'s lock does first, so that a leftover of a
/// target never written again (an interrupted `bless`, a scene since renamed) goes too.
pub fn clean_leftovers(dir: &Path) {
    let Ok(entries) = fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        if let Some(l) = parse_leftover(&entry.file_name()) {
            clean_leftover(&entry, &l, &dir.join(&l.name));
        }
    }
}

/// Remove one leftover folder of a killed run: one whose marker nobody holds; an empty one
/// (killed before its marker); one whose marker is gone (an interrupted cleanup removed it
/// first) once the process that made it no longer runs. When `target` is missing because a run
/// was killed between the two renames of the fallback, its old tree is put back instead. A
/// folder a live run holds is left alone.
fn clean_leftover(entry: &fs::DirEntry, leftover: &Leftover, target: &Path) {
    if !entry.file_type().is_ok_and(|t| t.is_dir()) {
        return;
    }
    let path = entry.path();
    match lock_marker(&path, false) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            if fs::remove_dir(&path).is_err() && owner_gone(leftover.pid) {
                let _ = fs::remove_dir_all(&path);
            }
        }
        Err(_) => {}
        Ok(_marker) => {
            if leftover.kind == Sibling::Old && rename_noreplace(&path, target).is_ok() {
                return;
            }
            let _ = fs::remove_dir_all(&path);
        }
    }
}

/// How an exchange went.
enum Swap {
    Done,
    NoTarget,
    Unsupported,
}

fn exchange(a: &Path, b: &Path) -> io::Result<Swap> {
    #[cfg(any(target_os = "linux", target_os = "android", target_vendor = "apple"))]
    {
        use rustix::fs::{renameat_with, RenameFlags, CWD};
        match renameat_with(CWD, a, CWD, b, RenameFlags::EXCHANGE) {
            Ok(()) => Ok(Swap::Done),
            Err(rustix::io::Errno::NOENT) => Ok(Swap::NoTarget),
            Err(rustix::io::Errno::INVAL | rustix::io::Errno::NOSYS | rustix::io::Errno::NOTSUP) => {
                Ok(Swap::Unsupported)
            }
            Err(e) => Err(e.into()),
        }
    }
    #[cfg(not(any(target_os = "linux", target_os = "android", target_vendor = "apple")))]
    {
        let _ = (a, b);
        Ok(Swap::Unsupported)
    }
}

/// Rename `from` to `to` unless `to` exists (`AlreadyExists` then).
fn rename_noreplace(from: &Path, to: &Path) -> io::Result<()> {
    #[cfg(any(target_os = "linux", target_os = "android", target_vendor = "apple"))]
    {
        use rustix::fs::{renameat_with, RenameFlags, CWD};
        match renameat_with(CWD, from, CWD, to, RenameFlags::NOREPLACE) {
            Ok(()) => return Ok(()),
            Err(rustix::io::Errno::EXIST) => return Err(io::ErrorKind::AlreadyExists.into()),
            Err(rustix::io::Errno::INVAL | rustix::io::Errno::NOSYS | rustix::io::Errno::NOTSUP) => {}
            Err(e) => return Err(e.into()),
        }
    }
    if fs::symlink_metadata(to).is_ok() {
        return Err(io::ErrorKind::AlreadyExists.into());
    }
    fs::rename(from, to)
}

/// The folder a new tree is built in, with its marker locked; dropped, it is removed (after an
/// exchange it holds the old tree).
struct Staging {
    path: PathBuf,
    /// The built tree's marker, locked while this run works on it.
    marker: File,
    _registration: Registration,
    /// Whether `path` now holds the old tree (or nothing) rather than the one built.
    installed: bool,
}

impl Staging {
    fn create(parent: &Path, name: &str) -> Result<Staging, FolderError> {
        let mut last = None;
        for _ in 0..100 {
            let path = sibling_path(parent, name, Sibling::New);
            match fs::create_dir(&path) {
                Ok(()) => {}
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
                Err(e) => return Err(io_error("creating", &path)(e)),
            }
            let registration = interrupt::register_folder(path.clone());
            match lock_marker(&path, true) {
                Ok(marker) => return Ok(Staging { path, marker, _registration: registration, installed: false }),
                // A concurrent cleanup took the folder before its marker was locked: another name.
                Err(e) if matches!(e.kind(), io::ErrorKind::NotFound | io::ErrorKind::WouldBlock) => last = Some(e),
                // A full disk: the empty folder just made is not left behind.
                Err(e) => {
                    let _ = fs::remove_dir_all(&path);
                    return Err(io_error("creating the marker in", &path)(e));
                }
            }
        }
        Err(io_error("creating a folder beside", &parent.join(name))(
            last.unwrap_or(io::ErrorKind::AlreadyExists.into()),
        ))
    }

    /// Swap the built tree into `target`. What is swapped out must be replaceable, else it is
    /// swapped back. The interrupt handler waits meanwhile: it never removes a tree mid-swap.
    fn install(&mut self, parent: &Path, name: &str, target: &Path) -> Result<(), FolderError> {
        for _ in 0..10 {
            let _held = interrupt::hold();
            match exchange(&self.path, target).map_err(io_error("replacing", target))? {
                Swap::Done => {
                    if let Err(e) = check_replaceable(&self.path, target) {
                        exchange(&self.path, target).map_err(io_error("restoring", target))?;
                        return Err(e);
                    }
                    self.installed = true;
                    return Ok(());
                }
                Swap::NoTarget => match rename_noreplace(&self.path, target) {
                    Ok(()) => {
                        self.installed = true;
                        return Ok(());
                    }
                    Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
                    Err(e) => return Err(io_error("replacing", target)(e)),
                },
                Swap::Unsupported => return self.install_by_renames(parent, name, target),
            }
        }
        Err(io_error("replacing", target)(io::ErrorKind::AlreadyExists.into()))
    }

    /// Without an atomic exchange: old tree aside, new tree in. A kill in between leaves no
    /// target and the old tree beside it, which the next run puts back.
    fn install_by_renames(&mut self, parent: &Path, name: &str, target: &Path) -> Result<(), FolderError> {
        let old = sibling_path(parent, name, Sibling::Old);
        match fs::rename(target, &old) {
            Ok(()) => {}
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                rename_noreplace(&self.path, target).map_err(io_error("replacing", target))?;
                self.installed = true;
                return Ok(());
            }
            Err(e) => return Err(io_error("replacing", target)(e)),
        }
        if let Err(e) = check_replaceable(&old, target) {
            fs::rename(&old, target).map_err(io_error("restoring", target))?;
            return Err(e);
        }
        if let Err(e) = fs::rename(&self.path, target) {
            fs::rename(&old, target).map_err(io_error("restoring", target))?;
            return Err(io_error("replacing", target)(e));
        }
        self.installed = true;
        // The old tree takes the staging name, which is removed on drop (and on interruption).
        // Should that fail, the old tree stays a sibling that the next run removes.
        let _ = fs::rename(&old, &self.path);
        Ok(())
    }
}

impl Drop for Staging {
    fn drop(&mut self) {
        // An old tree swapped out may still be locked by a concurrent run that built it (it
        // removes its own old tree first): wait for it rather than leave the tree behind.
        if self.installed {
            if let Ok(old) = File::open(self.path.join(MARKER)) {
                if !same_file(&old, &self.marker) {
                    let _ = old.lock();
                }
            }
        }
        let _ = fs::remove_dir_all(&self.path);
    }
}

/// Whether two open files are the same file (a second lock on one's own marker would wait forever).
fn same_file(a: &File, b: &File) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (a.metadata(), b.metadata()) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn listing(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> =
            fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
        v.sort();
        v
    }

    #[test]
    fn a_new_folder_is_written_with_its_marker() {
        let tmp = tempfile::tempdir().unwrap();
        let out = write_result_folder(tmp.path(), "scene", [("a.csv", "1\n"), ("b.csv", "2\n")]).unwrap();
        assert_eq!(listing(&out), [MARKER, "a.csv", "b.csv"]);
        assert_eq!(listing(tmp.path()), ["scene"]);
    }

    #[test]
    fn written_contents_land_as_bytes_would() {
        let tmp = tempfile::tempdir().unwrap();
        let files: Vec<(&str, Contents)> = vec![
            ("a.csv", "1\n".into()),
            ("b.csv", Contents::written(|w| w.write_all(b"2\n").and_then(|()| w.write_all(b"3\n")))),
        ];
        let out = write_result_folder(tmp.path(), "scene", files).unwrap();
        assert_eq!(fs::read_to_string(out.join("b.csv")).unwrap(), "2\n3\n");
        assert_eq!(Contents::written(|w| w.write_all(b"x")).into_bytes(), b"x");
    }

    #[test]
    fn a_writer_under_the_lock_does_not_list_the_folder_for_leftovers() {
        let tmp = tempfile::tempdir().unwrap();
        let dead = tmp.path().join(".scene.creepbench-new-999999-1");
        fs::create_dir(&dead).unwrap();
        fs::write(dead.join(MARKER), MARKER_TEXT).unwrap();
        write_result_folder_cleaned(tmp.path(), "scene", [("a.csv", "1")]).unwrap();
        assert_eq!(listing(tmp.path()), [".scene.creepbench-new-999999-1", "scene"]);
        write_result_folder(tmp.path(), "scene", [("a.csv", "1")]).unwrap();
        assert_eq!(listing(tmp.path()), ["scene"]);
    }

    #[test]
    fn a_result_folder_is_replaced_whole() {
        let tmp = tempfile::tempdir().unwrap();
        write_result_folder(tmp.path(), "scene", [("a.csv", "1\n"), ("b.csv", "2\n")]).unwrap();
        let out = write_result_folder(tmp.path(), "scene", [("c.csv", "3\n")]).unwrap();
        assert_eq!(listing(&out), [MARKER, "c.csv"]);
        assert_eq!(listing(tmp.path()), ["scene"]);
    }

    #[test]
    fn a_foreign_directory_or_file_is_never_replaced() {
        let tmp = tempfile::tempdir().unwrap();
        fs::create_dir(tmp.path().join("golden")).unwrap();
        fs::write(tmp.path().join("golden/keep.csv"), "x").unwrap();
        let e = write_result_folder(tmp.path(), "golden", [("a.csv", "1")]).unwrap_err();
        assert!(matches!(e, FolderError::NotOurs { .. }) && e.to_string().contains("golden"), "{e}");
        fs::write(tmp.path().join("notes"), "x").unwrap();
        let e = write_result_folder(tmp.path(), "notes", [("a.csv", "1")]).unwrap_err();
        assert!(matches!(e, FolderError::NotADirectory { .. }), "{e}");
        assert_eq!(listing(tmp.path()), ["golden", "notes"]);
        assert_eq!(listing(&tmp.path().join("golden")), ["keep.csv"]);
    }

    #[test]
    fn names_that_are_not_plain_are_refused() {
        let tmp = tempfile::tempdir().unwrap();
        for bad in ["", ".", "..", "../x", "a/b", ".hidden", "/abs"] {
            let e = write_result_folder(tmp.path(), bad, [("a.csv", "1")]).unwrap_err();
            assert!(matches!(e, FolderError::BadName { .. }), "{bad}: {e}");
        }
        for bad in ["../escape.csv", MARKER, "x/y.csv"] {
            let e = write_result_folder(tmp.path(), "s", [(bad, "1")]).unwrap_err();
            assert!(matches!(e, FolderError::BadName { .. }), "{bad}: {e}");
        }
        let e = write_result_folder(tmp.path(), "s", [("a.csv", "1"), ("a.csv", "2")]).unwrap_err();
        assert!(matches!(e, FolderError::Io { .. }), "{e}");
        assert!(listing(tmp.path()).is_empty(), "{:?}", listing(tmp.path()));
    }

    #[test]
    fn a_failed_or_panicking_build_leaves_the_old_tree_and_nothing_else() {
        let tmp = tempfile::tempdir().unwrap();
        let target = tmp.path().join("golden");
        write_result_folder(tmp.path(), "golden", [("a.csv", "1")]).unwrap();
        let r: Result<(), FolderError> = replace_tree_atomically(&target, |dir| {
            fs::write(dir.join("half.csv"), "x").unwrap();
            Err(FolderError::NotOurs { path: dir.into() })
        });
        assert!(r.is_err());
        let p = std::panic::catch_unwind(|| {
            let _: Result<(), FolderError> = replace_tree_atomically(&target, |_| panic!("build panics"));
        });
        assert!(p.is_err());
        assert_eq!(listing(tmp.path()), ["golden"]);
        assert_eq!(listing(&target), [MARKER, "a.csv"]);
    }

    #[test]
    fn stale_siblings_are_recognised_by_name_only() {
        assert!(parse_sibling(OsStr::new(".golden.creepbench-new-12-0"), "golden") == Some(Sibling::New));
        assert!(parse_sibling(OsStr::new(".golden.creepbench-old-12-3"), "golden") == Some(Sibling::Old));
        for other in [
            ".golden.creepbench-new-12-0x",
            ".golden.creepbench-new-12",
            ".golden.creepbench-tmp-1-2",
            "golden.creepbench-new-1-2",
            ".golden.creepbench-new-1-2.creepbench-new-3-4",
            ".goldenx.creepbench-new-1-2",
        ] {
            assert!(parse_sibling(OsStr::new(other), "golden").is_none(), "{other}");
        }
    }

    #[test]
    fn leftovers_are_cleaned_and_a_lost_target_is_put_back() {
        let tmp = tempfile::tempdir().unwrap();
        let target = tmp.path().join("golden");
        // A killed build (marker, unlocked), an empty folder killed before its marker, and the
        // old tree of a run killed between the two renames of the fallback.
        let dead_new = tmp.path().join(".golden.creepbench-new-999999-1");
        fs::create_dir(&dead_new).unwrap();
        fs::write(dead_new.join(MARKER), MARKER_TEXT).unwrap();
        fs::write(dead_new.join("half.csv"), "x").unwrap();
        fs::create_dir(tmp.path().join(".golden.creepbench-new-999999-2")).unwrap();
        let old = tmp.path().join(".golden.creepbench-old-999999-3");
        fs::create_dir(&old).unwrap();
        fs::write(old.join(MARKER), MARKER_TEXT).unwrap();
        fs::write(old.join("a.csv"), "old").unwrap();
        // A foreign folder that merely looks alike is left alone.
        fs::create_dir(tmp.path().join(".golden.creepbench-new-1-x")).unwrap();
        clean_stale(tmp.path(), "golden", &target);
        assert_eq!(listing(tmp.path()), [".golden.creepbench-new-1-x", "golden"]);
        assert_eq!(fs::read_to_string(target.join("a.csv")).unwrap(), "old");
    }

    #[test]
    fn a_live_build_is_not_cleaned_by_another_run() {
        let tmp = tempfile::tempdir().unwrap();
        let staging = Staging::create(tmp.path(), "golden").unwrap();
        fs::write(staging.path.join("part.csv"), "x").unwrap();
        clean_stale(tmp.path(), "golden", &tmp.path().join("golden"));
        assert!(staging.path.join("part.csv").exists());
        drop(staging);
        assert!(listing(tmp.path()).is_empty());
    }

    #[test]
    fn the_fallback_without_exchange_replaces_too() {
        let tmp = tempfile::tempdir().unwrap();
        let target = tmp.path().join("golden");
        write_result_folder(tmp.path(), "golden", [("a.csv", "1")]).unwrap();
        let mut staging = Staging::create(tmp.path(), "golden").unwrap();
        fs::write(staging.path.join("b.csv"), "2").unwrap();
        staging.install_by_renames(tmp.path(), "golden", &target).unwrap();
        drop(staging);
        assert_eq!(listing(&target), [MARKER, "b.csv"]);
        assert_eq!(listing(tmp.path()), ["golden"]);
    }
}
