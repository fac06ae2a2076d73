//! Report sections computed from several stored scenes at once: the thesis's figures beside
//! ours, error against run time, grid convergence, stability, timing and cost per step. Each
//! reads stored results and reference data only; the studies they need are scenes of the suite
//! `scenes/report/`, run and stored like any other, found by their declared report group
//! (`[report] group`) or, where a section draws one particular scene, by its name.

use crate::comparison::references::contact::{self, ContactCases};
use crate::comparison::references::thesis::{self, ThesisTables};
use crate::comparison::references::References;
use crate::comparison::tolerance_file::Loosening;
use crate::history::History;
use crate::metrics::oscillation_index::own_oscillation;
use crate::report::linked_table::{largest, place, Table};
use crate::report::plot::{line_chart, Axis, Bar, Series};
pub use crate::report::section::Section;
use crate::report::timed;
use crate::scene::report::ReportGroup;
use crate::suite::results::StoredScene;
use std::collections::BTreeMap;
use std::fmt::Write;

/// The run's rules that loosen what the defaults gate (issue 30: no gate disabled in silence);
/// none when there are none.
pub fn loosened(all: &[Loosening]) -> Option<Section> {
    if all.is_empty() {
        return None;
    }
    let mut body = String::from("Rules of this run's tolerance files that loosen comparisons the defaults gate:\n\n");
    for l in all {
        body.push_str(&format!("- {}\n", l.to_string().replace('|', "\\|")));
    }
    Some(Section::new("Loosened gates", body))
}

fn find<'a>(scenes: &'a [StoredScene], name: &str) -> Option<&'a StoredScene> {
    scenes.iter().find(|s| s.name == name)
}

/// Whether any stored scene is a case of the stability table (declared group `stability` or
/// `stability_falling`).
pub fn stability_applies(scenes: &[StoredScene]) -> bool {
    scenes.iter().any(|s| s.scene.report_group.is_stability())
}

/// Whether any stored scene is a run of the cost-per-step study (declared group `scaling`).
pub fn scaling_applies(scenes: &[StoredScene]) -> bool {
    scenes.iter().any(|s| s.scene.report_group == ReportGroup::Scaling)
}
/// The scene of the thesis's Hertz example (`scenes/report/`).
pub const HERTZ_RADII: &str = "report_hertz_radii";
/// The steady sweeps on three grids, with their grid (CONTACT's 88×88 is the reference).
const REFINED: [(&str, usize); 3] = [("steady_exact_g22", 22), ("steady_exact_g44", 44), ("steady_exact_g88", 88)];

/// The Table 4.3 studies: (scene, label).
const TABLE_4_3: [(&str, &str); 4] = [
    ("report_t43_kalker_parabolic", "Kalker L, parabolic bound (default)"),
    ("report_t43_kalker_ellipsoidal", "Kalker L, ellipsoidal bound"),
    ("report_t43_thesis_parabolic", "thesis Eq. 3.5 L, parabolic bound"),
    ("report_t43_thesis_ellipsoidal", "thesis Eq. 3.5 L, ellipsoidal bound"),
];

/// Whether the suite holds a scene the thesis comparison draws (the Hertz radii, Table 4.3).
pub fn thesis_applies(scenes: &[StoredScene]) -> bool {
    find(scenes, HERTZ_RADII).is_some() || TABLE_4_3.iter().any(|(name, _)| find(scenes, name).is_some())
}

/// Whether the suite holds a scene of the grid refinement (the steady exact sweeps).
pub fn grid_convergence_applies(scenes: &[StoredScene]) -> bool {
    REFINED.iter().any(|(name, _)| find(scenes, name).is_some())
}

/// The thesis's own figures beside this project's, with what explains the differences.
pub fn thesis_beside_ours(scenes: &[StoredScene], refs: &References) -> Section {
    let mut s = String::new();
    let thesis = refs.get::<ThesisTables>(thesis::AGAINST);
    let fig = |k: &str| thesis.and_then(|t| t.figure(k));
    let _ = writeln!(s, "| figure | thesis | this project | note |\n|---|---|---|---|");
    if let Some(h) = find(scenes, HERTZ_RADII) {
        let _ = writeln!(s, "| Hertz a, b from R_wx 575, R_wy 500, R_ry 300 mm, 100 kN, E 210 GPa, ν 0.28 | {} / {} mm | {:.3} / {:.3} mm | two-body modulus 1/E* = 2(1−ν²)/E; the thesis rounds |", fig("hertz_a_mm").unwrap_or(f64::NAN), fig("hertz_b_mm").unwrap_or(f64::NAN), h.scene.a_mm, h.scene.b_mm);
    }
    let t43 = fig("table_4_3_f_step29_cx001");
    for (name, label) in TABLE_4_3 {
        let ours = find(scenes, name)
            .and_then(|sc| sc.histories.get("uba")?.rows.iter().find(|r| r.sample.step == 29))
            .map(|r| r.fx_over_fn);
        let _ = writeln!(
            s,
            "| Table 4.3: UBA f after 29 steps at cx = 0.01, μ 0.4 — {label} | {} | {} | `{name}` |",
            t43.map(|v| format!("{v:.6}")).unwrap_or_default(),
            ours.map(|v| format!("{v:.6}")).unwrap_or_default()
        );
    }
    let _ = writeln!(
        s,
        "| UBA − FASTSIM, max over cx ∈ [0, 0.01] | {} ({} %) | 0 (round-off) with a shared leading edge; 0.0107 / 0.0047 / 0.0023 at 22 / 44 / 88 when FASTSIM integrates from the exact ellipse edge | first order in dx; see tests/all/simplified_models.rs |",
        fig("uba_fastsim_max_abs_error").unwrap_or(f64::NAN),
        fig("uba_fastsim_relative_error").map(|v| v * 100.0).unwrap_or(f64::NAN)
    );
    let _ = writeln!(
        s,
        "\nWith the parabolic bound every element slips at cx = 0.01 on this grid, so f = μ = 0.4 exactly; the thesis's 0.399757 keeps some adhesion, which only the ellipsoidal bound (whose slope at the edge is infinite) or other flexibilities give. The thesis never states its pressure, and its two validation figures (4.24/4.25 against FASTSIM, 4.27/4.28 against CONTACT) need different choices, so both stay options (`[model]`) and the defaults follow the CONTACT data: the parabolic bound and Kalker's flexibilities, the ones CONTACT's FASTSIM uses."
    );
    Section::new("The thesis's figures beside ours", s)
}

/// Timing: the isolated repeats' medians and intervals of the re-timed scenes (the
/// work–precision grids and the cost-per-step study), then every scene's single run of the
/// suite, with CONTACT's time for the same case; the slowest runs inline, every run in a linked table.
pub fn timing(scenes: &[StoredScene], refs: &References) -> Section {
    const TITLE: &str = "Timing";
    let mut s = isolated_timing(scenes, refs, TITLE);
    let (single, file) = single_runs(scenes, refs, TITLE);
    s.push_str(&single);
    let files = file.into_iter().chain(isolated_file(scenes, refs, TITLE)).collect();
    Section { tables: files, ..Section::new(TITLE, s) }
}

/// CONTACT's time for the case `name` [s] and per step [ms], as two cells (empty when none).
fn contact_cells(refs: &References, name: &str) -> (String, String) {
    let c = refs.get::<ContactCases>(contact::EXACT).and_then(|c| c.cases.get(name));
    (
        c.map(|c| format!("{:.2}", c.contact_wall_s)).unwrap_or_default(),
        c.map(|c| format!("{:.2}", 1e3 * c.contact_wall_s / (c.n_steps.max(1) as f64))).unwrap_or_default(),
    )
}

/// The table of the re-timed runs: per scene and solver, the median wall time with its interval.
fn isolated_table(scenes: &[StoredScene], refs: &References) -> Table {
    let mut table = Table::new(&[
        "scene",
        "steps",
        "solver",
        "repeats",
        "median wall",
        "95 % interval",
        "coverage",
        "median per step",
        "CONTACT s",
    ]);
    for sc in scenes.iter().filter(|s| !s.repeats.is_empty()) {
        for (solver, h) in &sc.histories {
            let Some(m) = timed::wall_s(sc, solver) else { continue };
            let (c_s, _) = contact_cells(refs, &sc.name);
            table.rows.push(format!(
                "| {} | {} | {solver} | {} | {} | {} | {} | {} | {c_s} |",
                sc.name,
                h.rows.len(),
                m.n,
                timed::fmt_s(m.median),
                m.interval_cell(timed::fmt_s),
                m.coverage.map_or("—".into(), |c| format!("{:.1} %", 100.0 * c)),
                timed::fmt_s(m.median / h.rows.len().max(1) as f64),
            ));
        }
    }
    table
}

/// The re-timed runs' paragraph and table (inline up to the linked-table limit).
fn isolated_timing(scenes: &[StoredScene], refs: &References, title: &str) -> String {
    let table = isolated_table(scenes, refs);
    let mut s = format!("**Re-timed alone.** {}.", timed::method(timed::repeats(scenes)));
    if table.rows.is_empty() {
        s.push_str(" No scene of this run was re-timed.\n\n");
        return s;
    }
    s.push_str(" The scenes the work–precision and cost-per-step sections draw:\n\n");
    let summary = format!("{} re-timed solver runs.", table.rows.len());
    s.push_str(&place("timing_isolated", title, &table, &summary, &[], "").inline);
    s.push('\n');
    s
}

/// The re-timed runs' linked table, when too long to stay inline.
fn isolated_file(scenes: &[StoredScene], refs: &References, title: &str) -> Option<(String, String)> {
    let table = isolated_table(scenes, refs);
    place("timing_isolated", title, &table, &format!("{} re-timed solver runs.", table.rows.len()), &[], "").file
}

/// Every scene's single run of the suite (contention included): the paragraph with the slowest
/// runs inline, and the linked table of all when too long.
fn single_runs(scenes: &[StoredScene], refs: &References, title: &str) -> (String, Option<(String, String)>) {
    const SLOWEST: usize = 10;
    let mut s = String::from("**Single runs of the suite.** Wall time of each solver over the whole scene on this machine, one run each while the scenes ran in parallel on 2 cores (figures include contention), and CONTACT's own time for the case (`contact_wall_s`, whole run incl. start-up and output).\n\n");
    let mut table =
        Table::new(&["scene", "steps", "solver", "wall s", "ms per step", "CONTACT s", "CONTACT ms per step"]);
    let mut walls = Vec::new();
    for sc in scenes {
        for (solver, h) in &sc.histories {
            let w = sc.timing.get(solver).map(|t| t.wall_s).unwrap_or(f64::NAN);
            walls.push(if w.is_finite() { w } else { 0.0 });
            let (c_s, c_ms) = contact_cells(refs, &sc.name);
            table.rows.push(format!(
                "| {} | {} | {solver} | {w:.4} | {:.4} | {c_s} | {c_ms} |",
                sc.name,
                h.rows.len(),
                1e3 * w / h.rows.len().max(1) as f64,
            ));
        }
    }
    let total: f64 = walls.iter().sum();
    let summary = format!(
        "{} solver runs of {} scenes, sum of solver wall times {total:.2} s.",
        table.rows.len(),
        scenes.iter().filter(|sc| !sc.histories.is_empty()).count()
    );
    let placed = place("timing", title, &table, &summary, &largest(&walls, SLOWEST), &format!("The {SLOWEST} slowest"));
    s.push_str(&placed.inline);
    if placed.file.is_none() {
        let _ = writeln!(s, "\n{summary}");
    }
    (s, placed.file)
}

/// The stability table's cases (declared groups `stability`, `stability_falling`): per scene and
/// solver, whether every value is finite, the largest |f|/μ, the oscillation and sawtooth
/// indicators and, for the iterating models, the iteration counts and the solves that hit the
/// iteration limit.
pub fn stability(scenes: &[StoredScene]) -> Section {
    let stab: Vec<&StoredScene> = scenes.iter().filter(|s| s.scene.report_group.is_stability()).collect();
    let mut s = String::from("Extreme and stiff cases (`scenes/stability/`). The traction bound keeps |τ| ≤ μp even when a scheme has blown up, so the bound proves nothing; the indicators do: *oscillation* is the fraction of steps where f turns (a smooth response: about 2 per period; a step-to-step sawtooth: about 1; changes below 1e-6 of max |f|, the jitter of a converged iterative solver, do not count), *sawtooth* the largest fraction of loaded elements where the traction field τx zig-zags along x, *oscillates* flags a history whose |f| turns at 6 or more consecutive steps, more than its loading does (a period-2 oscillation: the memoryless falling branch; also printed by `check` and `run`). A courant number above 1 is refused before anything runs (exit 2).\n\n| scene | solver | steps | all finite | max \\|f\\|/μ | last f | oscillation | sawtooth | oscillates | iterations max | iteration limit hit | warnings |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for sc in stab {
        for (solver, h) in &sc.histories {
            let finite = h
                .rows
                .iter()
                .all(|r| r.fx_over_fn.is_finite() && r.fy_over_fn.is_finite() && r.extra.iter().all(|v| v.is_finite()));
            let max_f = h.rows.iter().map(|r| r.fx_over_fn.hypot(r.fy_over_fn) / r.sample.mu).fold(0.0, f64::max);
            let col_max = |c: &str| h.column(c).map(|v| v.into_iter().fold(0.0, f64::max));
            let limit = h
                .column("termination")
                .map(|v| v.iter().filter(|&&c| c == crate::solvers::Termination::IterationLimit.code()).count());
            let metric = |m: &str| sc.metric(solver, m).map(|v| format!("{v:.3}")).unwrap_or("—".into());
            let _ = writeln!(
                s,
                "| {} | {solver} | {} | {} | {:.6} | {:.6} | {} | {} | {} | {} | {} | {} |",
                sc.name,
                h.rows.len(),
                if finite { "yes" } else { "**no**" },
                max_f,
                h.rows.last().map(|r| r.fx_over_fn).unwrap_or(f64::NAN),
                metric(crate::metrics::oscillation_index::NAME),
                metric(crate::metrics::sawtooth_index::NAME),
                own_oscillation(h, sc.scene.v_mm_s)
                    .map_or("no".to_string(), |o| format!("**yes** ({} turns in a row)", o.run)),
                col_max("iterations").map(|v| format!("{v:.0}")).unwrap_or("—".into()),
                limit.map(|v| v.to_string()).unwrap_or("—".into()),
                sc.scene.warnings.join("; ").replace('|', "/")
            );
        }
    }
    Section::new("Stability", s)
}

/// Convergence under grid refinement: the steady sweeps on 22, 44 and 88 against CONTACT's 88×88.
pub fn grid_convergence(scenes: &[StoredScene], refs: &References) -> Option<Section> {
    let contact = refs.get::<ContactCases>(contact::EXACT)?;
    let ff = contact.history(REFINED[2].0)?.column("fx_over_fn")?;
    let mut s = String::from("Steady sweeps cx = 0 … 0.01 (μ 0.4) on 22×22, 44×44 and 88×88: max |f − f_CONTACT,88×88| over the 101 creepages, and each grid's own CONTACT result for scale.\n\n| grid | solver | max error vs CONTACT 88×88 |\n|---|---|---|\n");
    let max_err =
        |h: &History| h.column("fx_over_fn").map(|c| c.iter().zip(&ff).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max));
    for (name, grid) in REFINED {
        if let Some(e) = contact.history(name).and_then(max_err) {
            let _ = writeln!(s, "| {grid} | CONTACT | {e:.5} |");
        }
        let Some(sc) = find(scenes, name) else { continue };
        for (solver, h) in &sc.histories {
            if let Some(e) = max_err(h) {
                let _ = writeln!(s, "| {grid} | {solver} | {e:.5} |");
            }
        }
    }
    Some(Section::new("Convergence under grid refinement", s))
}

/// Cost per step against element count from the stored scenes of the declared group `scaling`
/// (`report_scaling_<solver>_g<n>`): per step = (wall − set-up) / steps, the median of the
/// isolated repeats with its 95 % interval (error bars), with the fitted growth exponent of the
/// medians (least squares, log–log).
pub fn scaling(scenes: &[StoredScene]) -> Option<Section> {
    // Per solver: (elements, median per step [s], its interval).
    type Point = (f64, f64, Option<(f64, f64)>);
    let mut per_solver: BTreeMap<String, Vec<Point>> = BTreeMap::new();
    for sc in scenes.iter().filter(|s| s.scene.report_group == ReportGroup::Scaling) {
        for (solver, h) in &sc.histories {
            let steps = h.rows.len().max(1);
            let point = match timed::per_step_s(sc, solver, steps) {
                Some(m) => (m.median.max(1e-12), m.interval),
                None => {
                    let Some(t) = sc.timing.get(solver) else { continue };
                    (((t.wall_s - t.setup_s) / steps as f64).max(1e-12), None)
                }
            };
            per_solver.entry(solver.clone()).or_default().push(((sc.scene.mx * sc.scene.my) as f64, point.0, point.1));
        }
    }
    if per_solver.is_empty() {
        return None;
    }
    let mut s = format!("Wall time per time step against the number of grid elements (scenes `report_scaling_*`: step creepage 0.005 from zero traction on the default contact, μ 0.4): (wall − set-up)/steps, set-up being the model's construction and first load (kernels, normal problem), measured by the sample loop. {}; each cell gives the median and its 95 % interval (the figure's error bars). Exponent: slope of log(median time) against log(elements).\n\n| solver | elements: time per step [95 % interval] | exponent |\n|---|---|---|\n", timed::method(timed::repeats(scenes)));
    let mut series = Vec::new();
    for (solver, mut pts) in per_solver {
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        let logs: Vec<(f64, f64)> = pts.iter().map(|(n, t, _)| (n.ln(), t.ln())).collect();
        let m = logs.len() as f64;
        let (sx, sy) = (logs.iter().map(|p| p.0).sum::<f64>() / m, logs.iter().map(|p| p.1).sum::<f64>() / m);
        let slope = logs.iter().map(|p| (p.0 - sx) * (p.1 - sy)).sum::<f64>()
            / logs.iter().map(|p| (p.0 - sx).powi(2)).sum::<f64>();
        let cells: Vec<String> = pts
            .iter()
            .map(|(n, t, i)| {
                let interval =
                    i.map_or(String::new(), |(lo, hi)| format!(" [{}, {}]", timed::fmt_s(lo), timed::fmt_s(hi)));
                format!("{n:.0}: {}{interval}", timed::fmt_s(*t))
            })
            .collect();
        let _ = writeln!(s, "| {solver} | {} | {slope:.2} |", cells.join(", "));
        let bars = pts.iter().map(|p| Bar { x: None, y: p.2 }).collect();
        series.push(Series::model(solver, pts.iter().map(|p| (p.0, p.1)).collect()).with_bars(bars));
    }
    let svg = line_chart(
        "Cost per step against elements",
        &Axis::log("grid elements [–]"),
        &Axis::log("time per step [s]"),
        &series,
    );
    s.push_str("\n![cost per step](figures/cost_per_step.svg)\n");
    Some(Section {
        figures: vec![("cost_per_step.svg".into(), svg)],
        ..Section::new("Cost per step against grid size", s)
    })
}
