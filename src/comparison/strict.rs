//! `check --strict` refuses a run's rule that can loosen a default gate before any scene runs
//! (issue 48 item 8): a CI job learns of it at once, not after the whole suite. A rule can loosen
//! when a default rule of its label that may decide some comparison it covers gates that
//! comparison and the rule allows more (a larger `abs` or `rel`) or does not gate it. Patterns are
//! compared as `*` globs, erring on the side of a refusal where two of them may overlap; the
//! verdict's own check of every decided comparison ([`crate::comparison::tolerance_file::apply`])
//! stays behind it.

use crate::comparison::against::Against;
use crate::comparison::rule::{glob, Rule};
use crate::error::InputError;

/// The first of `rules` that can loosen one of `defaults`' gates, refused naming both.
pub fn refuse_loosening(rules: &[Rule], defaults: &[Rule]) -> Result<(), InputError> {
    for r in rules {
        if let Some(d) = loosened_default(r, defaults) {
            return Err(InputError::new(
                &r.origin,
                describe(r),
                format!(
                    "with --strict, no loosening of a default gate (checked before any scene runs): it covers \
                     comparisons that {} gates with {}",
                    d.origin,
                    describe(d)
                ),
            ));
        }
    }
    Ok(())
}

/// The default rule whose gate `r` can loosen: the defaults of its label (`previous` is judged
/// as `golden`) in order, up to the first that decides everything `r` covers.
fn loosened_default<'d>(r: &Rule, defaults: &'d [Rule]) -> Option<&'d Rule> {
    let label = if r.against == Against::Previous { Against::Golden } else { r.against };
    for d in defaults.iter().filter(|d| d.against == label) {
        if overlap(r, d) && looser(r, d) {
            return Some(d);
        }
        if subsumes(d, r) {
            return None;
        }
    }
    None
}

/// `r` allows more than the gated `d` for some reference value, or does not gate.
fn looser(r: &Rule, d: &Rule) -> bool {
    d.gated && (!r.gated || r.abs > d.abs || r.rel > d.rel)
}

/// Some comparison may be covered by both rules.
fn overlap(a: &Rule, b: &Rule) -> bool {
    patterns_overlap(&a.scene, &b.scene)
        && patterns_overlap(&a.solver, &b.solver)
        && patterns_overlap(&a.quantity, &b.quantity)
}

/// `d` covers every comparison `r` covers.
fn subsumes(d: &Rule, r: &Rule) -> bool {
    pattern_subsumes(&d.scene, &r.scene)
        && pattern_subsumes(&d.solver, &r.solver)
        && pattern_subsumes(&d.quantity, &r.quantity)
}

/// Some name may match both patterns: a name matches the other pattern; two patterns with `*`
/// overlap unless their fixed beginnings or ends differ.
fn patterns_overlap(p: &str, q: &str) -> bool {
    match (p.contains('*'), q.contains('*')) {
        (false, _) => glob(q, p),
        (_, false) => glob(p, q),
        (true, true) => {
            let (lp, lq) = (leading(p), leading(q));
            let (tp, tq) = (trailing(p), trailing(q));
            (lp.starts_with(lq) || lq.starts_with(lp)) && (tp.ends_with(tq) || tq.ends_with(tp))
        }
    }
}

/// Every name `r` matches, `d` matches (`d` a name, `*`, or one `*` between a fixed beginning
/// and end; otherwise not known, so no).
fn pattern_subsumes(d: &str, r: &str) -> bool {
    if d == r || d == "*" {
        return true;
    }
    if !r.contains('*') {
        return glob(d, r);
    }
    match d.split_once('*') {
        Some((a, b)) if !b.contains('*') => leading(r).starts_with(a) && trailing(r).ends_with(b),
        _ => false,
    }
}

/// The fixed text before a pattern's first `*`.
fn leading(p: &str) -> &str {
    p.split('*').next().unwrap_or("")
}

/// The fixed text after a pattern's last `*`.
fn trailing(p: &str) -> &str {
    p.rsplit('*').next().unwrap_or("")
}

/// A rule's reach and tolerance, short.
fn describe(r: &Rule) -> String {
    let gate = if r.gated { format!("abs {:e} rel {:e}", r.abs, r.rel) } else { "not gated".into() };
    format!("{} {}/{}/{} {gate}", r.against.label(), r.scene, r.solver, r.quantity)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rule(against: Against, [scene, solver, quantity]: [&str; 3], abs: f64, rel: f64, gated: bool) -> Rule {
        Rule {
            origin: format!("{scene}/{solver}/{quantity}"),
            against,
            scene: scene.into(),
            solver: solver.into(),
            quantity: quantity.into(),
            abs,
            rel,
            gated,
            disable: false,
            why: "test".into(),
            suite: None,
        }
    }

    /// The shape of the golden defaults: iterations, residual (reported), then everything.
    fn defaults() -> Vec<Rule> {
        vec![
            rule(Against::Golden, ["*", "*", "iterations"], 2.0, 0.05, true),
            rule(Against::Golden, ["*", "*", "residual"], f64::INFINITY, 0.0, false),
            rule(Against::Golden, ["*", "*", "*"], 1e-9, 1e-7, true),
        ]
    }

    #[test]
    fn a_rule_that_allows_more_or_ungates_is_found_before_anything_runs() {
        let d = defaults();
        for (r, loosens) in [
            (rule(Against::Golden, ["a_one", "uba", "fx_over_fn"], 0.01, 0.0, true), true),
            (rule(Against::Previous, ["a_one", "uba", "fx_over_fn"], 0.01, 0.0, true), true),
            (rule(Against::Golden, ["a_one", "uba", "fx_over_fn"], 0.0, 0.0, true), false),
            (rule(Against::Golden, ["*", "uba", "fx_over_fn"], 0.0, 1e-6, true), true),
            (rule(Against::Golden, ["a_*", "*", "*"], 0.0, 0.0, false), true),
            // Looser than iterations' default only where the catch-all gates tighter: still loose.
            (rule(Against::Golden, ["*", "*", "iter*"], 1.0, 0.0, true), true),
            // Iterations: tighter than its own default, which decides every one of them.
            (rule(Against::Golden, ["*", "*", "iterations"], 1.0, 0.0, true), false),
            // The residual is reported by default: gating it is no loosening.
            (rule(Against::Golden, ["*", "*", "residual"], 1.0, 0.0, true), false),
        ] {
            assert_eq!(loosened_default(&r, &d).is_some(), loosens, "{}", describe(&r));
        }
    }

    #[test]
    fn patterns_are_compared_as_globs() {
        assert!(patterns_overlap("sine_*", "sine_f10") && !patterns_overlap("sine_*", "step_1"));
        assert!(patterns_overlap("sine_*", "*_f10") && !patterns_overlap("a*b", "c*"));
        assert!(pattern_subsumes("*", "x*") && pattern_subsumes("sine_*", "sine_f*") && pattern_subsumes("a*", "ab"));
        assert!(!pattern_subsumes("sine_*", "*") && !pattern_subsumes("a*b", "a*"));
    }

    #[test]
    fn the_message_names_both_rules_and_the_flag() {
        let d = defaults();
        let r = rule(Against::Golden, ["a_one", "uba", "fx_over_fn"], 0.01, 0.0, true);
        let m = refuse_loosening(&[r], &d).unwrap_err().to_string();
        assert!(m.contains("a_one/uba/fx_over_fn") && m.contains("--strict") && m.contains("*/*/*"), "{m}");
    }
}
