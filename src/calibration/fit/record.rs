//! A fit's outcome as stored data (`<results>/fits/<name>.json`): what `creepbench run` keeps of
//! each fit of `fits/`, and what the report's calibration section reads.

use super::objective::SetErrors;
use super::spec::Norm;
use super::FitOutcome;
use serde::{Deserialize, Serialize};
use std::fmt::Write;

/// A fitted parameter.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ParamRecord {
    pub name: String,
    pub start: f64,
    pub min: f64,
    pub max: f64,
    pub value: f64,
}

/// One norm on one set of scenes, before and after (None: the set has no such value).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct NormRecord {
    /// "fitted" or "held out".
    pub set: String,
    pub scenes: usize,
    pub rows: usize,
    pub norm: String,
    /// The norm the fit minimised.
    pub minimised: bool,
    pub before: Option<f64>,
    pub after: Option<f64>,
}

/// |Δf| against the exact theory over one suite's scenes that run the model (max, RMS, 95th
/// percentile): the published model's and the fitted variant's, on the same rows.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SuiteRecord {
    pub suite: String,
    pub scenes: usize,
    pub rows: usize,
    /// (max, RMS, 95 %) of the published model and of the fitted variant.
    pub published: [f64; 3],
    pub fitted: [f64; 3],
}

/// One scene's curves of a fit (`super::curves`): f (column `y`) against the abscissa (column `x`,
/// [`crate::history::abscissa`]) of the target, of the model at the start values and at the
/// fitted values; finite points only.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CurveRecord {
    pub scene: String,
    /// "fitted" or "held out".
    pub set: String,
    pub x: String,
    pub y: String,
    pub target: Vec<(f64, f64)>,
    pub before: Vec<(f64, f64)>,
    pub after: Vec<(f64, f64)>,
}

/// A fit's outcome.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FitRecord {
    pub name: String,
    pub file: String,
    pub model: String,
    pub against: String,
    pub norm: String,
    pub params: Vec<ParamRecord>,
    pub fitted: Vec<String>,
    pub held_out: Vec<String>,
    pub norms: Vec<NormRecord>,
    pub iterations: u64,
    pub evaluations: u64,
    pub ended: String,
    /// The fitted variant beside the published model over the suites' scenes (`creepbench run`).
    #[serde(default)]
    pub suites: Vec<SuiteRecord>,
    /// The before/after curves of the fitted scenes and of the worst held-out one.
    #[serde(default)]
    pub curves: Vec<CurveRecord>,
}

fn finite(v: f64) -> Option<f64> {
    v.is_finite().then_some(v)
}

impl FitRecord {
    pub fn of(o: &FitOutcome) -> FitRecord {
        let spec = &o.spec;
        let mut norms = Vec::new();
        let sets = [("fitted", Some(o.before_fit), Some(o.after_fit)), ("held out", o.before_holdout, o.after_holdout)];
        for (set, before, after) in sets {
            let (Some(b), Some(a)): (Option<SetErrors>, Option<SetErrors>) = (before, after) else { continue };
            norms.extend(Norm::ALL.into_iter().map(|n| NormRecord {
                set: set.into(),
                scenes: b.scenes,
                rows: b.rows,
                norm: n.name().into(),
                minimised: n == spec.norm,
                before: finite(b.norm(n)),
                after: finite(a.norm(n)),
            }));
        }
        FitRecord {
            name: spec.name.clone(),
            file: spec.file.display().to_string(),
            model: spec.model.clone(),
            against: spec.target.label(),
            norm: spec.norm.name().into(),
            params: spec
                .params
                .iter()
                .zip(&o.values)
                .map(|(p, &value)| ParamRecord { name: p.name.clone(), start: p.start, min: p.min, max: p.max, value })
                .collect(),
            fitted: o.fitted.clone(),
            held_out: o.held_out.clone(),
            norms,
            iterations: o.iterations,
            evaluations: o.evaluations,
            ended: o.ended.clone(),
            suites: Vec::new(),
            curves: o.curves.clone(),
        }
    }

    /// The before/after table (Markdown): every norm on the fitted and the held-out scenes.
    pub fn table(&self) -> String {
        let cell = |v: Option<f64>| v.map_or_else(|| "—".into(), |v| format!("{v:.5}"));
        let mut s = String::from("| scenes | count | rows | norm | before | after |\n|---|---|---|---|---|---|\n");
        for n in &self.norms {
            let mark = if n.minimised { " (fitted)" } else { "" };
            let _ = writeln!(
                s,
                "| {} | {} | {} | {}{mark} | {} | {} |",
                n.set,
                n.scenes,
                n.rows,
                n.norm,
                cell(n.before),
                cell(n.after)
            );
        }
        s
    }

    /// The fitted variant beside the published model per suite (Markdown; empty without suites).
    pub fn suite_table(&self) -> String {
        if self.suites.is_empty() {
            return String::new();
        }
        let mut s = format!(
            "| suite | scenes | rows | `{m}` max \\|Δf\\| | fitted | `{m}` RMS | fitted | `{m}` 95 % | fitted |\n|---|---|---|---|---|---|---|---|---|\n",
            m = self.model
        );
        for r in &self.suites {
            let (p, f) = (r.published, r.fitted);
            let _ = writeln!(
                s,
                "| {} | {} | {} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} |",
                r.suite, r.scenes, r.rows, p[0], f[0], p[1], f[1], p[2], f[2]
            );
        }
        s
    }

    /// The parameters, `name = value (start s, bounds [min, max])`.
    pub fn param_lines(&self) -> Vec<String> {
        self.params
            .iter()
            .map(|p| format!("{} = {:.6} (start {}, bounds [{}, {}])", p.name, p.value, p.start, p.min, p.max))
            .collect()
    }
}
