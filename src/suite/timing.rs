//! Timings one can trust: after a suite has run its scenes in parallel, the models of the scenes
//! whose timings the report draws are run again, one model at a time on one thread (the models
//! spawn none), each `repeats` times; the report gives each run's median with a 95 % interval
//! ([`super::median`]). The histories of these runs are dropped: only their wall times are kept.

use crate::error::Error;
use crate::history::sample_loop;
use crate::pipeline::{self, Timing};
use crate::problem::Problem;
use crate::solvers;
use std::collections::BTreeMap;

/// Repeats per model when `run` is not told otherwise: the fewest that give a 95 % interval of
/// the median, [x₍₁₎, x₍₆₎] (96.9 %; 9 repeats would give [x₍₂₎, x₍₈₎], 96.1 %, at half as much
/// again: the 88×88 exact run alone takes seconds).
pub const DEFAULT_REPEATS: usize = super::median::MIN_SAMPLES;

/// Each built-in model of `problem` (external and in-process models are not re-timed) run
/// `repeats` times in turn on the calling thread, with the field indicators the suite's run
/// computed: its wall and set-up times per repeat, by model name.
pub fn retime(problem: &Problem, repeats: usize) -> Result<BTreeMap<String, Vec<Timing>>, Error> {
    let fields = pipeline::field_indicators(problem);
    let mut out = BTreeMap::new();
    for name in &problem.solvers {
        let Some(def) = solvers::builtin(name) else { continue };
        let mut times = Vec::with_capacity(repeats);
        for _ in 0..repeats {
            let r = sample_loop::run(problem, def, &fields, None).map_err(|e| Error::Solve {
                scene: problem.name.clone(),
                solver: name.clone(),
                source: Box::new(e),
            })?;
            times.push(Timing { wall_s: r.wall_s, setup_s: r.setup_s });
        }
        out.insert(name.clone(), times);
    }
    Ok(out)
}
