//! The subcommands behind the CLI: simulate, run, check, bless, merge.

use crate::error::{Error, InputError};
use crate::harness::compare::{self, Against, Finding};
use crate::harness::reference::References;
use crate::harness::report::{self, ReportInput};
use crate::harness::results::{self, StoredScene};
use crate::harness::sections;
use crate::harness::suite::{self, Shard};
use crate::{output, pipeline};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// `creepbench simulate`: one scene into `out/<name>/`.
pub fn simulate(scene: &Path, solvers: &[String], out: &Path) -> Result<PathBuf, Error> {
    let problem = pipeline::load(scene, solvers)?;
    for w in &problem.warnings {
        eprintln!("warning: {w}");
    }
    let result = pipeline::run(problem)?;
    let files = output::scene_files(&result.problem, &result.histories, &result.metrics);
    let dir = output::write_folder_atomically(out, &result.problem.name, &files)?;
    for (h, w) in result.histories.iter().zip(&result.wall_s) {
        eprintln!("{}: {} rows in {:.3} s", h.solver, h.rows.len(), w);
    }
    Ok(dir)
}

/// Run a suite (or one shard) and return its results as stored scenes.
fn run_suite(suite_dir: &[PathBuf], shard: Option<Shard>, progress: bool) -> Result<Vec<StoredScene>, Error> {
    let files = suite::scene_files(suite_dir, shard)?;
    if files.is_empty() {
        let dirs: Vec<String> = suite_dir.iter().map(|d| d.display().to_string()).collect();
        return Err(InputError::new(
            "--suite",
            dirs.join(", "),
            "folders with at least one scene (*.toml) in this shard",
        )
        .into());
    }
    let start = Instant::now();
    let results = suite::run(&files, progress)?;
    eprintln!("ran {} scene(s) in {:.2} s", results.len(), start.elapsed().as_secs_f64());
    Ok(results.iter().map(StoredScene::from_result).collect())
}

/// Build the report from stored scenes.
pub fn build_report(
    scenes: &[StoredScene],
    refs: &References,
    out: &Path,
    golden: Option<&Path>,
    scaling: bool,
) -> Result<PathBuf, Error> {
    let findings = compare::evaluate(scenes, refs, golden.filter(|g| g.exists()).map(|g| (g, Against::Golden)))?;
    std::fs::create_dir_all(out.join("figures"))?;
    let mut extra = vec![("The thesis's figures beside ours".to_string(), sections::thesis_beside_ours(refs))];
    if let Some(s) = sections::error_vs_time(scenes, refs, &out.join("figures")) {
        extra.push(("Error against run time".into(), s));
    }
    if let Some(s) = sections::grid_convergence(scenes, refs) {
        extra.push(("Convergence under grid refinement".into(), s));
    }
    if let Some(s) = sections::stability(scenes) {
        extra.push(("Stability".into(), s));
    }
    extra.push(("Timing".into(), sections::timing(scenes, refs)));
    if scaling {
        extra.push(("Cost per step against grid size".into(), sections::scaling(&out.join("figures"))));
    }
    // The report writer recreates figures/; keep the section plots by writing them after.
    let svgs: Vec<(String, Vec<u8>)> = ["error_vs_time.svg", "cost_per_step.svg"]
        .iter()
        .filter_map(|f| Some((f.to_string(), std::fs::read(out.join("figures").join(f)).ok()?)))
        .collect();
    report::write(out, &ReportInput { scenes, refs, findings: &findings, extra_sections: extra })?;
    crate::harness::table::write(out, &crate::harness::table::rows(scenes, &findings))?;
    for (f, svg) in svgs {
        std::fs::write(out.join("figures").join(f), svg)?;
    }
    Ok(out.join("validation.md"))
}

/// `creepbench run`: the suite (default: the thesis scenes) → results folders and the report.
pub fn run(
    suite_dir: &[PathBuf],
    reference: &Path,
    results_dir: &Path,
    report_dir: &Path,
    shard: Option<Shard>,
    golden: &Path,
    progress: bool,
) -> Result<(), Error> {
    let refs = References::load(reference)?;
    let scenes = run_suite(suite_dir, shard, progress)?;
    results::write_scenes(results_dir, &scenes, true)?;
    eprintln!("results in {}", results_dir.display());
    if shard.is_some() {
        eprintln!("shard done; build the report with `creepbench merge {} ...`", results_dir.display());
        return Ok(());
    }
    let md = build_report(&scenes, &refs, report_dir, Some(golden), true)?;
    println!("{}", md.display());
    Ok(())
}

/// `creepbench merge`: one report from the result folders of several shards.
pub fn merge(dirs: &[PathBuf], reference: &Path, report_dir: &Path, golden: &Path) -> Result<(), Error> {
    let refs = References::load(reference)?;
    let mut scenes = Vec::new();
    for d in dirs {
        for name in results::scene_names(d) {
            if scenes.iter().any(|s: &StoredScene| s.name == name) {
                return Err(InputError::new("merge", d.join(&name).display(), "each scene in one shard only").into());
            }
            scenes.push(results::read_scene(d, &name)?);
        }
    }
    scenes.sort_by(|a, b| a.name.cmp(&b.name));
    let md = build_report(&scenes, &refs, report_dir, Some(golden), false)?;
    println!("{}", md.display());
    Ok(())
}

/// `creepbench check`: run the suite, compare with golden/ (or `against`) and the references;
/// print the worst point per scene and solver; fail on gated drift.
pub fn check(
    suite_dir: &[PathBuf],
    reference: &Path,
    golden: &Path,
    against: Option<&Path>,
    shard: Option<Shard>,
    progress: bool,
) -> Result<(), Error> {
    let refs = References::load(reference)?;
    let (dir, key, what, kind) = match against {
        Some(dir) => {
            (dir, "--against", "a folder of results written by `creepbench run` (--results)", Against::Previous)
        }
        None => (golden, "--golden", "the golden folder (create it with `creepbench bless`)", Against::Golden),
    };
    if !dir.is_dir() {
        return Err(InputError::new(key, dir.display(), what).into());
    }
    let baseline = (dir, kind);
    let scenes = run_suite(suite_dir, shard, progress)?;
    let all = compare::evaluate(&scenes, &refs, Some(baseline))?;
    let worst = compare::worst_per_group(&all);
    print!("{}", compare::table(&worst));
    let fails = compare::failures(&all);
    let gated = all.iter().filter(|f| f.gated).count();
    if against.is_some() {
        let moved: Vec<&Finding> = all.iter().filter(|f| f.against == Against::Previous && f.diff > 0.0).collect();
        println!("\n{} quantities moved against {} (largest first):", moved.len(), baseline.0.display());
        let mut moved = moved;
        moved.sort_by(|a, b| b.diff.total_cmp(&a.diff));
        for f in moved.iter().take(30) {
            println!(
                "  {} {} {} step {}: {} -> {} (|diff| {:.3e})",
                f.scene,
                f.solver,
                f.quantity,
                f.step.map(|s| s.to_string()).unwrap_or("-".into()),
                f.theirs,
                f.ours,
                f.diff
            );
        }
    }
    println!("\n{} gated comparisons, {} failed", gated, fails.len());
    if fails.is_empty() {
        Ok(())
    } else {
        for f in &fails {
            eprintln!("{f}");
        }
        Err(Error::Drift(format!("{} gated comparison(s) drifted", fails.len())))
    }
}

/// `creepbench bless`: write the suite's results as the new golden data (the only writer of golden/).
pub fn bless(suite_dir: &[PathBuf], golden: &Path, shard: Option<Shard>, progress: bool) -> Result<(), Error> {
    let scenes = run_suite(suite_dir, shard, progress)?;
    results::write_scenes(golden, &scenes, false)?;
    eprintln!("blessed {} scene(s) into {}", scenes.len(), golden.display());
    Ok(())
}
