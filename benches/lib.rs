//! Shared by the benchmarks of this package (solvers.rs, wheelrail.rs, results.rs).

/// The repository's root (scenes/, golden/), one folder above this package.
pub const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
