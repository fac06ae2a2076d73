//! The abscissa a history is drawn against: time for a history in time, the quantity a steady
//! sweep moves for a sweep (the report's traction curves and the calibration's before/after).

use super::History;
use crate::problem::{LoadingKind, Sample};

/// A quantity of a row's sample at the scene's rolling speed [mm/s].
type Swept = fn(&Sample, f64) -> f64;

/// The quantities a sweep may move, by their column names.
const SWEPT: [(&str, Swept); 4] =
    [("cx", |s, _| s.cx), ("cy", |s, _| s.cy), ("cs", |s, _| s.cs), ("v_mm_s", |s, v| s.speed_mm_s(v))];

/// The x of each row of `h` and its column name: `t_s` unless the loading is a sweep; for a
/// sweep the one of cx, cy, cs and the rolling speed (`v_mm_s`, the scene's `v_mm_s` where a row
/// does not set it) with the largest spread relative to its magnitude.
pub fn abscissa(h: &History, kind: LoadingKind, v_mm_s: f64) -> (&'static str, Vec<f64>) {
    if kind != LoadingKind::Sweep {
        return ("t_s", h.rows.iter().map(|r| r.sample.t_s).collect());
    }
    let values = |q: Swept| -> Vec<f64> { h.rows.iter().map(|r| q(&r.sample, v_mm_s)).collect() };
    let spread = |q: Swept| {
        let vals = values(q);
        let (lo, hi) = vals.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)));
        (hi - lo) / hi.abs().max(lo.abs()).max(f64::MIN_POSITIVE)
    };
    let (name, q) = SWEPT.into_iter().max_by(|a, b| spread(a.1).total_cmp(&spread(b.1))).unwrap_or(SWEPT[0]);
    (name, values(q))
}
