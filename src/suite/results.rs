//! Result folders on disk: one folder per scene in the `simulate` format, plus `timing.csv`
//! (the suite's wall times) and `timing_repeats.csv` (the isolated repeats of `run`,
//! [`super::timing`]), kept apart so that the other files stay bit-identical run to run. `simulate`,
//! `run` and `bless` write them; `check --against`, `merge` and the report read them.

use crate::error::{Error, FormatError};
use crate::history::History;
use crate::metrics::Metric;
use crate::pipeline::{SceneResult, Timing};
use crate::problem::ResolvedScene;
use crate::safety::folder::{self, Contents};
use crate::safety::read::{read_text, GOLDEN_LIMIT_BYTES};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Metric values of a metrics.csv by (solver, metric, step).
pub type MetricMap = BTreeMap<(String, String, Option<usize>), f64>;

/// A scene's results as stored on disk.
#[derive(Debug, Clone)]
pub struct StoredScene {
    pub name: String,
    /// scene.json.
    pub scene: ResolvedScene,
    /// Histories by solver name.
    pub histories: BTreeMap<String, History>,
    pub metrics: MetricMap,
    /// Wall times per solver, when recorded (timing.csv).
    pub timing: BTreeMap<String, Timing>,
    /// Wall times of each solver's isolated repeats, when re-timed (timing_repeats.csv).
    pub repeats: BTreeMap<String, Vec<Timing>>,
    /// What external models printed, by file name (`<model>.stdout.txt`).
    pub logs: BTreeMap<String, String>,
}

impl StoredScene {
    /// From an in-memory result.
    pub fn from_result(r: &SceneResult) -> StoredScene {
        let ran: Vec<String> = r.histories.iter().map(|h| h.solver.clone()).collect();
        StoredScene {
            name: r.problem.name.clone(),
            scene: ResolvedScene::of(&r.problem, &ran),
            histories: r.histories.iter().map(|h| (h.solver.clone(), h.clone())).collect(),
            metrics: r.metrics.iter().map(|m| ((m.solver.clone(), m.name.clone(), m.step), m.value)).collect(),
            timing: r.histories.iter().zip(&r.timing).map(|(h, t)| (h.solver.clone(), *t)).collect(),
            repeats: BTreeMap::new(),
            logs: r.logs.iter().cloned().collect(),
        }
    }

    /// From an in-memory result, which it consumes: the histories and the loading are moved,
    /// not copied (a long scene is held once).
    pub fn from_owned(r: SceneResult) -> StoredScene {
        let ran: Vec<String> = r.histories.iter().map(|h| h.solver.clone()).collect();
        let timing = r.histories.iter().zip(&r.timing).map(|(h, t)| (h.solver.clone(), *t)).collect();
        StoredScene {
            name: r.problem.name.clone(),
            scene: ResolvedScene::of_owned(r.problem, &ran),
            histories: r.histories.into_iter().map(|h| (h.solver.clone(), h)).collect(),
            metrics: r.metrics.into_iter().map(|m| ((m.solver, m.name, m.step), m.value)).collect(),
            timing,
            repeats: BTreeMap::new(),
            logs: r.logs.into_iter().collect(),
        }
    }

    /// A scalar metric of one solver.
    pub fn metric(&self, solver: &str, name: &str) -> Option<f64> {
        self.metrics.get(&(solver.to_string(), name.to_string(), None)).copied()
    }

    /// The files of the result folder: scene.json, `<solver>.csv`, metrics.csv, the external
    /// models' `<model>.stdout.txt` / `<model>.stderr.txt` and, with `with_timing`, timing.csv
    /// (and timing_repeats.csv when re-timed).
    /// scene.json and the histories are written into their files as they are produced.
    pub fn files(&self, with_timing: bool) -> Vec<(String, Contents<'_>)> {
        let mut files = vec![("scene.json".to_string(), Contents::written(|w| self.scene.write_json(w)))];
        for (solver, h) in &self.histories {
            files.push((format!("{solver}.csv"), Contents::written(|w| h.write_csv(w))));
        }
        let metrics: Vec<Metric> = self
            .metrics
            .iter()
            .map(|((solver, name, step), v)| Metric {
                solver: solver.clone(),
                name: name.clone(),
                value: *v,
                step: *step,
            })
            .collect();
        files.push(("metrics.csv".into(), crate::metrics::to_csv(&metrics).into()));
        files.extend(self.logs.iter().map(|(f, text)| (f.clone(), Contents::from(text.as_str()))));
        if with_timing {
            let mut t = String::from("solver,wall_s,steps,setup_s\n");
            for (solver, w) in &self.timing {
                let steps = self.histories.get(solver).map(|h| h.rows.len()).unwrap_or(0);
                t.push_str(&format!("{solver},{},{steps},{}\n", w.wall_s, w.setup_s));
            }
            files.push(("timing.csv".into(), t.into()));
            if !self.repeats.is_empty() {
                files.push((REPEATS_FILE.into(), self.repeats_csv().into()));
            }
        }
        files
    }

    /// The files of [`StoredScene::files`] as text, each whole in memory.
    pub fn file_texts(&self, with_timing: bool) -> Vec<(String, String)> {
        let text = |c: Contents| String::from_utf8(c.into_bytes()).expect("result files are UTF-8");
        self.files(with_timing).into_iter().map(|(name, c)| (name, text(c))).collect()
    }

    /// timing_repeats.csv: one row per solver and repeat.
    fn repeats_csv(&self) -> String {
        let mut t = String::from("solver,repeat,wall_s,steps,setup_s\n");
        for (solver, runs) in &self.repeats {
            let steps = self.histories.get(solver).map(|h| h.rows.len()).unwrap_or(0);
            for (k, w) in runs.iter().enumerate() {
                t.push_str(&format!("{solver},{},{},{steps},{}\n", k + 1, w.wall_s, w.setup_s));
            }
        }
        t
    }
}

/// The isolated repeats' wall times (`run`, [`super::timing`]).
pub const REPEATS_FILE: &str = "timing_repeats.csv";

/// The repeats of a timing_repeats.csv text, by solver (rows that do not parse are skipped: the
/// file holds wall times only, never a result).
fn parse_repeats(text: &str) -> BTreeMap<String, Vec<Timing>> {
    let mut out: BTreeMap<String, Vec<Timing>> = BTreeMap::new();
    for line in text.lines().skip(1) {
        let parts: Vec<&str> = line.split(',').collect();
        let num = |i: usize| parts.get(i).and_then(|w| w.parse::<f64>().ok());
        if let (Some(n), Some(wall_s), Some(setup_s)) = (parts.first(), num(2), num(4)) {
            out.entry(n.to_string()).or_default().push(Timing { wall_s, setup_s });
        }
    }
    out
}

/// Write each scene's results as `dir/<name>/`, each folder atomically and marked as a result
/// folder (a directory creepbench did not write is never replaced). The caller holds `dir`'s
/// lock (`lock::lock_folder`, which removed the leftovers of killed runs) or is building `dir`
/// (bless's new tree): `dir` is not listed per scene, each write takes the same time whatever
/// `dir` holds ([`folder::write_result_folder_cleaned`]).
pub fn write_scenes(dir: &Path, scenes: &[StoredScene], with_timing: bool) -> Result<Vec<PathBuf>, Error> {
    scenes.iter().map(|s| Ok(folder::write_result_folder_cleaned(dir, &s.name, s.files(with_timing))?)).collect()
}

/// The scenes of a blessed tree that a new bless keeps: those it does not produce again.
pub fn copy_scene(from: &Path, to: &Path, name: &str) -> Result<(), Error> {
    let (src, dst) = (from.join(name), to.join(name));
    std::fs::create_dir_all(&dst).map_err(Error::io(&dst))?;
    for entry in std::fs::read_dir(&src).map_err(Error::io(&src))?.flatten() {
        let target = dst.join(entry.file_name());
        std::fs::copy(entry.path(), &target).map_err(Error::io(&target))?;
    }
    Ok(())
}

/// Parse metrics.csv text.
pub fn parse_metrics(text: &str) -> Result<MetricMap, FormatError> {
    let mut out = BTreeMap::new();
    let mut rdr = csv::ReaderBuilder::new().flexible(true).from_reader(text.as_bytes());
    for (n, rec) in rdr.records().enumerate() {
        let line = n + 2;
        let rec = rec.map_err(|e| FormatError::Csv { line, source: e })?;
        let field = |i: usize| rec.get(i).unwrap_or("");
        let value: f64 = field(2).parse().map_err(|_| FormatError::Value {
            line,
            column: "value".into(),
            value: crate::error::excerpt(field(2)),
            what: "a number",
        })?;
        let step = match field(3) {
            "" => None,
            s => Some(s.parse::<usize>().map_err(|_| FormatError::Value {
                line,
                column: "step".into(),
                value: crate::error::excerpt(s),
                what: "a step index",
            })?),
        };
        out.insert((field(0).to_string(), field(1).to_string(), step), value);
    }
    Ok(out)
}

/// Only the scene.json of `dir/<name>/` (which suite it is of, without reading its histories).
pub fn read_resolved(dir: &Path, name: &str) -> Result<ResolvedScene, Error> {
    let path = dir.join(name).join("scene.json");
    let text = read_text(&path, GOLDEN_LIMIT_BYTES, "result file")?;
    ResolvedScene::from_json(&text).map_err(|e| Error::Format { path, source: FormatError::Json(e) })
}

/// Read `dir/<name>/` back.
pub fn read_scene(dir: &Path, name: &str) -> Result<StoredScene, Error> {
    let d = dir.join(name);
    let read = |f: &str| read_text(&d.join(f), GOLDEN_LIMIT_BYTES, "result file");
    let scene = read_resolved(dir, name)?;
    let mut s = StoredScene {
        name: name.into(),
        histories: BTreeMap::new(),
        metrics: BTreeMap::new(),
        timing: BTreeMap::new(),
        repeats: BTreeMap::new(),
        logs: BTreeMap::new(),
        scene,
    };
    // A scene of no model compares nothing: refused, not merged as passing.
    if s.scene.solvers.is_empty() {
        let source = FormatError::MissingColumn { column: "at least one solver in scene.json's solvers".into() };
        return Err(Error::Format { path: d.join("scene.json"), source });
    }
    // Every history in the folder is one scene.json lists: an extra file is not silently ignored.
    for entry in std::fs::read_dir(&d).map_err(Error::io(&d))?.flatten() {
        let file = entry.file_name().to_string_lossy().to_string();
        if let Some(stem) = file.strip_suffix(".csv") {
            if !["metrics", "timing", "timing_repeats"].contains(&stem) && !s.scene.solvers.iter().any(|x| x == stem) {
                let source = FormatError::MissingColumn {
                    column: format!("{stem} in scene.json's solvers (the folder holds {file})"),
                };
                return Err(Error::Format { path: d.join("scene.json"), source });
            }
        }
    }
    // The declared loading sampled once: checked, and the rows' own speeds taken from it.
    let rows = s
        .scene
        .loading_rows()
        .map_err(|e| Error::Format { path: d.join("scene.json"), source: FormatError::Loading(e) })?;
    let speeds: BTreeMap<usize, f64> = rows.iter().filter_map(|s| Some((s.step, s.v_mm_s?))).collect();
    drop(rows);
    for solver in &s.scene.solvers {
        let file = d.join(format!("{solver}.csv"));
        let mut h = History::from_csv(solver, &read(&format!("{solver}.csv"))?).map_err(Error::format(&file))?;
        restore_speeds(&mut h, &speeds);
        s.histories.insert(solver.clone(), h);
        // What an external model printed, carried along (by `merge`) when the folder holds it.
        for log in [format!("{solver}.stdout.txt"), format!("{solver}.stderr.txt"), format!("{solver}_stress.csv")] {
            if d.join(&log).exists() {
                s.logs.insert(log.clone(), read(&log)?);
            }
        }
    }
    s.metrics = parse_metrics(&read("metrics.csv")?).map_err(Error::format(d.join("metrics.csv")))?;
    if let Ok(t) = read("timing.csv") {
        for line in t.lines().skip(1) {
            let parts: Vec<&str> = line.split(',').collect();
            let num = |i: usize| parts.get(i).and_then(|w| w.parse::<f64>().ok());
            if let (Some(n), Some(wall_s)) = (parts.first(), num(1)) {
                s.timing.insert(n.to_string(), Timing { wall_s, setup_s: num(3).unwrap_or(0.0) });
            }
        }
    }
    if let Ok(t) = read(REPEATS_FILE) {
        s.repeats = parse_repeats(&t);
    }
    Ok(s)
}

/// The rows' own rolling speeds (a table's `v_mm_s`, a speed sweep), which a history CSV does
/// not hold, from scene.json's loading (`speeds` by step).
fn restore_speeds(h: &mut History, speeds: &BTreeMap<usize, f64>) {
    if speeds.is_empty() {
        return;
    }
    for row in &mut h.rows {
        row.sample.v_mm_s = speeds.get(&row.sample.step).copied();
    }
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
