//! The gate protects its own data (issue 11): bounded reads that never block, short excerpts in
//! messages, result folders replaced atomically and only when creepbench wrote them, files written
//! whole, protected folders, folder locks, external processes with a timeout and no orphans,
//! checksum manifests, a console that may go away (stdout).
//! One job per file; the commands call these, nothing here knows about scenes or solvers.

pub mod excerpt;
pub mod folder;
pub mod guard;
pub mod interrupt;
pub mod link;
pub mod lock;
pub mod manifest;
pub mod process;
pub mod read;
pub mod relative;
pub mod stdout;
pub mod threads;
pub mod whole;
