//! Result folders on disk: one folder per scene in the `simulate` format, plus `timing.csv`
//! (wall times, kept apart so that the other files stay bit-identical run to run).
//! `run` writes them, `check --against` and the report read them, shards are merged from them.

use crate::error::Error;
use crate::history::History;
use crate::output;
use crate::pipeline::SceneResult;
use std::collections::BTreeMap;
use std::path::Path;

/// A scene's results as read back from disk.
#[derive(Debug, Clone, Default)]
pub struct StoredScene {
    pub name: String,
    /// scene.json as parsed JSON.
    pub scene: serde_json::Value,
    /// Histories by solver name.
    pub histories: BTreeMap<String, History>,
    /// (solver, metric, step) → value.
    pub metrics: MetricMap,
    /// Wall time per solver [s], when recorded.
    pub wall_s: BTreeMap<String, f64>,
}

/// Write each scene's results as `dir/<name>/` (atomically): scene.json, `<solver>.csv`,
/// metrics.csv, and with `with_timing` the wall times in timing.csv.
pub fn write_scenes(dir: &Path, scenes: &[StoredScene], with_timing: bool) -> Result<(), Error> {
    for s in scenes {
        let mut files: Vec<(String, String)> =
            vec![("scene.json".into(), serde_json::to_string_pretty(&s.scene).unwrap_or_default() + "\n")];
        for (solver, h) in &s.histories {
            files.push((format!("{solver}.csv"), h.to_csv()));
        }
        let metrics: Vec<crate::metrics::Metric> = s
            .metrics
            .iter()
            .map(|((solver, name, step), v)| crate::metrics::Metric {
                solver: solver.clone(),
                name: name.clone(),
                value: *v,
                step: *step,
            })
            .collect();
        files.push(("metrics.csv".into(), crate::metrics::to_csv(&metrics)));
        if with_timing {
            let mut t = String::from("solver,wall_s,steps\n");
            for (solver, w) in &s.wall_s {
                t.push_str(&format!("{solver},{w},{}\n", s.histories.get(solver).map(|h| h.rows.len()).unwrap_or(0)));
            }
            files.push(("timing.csv".into(), t));
        }
        output::write_folder_atomically(dir, &s.name, &files)?;
    }
    Ok(())
}

/// Metric values of a metrics.csv by (solver, metric, step).
pub type MetricMap = BTreeMap<(String, String, Option<usize>), f64>;

/// Parse metrics.csv text.
pub fn parse_metrics(text: &str) -> Result<MetricMap, String> {
    let mut out = BTreeMap::new();
    let mut rdr = csv::ReaderBuilder::new().flexible(true).from_reader(text.as_bytes());
    for rec in rdr.records() {
        let rec = rec.map_err(|e| e.to_string())?;
        let value: f64 = rec.get(2).unwrap_or("").parse().map_err(|_| format!("bad value in {rec:?}"))?;
        let step = rec.get(3).filter(|s| !s.is_empty()).and_then(|s| s.parse().ok());
        out.insert((rec[0].to_string(), rec[1].to_string(), step), value);
    }
    Ok(out)
}

/// Read `dir/<name>/` back.
pub fn read_scene(dir: &Path, name: &str) -> Result<StoredScene, Error> {
    let d = dir.join(name);
    let read =
        |f: &str| std::fs::read_to_string(d.join(f)).map_err(|e| Error::other(format!("{}: {e}", d.join(f).display())));
    let scene: serde_json::Value = serde_json::from_str(&read("scene.json")?)
        .map_err(|e| Error::other(format!("{}/scene.json: {e}", d.display())))?;
    let mut s = StoredScene { name: name.into(), scene, ..Default::default() };
    let solvers: Vec<String> = s.scene["solvers"]
        .as_array()
        .map(|a| a.iter().filter_map(|v| v.as_str().map(String::from)).collect())
        .unwrap_or_default();
    for solver in solvers {
        let text = read(&format!("{solver}.csv"))?;
        let h = History::from_csv(&solver, &text)
            .map_err(|e| Error::other(format!("{}/{solver}.csv: {e}", d.display())))?;
        s.histories.insert(solver, h);
    }
    s.metrics =
        parse_metrics(&read("metrics.csv")?).map_err(|e| Error::other(format!("{}/metrics.csv: {e}", d.display())))?;
    if let Ok(t) = read("timing.csv") {
        for line in t.lines().skip(1) {
            let parts: Vec<&str> = line.split(',').collect();
            if let (Some(n), Some(w)) = (parts.first(), parts.get(1).and_then(|w| w.parse().ok())) {
                s.wall_s.insert(n.to_string(), w);
            }
        }
    }
    Ok(s)
}

/// Names of the scene folders in `dir` (those holding a scene.json), sorted.
pub fn scene_names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .filter_map(|e| e.ok())
        .filter(|e| e.path().join("scene.json").exists())
        .filter_map(|e| e.file_name().to_str().map(String::from))
        .filter(|n| !n.starts_with('.'))
        .collect();
    names.sort();
    names
}

impl StoredScene {
    /// From an in-memory result (no disk round trip).
    pub fn from_result(r: &SceneResult) -> StoredScene {
        let ran: Vec<String> = r.histories.iter().map(|h| h.solver.clone()).collect();
        let scene = serde_json::from_str(&output::scene_json(&r.problem, &ran)).unwrap_or_default();
        StoredScene {
            name: r.problem.name.clone(),
            scene,
            histories: r.histories.iter().map(|h| (h.solver.clone(), h.clone())).collect(),
            metrics: r.metrics.iter().map(|m| ((m.solver.clone(), m.name.clone(), m.step), m.value)).collect(),
            wall_s: r.histories.iter().zip(&r.wall_s).map(|(h, w)| (h.solver.clone(), *w)).collect(),
        }
    }

    /// Sine period [s], if the scene is a sine.
    pub fn period_s(&self) -> Option<f64> {
        self.scene["freq_hz"].as_f64().map(|f| 1.0 / f)
    }
}
