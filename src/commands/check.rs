//! `creepbench check`: the gate — the suites against golden/ (or earlier results) and the
//! references, the verdict and its files (JUnit, JSON, step summary).

use super::*;

/// The files `check` reads and writes besides the suite (issue 15): tolerance rules in, the
/// verdict out.
#[derive(Debug, Clone, Default)]
pub struct GateFiles {
    /// Tolerance rule files (`--tolerances`), before each suite's `tolerances.toml`.
    pub tolerances: Vec<PathBuf>,
    /// JUnit XML.
    pub junit: Option<PathBuf>,
    /// Every finding as JSON.
    pub json: Option<PathBuf>,
    /// A Markdown summary; `$GITHUB_STEP_SUMMARY`, when set, gets it appended too.
    pub summary: Option<PathBuf>,
    /// Refuse every rule that loosens a comparison the defaults gate (CI).
    pub strict: bool,
    /// Print the full worst-point table and every drift (the console shows one screen otherwise).
    pub verbose: bool,
}

impl GateFiles {
    /// Every output file the user named, none of them inside golden/.
    fn check_paths(&self, golden: &Path) -> Result<(), Error> {
        for p in [&self.junit, &self.json, &self.summary].into_iter().flatten() {
            guard::guard_output_file(p, golden)?;
        }
        if let Some(step_summary) = step_summary() {
            guard::guard_output_file(&step_summary, golden)?;
        }
        Ok(())
    }

    /// Write each output whole (a temporary file in the same folder, renamed over the target).
    fn write(&self, all: &[Finding], loosened: &[Loosening]) -> Result<(), Error> {
        use crate::comparison::gate_output;
        let outputs = [
            (&self.junit, gate_output::junit as fn(&[Finding], &[Loosening]) -> String),
            (&self.json, gate_output::json),
            (&self.summary, gate_output::summary),
        ];
        for (path, make) in outputs {
            if let Some(path) = path {
                write_whole(path, &make(all, loosened))?;
            }
        }
        if let Some(path) = step_summary() {
            let io = |source| Error::Io { path: path.clone(), source };
            let mut f = std::fs::OpenOptions::new().append(true).create(true).open(&path).map_err(io)?;
            std::io::Write::write_all(&mut f, gate_output::summary(all, loosened).as_bytes()).map_err(io)?;
        }
        Ok(())
    }
}

/// `$GITHUB_STEP_SUMMARY`, when set.
pub(super) fn step_summary() -> Option<PathBuf> {
    std::env::var_os("GITHUB_STEP_SUMMARY").filter(|v| !v.is_empty()).map(PathBuf::from)
}

/// The gate's findings over a suite (or one shard): every comparison with the references and
/// the baseline (golden/, or `against`), the baseline's missing scenes, the run's tolerance files
/// applied (what `check` prints and writes).
#[derive(Debug, Clone)]
pub struct Gate {
    pub findings: Vec<Finding>,
    /// The rules of the run's files that loosen a default gate.
    pub loosened: Vec<Loosening>,
    /// Each scene's suite.
    pub suite_of: BTreeMap<String, String>,
    /// The histories flagged as oscillating (one line each; all of them with `verbose`).
    pub oscillating: Vec<String>,
}

/// What the gate compares the suites' results with besides the references: golden/, or the
/// folder of earlier results `against` when given (golden/ is then only protected).
#[derive(Debug, Clone, Copy)]
pub struct Baseline<'a> {
    pub golden: &'a Path,
    pub against: Option<&'a Path>,
}

/// Run the suite and gate it ([`Gate`]; `check` prints it): `runner` gives the shard and the
/// models run in this process; `against` (a folder of earlier results) replaces `golden` as the
/// baseline when given.
pub fn gate(
    suite_dir: &[PathBuf],
    reference: &Path,
    baseline: Baseline,
    runner: Runner,
    files: &GateFiles,
) -> Result<Gate, Error> {
    let Baseline { golden, against } = baseline;
    let shard = runner.shard;
    files.check_paths(golden)?;
    let refs = load_references(reference)?;
    let rules = file_rules(&files.tolerances, suite_dir)?;
    if files.strict {
        // Refused before any scene runs; the verdict's own check below covers what this cannot.
        crate::comparison::strict::refuse_loosening(&rules, tolerances::defaults())?;
    }
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
    let SuiteRun { scenes, wheelrail } = run_suite(SuiteFiles::read(suite_dir, shard)?, runner, true)?;
    let mut all = compare::evaluate(&scenes, &refs, Some(baseline))?;
    all.extend(wheelrail_findings(&refs, &wheelrail));
    let suites = suite_names(suite_dir);
    let expected = |name: &str, suite: &str| shard.is_none_or(|s| s.takes(name)) && suites.iter().any(|x| x == suite);
    all.extend(compare::missing_scenes(dir, &scenes, kind, expected)?);
    // On a shard, a rule may be meant for scenes of other shards: it must cover some scene of the
    // suites; `merge` then checks it against every comparison.
    let other_shards: Vec<String> = match shard {
        Some(s) => suite::scene_names(suite_dir)?.into_iter().filter(|n| !s.takes(n)).collect(),
        None => Vec::new(),
    };
    let suite_of = suite_of(&scenes, &wheelrail);
    let loosened = tolerance_file::apply(&rules, &mut all, &suite_of, |r| {
        other_shards.iter().any(|n| tolerance_file::glob(&r.scene, n))
    })?;
    if files.strict {
        if let Some(l) = loosened.first() {
            return Err(InputError::new(&l.origin, l.to_string(), "no loosening of a default gate (--strict)").into());
        }
    }
    let oscillating = console::oscillating(&scenes, files.verbose);
    Ok(Gate { findings: all, loosened, suite_of, oscillating })
}

/// `creepbench check`: run the suite, compare with golden/ (or `against`) and the references;
/// print the verdict first, then one screen (console: per suite and model, scenes without data,
/// the worst drifts; everything with `verbose`); write the verdict files asked for; fail on gated
/// drift.
pub fn check(
    suite_dir: &[PathBuf],
    reference: &Path,
    baseline: Baseline,
    runner: Runner,
    files: &GateFiles,
) -> Result<(), Error> {
    let Baseline { golden, against } = baseline;
    let Gate { findings: all, loosened, suite_of, oscillating } = gate(suite_dir, reference, baseline, runner, files)?;
    let verdict = Verdict::of(&all);
    outln!("{verdict}\n");
    out!("{}", console::per_model(&all, &suite_of));
    if files.verbose {
        outln!();
        out!("{}", compare::table(&compare::worst_per_group(&all)));
    }
    print_list("", &console::no_baseline(&all, files.verbose));
    print_list("", &oscillating);
    if !loosened.is_empty() {
        outln!("\n{} rule(s) of the run's files loosen what the defaults gate:", loosened.len());
        for l in &loosened {
            outln!("  {l}");
        }
    }
    if against.is_some() {
        let (n, lines) = console::moved(&all, files.verbose);
        let head = format!(
            "{n} quantities moved against {} (worst first, |diff| / allowed):",
            against.unwrap_or(golden).display()
        );
        print_list(&head, &lines);
    }
    files.write(&all, &loosened)?;
    if verdict.failed == 0 {
        Ok(())
    } else {
        for line in console::drifts(&all, files.verbose) {
            errln!("{line}");
        }
        Err(Error::Drift { count: verdict.failed })
    }
}
