//! The worker thread count is an input like any other: `RAYON_NUM_THREADS` beyond a sane number
//! (ten thousand threads for a two-core machine) is capped, with a warning.

/// Most worker threads per available core.
pub const THREADS_PER_CORE: usize = 4;

/// The cap on worker threads: [`THREADS_PER_CORE`] per available core.
pub fn max_threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get()) * THREADS_PER_CORE
}

/// Cap `RAYON_NUM_THREADS` at [`max_threads`] (before the first parallel work); the warning to
/// print when it was capped.
pub fn cap_threads() -> Option<String> {
    let asked: usize = std::env::var("RAYON_NUM_THREADS").ok()?.trim().parse().ok()?;
    let cap = max_threads();
    if asked <= cap {
        return None;
    }
    let built = rayon::ThreadPoolBuilder::new().num_threads(cap).build_global();
    Some(match built {
        Ok(()) => format!("RAYON_NUM_THREADS = {asked} capped at {cap} ({THREADS_PER_CORE} per available core)"),
        Err(e) => format!("RAYON_NUM_THREADS = {asked}: cannot cap the thread pool at {cap}: {e}"),
    })
}
