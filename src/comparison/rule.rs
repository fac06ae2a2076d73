//! A tolerance rule (issue 15): which comparisons it covers, its tolerance, whether a miss fails
//! the gate, and the first-match lookup over a list of rules. Tolerance files are read into
//! rules (`tolerance_file`); the defaults are the rules of `tolerances.toml` (`tolerances`).

use crate::comparison::against::Against;
use std::sync::LazyLock;

/// One rule: which comparisons it covers, its tolerance, and whether a miss fails the gate.
#[derive(Debug, Clone, PartialEq)]
pub struct Rule {
    /// Where it was read, `FILE rule[n]` (messages).
    pub origin: String,
    pub against: Against,
    /// Scene name or `*` pattern ([`glob`]).
    pub scene: String,
    /// Solver name or pattern.
    pub solver: String,
    /// Column (`fx_over_fn`, `iterations`, …) or metric name, or pattern.
    pub quantity: String,
    /// Absolute tolerance; ∞ for a reported rule given without one.
    pub abs: f64,
    pub rel: f64,
    /// A miss fails `creepbench check` (exit 1); otherwise it is only reported.
    pub gated: bool,
    /// Said explicitly: this rule may make a gate unable to fail (`disable = true`, with its why).
    pub disable: bool,
    pub why: String,
    /// The suite folder (its name) whose own `tolerances.toml` gave the rule: it covers that
    /// suite's scenes only. `None` for `--tolerances` files and the defaults: every scene.
    pub suite: Option<String>,
}

impl Rule {
    /// Allowed |difference| for a reference value.
    pub fn allowed(&self, theirs: f64) -> f64 {
        self.abs + self.rel * theirs.abs()
    }

    /// Whether the rule covers this comparison (the label exactly, the names by pattern).
    pub fn covers(&self, against: Against, scene: &str, solver: &str, quantity: &str) -> bool {
        self.against == against
            && glob(&self.scene, scene)
            && glob(&self.solver, solver)
            && glob(&self.quantity, quantity)
    }

    /// A rule that covers every comparison of its label, whatever the scene, solver and quantity:
    /// the last word for that label (it need not match anything on a given run).
    pub fn is_catch_all(&self) -> bool {
        [&self.scene, &self.solver, &self.quantity].iter().all(|p| p.as_str() == "*")
    }
}

/// `*`-wildcard match of the whole text.
pub fn glob(pattern: &str, text: &str) -> bool {
    let parts: Vec<&str> = pattern.split('*').collect();
    if parts.len() == 1 {
        return pattern == text;
    }
    let (first, last) = (parts[0], parts[parts.len() - 1]);
    if !text.starts_with(first) || text.len() < first.len() + last.len() || !text.ends_with(last) {
        return false;
    }
    let mut rest = &text[first.len()..text.len() - last.len()];
    for part in &parts[1..parts.len() - 1] {
        match rest.find(part) {
            Some(i) => rest = &rest[i + part.len()..],
            None => return false,
        }
    }
    true
}

/// What a comparison no rule covers gets: reported, no tolerance. (Every label of the defaults
/// ends in a catch-all, so it is never used by them.)
static NO_RULE: LazyLock<Rule> = LazyLock::new(|| reported("no rule".into(), Against::Golden, "no rule"));

/// The last rule of a label: every comparison of it that no rule before covers is reported, with
/// no tolerance (a reference set's entry in the registry gives its reason).
pub fn catch_all(against: Against, why: &str) -> Rule {
    reported(format!("{:?} catch-all (reference set registry)", against.label()), against, why)
}

/// A rule over every comparison of `against` that reports and never judges (no tolerance).
fn reported(origin: String, against: Against, why: &str) -> Rule {
    Rule {
        origin,
        against,
        scene: "*".into(),
        solver: "*".into(),
        quantity: "*".into(),
        abs: f64::INFINITY,
        rel: 0.0,
        gated: false,
        disable: false,
        why: why.into(),
        suite: None,
    }
}

/// The first of `rules` covering this comparison; `previous` is judged as `golden`.
pub fn first<'r>(rules: &'r [Rule], against: Against, scene: &str, solver: &str, quantity: &str) -> &'r Rule {
    let against = if against == Against::Previous { Against::Golden } else { against };
    rules.iter().find(|r| r.covers(against, scene, solver, quantity)).unwrap_or(&NO_RULE)
}
