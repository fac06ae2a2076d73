//! The `creepbench` command line.

use clap::{Parser, Subcommand};
use creepbench::error::Error;
use creepbench::{output, pipeline};
use std::path::PathBuf;

#[derive(Parser)]
#[command(name = "creepbench", version, about = "Validate and benchmark wheel-rail creep-force models")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run one scene and write DIR/<name>/{scene.json,<solver>.csv,metrics.csv}.
    Simulate {
        /// The scene file (TOML).
        scene: PathBuf,
        /// Run only these of the scene's solvers (repeatable).
        #[arg(long = "solver")]
        solvers: Vec<String>,
        /// Output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
    },
}

fn simulate(scene: PathBuf, solvers: Vec<String>, out: PathBuf) -> Result<(), Error> {
    let problem = pipeline::load(&scene, &solvers)?;
    for w in &problem.warnings {
        eprintln!("warning: {w}");
    }
    let result = pipeline::run(problem)?;
    let files = output::scene_files(&result.problem, &result.histories, &result.metrics);
    let dir = output::write_folder_atomically(&out, &result.problem.name, &files)?;
    for (h, w) in result.histories.iter().zip(&result.wall_s) {
        eprintln!("{}: {} rows in {:.3} s", h.solver, h.rows.len(), w);
    }
    println!("{}", dir.display());
    Ok(())
}

fn main() {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Simulate { scene, solvers, out } => simulate(scene, solvers, out),
    };
    if let Err(e) = result {
        eprintln!("error: {e}");
        std::process::exit(e.exit_code());
    }
}
