//! A suite: the scene files of a folder, optionally one shard of them, run in parallel.

use crate::error::{Error, InputError};
use crate::pipeline::{self, InProcess, SceneResult};
use crate::problem::Problem;
pub mod median;
pub mod results;
pub mod timing;
pub mod wheelrail;

pub use crate::scene::source::SceneSource;
use crate::scene::study;
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use std::path::{Path, PathBuf};

/// The default suites: the thesis scenes, CONTACT's case sets (envelope, non-Hertzian, test
/// table, falling friction and its variants), the stability scenes, the studies behind the report,
/// CONTACT's public examples and its wheel–rail decks (module 1, gated against CONTACT alone).
pub const DEFAULT_SUITES: [&str; 10] = [
    "scenes/thesis",
    "scenes/envelope",
    "scenes/nonhertz",
    "scenes/table",
    "scenes/stability",
    "scenes/report",
    "scenes/friction",
    "scenes/friction_variants",
    "scenes/contact_public",
    "scenes/wheelrail",
];

/// `--shard i/n`: this run takes the scenes whose name hashes to i − 1 modulo n.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub index: usize,
    pub count: usize,
}

/// A `--shard` value that is not `i/n` with 1 ≤ i ≤ n.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("--shard {given:?}: expected i/n with whole numbers 1 <= i <= n, e.g. 1/2")]
pub struct ShardError {
    pub given: String,
}

impl std::str::FromStr for Shard {
    type Err = ShardError;
    fn from_str(s: &str) -> Result<Self, ShardError> {
        let bad = || ShardError { given: crate::error::excerpt(s) };
        let (i, n) = s.split_once('/').ok_or_else(bad)?;
        let (i, n): (usize, usize) = (i.parse().map_err(|_| bad())?, n.parse().map_err(|_| bad())?);
        if n == 0 || i == 0 || i > n {
            return Err(bad());
        }
        Ok(Shard { index: i, count: n })
    }
}

impl Shard {
    /// Whether `scene` belongs to this shard (FNV-1a of the name: stable across machines).
    pub fn takes(&self, scene: &str) -> bool {
        let h = scene.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ b as u64).wrapping_mul(0x100_0000_01b3));
        (h % self.count as u64) as usize == self.index - 1
    }
}

/// A suite folder's tolerance rules (`tolerance_file`), not a scene.
pub const TOLERANCE_FILE: &str = "tolerances.toml";

/// The scenes of the folders `dirs` — scene files and the points of study files — sorted by
/// name and restricted to `shard` (a study's points are sharded one by one); every `*.toml`
/// but the folder's [`TOLERANCE_FILE`].
pub fn scene_files(dirs: &[PathBuf], shard: Option<Shard>) -> Result<Vec<SceneSource>, Error> {
    let mut files: Vec<PathBuf> = Vec::new();
    for dir in dirs {
        let entries = std::fs::read_dir(dir)
            .map_err(|e| InputError::new("--suite", dir.display(), format!("a folder of scene files ({e})")))?;
        files.extend(
            entries
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "toml") && !p.ends_with(TOLERANCE_FILE)),
        );
    }
    // File order decides which study a shared point lists first: sorted, never the folder's.
    files.sort();
    let mut out: Vec<SceneSource> = Vec::new();
    // Scene name -> its place in `out` (linear in the number of scenes).
    let mut index: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    for path in files {
        for point in sources_of_file(&path)? {
            // A point two studies share (same name, same scene) runs once, in both.
            if let Some(twin) = index.get(&point.name).map(|&i| &mut out[i]) {
                match (&mut twin.study, point.study) {
                    (Some((d, points)), Some((doc, more))) if *d == doc => {
                        points.extend(more);
                        continue;
                    }
                    _ => {
                        return Err(InputError::new(
                            "name",
                            format!("{:?} in both {} and {}", point.name, twin.path.display(), path.display()),
                            "distinct scene names in one run (a point two studies share must be the same scene)",
                        )
                        .into())
                    }
                }
            }
            index.insert(point.name.clone(), out.len());
            out.push(point);
        }
    }
    out.sort_by(|a, b| a.name.cmp(&b.name));
    if let Some(s) = shard {
        out.retain(|src| s.takes(&src.name));
    }
    Ok(out)
}

/// The scenes of one file: the file itself, or the points of a study file.
pub fn sources_of_file(path: &Path) -> Result<Vec<SceneSource>, Error> {
    // A file that does not parse is left to the scene reader, whose message names the place.
    let doc = crate::safety::read::read_text(path, crate::safety::read::SCENE_LIMIT_BYTES, "scene file")
        .ok()
        .and_then(|t| t.parse::<toml::Table>().ok());
    sources_of_doc(path, doc.as_ref())
}

/// [`sources_of_file`] of the file at `path` already parsed (`doc`; `None`: it does not parse).
pub fn sources_of_doc(path: &Path, doc: Option<&toml::Table>) -> Result<Vec<SceneSource>, Error> {
    let stem = path.file_stem().and_then(|n| n.to_str()).unwrap_or("").to_string();
    let doc = match doc {
        Some(doc) if study::is_study(doc) => doc,
        other => {
            // One identity for shards, bless and merge: the scene's `name` (its stem when it has
            // none, which the scene reader then refuses).
            let name = other.and_then(|d| d.get("name")).and_then(|v| v.as_str()).map_or(stem, str::to_string);
            return Ok(vec![SceneSource { path: path.to_path_buf(), name, study: None }]);
        }
    };
    let in_file = |mut e: InputError| {
        e.field = format!("{}: {}", path.display(), e.field);
        e
    };
    Ok(pipeline::expand_study(doc)
        .map_err(in_file)?
        .into_iter()
        .map(|p| SceneSource { path: path.to_path_buf(), name: p.name, study: Some((p.doc, vec![p.point])) })
        .collect())
}

/// The scene called `name` in the folders `dirs` (a scene file's stem or a study's point).
pub fn find(dirs: &[PathBuf], name: &str) -> Result<SceneSource, Error> {
    scene_files(dirs, None)?.into_iter().find(|s| s.name == name).ok_or_else(|| {
        let dirs: Vec<String> = dirs.iter().map(|d| d.display().to_string()).collect();
        InputError::new("scene", name, format!("a scene or study point of {}", dirs.join(", "))).into()
    })
}

/// The names of every scene of the folders (scene files' stems and study points), all shards.
pub fn scene_names(dirs: &[PathBuf]) -> Result<Vec<String>, Error> {
    Ok(scene_files(dirs, None)?.into_iter().map(|s| s.name).collect())
}

/// Validate every scene first (bad input stops the run before anything is computed), then run
/// them in parallel. The results come back in the files' order whatever the thread count.
pub fn run(files: &[SceneSource], progress: bool) -> Result<Vec<SceneResult>, Error> {
    run_with(files, progress, &[])
}

/// [`run`], where a scene may also list the models `in_process` (run in this process,
/// [`pipeline::InProcess`]) in its `solvers`.
pub fn run_with(files: &[SceneSource], progress: bool, in_process: &[InProcess]) -> Result<Vec<SceneResult>, Error> {
    let names: Vec<String> = in_process.iter().map(|(n, _)| n.to_string()).collect();
    let problems = files.iter().map(|f| pipeline::load_source_with(f, &[], &names)).collect::<Result<Vec<_>, _>>()?;
    // Two scenes of one name would write one result folder: refuse before anything runs.
    let mut seen: std::collections::HashMap<&str, usize> = std::collections::HashMap::new();
    for (i, p) in problems.iter().enumerate() {
        if let Some(&j) = seen.get(p.name.as_str()) {
            return Err(InputError::new(
                "name",
                format!("{:?} in both {} and {}", p.name, files[j].path.display(), files[i].path.display()),
                "distinct scene names in one run",
            )
            .into());
        }
        seen.insert(&p.name, i);
    }
    let bar = if progress && files.len() > 1 {
        let b = ProgressBar::new(problems.len() as u64);
        b.set_style(
            ProgressStyle::with_template("{bar:40} {pos}/{len} scenes {elapsed} {msg}")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        b
    } else {
        ProgressBar::hidden()
    };
    // Longest first, each worker taking the next scene when it is free (greedy list scheduling,
    // Graham's LPT rule): the costly 88x88 scenes start at once instead of ending the run alone.
    let mut order: Vec<(f64, usize, Problem)> =
        problems.into_iter().enumerate().map(|(i, p)| (crate::solvers::estimated_cost(&p), i, p)).collect();
    order.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
    let mut results = order
        .into_iter()
        .par_bridge()
        .map(|(_, i, p)| {
            let r = pipeline::run_with(p, in_process);
            bar.inc(1);
            (i, r)
        })
        .collect::<Vec<_>>();
    bar.finish_and_clear();
    // Back to file order, so that output never depends on the schedule.
    results.sort_by_key(|(i, _)| *i);
    results.into_iter().map(|(_, r)| r).collect()
}
