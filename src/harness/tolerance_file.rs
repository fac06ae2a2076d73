//! Tolerances as reviewed data (issue 15): TOML files of rules that take precedence over the
//! compiled defaults ([`super::tolerances::RULES`], which stay the project's default and reproduce
//! the gate exactly when no file is given). Sources, first match wins: each `--tolerances FILE`
//! in order, then each suite folder's `tolerances.toml`, then the compiled rules.
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
//! why = "our model's accepted gap against the exact theory"
//! ```
//!
//! An unknown key, a label no comparison uses, or a rule that matches no comparison of the run is
//! an input error naming the file and the rule.

use super::compare::Finding;
use crate::error::InputError;
use crate::scene::reader::{Range, Section};
use std::path::{Path, PathBuf};

/// One rule read from a file.
#[derive(Debug, Clone, PartialEq)]
pub struct FileRule {
    /// `FILE rule[n]`, for messages.
    pub origin: String,
    pub against: String,
    pub scene: String,
    pub solver: String,
    pub quantity: String,
    pub abs: f64,
    pub rel: f64,
    pub gated: bool,
    pub why: String,
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

impl FileRule {
    fn covers(&self, f: &Finding) -> bool {
        self.against == f.against.label()
            && glob(&self.scene, &f.scene)
            && glob(&self.solver, &f.solver)
            && glob(&self.quantity, &f.quantity)
    }
}

/// Read a rule file; `labels` are the comparison labels a rule may name.
pub fn load(path: &Path, labels: &[&str]) -> Result<Vec<FileRule>, InputError> {
    let name = path.display().to_string();
    let text = crate::safety::read::read_text(path, crate::safety::read::SCENE_LIMIT_BYTES, "tolerance file").map_err(
        |e| InputError::new("--tolerances", &name, format!("a readable TOML file of [[rule]] tables ({e})")),
    )?;
    let doc: toml::Table = text.parse().map_err(|e: toml::de::Error| {
        InputError::new(&name, "malformed TOML", format!("valid TOML ({})", e.message()))
    })?;
    if let Some(key) = doc.keys().find(|k| *k != "rule") {
        return Err(InputError::new(format!("{name} {key}"), "given", "only [[rule]] tables"));
    }
    let Some(toml::Value::Array(items)) = doc.get("rule") else {
        return Err(InputError::new(&name, "no [[rule]] table", "at least one [[rule]] table"));
    };
    let allowed_against = format!("one of {}", labels.join(", "));
    let mut out = Vec::new();
    for (n, item) in items.iter().enumerate() {
        let origin = format!("{name} rule[{n}]");
        let toml::Value::Table(t) = item else {
            return Err(InputError::new(&origin, "not a table", "a [[rule]] table"));
        };
        let mut s = Section::new(origin.clone(), t);
        let against = s.str("against", &allowed_against)?.to_string();
        if !labels.contains(&against.as_str()) {
            return Err(InputError::new(s.field("against"), format!("{against:?}"), allowed_against));
        }
        let pattern = |s: &mut Section, key: &str| -> Result<String, InputError> {
            Ok(s.opt_str(key, "a name or a pattern with *")?.unwrap_or("*").to_string())
        };
        let (scene, solver, quantity) =
            (pattern(&mut s, "scene")?, pattern(&mut s, "solver")?, pattern(&mut s, "quantity")?);
        let tol = Range::new(0.0, true, f64::INFINITY, true);
        let abs = s.f64("abs", tol)?;
        let rel = s.opt_f64("rel", tol)?.unwrap_or(0.0);
        let gated = s.opt_bool("gated")?.unwrap_or(true);
        let why = s.str("why", "the reason for this tolerance (reviewed with it)")?.to_string();
        s.finish()?;
        out.push(FileRule { origin, against, scene, solver, quantity, abs, rel, gated, why });
    }
    Ok(out)
}

/// Every rule file of a run: the `--tolerances` files, then each suite folder's `tolerances.toml`.
pub fn sources(given: &[PathBuf], suite_dirs: &[PathBuf]) -> Vec<PathBuf> {
    let suite_files = suite_dirs.iter().map(|d| d.join("tolerances.toml")).filter(|p| p.is_file());
    given.iter().cloned().chain(suite_files).collect()
}

/// Re-judge every finding by the first file rule that covers it (the compiled rule stays where
/// none does). A rule that covers no finding is an error: a pattern that matches nothing is a
/// typo, not a tolerance.
pub fn apply(rules: &[FileRule], findings: &mut [Finding]) -> Result<(), InputError> {
    let mut used = vec![false; rules.len()];
    for f in findings.iter_mut() {
        if let Some(i) = rules.iter().position(|r| r.covers(f)) {
            used[i] = true;
            f.allowed = rules[i].abs + rules[i].rel * f.theirs.abs();
            f.gated = rules[i].gated;
        }
    }
    if let Some(i) = used.iter().position(|u| !u) {
        let r = &rules[i];
        return Err(InputError::new(
            &r.origin,
            format!("against {:?}, scene {:?}, solver {:?}, quantity {:?}", r.against, r.scene, r.solver, r.quantity),
            "a rule that matches at least one comparison of this run (check the names and patterns)",
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::glob;

    #[test]
    fn glob_matches_whole_names() {
        assert!(glob("*", "anything") && glob("sine_*", "sine_f10") && !glob("sine_*", "step_sine"));
        assert!(glob("*_f10*", "sine_f10_mu04") && glob("a*b*c", "aXbYc") && !glob("a*b*c", "aXcYb"));
        assert!(glob("exact", "exact") && !glob("exact", "exactly") && glob("a*a", "aa") && !glob("a*a", "a"));
    }
}
