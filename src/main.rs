//! The `creepbench` command line (docs/commands.md).

use clap::{Parser, Subcommand};
use creepbench::commands;
use creepbench::suite::{Shard, DEFAULT_SUITES};
use std::path::PathBuf;

#[derive(Parser)]
#[command(name = "creepbench", version, about = "Validate and benchmark wheel-rail creep-force models against CONTACT")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(clap::Args)]
struct SuiteArgs {
    /// Folder(s) of scene files (repeatable).
    #[arg(long, default_values = DEFAULT_SUITES)]
    suite: Vec<PathBuf>,
    /// Reference data (CONTACT, thesis).
    #[arg(long, default_value = "reference")]
    reference: PathBuf,
    /// Golden data (this project's blessed results).
    #[arg(long, default_value = "golden")]
    golden: PathBuf,
    /// Run only shard i of n (deterministic by scene name), e.g. 1/2.
    #[arg(long)]
    shard: Option<Shard>,
    /// No progress bar.
    #[arg(long)]
    quiet: bool,
}

/// What `export` writes.
#[derive(Subcommand)]
enum ExportWhat {
    /// CONTACT module-3 input that computes the scene (one case per history row): OUT/<name>.inp
    /// (a study file: one input per point); a wheel–rail scene: module-1 input, one case per row
    /// of its cases table, its profiles named from OUT.
    Contact {
        /// The scene file (module-3 or wheel–rail), or a study file.
        scene: PathBuf,
        #[arg(long, default_value = "out/contact")]
        out: PathBuf,
        /// Refused as an output location (only `bless` writes there).
        #[arg(long, default_value = "golden")]
        golden: PathBuf,
    },
}

/// What `import` reads.
#[derive(Subcommand)]
enum ImportWhat {
    /// CONTACT input (FILE.inp) as scenes: module-3 cases one per history, module-1 cases one
    /// wheel–rail scene per run sharing all but the wheelset's position and velocity (profiles by
    /// their path from OUT): OUT/<deck>_<case>.toml with its tables (OUT defaults to a folder
    /// named after the deck).
    Contact {
        /// The CONTACT input file.
        deck: PathBuf,
        /// Output folder (default: a folder named after the deck, in the current folder).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Write the supported scenes and list the skipped cases (default: refuse a deck with any
        /// case that is not supported, writing nothing).
        #[arg(long)]
        supported_only: bool,
        /// Replace existing files of the same names.
        #[arg(long)]
        overwrite: bool,
        /// Refused as an output location (only `bless` writes there).
        #[arg(long, default_value = "golden")]
        golden: PathBuf,
    },
    /// CONTACT's printed output (.out, .ref_out): each module-3 case's totals as a reference CSV
    /// (standard output, or --out), this project's signs, each printed value's rounding.
    ContactOutput {
        /// CONTACT's output file.
        file: PathBuf,
        /// The CSV to write (written whole; default: standard output).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Only the cases A to B (`A-B`, or one case `A`).
        #[arg(long)]
        cases: Option<String>,
        /// Refused as an output location (only `bless` writes there).
        #[arg(long, default_value = "golden")]
        golden: PathBuf,
    },
}

#[derive(Subcommand)]
enum Command {
    /// Run scenes, in one process in the order given, and write OUT/<name>/{scene.json,<solver>.csv,metrics.csv} (a study file: each of its scenes).
    Simulate {
        /// The scene files (TOML) or study files; with --report, wheel–rail scenes.
        #[arg(required = true)]
        scene: Vec<PathBuf>,
        /// Run only these of the scene's solvers (repeatable).
        #[arg(long = "solver")]
        solvers: Vec<String>,
        /// Output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// The golden folder, which simulate never writes into.
        #[arg(long, default_value = "golden")]
        golden: PathBuf,
        /// Wheel–rail scenes only: also write DIR/validation.md with the section "Wheel–rail
        /// contact" of the scenes that declare [report] group = "wheelrail", "wheel_flat" or "crossing".
        #[arg(long, value_name = "DIR")]
        report: Option<PathBuf>,
    },
    /// Fit a model's free parameters (a fit file: model, target, norm, scenes, [[fit.param]], [set])
    /// and write them as a scene block OUT (default out/fits/<name>.toml; replaces none).
    Fit {
        /// The fit file (TOML with a [fit] table).
        file: PathBuf,
        #[arg(long)]
        out: Option<PathBuf>,
        /// Reference data (for against = "reference").
        #[arg(long, default_value = "reference")]
        reference: PathBuf,
        /// Refused as an output location (only `bless` writes there).
        #[arg(long, default_value = "golden")]
        golden: PathBuf,
    },
    /// Write a study's scenes as scene files OUT/<name>.toml (replaces none).
    Expand {
        /// The study file (TOML with a [study] table).
        study: PathBuf,
        #[arg(long, default_value = "out/scenes")]
        out: PathBuf,
        /// Refused as an output location (only `bless` writes there).
        #[arg(long, default_value = "golden")]
        golden: PathBuf,
    },
    /// Run the suites (default: the ten shipped suites of scenes/), then the fits of fits/, and
    /// write the report of this run's scenes (out/report/validation.md; `--report reports`
    /// regenerates the committed sample).
    Run {
        #[command(flatten)]
        suite: SuiteArgs,
        /// Where the per-scene results go (other runs' scene folders there are kept, left out of
        /// this run's report and named).
        #[arg(long, default_value = "out/results")]
        results: PathBuf,
        /// Where the report goes (validation.md, results.csv, figures/, tables/).
        #[arg(long, default_value = "out/report")]
        report: PathBuf,
        /// Fit files run after the suites (`creepbench fit`), their outcomes in the report's
        /// calibration section (default: the folder `fits` where there is one, when the shipped
        /// suites run; a suite of one's own runs no fits unless this is given).
        #[arg(long)]
        fits: Option<PathBuf>,
        /// After the suites, the models of the scenes whose timings the report draws (the
        /// work–precision grids, the cost-per-step study) are re-timed alone, this many times each:
        /// the report gives the median with a 95 % interval (at least 6 for an interval; 0: not
        /// re-timed).
        #[arg(long, default_value_t = creepbench::suite::timing::DEFAULT_REPEATS)]
        timing_repeats: usize,
    },
    /// Run the suites and compare with golden/ (or --against DIR) and the references; exit 1 on drift.
    Check {
        #[command(flatten)]
        suite: SuiteArgs,
        /// Compare with this result folder (from `run --results`) instead of golden/.
        #[arg(long)]
        against: Option<PathBuf>,
        /// Write the verdict as JUnit XML (one test case per scene x solver x comparison).
        #[arg(long)]
        junit: Option<PathBuf>,
        /// Write every comparison as JSON.
        #[arg(long)]
        json: Option<PathBuf>,
        /// Write a Markdown summary (also appended to $GITHUB_STEP_SUMMARY when that is set).
        #[arg(long)]
        summary: Option<PathBuf>,
        /// Tolerance rules (TOML, [[rule]] tables) taking precedence over each suite's
        /// tolerances.toml and the project's defaults (repeatable; first match wins).
        #[arg(long)]
        tolerances: Vec<PathBuf>,
        /// Refuse every tolerance rule that loosens a comparison the defaults gate (for CI).
        #[arg(long)]
        strict: bool,
        /// Print the full worst-point table (scene x model x comparison) and every drift; by
        /// default the console shows the verdict, one line per suite and model, and the worst drifts.
        #[arg(long)]
        verbose: bool,
    },
    /// Run the suites and write their results into golden/ (the only command that writes golden data).
    Bless {
        #[command(flatten)]
        suite: SuiteArgs,
    },
    /// Build one report from the result folders of several shards.
    Merge {
        /// Result folders written by `run --shard i/n --results DIR`.
        #[arg(required = true)]
        dirs: Vec<PathBuf>,
        /// Suite folders whose tolerances.toml applies to the merged scenes that came from them
        /// (repeatable; default: the shipped suites).
        #[arg(long, default_values = DEFAULT_SUITES)]
        suite: Vec<PathBuf>,
        /// Tolerance rules (TOML, [[rule]] tables) taking precedence over the suites'
        /// tolerances.toml and the defaults, as in `check` (repeatable; first match wins).
        #[arg(long)]
        tolerances: Vec<PathBuf>,
        #[arg(long, default_value = "reference")]
        reference: PathBuf,
        #[arg(long, default_value = "golden")]
        golden: PathBuf,
        /// Where the merged report goes.
        #[arg(long, default_value = "out/report")]
        report: PathBuf,
    },
    /// Write another program's input for a scene.
    Export {
        #[command(subcommand)]
        what: ExportWhat,
    },
    /// Read another program's files: CONTACT's input as scenes, its printed output as a reference CSV.
    Import {
        #[command(subcommand)]
        what: ImportWhat,
    },
    /// Write DIR/MANIFEST.sha256, the checksums reference data are verified against.
    Manifest {
        /// The folder (default: the reference data).
        #[arg(default_value = "reference")]
        dir: PathBuf,
    },
}

/// One line on the console (standard output, which may be closed or full: never a panic).
fn say(line: impl std::fmt::Display) {
    creepbench::safety::stdout::print(format_args!("{line}\n"));
}

/// glibc gives freed memory back to the kernel beyond its trim threshold and serves large blocks
/// by mmap, so the solvers' per-trial buffers (grids of MBs, made and dropped at every trial height
/// of every case) would be faulted in page by page again at each use. Kept instead: freed memory
/// stays with the process for the next allocation (`mallopt(3)`: M_TRIM_THRESHOLD, M_MMAP_THRESHOLD).
#[cfg(all(target_os = "linux", target_env = "gnu"))]
fn keep_freed_memory() {
    const KEEP_BYTES: libc::c_int = 1 << 30;
    // SAFETY: mallopt only sets two of the allocator's parameters; called before any thread starts.
    unsafe {
        libc::mallopt(libc::M_TRIM_THRESHOLD, KEEP_BYTES);
        libc::mallopt(libc::M_MMAP_THRESHOLD, 32 << 20);
    }
}

#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
fn keep_freed_memory() {}

fn main() {
    keep_freed_memory();
    let cli = Cli::parse();
    // An interrupted run kills the external models it started and removes their folders.
    if let Err(e) = creepbench::safety::interrupt::install() {
        creepbench::safety::stdout::print_err(format_args!("warning: {e}\n"));
    }
    if let Some(w) = creepbench::safety::threads::cap_threads() {
        creepbench::safety::stdout::print_err(format_args!("warning: {w}\n"));
    }
    let result = match cli.command {
        Command::Fit { file, out, reference, golden } => {
            commands::fit(&file, out.as_deref(), &reference, &golden).map(|f| say(f.display()))
        }
        Command::Expand { study, out, golden } => {
            commands::expand(&study, &out, &golden).map(|files| files.iter().for_each(|f| say(f.display())))
        }
        Command::Simulate { scene, solvers, out, golden, report } => match (report, scene.as_slice()) {
            (Some(dir), scenes) => commands::simulate_report(scenes, &solvers, &out, &dir, &golden),
            (None, scenes) => commands::simulate(scenes, &solvers, &out, &golden),
        }
        .map(|dirs| dirs.iter().for_each(|d| say(d.display()))),
        Command::Run { suite: s, results, report, fits, timing_repeats } => {
            // The shipped fits calibrate on the shipped suites: a suite of one's own runs none unless asked.
            let shipped = s.suite.iter().map(PathBuf::as_path).eq(DEFAULT_SUITES.iter().map(std::path::Path::new));
            let fits = fits.or_else(|| Some(PathBuf::from("fits")).filter(|d| shipped && d.is_dir()));
            let outputs = commands::RunOutputs { results_dir: &results, report_dir: &report, fits: fits.as_deref() };
            let runner = commands::Runner { timing_repeats, ..commands::Runner::cli(s.shard, !s.quiet) };
            commands::run(&s.suite, &s.reference, outputs, runner, &s.golden)
        }
        Command::Check { suite: s, against, junit, json, summary, tolerances, strict, verbose } => {
            let files = commands::GateFiles { tolerances, junit, json, summary, strict, verbose };
            let baseline = commands::Baseline { golden: &s.golden, against: against.as_deref() };
            commands::check(&s.suite, &s.reference, baseline, commands::Runner::cli(s.shard, !s.quiet), &files)
        }
        Command::Bless { suite: s } => commands::bless(&s.suite, &s.golden, s.shard, !s.quiet),
        Command::Merge { dirs, suite, tolerances, reference, golden, report } => {
            commands::merge(&dirs, &reference, &report, &golden, &suite, &tolerances)
        }
        Command::Manifest { dir } => commands::manifest(&dir),
        Command::Export { what: ExportWhat::Contact { scene, out, golden } } => {
            commands::export_contact(&scene, &out, &golden).map(|ps| ps.iter().for_each(|p| say(p.display())))
        }
        Command::Import { what: ImportWhat::Contact { deck, out, supported_only, overwrite, golden } } => {
            let options = commands::ImportOptions { supported_only, overwrite };
            commands::import_contact(&deck, out.as_deref(), options, &golden)
                .map(|ps| ps.iter().for_each(|p| say(p.display())))
        }
        Command::Import { what: ImportWhat::ContactOutput { file, out, cases, golden } } => {
            commands::import_contact_output(&file, out.as_deref(), cases.as_deref(), &golden)
        }
    };
    if let Err(e) = result {
        creepbench::safety::stdout::print_err(format_args!("error: {e}\n"));
        std::process::exit(e.exit_code());
    }
}
