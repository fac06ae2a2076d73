//! Interruption of creepbench (SIGINT, SIGTERM, SIGHUP): kill the process groups of the
//! external models still running, remove the temporary folders registered, exit 130, so that a
//! Ctrl-C or a CI cancel leaves no orphaned model and no gigabytes of temporary files behind.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::{Mutex, MutexGuard, OnceLock};

/// Exit status after an interruption (128 + SIGINT, the shell's convention).
pub const INTERRUPTED_EXIT_CODE: i32 = 130;

/// What the handler must clean up, by registration id.
struct Registry {
    next_id: u64,
    groups: BTreeMap<u64, i32>,
    folders: BTreeMap<u64, PathBuf>,
}

static REGISTRY: Mutex<Registry> =
    Mutex::new(Registry { next_id: 0, groups: BTreeMap::new(), folders: BTreeMap::new() });
static INSTALLED: OnceLock<Result<(), String>> = OnceLock::new();

/// The signal handler could not be installed (another one was installed first).
#[derive(Debug, Clone, thiserror::Error)]
#[error("cannot install the interrupt handler: {reason}")]
pub struct HandlerError {
    pub reason: String,
}

/// Install the handler once per process; later calls return the first outcome.
pub fn install() -> Result<(), HandlerError> {
    INSTALLED
        .get_or_init(|| ctrlc::set_handler(on_interrupt).map_err(|e| e.to_string()))
        .clone()
        .map_err(|reason| HandlerError { reason })
}

fn on_interrupt() {
    let registry = hold();
    for &group in registry.0.groups.values() {
        if let Some(pid) = rustix::process::Pid::from_raw(group) {
            let _ = rustix::process::kill_process_group(pid, rustix::process::Signal::KILL);
        }
    }
    for folder in registry.0.folders.values() {
        let _ = std::fs::remove_dir_all(folder);
    }
    std::process::exit(INTERRUPTED_EXIT_CODE);
}

/// The registry, locked: while it is held the handler cannot clean up, so a step that must not
/// be cut in two by the cleanup (spawn and register; swap a folder into place) runs under it.
pub struct Held(MutexGuard<'static, Registry>);

/// Lock the registry (a poisoned lock is still used: the registry stays consistent).
pub fn hold() -> Held {
    Held(REGISTRY.lock().unwrap_or_else(|e| e.into_inner()))
}

impl Held {
    /// Kill the process group `pgid` on interruption, until the registration is dropped.
    pub fn register_group(&mut self, pgid: i32) -> Registration {
        let id = self.next();
        self.0.groups.insert(id, pgid);
        Registration { id }
    }

    /// Remove `folder` on interruption, until the registration is dropped.
    pub fn register_folder(&mut self, folder: PathBuf) -> Registration {
        let id = self.next();
        self.0.folders.insert(id, folder);
        Registration { id }
    }

    fn next(&mut self) -> u64 {
        self.0.next_id += 1;
        self.0.next_id
    }
}

/// A cleanup entry; dropping it (never while [`Held`] is alive in the same thread) forgets it.
#[must_use = "the entry is forgotten when the registration is dropped"]
pub struct Registration {
    id: u64,
}

impl Drop for Registration {
    fn drop(&mut self) {
        let mut registry = hold();
        registry.0.groups.remove(&self.id);
        registry.0.folders.remove(&self.id);
    }
}

/// Remove `folder` on interruption, until the registration is dropped.
pub fn register_folder(folder: PathBuf) -> Registration {
    hold().register_folder(folder)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn registrations_are_forgotten_when_dropped() {
        let a = register_folder(PathBuf::from("/tmp/a"));
        let b = hold().register_group(12345);
        {
            let r = hold();
            assert!(r.0.folders.values().any(|f| f == &PathBuf::from("/tmp/a")));
            assert!(r.0.groups.values().any(|&g| g == 12345));
        }
        drop(a);
        drop(b);
        let r = hold();
        assert!(!r.0.folders.values().any(|f| f == &PathBuf::from("/tmp/a")));
        assert!(!r.0.groups.values().any(|&g| g == 12345));
    }
}
