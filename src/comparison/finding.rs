//! The worst point of one comparison ([`Finding`]) and the context that judges each compared
//! value by the tolerance rules ([`Ctx`]). Reference sets and the baseline comparison build them.

pub use crate::comparison::against::Against;
use crate::comparison::rule::{first, Rule};
use crate::history::History;
use std::collections::BTreeMap;

/// The worst point of one comparison.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    pub scene: String,
    pub solver: String,
    pub against: Against,
    pub quantity: String,
    /// Step of the worst point (histories and per-step metrics).
    pub step: Option<usize>,
    pub ours: f64,
    pub theirs: f64,
    /// |ours − theirs| (NaN when the two cannot be matched, e.g. missing steps).
    pub diff: f64,
    pub allowed: f64,
    pub gated: bool,
    /// A note, e.g. why the values cannot be matched.
    pub note: String,
}

impl Finding {
    pub fn passed(&self) -> bool {
        self.diff <= self.allowed
    }
    /// diff / allowed (∞ for a NaN diff), to rank findings.
    pub fn severity(&self) -> f64 {
        if self.diff.is_nan() {
            f64::INFINITY
        } else if self.allowed > 0.0 && self.allowed.is_finite() {
            self.diff / self.allowed
        } else {
            self.diff
        }
    }
}

/// The scene, model and baseline of a comparison.
pub struct Ctx<'a> {
    pub scene: &'a str,
    pub solver: &'a str,
    pub against: Against,
    /// The tolerance rules that judge it (first match wins; [`crate::comparison::rule::first`]).
    pub rules: &'a [Rule],
}

impl Ctx<'_> {
    /// One compared value, judged by the tolerance rule of this comparison.
    pub fn finding(&self, quantity: &str, step: Option<usize>, ours: f64, theirs: f64, note: &str) -> Finding {
        let rule = first(self.rules, self.against, self.scene, self.solver, quantity);
        Finding {
            scene: self.scene.into(),
            solver: self.solver.into(),
            against: self.against,
            quantity: quantity.into(),
            step,
            ours,
            theirs,
            diff: (ours - theirs).abs(),
            allowed: rule.allowed(theirs),
            gated: rule.gated,
            note: note.into(),
        }
    }

    /// A comparison that cannot be made (a missing or extra baseline item): never passes.
    pub fn unmatched(&self, quantity: &str, note: String) -> Finding {
        let mut f = self.finding(quantity, None, f64::NAN, f64::NAN, "");
        f.diff = f64::NAN;
        f.note = note;
        f
    }

    /// Worst difference of one column over the steps both histories have. Steps present in only
    /// one of them make the finding unmatched (NaN) when `require_same_steps`.
    pub fn column(&self, ours: &History, theirs: &History, col: &str, require_same_steps: bool) -> Option<Finding> {
        let (a, b) = (ours.column(col)?, theirs.column(col)?);
        let tb: BTreeMap<usize, f64> = theirs.rows.iter().map(|r| r.sample.step).zip(b).collect();
        let mut worst: Option<Finding> = None;
        let mut matched = 0;
        for (r, va) in ours.rows.iter().zip(a) {
            let Some(&vb) = tb.get(&r.sample.step) else { continue };
            matched += 1;
            let f = self.finding(col, Some(r.sample.step), va, vb, "");
            if worst.as_ref().is_none_or(|w| f.severity() > w.severity()) {
                worst = Some(f);
            }
        }
        if require_same_steps && (matched != ours.rows.len() || matched != theirs.rows.len()) {
            let mut f = self.finding(col, None, f64::NAN, f64::NAN, "");
            f.diff = f64::NAN;
            f.note =
                format!("steps differ: {} rows here, {} there, {matched} matched", ours.rows.len(), theirs.rows.len());
            return Some(f);
        }
        worst
    }
}
