//! `creepbench simulate`: scenes (or studies) into result folders, in one process; wheel–rail scenes with
//! their report section (`--report`).

use super::*;

/// What one scene file holds: a wheel–rail scene, or the problems of a scene (a study: each of
/// its scenes).
enum Loaded {
    WheelRail(Box<WheelRailScene>),
    Problems(Vec<crate::problem::Problem>),
}

impl Loaded {
    /// The scene file at `path`, every scene in it validated (`solvers` narrowing its models).
    fn read(path: &Path, solvers: &[String]) -> Result<Loaded, Error> {
        // The file read and parsed once for all three readers (wheel–rail, study, scene).
        let doc = crate::scene::wheelrail::read_scene_doc(path)?;
        if let Some(mut wr) = crate::scene::wheelrail::wheelrail_of(path, &doc)? {
            narrow(&mut wr, solvers)?;
            return Ok(Loaded::WheelRail(Box::new(wr)));
        }
        let sources = suite::sources_of_doc(path, Some(&doc))?;
        let load = |s: &crate::scene::source::SceneSource| pipeline::load_parsed(s, Some(&doc), solvers, &[]);
        let problems = sources.iter().map(load).collect::<Result<Vec<_>, _>>()?;
        Ok(Loaded::Problems(problems))
    }

    /// The names of its scenes, each the folder `out/<name>` it writes.
    fn names(&self) -> Vec<&str> {
        match self {
            Loaded::WheelRail(s) => vec![s.name.as_str()],
            Loaded::Problems(ps) => ps.iter().map(|p| p.name.as_str()).collect(),
        }
    }
}

/// `creepbench simulate SCENE...`: each file's scenes (a study file: each of its scenes) into
/// `out/<name>/`, in one process in the order given (kept influence tables serve the later
/// scenes). Every file is read and validated and every folder checked before any runs: bad input,
/// or two scenes of one name (one folder), writes nothing.
pub fn simulate(scenes: &[PathBuf], solvers: &[String], out: &Path, golden: &Path) -> Result<Vec<PathBuf>, Error> {
    let loaded = scenes.iter().map(|p| Loaded::read(p, solvers)).collect::<Result<Vec<_>, _>>()?;
    guard::guard_output_dir(out, golden)?;
    let mut seen = std::collections::BTreeSet::new();
    for name in loaded.iter().flat_map(Loaded::names) {
        if !seen.insert(name) {
            return Err(InputError::new("SCENE", name, "scenes of distinct names (each writes OUT/<name>)").into());
        }
        // The folder written is out/<name>: a scene named after a protected folder cannot reach it.
        guard::guard_not_under(&out.join(name), golden)?;
    }
    let mut dirs = Vec::new();
    for file in loaded {
        match file {
            Loaded::WheelRail(scene) => dirs.push(simulate_wheelrail(&scene, out)?),
            Loaded::Problems(problems) => {
                for problem in problems {
                    dirs.push(simulate_problem(problem, out)?);
                }
            }
        }
    }
    Ok(dirs)
}

/// One validated scene run and written into `out/<name>/`, its warnings and each solver's rows
/// and wall time on stderr.
fn simulate_problem(problem: crate::problem::Problem, out: &Path) -> Result<PathBuf, Error> {
    let before = problem.warnings.len();
    for w in &problem.warnings {
        errln!("warning: {w}");
    }
    let result = pipeline::run(problem)?;
    for w in &result.problem.warnings[before..] {
        errln!("warning: {w}");
    }
    let ran: Vec<String> = result
        .histories
        .iter()
        .zip(&result.timing)
        .map(|(h, t)| format!("{}: {} rows in {:.3} s", h.solver, h.rows.len(), t.wall_s))
        .collect();
    let stored = StoredScene::from_owned(result);
    // Writers into one folder take turns (as `run` does), so two simulations both land.
    let _lock = lock::lock_folder(out, lock::DEFAULT_LOCK_WAIT)?;
    let dir = results::write_scenes(out, std::slice::from_ref(&stored), false)?.remove(0);
    for line in ran {
        errln!("{line}");
    }
    Ok(dir)
}

/// `creepbench simulate` of a wheel–rail scene (its models narrowed, its folder checked): its
/// cases into `out/<name>/` (`<model>.csv`, `<model>_patches.csv`).
fn simulate_wheelrail(scene: &WheelRailScene, out: &Path) -> Result<PathBuf, Error> {
    let run = run_wheelrail(scene)?;
    // Writers into one folder take turns.
    let _lock = lock::lock_folder(out, lock::DEFAULT_LOCK_WAIT)?;
    suite::wheelrail::write(out, &run)
}

/// `creepbench simulate SCENE... --report DIR` of wheel–rail scenes: each into `out/<name>/`
/// as [`simulate`] writes it, then `DIR/validation.md` with the section "Wheel–rail contact" of
/// the scenes that declare `[report] group = "wheelrail"` (`report::wheelrail`). Every scene, its
/// profiles and its CONTACT output are read and checked before any runs.
pub fn simulate_report(
    scenes: &[PathBuf],
    solvers: &[String],
    out: &Path,
    report_dir: &Path,
    golden: &Path,
) -> Result<Vec<PathBuf>, Error> {
    use crate::scene::wheelrail::read_if_wheelrail;
    let mut read: Vec<WheelRailScene> = Vec::new();
    for path in scenes {
        let Some(mut scene) = read_if_wheelrail(path)? else {
            return Err(InputError::new(
                "--report",
                path.display(),
                "wheel–rail scenes (a [wheelrail] table); the report of other scenes is `creepbench run`'s",
            )
            .into());
        };
        narrow(&mut scene, solvers)?;
        pipeline::wheelrail_scene::prepare(&scene)?;
        read.push(scene);
    }
    let printed = read_printed(&read)?;
    if !read.iter().any(|s| s.report.in_section()) {
        return Err(InputError::new(
            "--report",
            scenes.iter().map(|p| p.display().to_string()).collect::<Vec<_>>().join(", "),
            "at least one scene with [report] group = \"wheelrail\", \"wheel_flat\" or \"crossing\" (the section draws the scenes that declare one)",
        )
        .into());
    }
    guard::guard_output_dir(out, golden)?;
    guard::guard_output_dir(report_dir, golden)?;
    report::check_outputs(report_dir, golden)?;
    for s in &read {
        guard::guard_not_under(&out.join(&s.name), golden)?;
    }
    let (mut dirs, mut runs) = (Vec::new(), Vec::new());
    for scene in read {
        let run = run_wheelrail(&scene)?;
        let lock = lock::lock_folder(out, lock::DEFAULT_LOCK_WAIT)?;
        dirs.push(suite::wheelrail::write(out, &run)?);
        drop(lock);
        runs.push((scene, run));
    }
    let n = runs.len();
    let section = wheelrail_section(&runs, &printed)?.expect("a scene declares the group (checked above)");
    let markdown = format!(
        "# creepbench wheel–rail report\n\nGenerated by `creepbench simulate --report` from {} wheel–rail scene(s).\n\n## {}\n\n{}\n",
        n,
        section.title,
        section.body
    );
    let report = report::Report { markdown, figures: section.figures, tables: section.tables };
    std::fs::create_dir_all(report_dir).map_err(Error::io(report_dir))?;
    report.write(report_dir)?;
    dirs.push(report_dir.join("validation.md"));
    Ok(dirs)
}

/// `--solver` narrows a wheel–rail scene's models (to none of them: an input error).
pub fn narrow(scene: &mut crate::scene::wheelrail::WheelRailScene, solvers: &[String]) -> Result<(), Error> {
    if !solvers.is_empty() {
        scene.solvers.retain(|m| solvers.contains(m));
        if scene.solvers.is_empty() {
            return Err(InputError::new("--solvers", solvers.join(","), "models the scene names").into());
        }
    }
    Ok(())
}

/// CONTACT's printed module-1 results of each scene (none without `[report] contact_output`),
/// read before any case runs: an unreadable file is an input error naming the scene's key.
pub(super) fn read_printed(scenes: &[WheelRailScene]) -> Result<Vec<Vec<PrintedCase>>, Error> {
    use crate::comparison::references::contact_output::wheelrail as printed;
    let read = |s: &WheelRailScene| match &s.report.contact_output {
        Some(file) => printed::read(file).map_err(|e| {
            Error::from(InputError::new(
                format!("scene {}: report.contact_output", s.name),
                file.display(),
                format!("CONTACT's printed module-1 output ({e})"),
            ))
        }),
        None => Ok(Vec::new()),
    };
    scenes.iter().map(read).collect()
}

/// The section "Wheel–rail contact" of the solved scenes that declare `[report] group =
/// "wheelrail"`, each beside its printed CONTACT results (none: no scene declares it).
pub(super) fn wheelrail_section(
    runs: &[(WheelRailScene, SceneRun)],
    printed: &[Vec<PrintedCase>],
) -> Result<Option<Section>, Error> {
    let mut views = Vec::new();
    let mut contacts = Vec::new();
    // Only the scenes that declare the section are viewed (their patch maps solved): the others
    // are gated, not drawn.
    for ((scene, run), contact) in runs.iter().zip(printed).filter(|((s, _), _)| s.report.in_section()) {
        views.push(pipeline::wheelrail_view::view(scene, run.clone())?);
        contacts.push(contact);
    }
    let wheels: Vec<report::wheelrail::Wheel> =
        views.iter().zip(contacts).map(|(view, contact)| report::wheelrail::Wheel { view, contact }).collect();
    Ok(report::wheelrail::section(&wheels))
}

/// Run a wheel–rail scene, with its time on the console.
pub(super) fn run_wheelrail(
    scene: &crate::scene::wheelrail::WheelRailScene,
) -> Result<pipeline::wheelrail_scene::SceneRun, Error> {
    let start = Instant::now();
    let run = pipeline::wheelrail_scene::run_scene(scene)?;
    errln!(
        "{}: {} cases, {} models in {:.3} s",
        run.name,
        run.cases.len(),
        run.models.len(),
        start.elapsed().as_secs_f64()
    );
    Ok(run)
}
