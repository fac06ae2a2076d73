//! Tolerance files (issue 15): TOML files of `[[rule]]` tables. The project's defaults are one
//! (`tolerances`, `tolerances.toml`, embedded in the binary); a run's files layer over
//! them. Sources, first match wins: each `--tolerances FILE` in order, then each suite folder's
//! `tolerances.toml`, then the defaults (which alone decide when no file is given).
//!
//! ```toml
//! [[rule]]
//! against = "CONTACT"          # golden, previous, or a reference set's label
//! scene = "sine_*"             # `*` matches any run of characters (default "*")
//! solver = "uba"               # default "*"
//! quantity = "fx_over_fn"      # a history column or metric (default "*")
//! abs = 0.05                   # |ours − theirs| ≤ abs + rel·|theirs|
//! rel = 0.0                    # default 0
//! gated = true                 # default true: a miss fails the gate
//! disable = false              # default false: see below
//! why = "our model's accepted gap against the exact theory"
//! ```
//!
//! No gate is disabled in silence (issue 30): a run's rule that loosens a comparison the defaults
//! gate (more allowed, or not gated) is listed in every verdict with its file, rule, why and the
//! comparisons it decided ([`Loosening`]); a rule that makes a gate unable to fail — a gated
//! `abs` or `rel` at or beyond [`HUGE_TOLERANCE`], `gated = false` over a comparison the defaults
//! gate, or a bare `*` over every scene, solver and quantity — is refused unless it says
//! `disable = true`; `check --strict` refuses every loosening.
//!
//! `abs` is required for a gated rule; a reported rule (`gated = false`) may omit it and then has
//! no tolerance (∞: TOML's `inf` is not accepted, there is one way to say it). An unknown key, a
//! label no comparison uses, or — in a run's files, not in the defaults — a rule that matches no
//! comparison of the run is an input error naming the file and the rule.

use crate::comparison::against::Against;
use crate::comparison::finding::Finding;
pub use crate::comparison::rule::{glob, Rule};
use crate::error::InputError;
use crate::scene::keys::{key, Absent, Allowed, Keys};
use crate::scene::reader::{Range, Section};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A tolerance, absolute or relative.
const TOLERANCE: Range = Range::new(0.0, true, f64::INFINITY, true);

/// `[[rule]]`'s keys (`<!-- keys:tolerance -->`); `against`'s labels are those of
/// [`crate::comparison::tolerances::labels`] (a test checks the list).
pub const KEYS: Keys = Keys {
    id: "tolerance",
    owner: file!(),
    keys: &[
        key(
            "against",
            "–",
            Allowed::Text("`golden`, `previous`, `CONTACT`, `CONTACT FASTSIM`, `CONTACT envelope`, `CONTACT non-Hertzian`, `CONTACT test table`, `thesis`, `CONTACT friction`, `CONTACT friction tight`, `CONTACT friction, not gated`, `CONTACT friction variants`, `CONTACT friction variants tight`, `CONTACT friction variants, not gated`, `CONTACT public`, `CONTACT wheel-rail`"),
            Absent::Required,
            r#"the comparison the rule decides: `against = "CONTACT"`"#,
        ),
        key("scene", "–", Allowed::Text("a scene name or a pattern with `*`"), Absent::Choice("*"), r#"the scenes it covers: `scene = "sine_*"`"#),
        key("solver", "–", Allowed::Text("a model name or a pattern"), Absent::Choice("*"), r#"the models it covers: `solver = "uba"`"#),
        key(
            "quantity",
            "–",
            Allowed::Text("a history column or a metric name, or a pattern"),
            Absent::Choice("*"),
            r#"the compared quantity: `quantity = "delay_ratio"`"#,
        ),
        key(
            "abs",
            "the quantity's",
            Allowed::Number(TOLERANCE, ""),
            Absent::Text("required for a gated rule"),
            r#"passes when \|ours − theirs\| ≤ abs + rel·\|theirs\|; a reported rule may omit it (no tolerance): `abs = 1e-9`"#,
        ),
        key("rel", "–", Allowed::Number(TOLERANCE, ""), Absent::Num(0.0), r#"the relative part: `rel = 1e-7`"#),
        key(
            "gated",
            "–",
            Allowed::Bool,
            Absent::Text("`true`"),
            r#"a miss of a gated rule fails the gate; a reported one is shown, never judged: `gated = false`"#,
        ),
        key(
            "disable",
            "–",
            Allowed::Bool,
            Absent::Text("`false`"),
            r#"said explicitly with its `why`: this rule may switch a gate off (a tolerance at or beyond 1e9, `gated = false` on a comparison the defaults gate, a bare `*` over everything); without it such a rule is refused (exit 2), and `check --strict` refuses every loosening: `disable = true`"#,
        ),
        key(
            "why",
            "–",
            Allowed::Text("a string: the reason for this tolerance"),
            Absent::Required,
            r#"the reason, reviewed with the number: `why = "floating-point noise"`"#,
        ),
    ],
};

/// Read a rule file; `labels` are the comparisons a rule may name.
pub fn load(path: &Path, labels: &[Against]) -> Result<Vec<Rule>, InputError> {
    let name = path.display().to_string();
    let text = crate::safety::read::read_text(path, crate::safety::read::SCENE_LIMIT_BYTES, "tolerance file").map_err(
        |e| InputError::new("--tolerances", &name, format!("a readable TOML file of [[rule]] tables ({e})")),
    )?;
    let rules = parse(&text, &name, labels)?;
    rules.iter().try_for_each(refuse_unfailable)?;
    Ok(rules)
}

/// A tolerance this large lets nothing fail: a rule of a run's file with a gated `abs` or `rel`
/// at or beyond it must say `disable = true`.
pub const HUGE_TOLERANCE: f64 = 1e9;

/// A rule of a run's file that would make its gates unable to fail, without `disable = true`:
/// a gated tolerance at or beyond [`HUGE_TOLERANCE`], or a bare `*` over everything.
fn refuse_unfailable(r: &Rule) -> Result<(), InputError> {
    if r.disable {
        return Ok(());
    }
    let said = "disable = true with its why, to switch a gate off (a tolerance below 1e9 otherwise)";
    if r.gated && (r.abs >= HUGE_TOLERANCE || r.rel >= HUGE_TOLERANCE) {
        return Err(InputError::new(&r.origin, format!("abs = {:e}, rel = {:e}", r.abs, r.rel), said));
    }
    if r.is_catch_all() {
        return Err(InputError::new(
            &r.origin,
            "scene, solver and quantity all \"*\"",
            format!("a rule naming a scene, solver or quantity, or {said}"),
        ));
    }
    Ok(())
}

/// A run's rule that loosened comparisons the defaults gate: listed in every verdict.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Loosening {
    /// `FILE rule[n]`.
    pub origin: String,
    /// The comparison label.
    pub against: &'static str,
    /// What it covers and allows, e.g. `scene "*" solver "uba" quantity "fx" abs 0.1 rel 0 gated`.
    pub rule: String,
    pub why: String,
    /// Comparisons it decided.
    pub decided: usize,
    /// Of those, comparisons the defaults gate that it allows more on, or does not gate.
    pub loosened: usize,
    /// Said `disable = true`.
    pub disable: bool,
}

impl std::fmt::Display for Loosening {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}: against {} {}{} — decided {} comparison(s), loosened {} the defaults gate; why: {}",
            self.origin,
            self.against,
            self.rule,
            if self.disable { " (disable = true)" } else { "" },
            self.decided,
            self.loosened,
            self.why
        )
    }
}

/// Parse the text of a rule file called `name` (in messages and each rule's origin).
pub fn parse(text: &str, name: &str, labels: &[Against]) -> Result<Vec<Rule>, InputError> {
    let doc = crate::scene::reader::parse_toml(text, name)?;
    if let Some(key) = doc.keys().find(|k| *k != "rule") {
        return Err(InputError::new(format!("{name} {key}"), "given", "only [[rule]] tables"));
    }
    let Some(toml::Value::Array(items)) = doc.get("rule") else {
        return Err(InputError::new(name, "no [[rule]] table", "at least one [[rule]] table"));
    };
    let names: Vec<&str> = labels.iter().map(|l| l.label()).collect();
    let allowed_against = format!("one of {}", names.join(", "));
    let mut out = Vec::new();
    for (n, item) in items.iter().enumerate() {
        let origin = format!("{name} rule[{n}]");
        let toml::Value::Table(t) = item else {
            return Err(InputError::new(&origin, "not a table", "a [[rule]] table"));
        };
        let mut s = Section::new(origin.clone(), t).declare(&KEYS);
        let label = s.str("against", &allowed_against)?;
        let Some(&against) = labels.iter().find(|l| l.label() == label) else {
            return Err(InputError::new(s.field("against"), format!("{label:?}"), allowed_against));
        };
        let pattern = |s: &mut Section, key: &str| -> Result<String, InputError> {
            Ok(s.opt_text(key)?.unwrap_or("*").to_string())
        };
        let (scene, solver, quantity) =
            (pattern(&mut s, "scene")?, pattern(&mut s, "solver")?, pattern(&mut s, "quantity")?);
        let gated = s.opt_bool("gated")?.unwrap_or(true);
        let abs = match s.opt_num("abs")? {
            Some(abs) => abs,
            None if !gated => f64::INFINITY,
            None => {
                return Err(InputError::new(
                    s.field("abs"),
                    "missing",
                    format!(
                        "required for a gated rule: {} (a reported rule, gated = false, may omit it)",
                        TOLERANCE.describe()
                    ),
                ))
            }
        };
        let rel = s.num_or_default("rel")?;
        let disable = s.opt_bool("disable")?.unwrap_or(false);
        let why = s.text("why")?.to_string();
        s.finish()?;
        out.push(Rule { origin, against, scene, solver, quantity, abs, rel, gated, disable, why, suite: None });
    }
    Ok(out)
}

/// Every rule file of a run: the `--tolerances` files (every scene), then each suite folder's
/// `tolerances.toml` with the folder's name (that suite's scenes only).
pub fn sources(given: &[PathBuf], suite_dirs: &[PathBuf]) -> Vec<(PathBuf, Option<String>)> {
    let suite_files = suite_dirs.iter().filter_map(|d| {
        let path = d.join(crate::suite::TOLERANCE_FILE);
        path.is_file().then(|| (path, d.file_name().map(|n| n.to_string_lossy().to_string())))
    });
    given.iter().map(|p| (p.clone(), None)).chain(suite_files).collect()
}

/// Re-judge every finding by the first file rule that covers it (the default rule stays where
/// none does), and return the rules that loosened a comparison the defaults gate. A rule that
/// covers no finding is an error — a pattern that matches nothing is a typo, not a tolerance —
/// unless `elsewhere` says it is meant for comparisons this run does not make (a shard's check:
/// scenes of other shards); so is a rule that ungates a default-gated comparison without
/// `disable = true`.
pub fn apply(
    rules: &[Rule],
    findings: &mut [Finding],
    suite_of: &BTreeMap<String, String>,
    elsewhere: impl Fn(&Rule) -> bool,
) -> Result<Vec<Loosening>, InputError> {
    let mut decided = vec![0usize; rules.len()];
    let mut loosened = vec![0usize; rules.len()];
    // A suite's own rule covers its suite's scenes only.
    let in_scope = |r: &Rule, scene: &str| r.suite.as_ref().is_none_or(|s| suite_of.get(scene) == Some(s));
    for f in findings.iter_mut() {
        let covers = |r: &Rule| r.covers(f.against, &f.scene, &f.solver, &f.quantity) && in_scope(r, &f.scene);
        if let Some(i) = rules.iter().position(covers) {
            let r = &rules[i];
            let allowed = r.allowed(f.theirs);
            decided[i] += 1;
            if f.gated && (!r.gated || allowed.partial_cmp(&f.allowed).is_none_or(std::cmp::Ordering::is_gt)) {
                if !r.gated && !r.disable {
                    return Err(InputError::new(
                        &r.origin,
                        format!(
                            "gated = false over {} {} {} against {}",
                            f.scene,
                            f.solver,
                            f.quantity,
                            r.against.label()
                        ),
                        "disable = true with its why, to switch off a comparison the defaults gate",
                    ));
                }
                loosened[i] += 1;
            }
            f.allowed = allowed;
            f.gated = r.gated;
        }
    }
    if let Some(i) = (0..rules.len()).find(|&i| decided[i] == 0 && !elsewhere(&rules[i])) {
        let r = &rules[i];
        return Err(InputError::new(
            &r.origin,
            format!(
                "against {:?}, scene {:?}, solver {:?}, quantity {:?}",
                r.against.label(),
                r.scene,
                r.solver,
                r.quantity
            ),
            "a rule that matches at least one comparison of this run (check the names and patterns)",
        ));
    }
    Ok((0..rules.len())
        .filter(|&i| loosened[i] > 0)
        .map(|i| {
            let r = &rules[i];
            Loosening {
                origin: r.origin.clone(),
                against: r.against.label(),
                rule: format!(
                    "scene {:?} solver {:?} quantity {:?} abs {:e} rel {:e} {}",
                    r.scene,
                    r.solver,
                    r.quantity,
                    r.abs,
                    r.rel,
                    if r.gated { "gated" } else { "not gated" }
                ),
                why: r.why.clone(),
                decided: decided[i],
                loosened: loosened[i],
                disable: r.disable,
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::{glob, parse};
    use crate::comparison::references::contact;
    use crate::comparison::tolerances::labels;

    fn one(body: &str) -> Result<super::Rule, String> {
        let text = format!("[[rule]]\n{body}\nwhy = \"test\"\n");
        parse(&text, "t.toml", &labels()).map(|mut v| v.remove(0)).map_err(|e| e.to_string())
    }

    #[test]
    fn a_reported_rule_may_omit_its_tolerance_a_gated_one_may_not() {
        let r = one("against = \"CONTACT FASTSIM\"\ngated = false").unwrap();
        assert_eq!((r.against, r.abs, r.rel, r.gated), (contact::FASTSIM, f64::INFINITY, 0.0, false));
        assert_eq!(r.origin, "t.toml rule[0]");
        let r = one("against = \"previous\"\nquantity = \"fx_*\"\nabs = 1e-3\nrel = 0.5").unwrap();
        assert_eq!((r.abs, r.rel, r.gated, r.quantity.as_str()), (1e-3, 0.5, true, "fx_*"));
        let e = one("against = \"golden\"").unwrap_err();
        assert!(e.contains("t.toml rule[0].abs") && e.contains("required for a gated rule"), "{e}");
        // TOML's inf is refused: no tolerance is said by leaving abs out of a reported rule.
        let e = one("against = \"golden\"\ngated = false\nabs = inf").unwrap_err();
        assert!(e.contains("rule[0].abs") && e.contains("inf"), "{e}");
        let e = one("against = \"golden\"\nabs = -1.0").unwrap_err();
        assert!(e.contains("rule[0].abs"), "{e}");
    }

    #[test]
    fn glob_matches_whole_names() {
        assert!(glob("*", "anything") && glob("sine_*", "sine_f10") && !glob("sine_*", "step_sine"));
        assert!(glob("*_f10*", "sine_f10_mu04") && glob("a*b*c", "aXbYc") && !glob("a*b*c", "aXcYb"));
        assert!(glob("exact", "exact") && !glob("exact", "exactly") && glob("a*a", "aa") && !glob("a*a", "a"));
    }

    /// The declared `against` lists exactly the labels a run's rule may name, in their order.
    #[test]
    fn the_declared_labels_are_the_comparisons() {
        let Some(super::Allowed::Text(text)) = super::KEYS.get("against").map(|k| k.allowed) else {
            panic!("against is declared as a text")
        };
        let want: Vec<String> = labels().iter().map(|l| format!("`{}`", l.label())).collect();
        assert_eq!(text, want.join(", "));
    }
}
