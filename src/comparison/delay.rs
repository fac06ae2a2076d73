//! The delay ratio of a reference history and the rule that says when it is ill-defined: computed
//! here, once, for the comparison (its findings) and the report (its delay table).

use crate::history::History;
use crate::metrics;

/// Where |f| reaches this fraction of μ near the creepage peak, f's maximum is a flat top and the
/// delay ill-defined (reference/README.md): such a delay is reported, never gated.
pub const SATURATION: f64 = 0.97;

/// Whether |f| = `f_abs` is on the flat top at μ = `mu`.
pub fn saturates(f_abs: f64, mu: f64) -> bool {
    f_abs >= SATURATION * mu
}

/// The delay ratio of a history over the period `period_s`: its metric (`metrics::delay_ratio`)
/// from its time, cx and fx/FN columns.
pub fn of_history(h: &History, period_s: f64) -> Option<f64> {
    metrics::delay_ratio(&h.column("t_s")?, &h.column("cx")?, &h.column("fx_over_fn")?, period_s)
}
