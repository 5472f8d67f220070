//! `walls-sim`: evaluate a walls file. `walls-sim scene FILE [--time T]` prints the
//! resolved scene as JSON (docs/spec.md §2); `walls-sim run` runs particles against it;
//! `walls-sim advise` suggests dKn, dKt and dDelta for the real pkdgrav run. Each
//! command is a module of [`walls_cli::commands::sim`]; this file parses and dispatches.
//!
//! Diagnostics go to standard error. A file with errors still gives the scene resolved
//! from what parsed, with exit status 1, as does a run that stopped early; exit status
//! 2 is a usage or I/O error, or input a run cannot use.

#![deny(clippy::print_stdout, clippy::print_stderr)]

use clap::{Parser, Subcommand};
use std::process::ExitCode;
use walls_cli::ContactModel;
use walls_cli::commands::sim::advise::AdviseArgs;
use walls_cli::commands::sim::preview::PreviewArgs;
use walls_cli::commands::sim::run::RunArgs;
use walls_cli::commands::sim::{self, ruled};
use walls_sim::io::par::Rule;

/// mimalloc, as in walls-lint: large files cost a few hundred page faults, not thousands.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

#[derive(Parser)]
#[command(
    name = "walls-sim",
    version,
    about = "Evaluate pkdgrav walls files: the resolved scene, wall motion, runs, and advice for pkdgrav's k_n and timestep.",
    after_help = "Exit status: 0 success; 1 findings (the walls file has errors: the output is what could be resolved) or a run that stopped early (its JSON says why in \"stopped\"); 2 usage or I/O error, or input a run cannot use."
)]
struct Args {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run particles against the walls (SSDEM or HSDEM) and report where they end up,
    /// what happened at walls, the energy and pkdgrav's warnings.
    Run(Box<RunArgs>),
    /// List the parts of the model a run would use (moving walls, spin, friction terms,
    /// edges, particle contacts, reactive walls, sticky and death walls, gravity), with
    /// the reason for each; takes the same options as `run`.
    Plan(Box<RunArgs>),
    /// Suggest the spring constants and timestep (dKn, dKt, dDelta) for the real
    /// pkdgrav run from the particles' size, mass and speed, and print the .par lines.
    Advise(Box<AdviseArgs>),
    /// Draw the walls (and particles) at a time, or their motion over a span: SVG
    /// (the default), POV-Ray, VTK or an interactive HTML page.
    Preview(Box<PreviewArgs>),
    /// Print the resolved scene as JSON: every wall with the effective value of every
    /// token, in pkdgrav units.
    Scene {
        /// The walls file; `-` reads standard input.
        #[arg(value_name = "FILE")]
        file: String,
        /// Also give each wall's `position` at this time (pkdgrav units).
        #[arg(long, value_name = "T", allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
        time: Option<f64>,
        /// The contact model the file is for (it decides which values are errors).
        #[arg(long, value_enum, default_value_t = ContactModel::Ssdem)]
        mode: ContactModel,
    },
}

fn main() -> ExitCode {
    let args = Args::parse();
    match args.command {
        Command::Scene { file, time, mode } => sim::scene::run(&file, time, mode),
        Command::Run(run) => sim::run::run(&run),
        Command::Plan(run) => sim::plan::run(&run),
        Command::Preview(args) => sim::preview::run(&args),
        Command::Advise(args) => sim::advise::run(&args),
    }
}
