//! Comparisons of a scene's results with golden data, a previous result set, CONTACT and the
//! thesis. Each comparison yields its worst point as a [`Finding`].

use super::reference::References;
use super::results::StoredScene;
use super::tolerances;
use crate::error::Error;
use crate::history::History;
use crate::metrics;
use std::collections::BTreeMap;

/// What results are compared against.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Against {
    /// golden/: this project's blessed results.
    Golden,
    /// Another result set (`check --against DIR`): drift between two model versions.
    Previous,
    /// CONTACT, exact theory (reference/contact).
    Contact,
    /// CONTACT's FASTSIM with the parabolic bound (reference/contact/steady_fastsim_g22).
    ContactFastsim,
    /// The thesis's published figures (reference/thesis).
    Thesis,
}

impl Against {
    pub fn label(self) -> &'static str {
        match self {
            Against::Golden => "golden",
            Against::Previous => "previous",
            Against::Contact => "CONTACT",
            Against::ContactFastsim => "CONTACT FASTSIM",
            Against::Thesis => "thesis",
        }
    }
}

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

struct Ctx<'a> {
    scene: &'a str,
    solver: &'a str,
    against: Against,
}

impl Ctx<'_> {
    fn finding(&self, quantity: &str, step: Option<usize>, ours: f64, theirs: f64, note: &str) -> Finding {
        let rule = tolerances::rule(self.against, self.solver, quantity);
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

    /// Worst difference of one column over the steps both histories have. Steps present in only
    /// one of them make the finding unmatched (NaN) when `require_same_steps`.
    fn column(&self, ours: &History, theirs: &History, col: &str, require_same_steps: bool) -> Option<Finding> {
        let (a, b) = (ours.column(col)?, theirs.column(col)?);
        let tb: BTreeMap<usize, f64> = theirs.rows.iter().map(|r| r.step).zip(b).collect();
        let mut worst: Option<Finding> = None;
        let mut matched = 0;
        for (r, va) in ours.rows.iter().zip(a) {
            let Some(&vb) = tb.get(&r.step) else { continue };
            matched += 1;
            let f = self.finding(col, Some(r.step), va, vb, "");
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

/// Compare `ours` with a stored result set of the same scene (golden or previous): every
/// history column and every metric.
pub fn against_results(ours: &StoredScene, theirs: Option<&StoredScene>, against: Against) -> Vec<Finding> {
    let mut out = Vec::new();
    for (solver, h) in &ours.histories {
        let ctx = Ctx { scene: &ours.name, solver, against };
        let Some(th) = theirs.and_then(|t| t.histories.get(solver)) else {
            let mut f = ctx.finding("fx_over_fn", None, f64::NAN, f64::NAN, "");
            f.note = format!(
                "no {} data for this scene and solver (run `creepbench bless` to accept new results)",
                against.label()
            );
            out.push(f);
            continue;
        };
        for col in ["fx_over_fn", "fy_over_fn"].iter().map(|s| s.to_string()).chain(h.extra_columns.iter().cloned()) {
            if col == "fx_over_fn" || th.extra_columns.contains(&col) || col == "fy_over_fn" {
                out.extend(ctx.column(h, th, &col, true));
            }
        }
        if let Some(t) = theirs {
            for ((s, name, step), v) in &ours.metrics {
                if s != solver {
                    continue;
                }
                match t.metrics.get(&(s.clone(), name.clone(), *step)) {
                    Some(tv) => out.push(ctx.finding(name, *step, *v, *tv, "")),
                    None => {
                        let mut f = ctx.finding(name, *step, *v, f64::NAN, "missing there");
                        f.diff = f64::NAN;
                        out.push(f);
                    }
                }
            }
        }
    }
    out
}

/// Compare every solver of a scene with the CONTACT reference of the same name, if any, and the
/// sine scenes' delay ratios with the thesis's Table 4.2 (μ = 1 scenes).
pub fn against_references(ours: &StoredScene, refs: &References) -> Result<Vec<Finding>, Error> {
    let mut out = Vec::new();
    let Some(case) = refs.cases.get(&ours.name) else { return Ok(out) };
    let Some(contact) = refs.contact_history(&ours.name)? else { return Ok(out) };
    let against = if case.method == "fastsim_parabolic" { Against::ContactFastsim } else { Against::Contact };
    let period = ours.period_s();
    let t = contact.column("t_s").unwrap_or_default();
    let (cx, f) = (contact.column("cx").unwrap_or_default(), contact.column("fx_over_fn").unwrap_or_default());
    let contact_delay = period.and_then(|p| metrics::delay_ratio(&t, &cx, &f, p));
    // Where f saturates at μ near the creepage peak the delay is ill-defined (flat top).
    let mu = ours.scene["mu"].as_f64().unwrap_or(f64::INFINITY);
    let f_peak = f.iter().fold(0.0f64, |a, &b| a.max(b.abs()));
    let saturated = f_peak >= 0.97 * mu;
    for (solver, h) in &ours.histories {
        let ctx = Ctx { scene: &ours.name, solver, against };
        out.extend(ctx.column(h, &contact, "fx_over_fn", false));
        let metric = |name: &str| ours.metrics.get(&(solver.clone(), name.to_string(), None)).copied();
        if let (Some(ours_d), Some(ref_d)) = (metric("delay_ratio"), contact_delay) {
            let mut fd =
                ctx.finding("delay_ratio", None, ours_d, ref_d, "CONTACT's delay from its history, same definition");
            if saturated {
                fd.gated = false;
                fd.note = format!("f reaches {:.0} % of mu: the maximum is a flat top and the delay ill-defined (reference README); reported only", 100.0 * f_peak / mu);
            }
            out.push(fd);
        }
        if let (Some(ours_a), Some(ref_a)) = (metric("loop_area"), case.loop_area) {
            out.push(ctx.finding("loop_area", None, ours_a, ref_a.abs(), "cases.csv loop_area (absolute value)"));
        }
        if let (Some(v), Some(rv)) = (metric("steady_value"), f.last()) {
            if case.kind != "steady" {
                out.push(ctx.finding("steady_value", None, v, *rv, ""));
            }
        }
        if let (Some(v), Some(rv)) = (metric("settling_time_s"), metrics::settling_time(&t, &f)) {
            out.push(ctx.finding("settling_time_s", None, v, rv, ""));
        }
        if let (Some(ours_d), Some(p)) = (metric("delay_ratio"), period) {
            if let Some(td) = refs.thesis_delays.iter().find(|d| (1.0 / d.freq_hz - p).abs() < 1e-9 * p) {
                if ours.scene["mu"].as_f64() == Some(1.0) && case.mx == 22 {
                    let tctx = Ctx { scene: &ours.name, solver, against: Against::Thesis };
                    out.push(tctx.finding(
                        "delay_ratio",
                        None,
                        ours_d,
                        td.delay_ratio,
                        "thesis Table 4.2 (CONTACT, mu = 1)",
                    ));
                }
            }
        }
    }
    Ok(out)
}

/// Every comparison of a result set: with the references and, if given, with a baseline result
/// folder (golden/ or a previous run).
pub fn evaluate(
    scenes: &[StoredScene],
    refs: &References,
    baseline: Option<(&std::path::Path, Against)>,
) -> Result<Vec<Finding>, Error> {
    let mut out = Vec::new();
    for s in scenes {
        out.extend(against_references(s, refs)?);
        if let Some((dir, against)) = baseline {
            let theirs = if dir.join(&s.name).join("scene.json").exists() {
                Some(super::results::read_scene(dir, &s.name)?)
            } else {
                None
            };
            out.extend(against_results(s, theirs.as_ref(), against));
        }
    }
    Ok(out)
}

/// The worst finding per (scene, solver, against), in a stable order.
pub fn worst_per_group(findings: &[Finding]) -> Vec<Finding> {
    let mut groups: BTreeMap<(String, String, Against), Finding> = BTreeMap::new();
    for f in findings {
        let key = (f.scene.clone(), f.solver.clone(), f.against);
        let replace = match groups.get(&key) {
            None => true,
            Some(w) => (f.gated && !f.passed(), f.severity()) > (w.gated && !w.passed(), w.severity()),
        };
        if replace {
            groups.insert(key, f.clone());
        }
    }
    groups.into_values().collect()
}

fn fmt(v: f64) -> String {
    if v.is_nan() {
        "—".into()
    } else if v.is_infinite() {
        "∞".into()
    } else {
        format!("{v:.6}")
    }
}

/// The table `check` prints: worst point per scene, solver and reference.
pub fn table(worst: &[Finding]) -> String {
    let mut s = format!(
        "{:<22} {:<8} {:<15} {:<16} {:>5} {:>12} {:>12} {:>10} {:>10}  {}\n",
        "scene", "solver", "against", "quantity", "step", "ours", "theirs", "|diff|", "allowed", "status"
    );
    for f in worst {
        let status = match (f.gated, f.passed()) {
            (true, true) => "ok",
            (true, false) => "DRIFT",
            (false, _) => "info",
        };
        let step = f.step.map(|k| k.to_string()).unwrap_or_else(|| "-".into());
        s.push_str(&format!(
            "{:<22} {:<8} {:<15} {:<16} {:>5} {:>12} {:>12} {:>10} {:>10}  {}{}\n",
            f.scene,
            f.solver,
            f.against.label(),
            f.quantity,
            step,
            fmt(f.ours),
            fmt(f.theirs),
            if f.diff.is_nan() { "—".into() } else { format!("{:.2e}", f.diff) },
            if f.allowed.is_infinite() { "—".into() } else { format!("{:.1e}", f.allowed) },
            status,
            if f.note.is_empty() || f.passed() { String::new() } else { format!(" ({})", f.note) }
        ));
    }
    s
}

/// One line per gated miss, naming scene, solver, metric, step and both values.
pub fn failures(findings: &[Finding]) -> Vec<String> {
    findings
        .iter()
        .filter(|f| f.gated && !f.passed())
        .map(|f| {
            format!(
                "DRIFT scene {} solver {} against {} metric {} step {}: ours {} vs {} (|diff| {} > allowed {:e}){}",
                f.scene,
                f.solver,
                f.against.label(),
                f.quantity,
                f.step.map(|k| k.to_string()).unwrap_or_else(|| "-".into()),
                f.ours,
                f.theirs,
                f.diff,
                f.allowed,
                if f.note.is_empty() { String::new() } else { format!(": {}", f.note) }
            )
        })
        .collect()
}
