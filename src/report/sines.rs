//! The report's sections on the sine scenes: delay ratios and hysteresis loop areas, the thesis's
//! and CONTACT's values beside each solver's.

use crate::comparison::delay;
use crate::comparison::references::contact::{self, ContactCases};
use crate::comparison::references::thesis::{self, ThesisTables};
use crate::report::ReportInput;
use crate::suite::results::StoredScene;
use std::fmt::Write;

/// The scenes with a period (sines), in the order stored.
fn sine_scenes(scenes: &[StoredScene]) -> Vec<&StoredScene> {
    scenes.iter().filter(|s| s.scene.period_s().is_some()).collect()
}

fn fmt(v: Option<f64>, digits: usize) -> String {
    match v {
        Some(x) if x.is_finite() => format!("{x:.digits$}"),
        _ => "—".into(),
    }
}

/// A Markdown table header: the fixed columns, then one per solver.
fn table_head(md: &mut String, fixed: &[&str], solvers: &[String]) {
    let cols: Vec<&str> = fixed.iter().copied().chain(solvers.iter().map(String::as_str)).collect();
    let _ = writeln!(md, "| {} |\n|{}", cols.join(" | "), "---|".repeat(cols.len()));
}

/// Section: the delay ratio of each sine scene, the thesis's (Table 4.2) and CONTACT's beside each
/// solver's; none without sine scenes.
pub fn delay_ratios(md: &mut String, input: &ReportInput, solvers: &[String]) {
    let sines = sine_scenes(input.scenes);
    if sines.is_empty() {
        return;
    }
    let thesis = input.refs.get::<ThesisTables>(thesis::AGAINST);
    let contact = input.refs.get::<ContactCases>(contact::EXACT);
    let _ = writeln!(md, "## Delay ratios\n\nTime from the maximum of cx to the next maximum of f in the second period, over the period (parabolic peak interpolation). Thesis Table 4.2 (CONTACT, μ = 1, 22×22): 0.040 / 0.128 / 0.220 at 10 / 30 / 60 Hz. † f reaches μ (within 3 %): the maximum is a flat top and the delay ill-defined (reported, not gated).\n");
    table_head(md, &["scene", "thesis", "CONTACT"], solvers);
    for sc in &sines {
        let p = sc.scene.period_s().unwrap_or(1.0);
        let thesis = thesis.and_then(|t| t.delay_for(sc));
        let contact = contact.and_then(|c| c.history(&sc.name)).and_then(|h| delay::of_history(h, p));
        let _ = write!(md, "| {} | {} | {} |", sc.name, fmt(thesis, 3), fmt(contact, 4));
        for s in solvers {
            let _ = write!(md, " {} |", delay_cell(sc, s));
        }
        md.push('\n');
    }
    md.push('\n');
}

/// A solver's delay ratio in a sine scene, marked † where its f reaches μ (a flat top).
fn delay_cell(sc: &StoredScene, solver: &str) -> String {
    let flat = sc
        .histories
        .get(solver)
        .is_some_and(|h| h.rows.iter().any(|r| delay::saturates(r.fx_over_fn.abs(), r.sample.mu)));
    let d = fmt(sc.metrics.get(&(solver.to_string(), crate::metrics::delay_ratio::NAME.into(), None)).copied(), 4);
    format!("{d}{}", if flat { " †" } else { "" })
}

/// Section: the loop area of each sine scene, CONTACT's beside each solver's (with the relative
/// difference to it); none without sine scenes.
pub fn loop_areas(md: &mut String, input: &ReportInput, solvers: &[String]) {
    let sines = sine_scenes(input.scenes);
    if sines.is_empty() {
        return;
    }
    let contact = input.refs.get::<ContactCases>(contact::EXACT);
    let _ = writeln!(md, "## Hysteresis loop areas\n\n|∮ f dcx| over the last full period (trapezoidal; CONTACT's value from `cases.csv`). In brackets: relative difference to CONTACT.\n");
    table_head(md, &["scene", "CONTACT"], solvers);
    for sc in &sines {
        let c = contact.and_then(|c| c.cases.get(&sc.name)).and_then(|c| c.loop_area).map(f64::abs);
        let _ = write!(md, "| {} | {} |", sc.name, fmt(c, 6));
        for s in solvers {
            let _ = write!(md, " {} |", loop_area_cell(sc, s, c));
        }
        md.push('\n');
    }
    md.push('\n');
}

/// A solver's loop area in a sine scene and, in brackets, its relative difference to CONTACT's
/// `contact` (where that is positive).
fn loop_area_cell(sc: &StoredScene, solver: &str, contact: Option<f64>) -> String {
    let v = sc.metrics.get(&(solver.to_string(), crate::metrics::loop_area::NAME.into(), None)).copied();
    let rel = match (v, contact) {
        (Some(v), Some(c)) if c > 0.0 => format!(" ({:+.1} %)", 100.0 * (v / c - 1.0)),
        _ => String::new(),
    };
    format!("{}{rel}", fmt(v, 6))
}
