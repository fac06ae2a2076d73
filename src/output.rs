//! Writing results: the resolved scene as JSON and a scene's output folder, written into a
//! temporary folder and renamed at the end so that a failure leaves no partial output.

use crate::history::History;
use crate::metrics::Metric;
use crate::problem::{Problem, Sample};
use serde::Serialize;
use std::path::{Path, PathBuf};

#[derive(Serialize)]
struct SceneJson<'a> {
    name: &'a str,
    solvers: &'a [String],
    kind: crate::problem::LoadingKind,
    a_mm: f64,
    b_mm: f64,
    fn_n: f64,
    mu: f64,
    /// Hertz peak pressure 3FN/(2πab) [MPa].
    p0_mpa: f64,
    /// Peak of the simplified models' pressure (`model.pressure`) [MPa].
    p_model_peak_mpa: f64,
    g_mpa: f64,
    e_mpa: f64,
    poisson: f64,
    c11: f64,
    c22: f64,
    c23: f64,
    l1_mm3_n: f64,
    l2_mm3_n: f64,
    l3_mm3_n: f64,
    mx: usize,
    my: usize,
    dx_mm: f64,
    dy_mm: f64,
    v_mm_s: f64,
    courant: f64,
    dq_mm: f64,
    dt_s: f64,
    n_steps: usize,
    freq_hz: Option<f64>,
    init: crate::scene::InitKind,
    model: crate::scene::ModelOptions,
    contact_solver: crate::scene::ContactSolverOptions,
    metrics: &'a [String],
    skipped_metrics: Vec<[&'a str; 2]>,
    warnings: &'a [String],
    /// The loading at every step (step 0 = the initial state at t = 0, when the scene has one).
    history: Vec<Sample>,
}

/// The resolved scene (interface.md: at least a_mm, b_mm, p0_mpa, c11, c22, c23, dx_mm, dy_mm,
/// dt_s, n_steps and the solvers that ran), with the sampled loading for external models.
pub fn scene_json(p: &Problem, solvers_ran: &[String]) -> String {
    let flex = p.flexibilities();
    let doc = SceneJson {
        name: &p.name,
        solvers: solvers_ran,
        kind: p.kind,
        a_mm: p.hertz.a_mm,
        b_mm: p.hertz.b_mm,
        fn_n: p.hertz.fn_n,
        mu: p.mu,
        p0_mpa: p.hertz.p0_mpa(),
        p_model_peak_mpa: p.pressure_peak_mpa(),
        g_mpa: p.material.g_mpa,
        e_mpa: p.material.e_mpa,
        poisson: p.material.poisson,
        c11: p.coefficients.c11,
        c22: p.coefficients.c22,
        c23: p.coefficients.c23,
        l1_mm3_n: flex.l1_mm3_n,
        l2_mm3_n: flex.l2_mm3_n,
        l3_mm3_n: flex.l3_mm3_n,
        mx: p.grid.mx,
        my: p.grid.my,
        dx_mm: p.grid.dx_mm,
        dy_mm: p.grid.dy_mm,
        v_mm_s: p.v_mm_s,
        courant: p.courant,
        dq_mm: p.dq_mm,
        dt_s: p.dt_s,
        n_steps: p.samples.len(),
        freq_hz: p.freq_hz,
        init: p.init,
        model: p.model,
        contact_solver: p.contact_solver,
        metrics: &p.metrics,
        skipped_metrics: p.skipped_metrics.iter().map(|(m, w)| [m.as_str(), w.as_str()]).collect(),
        warnings: &p.warnings,
        history: p.initial.iter().chain(p.samples.iter()).copied().collect(),
    };
    serde_json::to_string_pretty(&doc).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}")) + "\n"
}

/// Write `files` (name, contents) as the folder `dir/name`, atomically replacing an old one.
pub fn write_folder_atomically(dir: &Path, name: &str, files: &[(String, String)]) -> std::io::Result<PathBuf> {
    std::fs::create_dir_all(dir)?;
    let target = dir.join(name);
    let tmp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
    if tmp.exists() {
        std::fs::remove_dir_all(&tmp)?;
    }
    std::fs::create_dir_all(&tmp)?;
    let result = (|| {
        for (file, text) in files {
            std::fs::write(tmp.join(file), text)?;
        }
        if target.exists() {
            let old = dir.join(format!(".{name}.old-{}", std::process::id()));
            std::fs::rename(&target, &old)?;
            std::fs::rename(&tmp, &target)?;
            std::fs::remove_dir_all(&old)?;
        } else {
            std::fs::rename(&tmp, &target)?;
        }
        Ok(target.clone())
    })();
    if result.is_err() {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    result
}

/// The files of one simulated scene: scene.json, `<solver>.csv` and metrics.csv.
pub fn scene_files(p: &Problem, histories: &[History], metrics: &[Metric]) -> Vec<(String, String)> {
    let ran: Vec<String> = histories.iter().map(|h| h.solver.clone()).collect();
    let mut files = vec![("scene.json".to_string(), scene_json(p, &ran))];
    for h in histories {
        files.push((format!("{}.csv", h.solver), h.to_csv()));
    }
    files.push(("metrics.csv".to_string(), crate::metrics::to_csv(metrics)));
    files
}
