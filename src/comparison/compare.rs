//! Comparisons of a scene's results with golden data, a previous result set, CONTACT and the
//! thesis. Each comparison yields its worst point as a [`Finding`].

pub use crate::comparison::finding::{Against, Ctx, Finding};
use crate::comparison::references::References;
use crate::comparison::tolerances;
use crate::error::{number, Error};
use crate::suite::results::{self, StoredScene};
use std::collections::BTreeMap;

/// Columns compared with a baseline besides the model's extra columns: the loading (a changed
/// loading is a changed scene) and the traction coefficients.
const BASELINE_COLUMNS: [&str; 8] = ["t_s", "cx", "cy", "cs", "fn_n", "mu", "fx_over_fn", "fy_over_fn"];

/// Compare `ours` with a stored result set of the same scene (golden or previous): every
/// history column and every metric.
pub fn against_results(ours: &StoredScene, theirs: Option<&StoredScene>, against: Against) -> Vec<Finding> {
    let mut out = Vec::new();
    if let Some(t) = theirs {
        out.extend(expected_sets(ours, t, against));
    }
    for (solver, h) in &ours.histories {
        let ctx = Ctx { scene: &ours.name, solver, against, rules: tolerances::defaults() };
        let Some(th) = theirs.and_then(|t| t.histories.get(solver)) else {
            out.push(ctx.unmatched("fx_over_fn", no_baseline_note(against)));
            continue;
        };
        if h.extra_columns != th.extra_columns {
            let note = format!("columns differ: here {:?}, there {:?}", h.extra_columns, th.extra_columns);
            out.push(ctx.unmatched("columns", note));
        }
        for col in BASELINE_COLUMNS.iter().map(|s| s.to_string()).chain(h.extra_columns.iter().cloned()) {
            if BASELINE_COLUMNS.contains(&col.as_str()) || th.extra_columns.contains(&col) {
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
                        let mut f = ctx.unmatched(name, "missing there".into());
                        (f.step, f.ours) = (*step, *v);
                        out.push(f);
                    }
                }
            }
        }
    }
    out
}

/// The note of a scene and solver the baseline has no data for (one place, so the console can
/// report such scenes once as "no golden data" rather than as unmatched values).
pub fn no_baseline_note(against: Against) -> String {
    format!("no {} data for this scene and solver (run `creepbench bless` to accept new results)", against.label())
}

/// Whether `f` says the baseline has no data for its scene and solver.
pub fn is_no_baseline(f: &Finding) -> bool {
    f.diff.is_nan() && f.note == no_baseline_note(f.against)
}

/// The keys of scene.json that say where a scene is shown, not what it computes: a baseline's
/// scene.json is compared without them (a scene moved to another report group is no drift).
const NOT_A_RESULT: [&str; 1] = ["report_group"];

/// What a baseline holds that this result set does not: solvers, metric values, and a scene.json
/// that differs (a changed scene is a changed baseline; [`NOT_A_RESULT`] aside).
fn expected_sets(ours: &StoredScene, theirs: &StoredScene, against: Against) -> Vec<Finding> {
    let mut out = Vec::new();
    let scene_ctx = Ctx { scene: &ours.name, solver: "-", against, rules: tolerances::defaults() };
    for solver in theirs.histories.keys().filter(|s| !ours.histories.contains_key(*s)) {
        out.push(
            scene_ctx
                .unmatched("solvers", format!("{} has {solver}.csv, this run has no such solver", against.label())),
        );
    }
    for (solver, name, step) in theirs.metrics.keys().filter(|k| !ours.metrics.contains_key(*k)) {
        let ctx = Ctx { scene: &ours.name, solver, against, rules: tolerances::defaults() };
        let mut f = ctx.unmatched(name, format!("{} has this metric value, this run has not", against.label()));
        f.step = *step;
        out.push(f);
    }
    let (a, b) = (serde_json::to_value(&ours.scene), serde_json::to_value(&theirs.scene));
    if let (Ok(serde_json::Value::Object(a)), Ok(serde_json::Value::Object(b))) = (a, b) {
        let differ: Vec<&String> = a
            .keys()
            .chain(b.keys().filter(|k| !a.contains_key(*k)))
            .filter(|k| !NOT_A_RESULT.contains(&k.as_str()) && a.get(*k) != b.get(*k))
            .collect();
        if !differ.is_empty() {
            out.push(scene_ctx.unmatched("scene.json", format!("resolved scene differs in {differ:?}")));
        }
    }
    out
}

/// The scenes of a baseline folder that this result set lacks, among those it is `expected` to
/// produce (by name and suite folder: a shard expects its own, a suite the scenes blessed from
/// it): each is a failure, so a baseline does not vanish unnoticed.
pub fn missing_scenes(
    dir: &std::path::Path,
    scenes: &[StoredScene],
    against: Against,
    expected: impl Fn(&str, &str) -> bool,
) -> Result<Vec<Finding>, Error> {
    let mut out = Vec::new();
    for n in results::scene_names(dir).into_iter().filter(|n| !scenes.iter().any(|s| &s.name == n)) {
        let theirs = results::read_resolved(dir, &n)?;
        if expected(&n, &theirs.suite) {
            let ctx = Ctx { scene: &n, solver: "-", against, rules: tolerances::defaults() };
            out.push(ctx.unmatched(
                "scene",
                format!("{} has this scene of suite {:?}, the run did not produce it", against.label(), theirs.suite),
            ));
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
        for set in refs.sets() {
            out.extend(set.compare(s, tolerances::defaults()));
        }
        if let Some((dir, against)) = baseline {
            let theirs = if dir.join(&s.name).join("scene.json").exists() {
                Some(results::read_scene(dir, &s.name)?)
            } else {
                None
            };
            out.extend(against_results(s, theirs.as_ref(), against));
        }
        out.extend(traction_bound(s, baseline.map_or(Against::Golden, |b| b.1)));
    }
    Ok(out)
}

/// Relative margin by which a model's traction coefficient may exceed its bound μ (rounding).
pub const BOUND_MARGIN: f64 = 1e-6;

/// A model's traction coefficient |(Fx, Fy)|/FN beyond its bound μ (thesis Eq. 2.27; μ times the
/// load its pressure carries over FN where the model reports that load,
/// [`crate::solvers::fastsim_contact::CARRIED_LOAD`]) by more
/// than [`BOUND_MARGIN`], or not finite: a gated finding per scene and model (none when within),
/// so a model that breaks physics fails the gate whatever its baseline says.
pub fn traction_bound(s: &StoredScene, against: Against) -> Vec<Finding> {
    let mut out = Vec::new();
    // The law's largest μ over the row's (FSTAT): above 1 only for friction rising with the
    // temperature (L = 6, DFHEAT > 0).
    let rise = s.scene.friction.as_ref().map_or(1.0, |law| law.mu_max() / law.mu_static());
    for (solver, h) in &s.histories {
        let carried: Option<BTreeMap<usize, f64>> = h
            .column(crate::solvers::fastsim_contact::CARRIED_LOAD)
            .map(|v| h.rows.iter().map(|r| r.sample.step).zip(v).collect());
        let share = |r: &crate::history::Row| {
            carried.as_ref().and_then(|c| c.get(&r.sample.step)).map_or(1.0, |n| n / r.sample.fn_n)
        };
        let beyond = |(coef, r): &(f64, &crate::history::Row)| {
            let limit =
                if r.sample.mu.is_nan() { f64::INFINITY } else { r.sample.mu * rise * share(r) * (1.0 + BOUND_MARGIN) };
            // NaN counts as beyond.
            coef.partial_cmp(&limit).is_none_or(std::cmp::Ordering::is_gt)
        };
        let worst = h
            .rows
            .iter()
            .map(|r| (r.fx_over_fn.hypot(r.fy_over_fn), r))
            .filter(beyond)
            .max_by(|a, b| a.0.total_cmp(&b.0));
        if let Some((coef, r)) = worst {
            out.push(Finding {
                scene: s.name.clone(),
                solver: solver.clone(),
                against,
                quantity: "traction_bound".into(),
                step: Some(r.sample.step),
                ours: coef,
                theirs: r.sample.mu * rise,
                diff: if coef.is_finite() { coef - r.sample.mu * rise } else { f64::NAN },
                allowed: BOUND_MARGIN * (r.sample.mu * rise).abs(),
                gated: true,
                note: format!("|(Fx, Fy)|/FN beyond mu by more than {BOUND_MARGIN:e} relative"),
            });
        }
    }
    out
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
    findings.iter().filter(|f| f.gated && !f.passed()).map(drift_line).collect()
}

/// A gated miss: scene, solver, metric, step, both values and |diff| against allowed (or why the
/// values could not be matched); a number whose plain form is long (1.7e308) with an exponent.
pub fn drift_line(f: &Finding) -> String {
    let head = format!(
        "DRIFT scene {} solver {} against {} metric {} step {}",
        f.scene,
        f.solver,
        f.against.label(),
        f.quantity,
        f.step.map(|k| k.to_string()).unwrap_or_else(|| "-".into()),
    );
    if f.diff.is_nan() && f.ours.is_nan() && f.theirs.is_nan() {
        return format!("{head}: unmatched: {}", f.note);
    }
    format!(
        "{head}: ours {} vs {} (|diff| {} > allowed {}){}",
        number(f.ours),
        number(f.theirs),
        crate::error::deviation(f.diff),
        crate::error::deviation(f.allowed),
        if f.note.is_empty() { String::new() } else { format!(": {}", f.note) }
    )
}
