//! The report's sections on CONTACT's case sets (issues 12, 13): the envelope (lateral creepage,
//! spin, combined creepage, friction and load that change in time, other Courant numbers and
//! grids) and the non-Hertzian contacts. Every solver against CONTACT: the worst difference per
//! case in fx/fn, fy/fn and mz/(FN a), one figure per case with CONTACT's points, and a map of the
//! contact patch where the set ships CONTACT's field. Reads stored results and reference data only.

use crate::comparison::references::envelope::EnvelopeCases;
use crate::comparison::references::{References, ENVELOPE_SECTION, NONHERTZ_SECTION};
use crate::history::abscissa::{abscissa, Drawn};
use crate::history::{History, MZ};
use crate::report::plot::{line_chart, patch_map, titles, Axis, PatchCell, Series};
use crate::report::section::Section;
use crate::suite::results::StoredScene;
use std::collections::BTreeMap;
use std::fmt::Write;

/// Worst |ours − theirs| of one column over the steps both have, and its step.
fn worst(ours: &[(usize, f64)], theirs: &BTreeMap<usize, f64>) -> Option<(f64, usize)> {
    ours.iter().filter_map(|(k, v)| Some(((v - theirs.get(k)?).abs(), *k))).fold(None, |m: Option<(f64, usize)>, d| {
        if m.is_none_or(|m| d.0 > m.0) {
            Some(d)
        } else {
            m
        }
    })
}

/// (step, value) of a column; `mz_nmm` made dimensionless by FN a.
fn column(h: &History, col: &str, a_mm: f64) -> Vec<(usize, f64)> {
    let v = h.column(col).unwrap_or_default();
    h.rows.iter().zip(v).map(|(r, v)| (r.sample.step, if col == MZ { v / (r.sample.fn_n * a_mm) } else { v })).collect()
}

fn cell(w: Option<(f64, usize)>) -> String {
    match w {
        Some((d, k)) if d < 1e-3 => format!("{d:.1e} ({k})"),
        Some((d, k)) => format!("{d:.4} ({k})"),
        None => "—".into(),
    }
}

/// What differs between the case-set sections.
struct Spec {
    title: &'static str,
    intro: &'static str,
    /// Prefix of the figure files.
    prefix: &'static str,
}

const ENVELOPE: Spec = Spec {
    title: "Envelope: lateral creepage, spin, friction and load in time, Courant number",
    intro: "CONTACT's cases beyond the thesis family (`reference/contact_envelope/`, scenes in `scenes/envelope/`). Per case and solver: the worst |Δ| over every step or sweep point of fx/fn, fy/fn and mz/(FN a) (a: the nominal semi-axis along x; step in brackets). Gated for `contact` at 1e-5 (two cases carry a named, measured known gap: `tolerances.toml`); the fast models are reported. Signs: CONTACT's (a positive spin gives a positive fy, Kalker's C23 > 0).",
    prefix: "envelope",
};

const NONHERTZ: Spec = Spec {
    title: "Non-Hertzian contacts: patches from lateral profiles",
    intro: "CONTACT's cases on non-Hertzian contacts (`reference/contact_nonhertz/`, scenes in `scenes/nonhertz/`): h = a1 x² + g(y) with g linear between the points of a lateral profile, the normal problem solved on the grid (several patches that merge as the load rises in `nh_two_fn_ramp`). Per case and solver: the worst |Δ| of fx/fn, fy/fn and mz/(FN a) (a: the equivalent ellipse's semi-axis along x, Kik & Piotrowski). Gated for `contact` at 1e-5; the fast models run on the exact normal pressure with the flexibilities of the equivalent ellipse (`[model] nonhertz_flexibility`, README) and are reported. The patch maps are CONTACT's fields (shade: pressure; red outline: slip).",
    prefix: "nonhertz",
};

/// The envelope section, if any stored scene is an envelope case.
pub fn section(scenes: &[StoredScene], refs: &References) -> Option<Section> {
    case_section(scenes, refs.of_section::<EnvelopeCases>(ENVELOPE_SECTION)?, &ENVELOPE)
}

/// The non-Hertzian section, if any stored scene is a non-Hertzian case.
pub fn nonhertz_section(scenes: &[StoredScene], refs: &References) -> Option<Section> {
    case_section(scenes, refs.of_section::<EnvelopeCases>(NONHERTZ_SECTION)?, &NONHERTZ)
}

fn case_section(scenes: &[StoredScene], set: &EnvelopeCases, spec: &Spec) -> Option<Section> {
    let cases: Vec<(&StoredScene, &History)> =
        scenes.iter().filter_map(|s| Some((s, set.histories.get(&s.name)?))).collect();
    if cases.is_empty() {
        return None;
    }
    let mut solvers: Vec<&str> = cases.iter().flat_map(|(s, _)| s.histories.keys().map(String::as_str)).collect();
    solvers.sort_by_key(|s| crate::solvers::MODELS.iter().position(|m| m.name == *s).unwrap_or(usize::MAX));
    solvers.dedup();
    let mut body = String::new();
    let _ = writeln!(body, "{}\n", spec.intro);
    let _ = write!(body, "| case | what |");
    for s in &solvers {
        let _ = write!(body, " {s}: fx | fy | mz |");
    }
    let _ = write!(body, "\n|---|---|{}\n", "---|---|---|".repeat(solvers.len()));
    let mut figures = Vec::new();
    let mut pictures = String::new();
    for (sc, contact) in &cases {
        let a_mm = sc.scene.a_mm;
        let note = set.notes.get(&sc.name).map(String::as_str).unwrap_or("");
        let _ = write!(body, "| {} | {} |", sc.name, note);
        for s in &solvers {
            for col in ["fx_over_fn", "fy_over_fn", MZ] {
                let theirs: BTreeMap<usize, f64> = column(contact, col, a_mm).into_iter().collect();
                let w = sc.histories.get(*s).and_then(|h| worst(&column(h, col, a_mm), &theirs));
                let _ = write!(body, " {} |", cell(w));
            }
        }
        body.push('\n');
        // The figure: the larger force component of CONTACT's history (both when both matter).
        let size = |col: &str| contact.column(col).unwrap_or_default().iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let (sx, sy) = (size("fx_over_fn"), size("fy_over_fn"));
        let drawn = Drawn::of_scene(&sc.scene);
        let xl = titles::of(abscissa(contact, drawn).0);
        for (col, label, shown) in [("fx_over_fn", "fx/fn", sx >= 0.3 * sy), ("fy_over_fn", "fy/fn", sy >= 0.3 * sx)] {
            if !shown {
                continue;
            }
            let mut series: Vec<Series> = Vec::new();
            for (name, h) in &sc.histories {
                let points = abscissa(h, drawn).1.into_iter().zip(h.column(col).unwrap_or_default()).collect();
                series.push(Series::model(name, points));
            }
            let theirs = abscissa(contact, drawn).1.into_iter().zip(contact.column(col).unwrap_or_default());
            series.push(Series::reference("CONTACT", theirs.collect()));
            let file = format!("{}_{}_{}.svg", spec.prefix, sc.name, &col[..2]);
            figures.push((
                file.clone(),
                line_chart(
                    &format!("{} — {note}", sc.name),
                    &Axis::linear(&xl),
                    &Axis::linear(titles::of(col)),
                    &series,
                ),
            ));
            let _ = writeln!(pictures, "![{} {label}](figures/{file})", sc.name);
        }
        for (step, field) in set.fields.get(&sc.name).into_iter().flatten() {
            let cells: Vec<PatchCell> = field.iter().map(|c| (c.x_mm, c.y_mm, c.pn_mpa, c.state == 'S')).collect();
            let file = format!("{}_{}_patch_{step}.svg", spec.prefix, sc.name);
            let title = format!("{}, step {step}: CONTACT's patch", sc.name);
            figures.push((file.clone(), patch_map(&title, &cells, (sc.scene.dx_mm, sc.scene.dy_mm))));
            let _ = writeln!(pictures, "![{} patch, step {step}](figures/{file})", sc.name);
        }
    }
    let _ = writeln!(body, "\n{pictures}");
    Some(Section { figures, ..Section::new(spec.title, body) })
}
