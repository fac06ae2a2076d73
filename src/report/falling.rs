//! The report's "Falling friction" section (issue 33 item 5): the cases of CONTACT's
//! falling-friction set (reference/contact_friction) run by every model (`scenes/friction/`,
//! scene `fr_<case>`, CONTACT's case of the same name, declared `[report] group =
//! "falling_friction"`): the traction curves f(creepage) per law with CONTACT's points, the peak
//! of each steady curve (the creepage at the maximum and the maximum) per model against CONTACT's,
//! the worst |Δf| per case, the transient histories, and the stability suite's falling-friction
//! cases (group `stability_falling`). Reads stored results and reference data only.

use crate::comparison::references::References;
use crate::history::abscissa::{abscissa, Drawn};
use crate::history::History;
use crate::metrics::oscillation_index::{oscillation_index, own_oscillation};
use crate::problem::LoadingKind;
use crate::report::plot::{line_chart, titles, Axis, Series};
use crate::report::section::Section;
use crate::scene::report::ReportGroup;
use crate::suite::results::StoredScene;
use std::fmt::Write;

/// The declared group of the section's scenes (the falling-friction cases run by every model).
const CASES: ReportGroup = ReportGroup::FallingFriction;
/// The declared group of the stability table's falling-friction cases (also in this section).
const STABILITY: ReportGroup = ReportGroup::StabilityFalling;

/// The section's id.
pub const ID: &str = "falling_friction";

/// Whether any stored scene is a falling-friction case or a falling-friction stability case.
pub fn applies(scenes: &[StoredScene]) -> bool {
    scenes.iter().any(|s| [CASES, STABILITY].contains(&s.scene.report_group))
}

/// CONTACT's reference case of a falling-friction scene: the scene's own name.
fn case_of(name: &str) -> String {
    name.to_string()
}

/// The x of a row: the quantity a sweep moves (cx, cy, cs or the speed), time otherwise.
fn x_of(sc: &StoredScene, h: &History) -> (&'static str, Vec<f64>) {
    abscissa(h, Drawn::of_scene(&sc.scene))
}

/// |f| = |(fx, fy)|/FN of each row.
fn resultant(h: &History) -> Vec<f64> {
    h.rows.iter().map(|r| r.fx_over_fn.hypot(r.fy_over_fn)).collect()
}

/// (x at the maximum of |f|, the maximum).
fn peak(x: &[f64], f: &[f64]) -> (f64, f64) {
    let k = (0..f.len()).fold(0, |b, k| if f[k] > f[b] { k } else { b });
    (x.get(k).copied().unwrap_or(f64::NAN), f.get(k).copied().unwrap_or(f64::NAN))
}

/// Worst |Δ(fx, fy)| of a history against CONTACT's over the steps both have.
fn worst(h: &History, contact: &History) -> f64 {
    let theirs: std::collections::BTreeMap<usize, (f64, f64)> =
        contact.rows.iter().map(|r| (r.sample.step, (r.fx_over_fn, r.fy_over_fn))).collect();
    h.rows
        .iter()
        .filter_map(|r| theirs.get(&r.sample.step).map(|t| (r.fx_over_fn - t.0).hypot(r.fy_over_fn - t.1)))
        .fold(0.0, f64::max)
}

const INTRO: &str = "CONTACT's cases with friction falling with the local slip velocity s (`reference/contact_friction/`: laws linear, rational and exponential, with and without friction memory) run by every model (`scenes/friction/`, each scene named after CONTACT's case, where the exact solver is also gated). FASTSIM and the UBA take each element's bound μ(s) p from the scene's law (physics/friction.rs): the slip of an element per unit rolling distance w = (L1 (ux − τx), L2 (uy − τy))/dq (u the traction before the bound, τ after it, dq = dx per element of a steady march, C dx per UBA sub-step) and its slip velocity s = V |w|; the bound g solves g = p μ(s(g)) by Newton until a step is at most 1e-12 |u| (physics/bound.rs `falling_bound`). The memory's μ is carried with the material from the leading edge (backward Euler over the time the material takes to cross an element). FASTSIM is quasi-steady (no memory in time); the relaxation model lags FASTSIM's falling steady force (no slip-velocity feedback, so it cannot oscillate); Polach uses its own law μ0((1 − A) e^(−B w) + A) from the static value, w = |creepage| V (scene values here; `fits/polach_falling.toml` fits A and B). The UBA refuses a memoryless falling law on a time history when its stiffness κ = p_max V L max|dμ/ds|/(C dx) ≥ 1 (the element's bound may then have several roots, sub-steps only raise κ).";

/// The section, if any falling-friction scene is stored.
pub fn section(scenes: &[StoredScene], refs: &References) -> Option<Section> {
    let cases: Vec<&StoredScene> = scenes.iter().filter(|s| s.scene.report_group == CASES).collect();
    let mut body = format!("{INTRO}\n\n");
    let mut figures = Vec::new();
    let mut pictures = String::new();
    let models = |sc: &StoredScene| -> Vec<String> {
        let mut m: Vec<String> = sc.histories.keys().cloned().collect();
        m.sort_by_key(|s| crate::solvers::MODELS.iter().position(|d| d.name == s).unwrap_or(usize::MAX));
        m
    };
    // The peaks of the steady curves.
    let _ = writeln!(body, "**Peak of the steady traction curves** (|f| = |(fx, fy)|/FN; at: the swept quantity at the maximum; CONTACT: its published points):\n\n| case | model | at | max \\|f\\| | Δ at | Δ max |\n|---|---|---|---|---|---|");
    for sc in cases.iter().filter(|s| s.scene.kind == LoadingKind::Sweep) {
        let Some(contact) = refs.history(&case_of(&sc.name)) else { continue };
        let (xname, xc) = x_of(sc, contact);
        let (at_c, max_c) = peak(&xc, &resultant(contact));
        let _ = writeln!(body, "| {} | CONTACT | {xname} = {at_c} | {max_c:.4} | | |", sc.name);
        for m in models(sc) {
            let h = &sc.histories[&m];
            let (_, x) = x_of(sc, h);
            let (at, max) = peak(&x, &resultant(h));
            let _ = writeln!(body, "| {} | {m} | {at} | {max:.4} | {:+.4} | {:+.4} |", sc.name, at - at_c, max - max_c);
        }
    }
    // Worst difference per case and model.
    let mut solvers: Vec<String> = cases.iter().flat_map(|s| models(s)).collect();
    solvers.sort_by_key(|s| crate::solvers::MODELS.iter().position(|d| d.name == s).unwrap_or(usize::MAX));
    solvers.dedup();
    let _ = write!(body, "\n**Worst |Δ(fx, fy)|/FN against CONTACT's published values**, every step or sweep point:\n\n| case | CONTACT's case |");
    for s in &solvers {
        let _ = write!(body, " {s} |");
    }
    let _ = writeln!(body, "\n|---|---|{}", "---|".repeat(solvers.len()));
    for sc in &cases {
        let Some(contact) = refs.history(&case_of(&sc.name)) else { continue };
        let _ = write!(body, "| {} | {} |", sc.name, case_of(&sc.name));
        for s in &solvers {
            let cell = sc.histories.get(s).map_or("—".to_string(), |h| format!("{:.4}", worst(h, contact)));
            let _ = write!(body, " {cell} |");
        }
        body.push('\n');
        // The figure: fx/fn against the swept quantity or time, every model and CONTACT's points.
        let Some(any) = sc.histories.values().next() else { continue };
        let (xname, _) = x_of(sc, any);
        let series: Vec<Series> = models(sc)
            .iter()
            .map(|m| {
                let h = &sc.histories[m];
                Series::model(m, x_of(sc, h).1.into_iter().zip(h.column("fx_over_fn").unwrap_or_default()).collect())
            })
            .chain([Series::reference(
                "CONTACT",
                x_of(sc, contact).1.into_iter().zip(contact.column("fx_over_fn").unwrap_or_default()).collect(),
            )])
            .collect();
        let file = format!("falling_{}.svg", sc.name);
        let title = format!("{} — friction falling with the slip velocity", sc.name);
        figures.push((
            file.clone(),
            line_chart(&title, &Axis::linear(titles::of(xname)), &Axis::linear(titles::of("fx_over_fn")), &series),
        ));
        let _ = writeln!(pictures, "![{} fx/fn](figures/{file})", sc.name);
    }
    let _ = writeln!(body, "\n{pictures}");
    body.push_str(&stability_table(scenes));
    Some(Section { figures, ..Section::new("Falling friction", body) })
}

/// The stability suite's falling-friction cases: per scene and solver, the steps, the
/// oscillation index of |f|, whether the history oscillates on its own, and the last |f|.
fn stability_table(scenes: &[StoredScene]) -> String {
    let mut s = String::from("\n**Stability on the falling branch** (`scenes/stability/stab_fr_*`: a step into the falling branch with and without memory, a sine across the peak, a speed ramp; courant 1 and 0.5). *oscillates*: |f| turns at 6 or more consecutive steps, more than the loading (also printed by `check` and `run`). The UBA refuses `stab_fr_step_nomem_c05` (κ = 1.76 ≥ 1), which runs FASTSIM only.\n\n| scene | solver | steps | oscillation index of \\|f\\| | oscillates | last \\|f\\| |\n|---|---|---|---|---|---|\n");
    for sc in scenes.iter().filter(|s| s.scene.report_group == STABILITY) {
        for (solver, h) in &sc.histories {
            let f = resultant(h);
            let first = h.rows.iter().position(|r| r.sample.step >= 1).unwrap_or(0);
            let flag = own_oscillation(h, sc.scene.v_mm_s)
                .map_or("no".to_string(), |o| format!("**yes** ({} turns in a row)", o.run));
            let _ = writeln!(
                s,
                "| {} | {solver} | {} | {:.3} | {flag} | {:.4} |",
                sc.name,
                h.rows.len(),
                oscillation_index(&f[first..]),
                f.last().copied().unwrap_or(f64::NAN)
            );
        }
    }
    s
}
