//! The report's timings from isolated repeats (`run --timing-repeats`, [`crate::suite::timing`]):
//! which stored scenes are re-timed (those the work–precision and cost-per-step sections draw),
//! and each model's median with its 95 % interval ([`crate::suite::median`]).

use crate::pipeline::Timing;
use crate::scene::report::ReportGroup;
use crate::suite::median::{median_interval, MedianInterval};
use crate::suite::results::StoredScene;

/// Whether the report draws the scene's timings: the work–precision grids and the scenes of the
/// cost-per-step study (group `scaling`).
pub fn wants_isolated(s: &StoredScene) -> bool {
    super::work_precision::GRIDS.iter().any(|(n, _)| *n == s.name) || s.scene.report_group == ReportGroup::Scaling
}

/// `f` of each isolated repeat of `solver` in the scene, as its median with its interval (None
/// when the scene was not re-timed).
fn of_repeats(sc: &StoredScene, solver: &str, f: impl Fn(&Timing) -> f64) -> Option<MedianInterval> {
    median_interval(&sc.repeats.get(solver)?.iter().map(f).collect::<Vec<_>>())
}

/// The wall time of the whole run [s], over the repeats.
pub fn wall_s(sc: &StoredScene, solver: &str) -> Option<MedianInterval> {
    of_repeats(sc, solver, |t| t.wall_s)
}

/// The time per step after set-up, (wall − set-up) / steps [s], over the repeats.
pub fn per_step_s(sc: &StoredScene, solver: &str, steps: usize) -> Option<MedianInterval> {
    of_repeats(sc, solver, |t| (t.wall_s - t.setup_s) / steps.max(1) as f64)
}

impl MedianInterval {
    /// The median and interval times `scale`.
    pub fn scaled(&self, scale: f64) -> MedianInterval {
        MedianInterval {
            median: self.median * scale,
            interval: self.interval.map(|(lo, hi)| (lo * scale, hi * scale)),
            ..*self
        }
    }

    /// "[lo, hi]" in `fmt`'s notation (e.g. [`fmt_s`]), or "—" without an interval (too few repeats).
    pub fn interval_cell(&self, fmt: impl Fn(f64) -> String) -> String {
        self.interval.map_or("—".into(), |(lo, hi)| format!("[{}, {}]", fmt(lo), fmt(hi)))
    }
}

/// A time with its unit, to about three significant digits: `1.255 s`, `7.600 ms`, `31.20 µs`.
pub fn fmt_s(v: f64) -> String {
    match v.abs() {
        a if !a.is_finite() => "—".into(),
        a if a >= 1.0 => format!("{v:.3} s"),
        a if a >= 1e-3 => format!("{:.3} ms", v * 1e3),
        _ => format!("{:.2} µs", v * 1e6),
    }
}

/// The sentence that says how the timings were taken (for a section's introduction).
pub fn method(repeats: Option<usize>) -> String {
    match repeats {
        Some(n) => format!(
            "Each model re-timed alone after the suite (one model at a time on one thread, {n} repeats): the median and its distribution-free 95 % interval [x₍k₎, x₍n+1−k₎] from order statistics, k the largest with P(k ≤ B ≤ n − k) ≥ 0.95 for B ~ Binomial(n, ½) (Conover 1999, §3.2); fewer than 6 repeats give no interval"
        ),
        None => "Not re-timed (`run --timing-repeats 0`, or results from before it): single wall-clock runs taken while the scenes ran in parallel, so the figures include contention".into(),
    }
}

/// The repeat count of the scenes' isolated timings (the largest stored), None when none was re-timed.
pub fn repeats(scenes: &[StoredScene]) -> Option<usize> {
    scenes.iter().flat_map(|s| s.repeats.values().map(Vec::len)).max()
}
