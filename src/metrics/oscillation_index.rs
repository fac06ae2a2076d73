//! `oscillation_index`, a stability diagnostic (computed when a scene lists it): the fraction of
//! interior steps where f turns, from the first step after the initial state.

use super::{HistoryColumns, MetricDef, MetricKind, MetricValue};
use crate::history::History;
use crate::problem::Loading;

/// The metric's name in scenes and metrics.csv.
pub const NAME: &str = "oscillation_index";

pub const METRIC: MetricDef = MetricDef {
    name: NAME,
    default: false,
    fits: |l, _| if l.is_transient() { Ok(()) } else { Err(super::Unfit::TimeHistoryOnly) },
    kind: MetricKind::History(compute),
};

fn compute(_: &Loading, h: &HistoryColumns) -> Vec<MetricValue> {
    vec![(None, oscillation_index(&h.f[h.first_step..]))]
}

/// Number of turns in a sequence: sign changes between consecutive first differences larger than
/// `tiny`, smaller ones skipped (so a rounded extremum counts once even when its middle
/// difference is tiny, and jitter below `tiny` counts nothing). Shared by the oscillation and
/// sawtooth indicators.
pub fn turns(values: impl IntoIterator<Item = f64>, tiny: f64) -> usize {
    let mut it = values.into_iter();
    let Some(mut prev) = it.next() else { return 0 };
    let mut last_sign = 0.0f64;
    let mut n = 0;
    for v in it {
        let d = v - prev;
        prev = v;
        if d.abs() > tiny {
            let sign = d.signum();
            n += usize::from(last_sign != 0.0 && sign != last_sign);
            last_sign = sign;
        }
    }
    n
}

/// Oscillation index of a time history: the fraction of interior steps where f turns. A smooth
/// response scores about 2 per period (its extrema); a step-to-step sawtooth scores ~1.
/// Differences count only above [`OSCILLATION_FLOOR`] of `max |f|` (and above 1e-9 of the range
/// of f): an iterative solver converged to its tolerance (the exact-theory solver's default
/// 1e-7 of the traction bound) leaves a jitter of that order on a plateau, which is not an
/// oscillation.
pub fn oscillation_index(f: &[f64]) -> f64 {
    if f.len() < 3 {
        return 0.0;
    }
    turns(f.iter().copied(), floor(f)) as f64 / (f.len() - 2) as f64
}

/// The smallest difference that counts as a move of f: [`OSCILLATION_FLOOR`] of `max |f|`, at
/// least 1e-9 of the range of f.
fn floor(f: &[f64]) -> f64 {
    let (lo, hi) = f.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
    let scale = lo.abs().max(hi.abs());
    (1e-9 * (hi - lo)).max(OSCILLATION_FLOOR * scale).max(f64::MIN_POSITIVE)
}

/// The longest run of consecutive steps at which the sequence turns (moves below `tiny`
/// skipped, as [`turns`]): a step-to-step (period-2) oscillation turns at every step.
pub fn zigzag_run(values: &[f64], tiny: f64) -> usize {
    let (mut best, mut run, mut last_sign, mut last_turn) = (0, 0, 0.0f64, None);
    for (k, w) in values.windows(2).enumerate() {
        let d = w[1] - w[0];
        if d.abs() > tiny {
            let sign = d.signum();
            if last_sign != 0.0 && sign != last_sign {
                run = if last_turn == Some(k - 1) { run + 1 } else { 1 };
                last_turn = Some(k);
                best = best.max(run);
            }
            last_sign = sign;
        }
    }
    best
}

/// Consecutive step-to-step turns of |f| that flag a time history as oscillating on its own:
/// three periods of a period-2 oscillation. (A converged response to a steady or slow loading
/// turns at most at its extrema; the shipped suites' longest run is 4, where the loading itself
/// turns every step or a contact patch jumps between grid rows.)
pub const ZIGZAG_FLAG: usize = 6;

/// A time history that oscillates on its own: its resultant |f| turns at [`ZIGZAG_FLAG`] or more
/// consecutive steps and more of them than any loading quantity (cx, cy, cs, FN, μ, V) does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OwnOscillation {
    /// The longest run of consecutive turns of |f|.
    pub run: usize,
    /// The loading's longest run.
    pub loading_run: usize,
    /// [`oscillation_index`] of |f|.
    pub index: f64,
}

/// Whether the time history oscillates on its own ([`OwnOscillation`]); `None` for a history
/// without time steps (a sweep) or one that does not.
pub fn own_oscillation(h: &History, rolling_v_mm_s: f64) -> Option<OwnOscillation> {
    let rows: Vec<_> = h.rows.iter().filter(|r| r.sample.step >= 1).collect();
    if rows.len() < 3 || rows.iter().all(|r| r.sample.t_s == 0.0) {
        return None;
    }
    let f: Vec<f64> = rows.iter().map(|r| r.fx_over_fn.hypot(r.fy_over_fn)).collect();
    let run = zigzag_run(&f, floor(&f));
    if run < ZIGZAG_FLAG {
        return None;
    }
    let loading: [fn(&crate::history::RowSample, f64) -> f64; 6] =
        [|s, _| s.cx, |s, _| s.cy, |s, _| s.cs, |s, _| s.fn_n, |s, _| s.mu, |s, v| s.speed_mm_s(v)];
    let loading_run = loading
        .iter()
        .map(|q| {
            let v: Vec<f64> = rows.iter().map(|r| q(&r.sample, rolling_v_mm_s)).collect();
            zigzag_run(&v, floor(&v))
        })
        .max()
        .unwrap_or(0);
    (run > loading_run).then(|| OwnOscillation { run, loading_run, index: oscillation_index(&f) })
}

/// Noise floor of [`oscillation_index`], relative to `max |f|`: ten times the exact-theory
/// solver's default tolerance.
pub const OSCILLATION_FLOOR: f64 = 1e-6;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn oscillation_index_sees_sawtooth_not_convergence_jitter() {
        // A plateau at 0.4 with solver jitter of 1e-11 (tolerance level): no turns.
        let jitter: Vec<f64> = (0..40).map(|i| 0.4 + if i % 2 == 0 { 1e-11 } else { -1e-11 }).collect();
        assert_eq!(oscillation_index(&jitter), 0.0);
        // The same plateau with a 1e-4 sawtooth: every interior step turns.
        let saw: Vec<f64> = (0..40).map(|i| 0.4 + if i % 2 == 0 { 1e-4 } else { -1e-4 }).collect();
        assert!((oscillation_index(&saw) - 1.0).abs() < 1e-12);
        // A smooth sine over 3 periods of 60 steps: 6 extrema in 178 interior steps.
        let sine: Vec<f64> =
            (0..180).map(|i| 0.3 + 0.1 * (2.0 * std::f64::consts::PI * (i as f64 + 0.3) / 60.0).sin()).collect();
        assert!((oscillation_index(&sine) - 6.0 / 178.0).abs() < 1e-12, "{}", oscillation_index(&sine));
        // A rounded peak whose middle difference is below the floor still counts once.
        assert_eq!(turns([0.0, 0.5, 1.0, 1.0 + 1e-9, 0.5, 0.0], 1e-6), 1);
    }
    #[test]
    fn zigzag_run_counts_consecutive_turns() {
        // A smooth rise and fall: one turn.
        assert_eq!(zigzag_run(&[0.0, 1.0, 2.0, 1.0, 0.0], 1e-9), 1);
        // A period-2 oscillation from the third value on: 0 1 2 1 2 1 2 1 turns at 5 steps in a row.
        assert_eq!(zigzag_run(&[0.0, 1.0, 2.0, 1.0, 2.0, 1.0, 2.0, 1.0], 1e-9), 5);
        // Below the floor nothing turns.
        assert_eq!(zigzag_run(&[0.0, 1e-12, 0.0, 1e-12, 0.0], 1e-9), 0);
    }
}
