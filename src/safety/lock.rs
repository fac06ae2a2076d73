//! A lock on a folder that results are written into, so that two runs into one folder take
//! turns (or the later one stops with a clear message) instead of failing on each other's files.

use super::folder;
use std::fs::{File, TryLockError};
use std::io;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// A run started while another finishes writing waits for it; one that would wait for a whole
/// other run stops with a message instead.
pub const DEFAULT_LOCK_WAIT: Duration = Duration::from_secs(60);
/// Pause between two attempts to take a busy lock.
const RETRY: Duration = Duration::from_millis(20);

/// Why a folder could not be locked.
#[derive(Debug, thiserror::Error)]
pub enum LockError {
    #[error("{} is in use by another creepbench run (waited {} s); wait for it to finish or write elsewhere", path.display(), waited.as_secs_f64())]
    Busy { path: PathBuf, waited: Duration },
    #[error("cannot lock {}: {source}", path.display())]
    Io {
        path: PathBuf,
        #[source]
        source: io::Error,
    },
}

/// Held while writing into the folder; dropping it releases the lock (so does the end of the
/// process, however it ends).
#[derive(Debug)]
pub struct FolderLock {
    _file: File,
}

/// Lock `dir` (created if missing) for writing, waiting up to `wait` for another holder. The
/// lock is on the folder itself, an advisory `flock`: lock the folder that holds result folders
/// (never one that is replaced whole), once per process. Once it is taken, the leftovers of
/// killed runs in `dir` are removed ([`folder::clean_leftovers`]: this tool's own folders by
/// their name pattern, whose owner no longer runs or no live run holds).
pub fn lock_folder(dir: &Path, wait: Duration) -> Result<FolderLock, LockError> {
    let io_err = |source| LockError::Io { path: dir.into(), source };
    std::fs::create_dir_all(dir).map_err(io_err)?;
    let file = File::open(dir).map_err(io_err)?;
    let start = Instant::now();
    loop {
        match file.try_lock() {
            Ok(()) => {
                folder::clean_leftovers(dir);
                return Ok(FolderLock { _file: file });
            }
            Err(TryLockError::Error(e)) => return Err(io_err(e)),
            Err(TryLockError::WouldBlock) if start.elapsed() >= wait => {
                return Err(LockError::Busy { path: dir.into(), waited: start.elapsed() });
            }
            Err(TryLockError::WouldBlock) => std::thread::sleep(RETRY.min(wait.saturating_sub(start.elapsed()))),
        }
    }
}

/// Lock a folder that is replaced whole (golden/): the lock is on the folder that holds it,
/// which outlives each swap, so every writer of `tree` — whatever path it was given — takes the
/// same lock.
pub fn lock_protected(tree: &Path, wait: Duration) -> Result<FolderLock, LockError> {
    let absolute = std::path::absolute(tree).map_err(|source| LockError::Io { path: tree.into(), source })?;
    let parent = absolute.parent().unwrap_or(Path::new("/"));
    lock_folder(parent, wait)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_second_writer_waits_then_gets_the_lock_or_a_clear_error() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path().join("results");
        let first = lock_folder(&dir, Duration::ZERO).unwrap();
        let e = lock_folder(&dir, Duration::from_millis(50)).unwrap_err();
        assert!(matches!(e, LockError::Busy { .. }) && e.to_string().contains("results"), "{e}");
        let waiter = {
            let dir = dir.clone();
            std::thread::spawn(move || lock_folder(&dir, Duration::from_secs(20)).map(|_| ()))
        };
        std::thread::sleep(Duration::from_millis(100));
        drop(first);
        waiter.join().unwrap().unwrap();
    }
}
