//! The report's work–precision section (issue 14, item 4): every model on the 22×22, 44×44 and
//! 88×88 grids of sine_f30_mu10, its error against a grid-converged reference — the exact
//! solver's three grids extrapolated to zero element size (Richardson, with the observed order) —
//! against its wall time per simulated second, on one log–log diagram. Reads stored results only.

use crate::comparison::references::contact::{self, ContactCases};
use crate::comparison::references::References;
use crate::history::History;
use crate::report::plot::{line_chart, Axis, Bar, Series};
use crate::report::section::Section;
use crate::report::timed;
use crate::suite::results::StoredScene;
use std::collections::BTreeMap;
use std::fmt::Write;

/// The scene on its three grids (the element size halves from one to the next, at one Courant
/// number: time steps halve with it, so each coarse time is a sample of the finer runs).
pub const GRIDS: [(&str, usize); 3] = [("sine_f30_mu10", 22), ("sine_f30_mu10_g44", 44), ("sine_f30_mu10_g88", 88)];
/// A point of the work–precision figure (cost, error) with its error bar.
type Point = ((f64, f64), Bar);

/// The model extrapolated.
const EXACT: &str = crate::solvers::contact::NAME;

/// fx/FN of `h` at time `t`, linearly interpolated (None outside its times).
fn at(t_h: &[f64], f_h: &[f64], t: f64) -> Option<f64> {
    let k = t_h.partition_point(|&x| x < t - 1e-12);
    if k >= t_h.len() {
        return None;
    }
    if (t_h[k] - t).abs() < 1e-12 || k == 0 {
        return Some(f_h[k]);
    }
    Some(f_h[k - 1] + (f_h[k] - f_h[k - 1]) * (t - t_h[k - 1]) / (t_h[k] - t_h[k - 1]))
}

fn columns(h: &History) -> (Vec<f64>, Vec<f64>) {
    (h.column("t_s").unwrap_or_default(), h.column("fx_over_fn").unwrap_or_default())
}

/// A grid-converged reference: fx/FN at the coarse run's times.
#[derive(Debug, Clone, PartialEq)]
pub struct Extrapolated {
    pub t_s: Vec<f64>,
    pub f: Vec<f64>,
    /// The observed order p = log2(d(h, h/2) / d(h/2, h/4)), d the max difference over the times.
    pub order: f64,
    pub d_coarse: f64,
    pub d_fine: f64,
}

/// Richardson's extrapolation of three runs with element sizes h, h/2, h/4 at the coarse run's
/// times: `f∞ = f_{h/4} + (f_{h/4} − f_{h/2}) / (2^p − 1)` with the observed order p (None when
/// the differences do not shrink).
pub fn richardson(coarse: &History, mid: &History, fine: &History) -> Option<Extrapolated> {
    let ((tc, fc), (tm, fm), (tf, ff)) = (columns(coarse), columns(mid), columns(fine));
    let mut rows = Vec::new();
    for (&t, &c) in tc.iter().zip(&fc) {
        if let (Some(m), Some(f)) = (at(&tm, &fm, t), at(&tf, &ff, t)) {
            rows.push((t, c, m, f));
        }
    }
    let d_coarse = rows.iter().map(|r| (r.2 - r.1).abs()).fold(0.0, f64::max);
    let d_fine = rows.iter().map(|r| (r.3 - r.2).abs()).fold(0.0, f64::max);
    if !(d_fine > 0.0 && d_coarse > d_fine) {
        return None;
    }
    let order = (d_coarse / d_fine).log2();
    let gain = 1.0 / (2f64.powf(order) - 1.0);
    Some(Extrapolated {
        t_s: rows.iter().map(|r| r.0).collect(),
        f: rows.iter().map(|r| r.3 + (r.3 - r.2) * gain).collect(),
        order,
        d_coarse,
        d_fine,
    })
}

impl Extrapolated {
    /// Max |f − f∞| over the reference's times within `h`'s (h interpolated where it has no sample).
    pub fn error(&self, h: &History) -> f64 {
        let (th, fh) = columns(h);
        self.t_s.iter().zip(&self.f).filter_map(|(&t, &r)| at(&th, &fh, t).map(|v| (v - r).abs())).fold(0.0, f64::max)
    }
}

/// Whether the scene's three grids are stored (the section needs them, and their convergence).
pub fn applies(scenes: &[StoredScene]) -> bool {
    GRIDS.iter().all(|(n, _)| scenes.iter().any(|s| s.name == *n))
}

/// The section, if the three grids of the exact solver are stored and converge.
pub fn section(scenes: &[StoredScene], refs: &References) -> Option<Section> {
    let find = |name: &str| scenes.iter().find(|s| s.name == name);
    let contact = refs.get::<ContactCases>(contact::EXACT);
    let exact: Vec<&History> = GRIDS.iter().filter_map(|(n, _)| find(n).and_then(|s| s.histories.get(EXACT))).collect();
    let [c, m, f] = exact[..] else { return None };
    let x = richardson(c, m, f)?;
    let mut s = format!(
        "Scene sine_f30_mu10 (30 Hz, μ = 1) on 22×22, 44×44 and 88×88 grids. Reference: the exact solver's (`{EXACT}`) three grids extrapolated to zero element size at the 22×22 run's {} times (Richardson: f∞ = f88 + (f88 − f44)/(2^p − 1), observed order p = log2(d(22, 44)/d(44, 88)) = log2({:.5}/{:.5}) = {:.2}). Error: max |fx/FN − f∞| over those times; cost: wall time per simulated second on this machine, the median with its 95 % interval (the figure's error bars). {}. CONTACT's own runs of the three grids are scored the same way (`contact_wall_s` includes start-up and file output). The 88×88 exact run's distance from f∞ is the discretisation error left at that grid, which a comparison with CONTACT's own 88×88 (1e-7) does not show.\n\n| model | grid | max \\|f − f∞\\| | wall s per simulated s | 95 % interval | wall ms per step |\n|---|---|---|---|---|---|\n",
        x.t_s.len(),
        x.d_coarse,
        x.d_fine,
        x.order,
        timed::method(timed::repeats(scenes))
    );
    let mut curves: BTreeMap<String, Vec<Point>> = Default::default();
    for (name, grid) in GRIDS {
        let Some(sc) = find(name) else { continue };
        let rows = sc.scene.loading_rows().unwrap_or_default();
        let sim_s = rows.last().map(|r| r.t_s).unwrap_or(f64::NAN);
        for (solver, h) in &sc.histories {
            let err = x.error(h);
            let single = || sc.timing.get(solver).map(|t| t.wall_s).unwrap_or(f64::NAN);
            let wall = timed::wall_s(sc, solver);
            let per_sim = wall.map(|m| m.scaled(1.0 / sim_s));
            let median = wall.map_or_else(single, |m| m.median);
            let _ = writeln!(
                s,
                "| {solver} | {grid} | {err:.2e} | {:.2e} | {} | {:.2e} |",
                median / sim_s,
                per_sim.map_or("—".into(), |m| m.interval_cell(|v| format!("{v:.2e}"))),
                1e3 * median / h.rows.len() as f64
            );
            let bar = Bar { x: per_sim.and_then(|m| m.interval), y: None };
            curves.entry(solver.clone()).or_default().push(((median / sim_s, err.max(1e-12)), bar));
        }
        if let (Some(c), Some(ch)) = (contact.and_then(|c| c.cases.get(name)), contact.and_then(|c| c.history(name))) {
            let err = x.error(ch);
            let _ = writeln!(
                s,
                "| CONTACT (reference run) | {grid} | {err:.2e} | {:.2e} | one run | {:.2e} |",
                c.contact_wall_s / sim_s,
                1e3 * c.contact_wall_s / (c.n_steps as f64 + 1.0)
            );
            curves
                .entry("CONTACT".into())
                .or_default()
                .push(((c.contact_wall_s / sim_s, err.max(1e-12)), Bar::default()));
        }
    }
    let series: Vec<Series> = curves
        .into_iter()
        .map(|(label, points)| {
            let (points, bars): (Vec<_>, Vec<_>) = points.into_iter().unzip();
            match label.as_str() {
                "CONTACT" => Series::reference(label, points),
                _ => Series::model(label, points).with_bars(bars),
            }
        })
        .collect();
    let svg = line_chart(
        "Work-precision (sine_f30_mu10, grids 22, 44, 88)",
        &Axis::log("wall time per simulated time [s/s]"),
        &Axis::log("max |f − f_∞| [–]"),
        &series,
    );
    s.push_str("\n![work-precision](figures/error_vs_time.svg)\n");
    Some(Section {
        figures: vec![("error_vs_time.svg".into(), svg)],
        ..Section::new("Work–precision: error against a grid-converged reference and run time", s)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::history::Row;
    use crate::problem::Sample;

    fn history(dt: f64, n: usize, f: impl Fn(f64) -> f64) -> History {
        let mut h = History::new("m", &[]);
        for k in 0..=n {
            let t = k as f64 * dt;
            let row = Row {
                sample: Sample::given(k, t, 0.0, 0.0, 0.0, 1.0, 1.0).into(),
                fx_over_fn: f(t),
                fy_over_fn: 0.0,
                extra: Vec::new(),
            };
            h.rows.push(row);
        }
        h
    }

    /// Three runs whose error is C h^p exactly (p = 1.5): the observed order is p and the
    /// extrapolation is the exact function to rounding.
    #[test]
    fn richardson_recovers_order_and_limit() {
        let exact = |t: f64| (3.0 * t).sin();
        let run = |h: f64, n: usize| history(0.1 * h, n, move |t| exact(t) + 0.2 * h.powf(1.5) * (1.0 + t));
        let (c, m, f) = (run(1.0, 10), run(0.5, 20), run(0.25, 40));
        let x = richardson(&c, &m, &f).unwrap();
        assert!((x.order - 1.5).abs() < 1e-12, "{}", x.order);
        assert_eq!(x.t_s.len(), 11);
        for (t, v) in x.t_s.iter().zip(&x.f) {
            assert!((v - exact(*t)).abs() < 1e-14, "{t}: {v}");
        }
        // A run's error against the limit is its own C h^p at the reference times.
        assert!((x.error(&f) - 0.2 * 0.25f64.powf(1.5) * 2.0).abs() < 1e-14);
        // Differences that do not shrink give no reference.
        assert!(richardson(&f, &m, &c).is_none());
    }
}
