//! The project's default tolerances (issue 15, tolerances as reviewed data): the `[[rule]]` tables
//! of `tolerances.toml` at the repository's top, in the format of tolerance files
//! ([`crate::comparison::tolerance_file`]), each with its reason. The file is embedded into the binary
//! (`include_str!`, so an installed binary has it) and parsed once, on first use. A comparison
//! passes when `|ours − theirs| ≤ abs + rel·|theirs|`; the first rule that covers it wins.

use crate::comparison::against::Against;
use crate::comparison::references;
use crate::comparison::rule::first;
pub use crate::comparison::rule::Rule;
use crate::comparison::tolerance_file;
use std::sync::LazyLock;

/// The defaults' file, as messages name it (embedded at build time).
pub const DEFAULT_FILE: &str = "tolerances.toml";
const DEFAULT_TEXT: &str = include_str!("../../tolerances.toml");

/// The labels the defaults may name: golden (which also judges `check --against`, "previous")
/// and every reference set's.
pub fn default_labels() -> Vec<Against> {
    std::iter::once(Against::Golden).chain(references::labels()).collect()
}

/// The comparisons a run's rule files may name: golden, previous and every reference set's.
pub fn labels() -> Vec<Against> {
    [Against::Golden, Against::Previous].into_iter().chain(references::labels()).collect()
}

/// The rules of `tolerances.toml`, then each reference set's catch-all (the registry's): a
/// label's rules never interact with another's, so its catch-all after every file rule is its last.
static DEFAULTS: LazyLock<Vec<Rule>> = LazyLock::new(|| {
    let mut rules = tolerance_file::parse(DEFAULT_TEXT, DEFAULT_FILE, &default_labels())
        // Compiled in and parsed by a unit test: a broken file cannot reach a build that passes.
        .unwrap_or_else(|e| panic!("the embedded {DEFAULT_FILE} is invalid: {e}"));
    rules.extend(references::catch_alls());
    rules
});

/// The project's default rules, in order (first match wins).
pub fn defaults() -> &'static [Rule] {
    &DEFAULTS
}

/// The first default rule covering this comparison; `previous` is judged as `golden`.
pub fn rule(against: Against, scene: &str, solver: &str, quantity: &str) -> &'static Rule {
    first(defaults(), against, scene, solver, quantity)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::comparison::references::{contact, envelope, table, thesis};

    const INF: f64 = f64::INFINITY;

    /// The compiled `RULES` table as it stood before the rules became data (commit 2451b71),
    /// with the four rules of CONTACT's test table added since (issue 14) and the known gaps of
    /// fn_sine_f20 and mu_ramp removed (issue 12): (against, scene, solver, quantity, abs, rel,
    /// gated), in order — the rules of `tolerances.toml`, then the reference sets' catch-alls in
    /// the registry's order (a label's rules never interact with another's).
    const FROZEN: [(Against, &str, &str, &str, f64, f64, bool); 24] = [
        (Against::Golden, "*", "*", "iterations", 2.0, 0.05, true),
        (Against::Golden, "*", "*", "residual", INF, 0.0, false),
        (Against::Golden, "*", "*", "*", 1e-9, 1e-7, true),
        (contact::EXACT, "*", "contact", "fx_over_fn", 1e-5, 0.0, true),
        (contact::EXACT, "*", "contact", "delay_ratio", 0.005, 0.0, true),
        (contact::EXACT, "*", "contact", "loop_area", 0.0, 0.02, true),
        (contact::EXACT, "*", "contact", "steady_value", 1e-5, 0.0, true),
        (envelope::ENVELOPE, "*", "contact", "fx_over_fn", 1e-5, 0.0, true),
        (envelope::ENVELOPE, "*", "contact", "fy_over_fn", 1e-5, 0.0, true),
        (envelope::ENVELOPE, "*", "contact", "mz_over_fn_a", 1e-5, 0.0, true),
        (table::TABLE, "*", "contact", "fx_over_fn", 1e-5, 0.0, true),
        (table::TABLE, "*", "contact", "fy_over_fn", 1e-5, 0.0, true),
        (table::TABLE, "*", "contact", "mz_over_fn_a", 1e-5, 0.0, true),
        (envelope::NONHERTZ, "*", "contact", "fx_over_fn", 1e-5, 0.0, true),
        (envelope::NONHERTZ, "*", "contact", "fy_over_fn", 1e-5, 0.0, true),
        (envelope::NONHERTZ, "*", "contact", "mz_over_fn_a", 1e-5, 0.0, true),
        (contact::FASTSIM, "*", "fastsim", "fx_over_fn", 0.0015, 0.0, true),
        (contact::FASTSIM, "*", "uba", "fx_over_fn", 0.0015, 0.0, true),
        (contact::EXACT, "*", "*", "*", INF, 0.0, false),
        (contact::FASTSIM, "*", "*", "*", INF, 0.0, false),
        (envelope::ENVELOPE, "*", "*", "*", INF, 0.0, false),
        (envelope::NONHERTZ, "*", "*", "*", INF, 0.0, false),
        (table::TABLE, "*", "*", "*", INF, 0.0, false),
        (thesis::AGAINST, "*", "*", "*", INF, 0.0, false),
    ];

    #[test]
    fn the_defaults_reproduce_the_compiled_table_exactly() {
        // The labels of the frozen table only: a reference set added since brings its own rules.
        let rules: Vec<&Rule> = defaults().iter().filter(|r| FROZEN.iter().any(|f| f.0 == r.against)).collect();
        assert_eq!(rules.len(), FROZEN.len());
        let from_file = defaults().iter().take_while(|r| !r.origin.contains("catch-all")).count();
        // The frozen labels' rules of the file come first in it (a later set's rules follow).
        let frozen_in_file = rules.iter().take_while(|r| !r.origin.contains("catch-all")).count();
        for (n, (r, f)) in rules.iter().zip(FROZEN).enumerate() {
            let got = (r.against, r.scene.as_str(), r.solver.as_str(), r.quantity.as_str(), r.abs, r.rel, r.gated);
            // Bit for bit: the numbers as TOML reads them are the Rust literals.
            assert_eq!((got.0, got.1, got.2, got.3, got.6), (f.0, f.1, f.2, f.3, f.6), "rule[{n}]");
            assert_eq!((got.4.to_bits(), got.5.to_bits()), (f.4.to_bits(), f.5.to_bits()), "rule[{n}] numbers");
            assert!(!r.why.trim().is_empty(), "rule[{n}] says why");
            if n < frozen_in_file {
                assert_eq!(r.origin, format!("{DEFAULT_FILE} rule[{n}]"));
            }
        }
        // Every reference set's catch-all comes from the registry, none from the file.
        assert_eq!(defaults().len() - from_file, references::labels().count());
        assert!(defaults()[from_file..].iter().all(|r| r.is_catch_all() && !r.gated && r.abs == INF));
    }

    #[test]
    fn every_label_ends_in_a_catch_all_and_previous_is_judged_as_golden() {
        for label in default_labels() {
            let last = defaults().iter().rposition(|r| r.against == label).expect("a rule per label");
            assert!(defaults()[last].is_catch_all(), "{label:?}: last rule {:?}", defaults()[last]);
        }
        assert!(std::ptr::eq(
            rule(Against::Previous, "sine_f10_mu10", "contact", "iterations"),
            rule(Against::Golden, "sine_f10_mu10", "contact", "iterations")
        ));
        let r = rule(envelope::ENVELOPE, "mu_ramp", "contact", "fx_over_fn");
        assert_eq!((r.abs, r.gated), (1e-5, true));
        let r = rule(envelope::ENVELOPE, "mu_ramp", "contact", "fy_over_fn");
        assert_eq!((r.abs, r.gated), (1e-5, true));
        let r = rule(envelope::ENVELOPE, "mu_ramp", "uba", "fx_over_fn");
        assert_eq!((r.allowed(0.3), r.gated), (INF, false));
    }
}
