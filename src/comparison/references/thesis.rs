//! The thesis's published figures (reference/thesis): Table 4.2's delay ratios (CONTACT, μ = 1,
//! 22×22) and scalar figures (Hertz semi-axes, Table 4.3, the UBA–FASTSIM error of Fig. 4.24).

use super::{read, ReferenceSet};
use crate::comparison::finding::{Against, Ctx, Finding};
use crate::comparison::rule::Rule;
use crate::error::Error;
use crate::history::History;
use crate::suite::results::StoredScene;
use std::collections::BTreeMap;
use std::path::Path;

/// Table 4.2 of the thesis: one row.
#[derive(Debug, Clone, Copy)]
pub struct ThesisDelay {
    pub freq_hz: f64,
    pub delay_ms: f64,
    pub delay_ratio: f64,
}

/// The thesis's tables.
#[derive(Debug, Clone, Default)]
pub struct ThesisTables {
    pub delays: Vec<ThesisDelay>,
    /// Scalar figures by key (thesis_figures.csv).
    pub figures: BTreeMap<String, f64>,
}

/// Findings against the thesis are labelled so.
pub const AGAINST: Against = Against::Reference("thesis");

impl ThesisTables {
    pub fn load(dir: &Path) -> Result<ThesisTables, Error> {
        let mut t = ThesisTables::default();
        let t42 = read(&dir.join("thesis/table_4_2_delay.csv"))?;
        for line in t42.lines().skip(1).filter(|l| !l.trim().is_empty()) {
            let v: Vec<f64> = line.split(',').filter_map(|x| x.trim().parse().ok()).collect();
            if v.len() >= 4 {
                t.delays.push(ThesisDelay { freq_hz: v[0], delay_ms: v[2], delay_ratio: v[3] });
            }
        }
        let figs = read(&dir.join("thesis/thesis_figures.csv"))?;
        for line in figs.lines().skip(1).filter(|l| !l.trim().is_empty()) {
            let parts: Vec<&str> = line.splitn(3, ',').collect();
            if let (Some(k), Some(v)) = (parts.first(), parts.get(1).and_then(|v| v.trim().parse().ok())) {
                t.figures.insert(k.trim().to_string(), v);
            }
        }
        Ok(t)
    }

    /// Table 4.2's delay ratio for a scene: a sine at a tabulated frequency, μ = 1, 22×22.
    pub fn delay_for(&self, scene: &StoredScene) -> Option<f64> {
        let p = scene.scene.period_s()?;
        if scene.scene.mu != 1.0 || scene.scene.mx != 22 {
            return None;
        }
        self.delays.iter().find(|d| (1.0 / d.freq_hz - p).abs() < 1e-9 * p).map(|d| d.delay_ratio)
    }

    /// A scalar figure by key.
    pub fn figure(&self, key: &str) -> Option<f64> {
        self.figures.get(key).copied()
    }
}

impl ReferenceSet for ThesisTables {
    fn label(&self) -> &'static str {
        "thesis"
    }

    fn compare(&self, ours: &StoredScene, rules: &[Rule]) -> Vec<Finding> {
        let Some(td) = self.delay_for(ours) else { return Vec::new() };
        let mut out = Vec::new();
        for solver in ours.histories.keys() {
            if let Some(d) = ours.metric(solver, crate::metrics::delay_ratio::NAME) {
                let ctx = Ctx { scene: &ours.name, solver, against: AGAINST, rules };
                out.push(ctx.finding(
                    crate::metrics::delay_ratio::NAME,
                    None,
                    d,
                    td,
                    "thesis Table 4.2 (CONTACT, mu = 1)",
                ));
            }
        }
        out
    }

    fn history(&self, _: &str) -> Option<&History> {
        None
    }
}
