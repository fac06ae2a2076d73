//! What `check` and `run` print (issue 31 item 3): the verdict first, then one line per suite and
//! model (gated, failed, the worst comparison relative to its tolerance), the scenes without
//! baseline data once each, and the drifts worst first by |diff| / allowed, at most
//! [`CONSOLE_LINES`] of each list unless verbose. Pure functions of the findings; the JSON, JUnit
//! and summary files keep everything.

use crate::comparison::compare::{self, Finding};
use crate::metrics::oscillation_index::own_oscillation;
use crate::suite::results::StoredScene;
use std::collections::BTreeMap;
use std::fmt::{self, Write};

/// Most lines of a list (drifts, moved quantities, scenes without data) shown unless verbose.
pub const CONSOLE_LINES: usize = 20;

/// The gate's verdict: gated comparisons and how many of them failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Verdict {
    pub gated: usize,
    pub failed: usize,
}

impl Verdict {
    pub fn of(all: &[Finding]) -> Self {
        Verdict { gated: all.iter().filter(|f| f.gated).count(), failed: failed(all).count() }
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        let word = if self.failed == 0 { "PASS" } else { "FAIL" };
        write!(f, "{word}: {} gated comparisons, {} failed", self.gated, self.failed)
    }
}

/// The gated findings that miss their tolerance.
fn failed(all: &[Finding]) -> impl Iterator<Item = &Finding> {
    all.iter().filter(|f| f.gated && !f.passed())
}

/// |diff| / allowed as text: "unmatched" for a comparison that could not be made, "∞" for a
/// difference where none is allowed.
pub fn ratio(f: &Finding) -> String {
    if f.diff.is_nan() {
        "unmatched".into()
    } else if f.allowed > 0.0 && f.allowed.is_finite() {
        format!("{:.3}", f.diff / f.allowed)
    } else if f.diff == 0.0 {
        "0".into()
    } else {
        "∞".into()
    }
}

/// Where a finding's worst point is: scene, comparison, quantity, step.
fn place(f: &Finding) -> String {
    let step = f.step.map_or("-".to_string(), |s| s.to_string());
    format!("{} {} {} step {step}", f.scene, f.against.label(), f.quantity)
}

/// Findings worst first by |diff| / allowed (unmatched first), ties in input order.
fn worst_first<'a>(fs: impl Iterator<Item = &'a Finding>) -> Vec<&'a Finding> {
    let mut v: Vec<&Finding> = fs.collect();
    v.sort_by(|a, b| b.severity().total_cmp(&a.severity()));
    v
}

/// One line per suite and model: gated comparisons, failures, and the worst gated comparison
/// relative to its tolerance (scenes without baseline data are listed by [`no_baseline`]).
/// `suite_of` maps a scene to its suite folder ("-" for scenes the run did not produce).
pub fn per_model(all: &[Finding], suite_of: &BTreeMap<String, String>) -> String {
    let mut groups: BTreeMap<(&str, &str), Vec<&Finding>> = BTreeMap::new();
    for f in all {
        let suite = suite_of.get(&f.scene).map_or("-", String::as_str);
        groups.entry((suite, f.solver.as_str())).or_default().push(f);
    }
    let w_suite = groups.keys().map(|k| k.0.chars().count()).chain([5]).max().unwrap_or(5);
    let w_model = groups.keys().map(|k| k.1.chars().count()).chain([5]).max().unwrap_or(5);
    let mut out = format!(
        "{:<w_suite$}  {:<w_model$}  {:>6}  {:>6}  {:>10}  worst at (scene, against, quantity, step)\n",
        "suite", "model", "gated", "failed", "|diff|/tol"
    );
    for ((suite, model), fs) in &groups {
        let gated: Vec<&Finding> = fs.iter().copied().filter(|f| f.gated && !compare::is_no_baseline(f)).collect();
        let n_failed = fs.iter().filter(|f| f.gated && !f.passed()).count();
        let worst = worst_first(gated.iter().copied()).into_iter().next();
        let (r, at) = match worst {
            None => ("—".to_string(), String::new()),
            Some(w) if w.diff == 0.0 => ("0".to_string(), "no difference".to_string()),
            Some(w) => (ratio(w), place(w)),
        };
        let _ = writeln!(
            out,
            "{suite:<w_suite$}  {model:<w_model$}  {:>6}  {n_failed:>6}  {r:>10}  {at}",
            fs.iter().filter(|f| f.gated).count()
        );
    }
    out
}

/// The scenes a baseline has no data for, once each with their models, and what to do.
pub fn no_baseline(all: &[Finding], verbose: bool) -> Vec<String> {
    let mut scenes: BTreeMap<(&str, &str), Vec<&str>> = BTreeMap::new();
    for f in all.iter().filter(|f| compare::is_no_baseline(f)) {
        scenes.entry((f.against.label(), &f.scene)).or_default().push(&f.solver);
    }
    let lines = scenes.iter().map(|((label, scene), models)| {
        format!("{scene}: no {label} data (models {}): run `creepbench bless` to accept its results", models.join(", "))
    });
    capped(lines.collect(), verbose)
}

/// The gated failures other than missing baseline data, worst first by |diff| / allowed, as
/// DRIFT lines.
pub fn drifts(all: &[Finding], verbose: bool) -> Vec<String> {
    let fails = worst_first(failed(all).filter(|f| !compare::is_no_baseline(f)));
    capped(fails.into_iter().map(compare::drift_line).collect(), verbose)
}

/// The quantities that moved against a previous result set (how many, and the lines), worst first
/// by |diff| / allowed.
pub fn moved(all: &[Finding], verbose: bool) -> (usize, Vec<String>) {
    let moved = worst_first(all.iter().filter(|f| f.against == compare::Against::Previous && f.diff > 0.0));
    let lines = moved.iter().map(|f| {
        format!(
            "{} {} {} step {}: {} -> {} (|diff| {}, {} of allowed)",
            f.scene,
            f.solver,
            f.quantity,
            f.step.map_or("-".to_string(), |s| s.to_string()),
            crate::error::number(f.theirs),
            crate::error::number(f.ours),
            crate::error::deviation(f.diff),
            ratio(f)
        )
    });
    (moved.len(), capped(lines.collect(), verbose))
}

/// The time histories that oscillate on their own ([`own_oscillation`]: |f| turning at
/// [`crate::metrics::oscillation_index::ZIGZAG_FLAG`] or more consecutive steps, more than the loading
/// does), one OSCILLATES line
/// each, so that no oscillating history passes in silence (e.g. the memoryless falling branch).
pub fn oscillating(scenes: &[StoredScene], verbose: bool) -> Vec<String> {
    let mut lines = Vec::new();
    for sc in scenes {
        for (solver, h) in &sc.histories {
            if let Some(o) = own_oscillation(h, sc.scene.v_mm_s) {
                lines.push(format!(
                    "OSCILLATES: {} {solver}: |f| turns at {} consecutive steps (the loading at {}), oscillation index {:.3}",
                    sc.name, o.run, o.loading_run, o.index
                ));
            }
        }
    }
    capped(lines, verbose)
}

/// At most [`CONSOLE_LINES`] lines unless verbose, the rest counted in a last line.
fn capped(mut lines: Vec<String>, verbose: bool) -> Vec<String> {
    if !verbose && lines.len() > CONSOLE_LINES {
        let more = lines.len() - CONSOLE_LINES;
        lines.truncate(CONSOLE_LINES);
        lines.push(format!("... and {more} more (see --verbose / --json)"));
    }
    lines
}
