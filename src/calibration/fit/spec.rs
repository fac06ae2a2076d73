//! The fit file (`creepbench fit FILE`), read and validated once: which model, against what,
//! which norm, which scenes are fitted and which held out, the free parameters with their bounds,
//! and the scene keys they set.
//!
//! ```toml
//! [fit]
//! name = "uba_sine"                      # the fit's id ([a-z0-9_]+)
//! model = "uba"                          # a built-in model or an [external.NAME] of the scenes
//! against = "solver:contact"             # a model run on the scenes as written, or "reference"
//! norm = "rms_df"                        # rms_df | max_df | delay_ratio | loop_area
//! suites = ["../scenes/thesis"]          # folders, relative to this file
//! fit = ["sine_f10_mu10", "sine_f30_mu10"]   # scene names or patterns (* and ?)
//! holdout = ["sine_f*_mu10"]             # judged with the fitted values, never fitted on
//! max_iterations = 200                   # Nelder–Mead iterations (default 200)
//!
//! [[fit.param]]
//! name = "k0"
//! start = 1.0
//! bounds = [0.3, 3.0]
//!
//! [set]                                  # dotted scene keys; "{k0}" is the parameter's value
//! "model.slope_reduction" = ["{k0}", 1.0, 0.0]
//! ```

use crate::error::InputError;
use crate::scene::keys::{bound, key, Absent, Allowed, Keys};
use crate::scene::reader::{Range, Section};
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// A fit file's tables, each documented under its own heading (`<!-- keys:fit -->`).
pub const FILE_KEYS: Keys = Keys {
    id: "fit",
    owner: file!(),
    keys: &[
        key("fit", "–", Allowed::Section, Absent::Required, "the fit: its keys below"),
        key("set", "–", Allowed::Section, Absent::Required, "the scene keys the parameters set"),
    ],
};

/// `[fit]`'s keys (`<!-- keys:fit -->`).
pub const KEYS: Keys = Keys {
    id: "fit",
    owner: file!(),
    keys: &[
        key(
            "name",
            "–",
            Allowed::Text("1 to 100 characters of `a-z`, `0-9`, `_`"),
            Absent::Required,
            r#"the fit's id and its output file: `name = "uba_sine"`"#,
        ),
        key(
            "model",
            "–",
            Allowed::Text("a built-in model or an `[external.NAME]` of the scenes"),
            Absent::Required,
            r#"the model whose parameters are fitted: `model = "uba"`"#,
        ),
        key(
            "against",
            "–",
            Allowed::Text("`\"solver:NAME\"` (a model of the scenes) or `\"reference\"`"),
            Absent::Required,
            r#"the target: a model run on the scenes as written (the fitted model too), or the reference data (CONTACT's results): `against = "solver:contact"`"#,
        ),
        key(
            "norm",
            "–",
            Allowed::Choice(&["rms_df", "max_df", "delay_ratio", "loop_area"], ""),
            Absent::Required,
            r#"what is minimised: RMS or largest \|Δf\| over every row, RMS of the delay-ratio difference, or RMS of the relative loop-area difference: `norm = "rms_df"`"#,
        ),
        key(
            "suites",
            "–",
            Allowed::Text("a non-empty list of folders of scenes, relative to the fit file"),
            Absent::Required,
            r#"where the scenes are: `suites = ["../scenes/thesis"]`"#,
        ),
        key(
            "fit",
            "–",
            Allowed::Text("a non-empty list of scene names or patterns (`*`, `?`)"),
            Absent::Required,
            r#"the scenes fitted on: `fit = ["sine_f10_mu10"]`"#,
        ),
        key(
            "holdout",
            "–",
            Allowed::Text("scene names or patterns (`*`, `?`)"),
            Absent::Text("none"),
            r#"judged with the fitted values, never fitted on (a scene both name is fitted): `holdout = ["sine_f*_mu06"]`"#,
        ),
        key(
            "max_iterations",
            "–",
            Allowed::Whole(1, 100_000, ""),
            Absent::Whole(200),
            r#"Nelder–Mead iterations: `max_iterations = 400`"#,
        ),
        key("param", "–", Allowed::Text("one or more `[[fit.param]]` tables"), Absent::Required, "the free parameters"),
    ],
};

/// `[[fit.param]]`'s keys (`<!-- keys:fit_param -->`).
pub const PARAM_KEYS: Keys = Keys {
    id: "fit_param",
    owner: file!(),
    keys: &[
        key(
            "name",
            "–",
            Allowed::Text("1 to 100 characters of `a-z`, `0-9`, `_` no other parameter has"),
            Absent::Required,
            r#"the parameter's name, written `"{name}"` in `[set]`: `name = "length_mm"`"#,
        ),
        key(
            "bounds",
            "the parameter's",
            Allowed::Numbers {
                range: Range::new(f64::NEG_INFINITY, false, f64::INFINITY, false),
                min_len: 2,
                max_len: 2,
                note: "`[min, max]`, min < max",
            },
            Absent::Required,
            r#"the values the fit may take: `bounds = [1.0, 100.0]`"#,
        ),
        key(
            "start",
            "the parameter's",
            Allowed::Text("a number in `[min, max]`"),
            Absent::Required,
            r#"where the search starts: `start = 13.44`"#,
        ),
    ],
};

/// The declared text of what `keys` allows for `k`, as a message says it.
fn allowed(keys: &Keys, k: &str) -> String {
    keys.get(k).map_or_else(String::new, |spec| spec.allowed.message())
}

/// What a fit minimises over its scenes (each a number ≥ 0, 0 when the model equals the target).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Norm {
    /// RMS of |Δf| over every row of every scene.
    RmsDf,
    /// Largest |Δf| over every row of every scene.
    MaxDf,
    /// RMS over the scenes with a delay ratio of the difference in delay ratio.
    DelayRatio,
    /// RMS over the scenes with a loop area of the relative loop-area difference.
    LoopArea,
}

impl Norm {
    pub const ALL: [Norm; 4] = [Norm::RmsDf, Norm::MaxDf, Norm::DelayRatio, Norm::LoopArea];

    pub fn name(self) -> &'static str {
        match self {
            Norm::RmsDf => "rms_df",
            Norm::MaxDf => "max_df",
            Norm::DelayRatio => crate::metrics::delay_ratio::NAME,
            Norm::LoopArea => crate::metrics::loop_area::NAME,
        }
    }

    fn parse(s: &str) -> Option<Norm> {
        Norm::ALL.into_iter().find(|n| n.name() == s)
    }
}

/// What the model is measured against.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// A model of the scenes (built-in or external; the fitted one too), run once on each scene
    /// as written, without `[set]`.
    Solver(String),
    /// The reference data held for each scene (CONTACT's results).
    Reference,
}

impl Target {
    pub fn label(&self) -> String {
        match self {
            Target::Solver(s) => format!("solver:{s}"),
            Target::Reference => "reference".into(),
        }
    }
}

/// A free parameter and its bounds (`min < start < max` is not required: `start` may sit on a bound).
#[derive(Debug, Clone, PartialEq)]
pub struct Param {
    pub name: String,
    pub start: f64,
    pub min: f64,
    pub max: f64,
}

impl Param {
    /// The optimiser's unbounded coordinate → the parameter: `min + (max − min)(1 + sin z)/2`
    /// (the sine transform of bounded simplex searches, as MINUIT's), inside the bounds for any z.
    pub fn value(&self, z: f64) -> f64 {
        (self.min + (self.max - self.min) * 0.5 * (1.0 + z.sin())).clamp(self.min, self.max)
    }

    /// The coordinate of a value inside the bounds (the inverse of [`Param::value`] on [−π/2, π/2]).
    pub fn coordinate(&self, x: f64) -> f64 {
        (2.0 * (x - self.min) / (self.max - self.min) - 1.0).clamp(-1.0, 1.0).asin()
    }
}

/// A validated fit file.
#[derive(Debug, Clone)]
pub struct FitSpec {
    /// The file it was read from (messages, the output's header).
    pub file: PathBuf,
    pub name: String,
    pub model: String,
    pub target: Target,
    pub norm: Norm,
    pub suites: Vec<PathBuf>,
    pub fit: Vec<String>,
    pub holdout: Vec<String>,
    pub max_iterations: u64,
    pub params: Vec<Param>,
    /// The scene keys set on every scene, values holding `"{name}"` placeholders.
    pub set: Vec<(String, Value)>,
}

fn is_name(s: &str) -> bool {
    !s.is_empty() && s.len() <= 100 && s.bytes().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == b'_')
}

/// The parameter names a value refers to (`"{name}"` strings, in arrays too).
fn placeholders(v: &Value, out: &mut Vec<String>) {
    match v {
        Value::String(s) if s.starts_with('{') && s.ends_with('}') && s.len() > 2 => {
            out.push(s[1..s.len() - 1].to_string())
        }
        Value::Array(a) => a.iter().for_each(|x| placeholders(x, out)),
        _ => {}
    }
}

/// `v` with each `"{name}"` replaced by that parameter's value.
pub fn substitute(v: &Value, values: &[(String, f64)]) -> Value {
    match v {
        Value::String(s) if s.starts_with('{') && s.ends_with('}') => {
            values.iter().find(|(n, _)| *n == s[1..s.len() - 1]).map_or_else(|| v.clone(), |(_, x)| Value::Float(*x))
        }
        Value::Array(a) => Value::Array(a.iter().map(|x| substitute(x, values)).collect()),
        other => other.clone(),
    }
}

impl FitSpec {
    /// Read (bounded) and validate a fit file.
    pub fn from_file(file: &Path) -> Result<FitSpec, crate::error::Error> {
        let text = crate::safety::read::read_text(file, crate::safety::read::SCENE_LIMIT_BYTES, "fit file")?;
        let doc = crate::scene::reader::parse_toml(&text, file.display().to_string())?;
        Ok(FitSpec::from_table(&doc, file)?)
    }

    /// Read and validate a fit file's table; `file` names it in every error.
    pub fn from_table(doc: &Table, file: &Path) -> Result<FitSpec, InputError> {
        let place = file.display().to_string();
        let in_file = |mut e: InputError| {
            e.field = format!("{place}: {}", e.field);
            e
        };
        Self::read(doc, file).map_err(in_file)
    }

    /// The fit file's tables in order: [fit] with its [[fit.param]], then [set].
    fn read(doc: &Table, file: &Path) -> Result<FitSpec, InputError> {
        let mut top = Section::new("", doc).declare(&FILE_KEYS);
        let mut f = top.table("fit")?.declare(&KEYS);
        let name = Self::name(&mut f)?;
        let model = f.text("model")?.to_string();
        let target = Self::target(&mut f)?;
        let norm = Self::norm(&mut f)?;
        let suites = Self::suites(&mut f, file)?;
        let fit = Self::fitted(&mut f)?;
        let holdout = Self::patterns(&mut f, "holdout")?;
        let max_iterations = f.whole_or_default("max_iterations")? as u64;
        let params = Self::params(&mut f)?;
        f.finish()?;
        let set = Self::set(&mut top, &params)?;
        top.finish()?;
        Ok(FitSpec {
            file: file.to_path_buf(),
            name,
            model,
            target,
            norm,
            suites,
            fit,
            holdout,
            max_iterations,
            params,
            set,
        })
    }

    /// `fit.name`: 1 to 100 characters of [a-z0-9_].
    fn name(f: &mut Section) -> Result<String, InputError> {
        let name = f.text("name")?.to_string();
        if !is_name(&name) {
            return Err(InputError::new(f.field("name"), format!("{name:?}"), allowed(&KEYS, "name")));
        }
        Ok(name)
    }

    /// `fit.against`: "solver:NAME" or "reference".
    fn target(f: &mut Section) -> Result<Target, InputError> {
        let against = f.text("against")?;
        match against.strip_prefix("solver:") {
            // The same model is allowed: the target runs the scene as written, the fit with [set].
            Some(s) if !s.is_empty() => Ok(Target::Solver(s.to_string())),
            None if against == "reference" => Ok(Target::Reference),
            _ => Err(InputError::new(f.field("against"), format!("{against:?}"), allowed(&KEYS, "against"))),
        }
    }

    /// `fit.norm`: one of [`Norm::ALL`] by name.
    fn norm(f: &mut Section) -> Result<Norm, InputError> {
        f.pick("norm").map(|n| Norm::parse(n).unwrap_or(Norm::RmsDf))
    }

    /// `fit.suites`: a non-empty list of folders, joined to the fit file's folder.
    fn suites(f: &mut Section, file: &Path) -> Result<Vec<PathBuf>, InputError> {
        let dir = file.parent().map(Path::to_path_buf).unwrap_or_default();
        Ok(f.opt_str_list("suites", &allowed(&KEYS, "suites"))?
            .filter(|s| !s.is_empty())
            .ok_or_else(|| InputError::new(f.field("suites"), "missing", allowed(&KEYS, "suites")))?
            .iter()
            .map(|s| dir.join(s))
            .collect())
    }

    /// `fit.fit`: the scenes fitted on, one pattern or more.
    fn fitted(f: &mut Section) -> Result<Vec<String>, InputError> {
        let fit = Self::patterns(f, "fit")?;
        if fit.is_empty() {
            return Err(InputError::new(f.field("fit"), "missing or empty", allowed(&KEYS, "fit")));
        }
        Ok(fit)
    }

    /// An optional list of scene names or patterns (* and ?), empty when absent.
    fn patterns(f: &mut Section, key: &str) -> Result<Vec<String>, InputError> {
        Ok(f.opt_str_list(key, &allowed(&KEYS, "holdout"))?.unwrap_or_default())
    }

    /// The [set] table: each dotted scene key with its value, every parameter used by some value.
    fn set(top: &mut Section, params: &[Param]) -> Result<Vec<(String, Value)>, InputError> {
        let s = top.table("set")?;
        let mut set = Vec::new();
        let mut used = Vec::new();
        for (key, v) in s.raw() {
            let field = s.field(&format!("\"{key}\""));
            Self::set_key(key, &field)?;
            used.extend(Self::set_refs(v, params, &field)?);
            set.push((key.clone(), v.clone()));
        }
        Self::all_used(params, &used)?;
        Ok(set)
    }

    /// A [set] key: dotted scene keys with no empty part, not `name` or `solvers`.
    fn set_key(key: &str, field: &str) -> Result<(), InputError> {
        if key.split('.').any(str::is_empty) || key == "name" || key == "solvers" {
            return Err(InputError::new(
                field,
                format!("{key:?}"),
                "dotted scene keys such as \"model.relaxation_length_mm\" (not name or solvers)",
            ));
        }
        Ok(())
    }

    /// The parameter names a [set] value refers to, each one of `params`.
    fn set_refs(v: &Value, params: &[Param], field: &str) -> Result<Vec<String>, InputError> {
        let mut refs = Vec::new();
        placeholders(v, &mut refs);
        if let Some(r) = refs.iter().find(|r| !params.iter().any(|p| &p.name == *r)) {
            let names: Vec<&str> = params.iter().map(|p| p.name.as_str()).collect();
            return Err(InputError::new(
                field,
                format!("\"{{{r}}}\""),
                format!("a placeholder of a [[fit.param]]: {}", names.join(", ")),
            ));
        }
        Ok(refs)
    }

    /// Every parameter among the names `used` by the [set] values.
    fn all_used(params: &[Param], used: &[String]) -> Result<(), InputError> {
        if let Some(p) = params.iter().find(|p| !used.contains(&p.name)) {
            return Err(InputError::new(
                format!("fit.param {}", p.name),
                "not used",
                format!("a parameter that some [set] value names as \"{{{}}}\"", p.name),
            ));
        }
        Ok(())
    }

    fn params(f: &mut Section) -> Result<Vec<Param>, InputError> {
        let field = f.field("param");
        let list = f.opt_tables("param")?.unwrap_or_default();
        if list.is_empty() {
            return Err(InputError::new(field, "missing", allowed(&KEYS, "param")));
        }
        let mut params: Vec<Param> = Vec::new();
        for p in list {
            let mut p = p.declare(&PARAM_KEYS);
            let name = p.text("name")?.to_string();
            if !is_name(&name) || params.iter().any(|q| q.name == name) {
                return Err(InputError::new(p.field("name"), format!("{name:?}"), allowed(&PARAM_KEYS, "name")));
            }
            let bounds = allowed(&PARAM_KEYS, "bounds");
            let [min, max] =
                p.opt_nums::<2>("bounds")?.ok_or_else(|| InputError::new(p.field("bounds"), "missing", &bounds))?;
            if min >= max {
                return Err(InputError::new(p.field("bounds"), format!("[{}, {}]", bound(min), bound(max)), bounds));
            }
            let start = p.f64("start", Range::new(min, true, max, true))?;
            p.finish()?;
            params.push(Param { name, start, min, max });
        }
        Ok(params)
    }

    /// The scene names of `names` that the fit (`holdout = false`) or the hold-out set takes;
    /// a scene both name is fitted, never held out.
    pub fn select(&self, names: &[String], holdout: bool) -> Vec<String> {
        let takes = |patterns: &[String], n: &str| patterns.iter().any(|p| wildcard(p, n));
        names
            .iter()
            .filter(|n| if holdout { takes(&self.holdout, n) && !takes(&self.fit, n) } else { takes(&self.fit, n) })
            .cloned()
            .collect()
    }

    /// The first pattern of `fit` or `holdout` that matches none of `names`: (key, pattern).
    pub fn unmatched<'a>(&'a self, names: &[String]) -> Option<(&'static str, &'a str)> {
        let lists = [("fit", &self.fit), ("holdout", &self.holdout)];
        lists
            .into_iter()
            .find_map(|(key, ps)| ps.iter().find(|p| !names.iter().any(|n| wildcard(p, n))).map(|p| (key, p.as_str())))
    }

    /// The parameter values to validate a scene with before any run: the start, and each
    /// parameter alone at its bounds.
    pub fn probes(&self) -> Vec<Vec<f64>> {
        let start: Vec<f64> = self.params.iter().map(|p| p.start).collect();
        let mut out = vec![start.clone()];
        for (i, p) in self.params.iter().enumerate() {
            for b in [p.min, p.max] {
                let mut v = start.clone();
                v[i] = b;
                out.push(v);
            }
        }
        out
    }

    /// The parameters' values at the optimiser's coordinates `z` ([`Param::value`]).
    pub fn values(&self, z: &[f64]) -> Vec<f64> {
        self.params.iter().zip(z).map(|(p, &z)| p.value(z)).collect()
    }

    /// The set keys with the parameters' values in place.
    pub fn assignments(&self, values: &[f64]) -> Vec<(String, Value)> {
        let named: Vec<(String, f64)> =
            self.params.iter().map(|p| p.name.clone()).zip(values.iter().copied()).collect();
        self.set.iter().map(|(k, v)| (k.clone(), substitute(v, &named))).collect()
    }
}

/// A whole-name match where `*` stands for any run of characters and `?` for one character
/// (linear in time for each position pair: the classic backtracking over the last `*`).
pub fn wildcard(pattern: &str, name: &str) -> bool {
    let (p, n): (Vec<char>, Vec<char>) = (pattern.chars().collect(), name.chars().collect());
    let (mut i, mut j, mut star, mut mark) = (0, 0, None, 0);
    while j < n.len() {
        if i < p.len() && (p[i] == '?' || p[i] == n[j]) {
            i += 1;
            j += 1;
        } else if i < p.len() && p[i] == '*' {
            star = Some(i);
            mark = j;
            i += 1;
        } else if let Some(s) = star {
            i = s + 1;
            mark += 1;
            j = mark;
        } else {
            return false;
        }
    }
    p[i..].iter().all(|&c| c == '*')
}

#[cfg(test)]
mod tests {
    use super::{Allowed, Norm, KEYS};

    /// The declared norms are [`Norm::ALL`]'s names, in its order.
    #[test]
    fn the_declared_norms_are_the_norms() {
        let names: Vec<&str> = Norm::ALL.iter().map(|n| n.name()).collect();
        let Some(Allowed::Choice(declared, _)) = KEYS.get("norm").map(|k| k.allowed) else {
            panic!("norm is a choice")
        };
        assert_eq!(declared, names.as_slice());
    }
}
