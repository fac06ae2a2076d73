//! A wheel–rail scene's result folder (docs/scene-format.md, "Wheel–rail result folders"): per
//! model `<model>.csv`, one row per case with the totals on the rail in track and wheelset
//! coordinates, and `<model>_patches.csv`, one row per case and patch (CONTACT's order, from 1).
//! Signs and frames are CONTACT's module-1 output's: forces on the rail, y to the right on both
//! sides, the rail's y towards the track centre on the left and to the field side on the right.

use crate::error::Error;
use crate::pipeline::wheelrail::{CaseResult, PatchForces};
use crate::pipeline::wheelrail_scene::SceneRun;
use crate::safety::folder;
use crate::scene::wheelrail::WheelRailScene;
use crate::wheelrail::NormalPatch;
use std::path::{Path, PathBuf};

/// Columns of `<model>.csv`.
pub const TOTAL_COLUMNS: [&str; 10] = [
    "contact_case",
    "n_patches",
    "z_ws_mm",
    "fx_tr_n",
    "fy_tr_n",
    "fz_tr_n",
    "fx_ws_n",
    "fy_ws_n",
    "fz_ws_n",
    "vpitch_rad_s",
];

/// Columns of `<model>_patches.csv`.
pub const PATCH_COLUMNS: [&str; 24] = [
    "contact_case",
    "patch",
    "xcp_tr_mm",
    "ycp_tr_mm",
    "zcp_tr_mm",
    "deltcp_rad",
    "ycp_r_mm",
    "zcp_r_mm",
    "cksi",
    "ceta",
    "cphi_per_mm",
    "veloc_mm_s",
    "pen_mm",
    "fn_n",
    "fx_n",
    "fs_n",
    "mn_nmm",
    "mx",
    "my",
    "npot",
    "ncon",
    "nadh",
    "nslip",
    "pmax_mpa",
];

/// CSV text of rows of numbers under `header`.
fn csv_text(header: &[&str], rows: &[Vec<String>]) -> Vec<u8> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header).expect("writing to memory");
    for r in rows {
        w.write_record(r).expect("writing to memory");
    }
    w.into_inner().expect("writing to memory")
}

/// Columns of `<model>.csv` after [`TOTAL_COLUMNS`] on a massless rail (`[massless_rail]`): the
/// rail's deflections found, DY_DEFL along the side's own y and DZ_DEFL downwards (CONTACT's).
pub const DEFLECTION_COLUMNS: [&str; 2] = ["dy_defl_mm", "dz_defl_mm"];

/// One model's totals row for a case (with the rail's deflections where `deflected`).
fn total_row(case: u64, r: &CaseResult, model: usize, deflected: bool) -> Vec<String> {
    let (name, _, t) = &r.models[model];
    let normal = r.normal_of(name);
    let mut row = vec![case.to_string(), normal.patches.len().to_string(), normal.z_ws_mm.to_string()];
    row.extend(t.track_n.iter().chain(&t.wheelset_n).map(|v| number(*v)));
    row.push(number(r.pitch.rad_s()));
    if deflected {
        row.extend(r.rail_deflection_mm.unwrap_or([f64::NAN; 2]).map(number));
    }
    row
}

/// A number as written: shortest round-trip digits, a negative zero (a case without contact's
/// forces turned to the side's frame) as 0.
fn number(v: f64) -> String {
    (v + 0.0).to_string()
}

/// The numbers of a patch's row after `contact_case` and `patch` (the columns of
/// [`PATCH_COLUMNS`] from `xcp_tr_mm` to `mn_nmm`), in the side's frame.
pub fn patch_numbers(r: &CaseResult, p: &NormalPatch, f: &PatchForces) -> [f64; 15] {
    let m = r.normal.side.sign();
    let o = &p.geometry.frame.origin;
    let [y_r, z_r] = r.normal.in_rail_mm(o.y, o.z);
    let c = &p.creepages;
    [o.x, m * o.y, o.z, m * p.geometry.frame.delta_rad, m * y_r, z_r, c.cksi, m * c.ceta, m * c.cphi_per_mm]
        .into_iter()
        .chain([c.veloc_mm_s, p.pen_mm, f.fn_n, f.fx_n, f.fs_n, f.mn_nmm])
        .collect::<Vec<_>>()
        .try_into()
        .expect("15 numbers")
}

/// One model's row for a patch of a case, in the side's frame.
fn patch_row(case: u64, k: usize, r: &CaseResult, p: &NormalPatch, f: &PatchForces) -> Vec<String> {
    let g = &p.geometry.grid;
    let count = |n: Option<usize>| n.map_or(String::new(), |v| v.to_string());
    let ncon = p.pn_mpa.iter().filter(|&&v| v > 0.0).count();
    let pmax = p.pn_mpa.iter().copied().fold(0.0, f64::max);
    let mut row = vec![case.to_string(), (k + 1).to_string()];
    row.extend(patch_numbers(r, p, f).map(number));
    row.extend([g.mx.to_string(), g.ms.to_string(), g.len().to_string(), ncon.to_string()]);
    row.extend([count(f.n_adhesion), count(f.n_slip), pmax.to_string()]);
    row
}

/// The files of the result folder: name and contents.
pub fn files(run: &SceneRun) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    let deflected = run.cases.iter().any(|(_, r)| r.rail_deflection_mm.is_some());
    let mut header = TOTAL_COLUMNS.to_vec();
    if deflected {
        header.extend(DEFLECTION_COLUMNS);
    }
    for (k, model) in run.models.iter().enumerate() {
        let totals: Vec<_> = run.cases.iter().map(|(c, r)| total_row(*c, r, k, deflected)).collect();
        let patches: Vec<_> = run
            .cases
            .iter()
            .flat_map(|(c, r)| {
                r.normal_of(model)
                    .patches
                    .iter()
                    .zip(&r.models[k].1)
                    .enumerate()
                    .map(move |(j, (p, f))| patch_row(*c, j, r, p, f))
            })
            .collect();
        out.push((format!("{model}.csv"), csv_text(&header, &totals)));
        out.push((format!("{model}_patches.csv"), csv_text(&PATCH_COLUMNS, &patches)));
    }
    out
}

/// Write the scene's result folder `dir/<name>` (replaced whole, as every result folder); the
/// caller holds `dir`'s lock, as for `results::write_scenes`.
pub fn write(dir: &Path, run: &SceneRun) -> Result<PathBuf, Error> {
    Ok(folder::write_result_folder_cleaned(dir, &run.name, files(run))?)
}

/// The suite's scene files split into module-3 scenes and wheel–rail scenes (a `[wheelrail]`
/// table), the latter read and their profiles and models checked: bad input stops the run before
/// anything is computed.
pub fn split(
    files: Vec<crate::suite::SceneSource>,
) -> Result<(Vec<crate::suite::SceneSource>, Vec<WheelRailScene>), Error> {
    let (mut plain, mut wheelrail) = (Vec::new(), Vec::new());
    for f in files {
        if !is_wheelrail(&f) {
            plain.push(f);
            continue;
        }
        if let Some(s) = crate::scene::wheelrail::read_if_wheelrail(&f.path)? {
            crate::pipeline::wheelrail_scene::prepare(&s)?;
            wheelrail.push(s);
        }
    }
    Ok((plain, wheelrail))
}

/// Whether a scene file is a wheel–rail scene (a `[wheelrail]` table), without reading its
/// profiles; a file that does not parse, or a study's scene, is the module-3 reader's.
pub fn is_wheelrail(f: &crate::suite::SceneSource) -> bool {
    let doc = crate::safety::read::read_text(&f.path, crate::safety::read::SCENE_LIMIT_BYTES, "scene file")
        .ok()
        .and_then(|t| t.parse::<toml::Table>().ok());
    f.study.is_none() && doc.is_some_and(|d| crate::scene::wheelrail::is_wheelrail(&d))
}

/// Run the wheel–rail scenes side by side (rayon; a scene's shift and rolling sequences are serial,
/// so one after the other they left a core idle), their runs in the scenes' order; on failures,
/// the first failing scene's error in that order.
pub fn run_all(scenes: &[WheelRailScene]) -> Result<Vec<SceneRun>, Error> {
    use rayon::prelude::*;
    let runs: Vec<Result<SceneRun, Error>> =
        scenes.par_iter().map(crate::pipeline::wheelrail_scene::run_scene).collect();
    runs.into_iter().collect()
}

/// The suite folder a wheel–rail scene belongs to (its file's folder name).
pub fn suite_of(scene: &WheelRailScene) -> String {
    scene.dir.file_name().map_or_else(|| "-".into(), |n| n.to_string_lossy().to_string())
}
