//! External models: any executable that reads the resolved scene (scene.json) and writes a
//! history CSV in the `simulate` format. Protocol (README, "Bring your own model"):
//! the command is run in the scene's folder as `COMMAND... SCENE_JSON OUT_CSV`; it must exit 0
//! and leave OUT_CSV with the header `step,t_s,cx,cy,cs,fn_n,fx_over_fn,fy_over_fn[,...]` and
//! one row per step of the scene (the step column must match the scene's steps; a row for
//! step 0, the initial state, is dropped unless the scene starts from a steady state).

use crate::error::Error;
use crate::history::History;
use crate::problem::{Problem, ResolvedScene};
use crate::scene::ExternalSolver;
use std::process::Command;

/// A user-supplied model run as a child process.
pub struct External {
    spec: ExternalSolver,
}

impl External {
    pub fn new(spec: ExternalSolver) -> Self {
        External { spec }
    }
}

impl External {
    /// The model's name in the scene.
    pub fn name(&self) -> &str {
        &self.spec.name
    }

    /// Run the model over the whole scene and read its history back.
    pub fn run(&self, problem: &Problem) -> Result<History, Error> {
        let fail = |m: String| Error::External { scene: problem.name.clone(), solver: self.spec.name.clone(), message: m };
        let dir =
            tempfile::Builder::new().prefix("creepbench-ext").tempdir().map_err(|e| fail(format!("temp dir: {e}")))?;
        let scene_json = dir.path().join("scene.json");
        let out_csv = dir.path().join(format!("{}.csv", self.spec.name));
        let json = ResolvedScene::of(problem, &problem.solvers).to_json();
        std::fs::write(&scene_json, json).map_err(|e| fail(format!("writing scene.json: {e}")))?;
        let mut program = std::path::PathBuf::from(&self.spec.command[0]);
        if program.components().count() > 1 && program.is_relative() {
            program = problem.scene_dir.join(program);
        }
        let status = Command::new(&program)
            .args(&self.spec.command[1..])
            .arg(&scene_json)
            .arg(&out_csv)
            .current_dir(if problem.scene_dir.as_os_str().is_empty() {
                std::path::Path::new(".")
            } else {
                &problem.scene_dir
            })
            .status()
            .map_err(|e| fail(format!("could not start {}: {e}", program.display())))?;
        if !status.success() {
            return Err(fail(format!("{} exited with {status}", program.display())));
        }
        let text =
            std::fs::read_to_string(&out_csv).map_err(|e| fail(format!("no output {}: {e}", out_csv.display())))?;
        let mut h = History::from_csv(&self.spec.name, &text).map_err(|e| fail(format!("output CSV: {e}")))?;
        // Step 0 (the initial state) is part of the output only when the scene starts steady.
        let with_initial = problem.loading.steady_start().is_some();
        if !with_initial {
            h.rows.retain(|r| r.step != 0);
        }
        let expected: Vec<usize> = problem.loading.rows().map(|s| s.step).collect();
        let got: Vec<usize> = h.rows.iter().map(|r| r.step).collect();
        if got != expected {
            return Err(fail(format!(
                "output has {} rows (steps {:?}..{:?}); the scene has {} steps",
                got.len(),
                got.first(),
                got.last(),
                expected.len()
            )));
        }
        if let Some(r) = h.rows.iter().find(|r| !r.fx_over_fn.is_finite() || !r.fy_over_fn.is_finite()) {
            return Err(fail(format!("non-finite traction coefficient at step {}", r.step)));
        }
        for (r, s) in h.rows.iter_mut().zip(problem.loading.rows()) {
            r.mu = s.mu;
        }
        Ok(h)
    }
}
