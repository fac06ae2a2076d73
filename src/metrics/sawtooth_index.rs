//! `sawtooth_index`, a stability diagnostic of the traction field (computed when a scene lists
//! it, for the models that have a field): the largest, over every solve, fraction of interior
//! loaded elements (along x, in each row) where the first difference of τx changes sign between
//! significant differences. A smooth field scores near 0 (one change per row at most, at the
//! peak); the odd-even mode of an unstable (e.g. downwind) scheme scores near 1 — even when the
//! traction bound keeps |τ| ≤ μp, so bound checks alone would not see it.

use super::oscillation_index::turns;
use super::{MetricDef, MetricKind};
use crate::solvers::FieldView;

/// The metric's name in scenes and metrics.csv.
pub const NAME: &str = "sawtooth_index";

pub const METRIC: MetricDef =
    MetricDef { name: NAME, default: false, fits: |_, _| Ok(()), kind: MetricKind::Field(sawtooth_index) };

/// The indicator of one traction field.
pub fn sawtooth_index(v: &FieldView) -> f64 {
    let (grid, pressure, tx) = (v.grid, v.pressure_mpa, v.tx_mpa);
    let scale = tx.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if scale == 0.0 {
        return 0.0;
    }
    let tiny = 1e-9 * scale;
    let (mut changes, mut interior) = (0usize, 0usize);
    for j in 0..grid.my {
        // Each maximal run of three or more loaded elements along x.
        let mut i = 0;
        while i < grid.mx {
            let start = i;
            while i < grid.mx && pressure[grid.index(i, j)] > 0.0 {
                i += 1;
            }
            if i - start >= 3 {
                interior += i - start - 2;
                changes += turns((start..i).map(|ii| tx[grid.index(ii, j)]), tiny);
            }
            i += 1;
        }
    }
    let rows_with_peak = grid.my as f64;
    if interior == 0 {
        0.0
    } else {
        ((changes as f64 - rows_with_peak).max(0.0) / interior as f64).min(1.0)
    }
}
