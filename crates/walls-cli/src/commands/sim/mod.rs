//! `walls-sim`'s command line ([`SimArgs`], run by [`dispatch`]) and its commands, one
//! module each: [`scene`], [`run`], [`plan`], [`advise`], [`preview`] and [`export`]; and what they
//! share: reading the walls file, and the exit statuses. The value parsers of numbers
//! with a range are walls-sim's ([`walls_sim::cli`]), as are `run`'s and `plan`'s
//! options ([`walls_sim::config::Flags`]).
//!
//! Diagnostics go to standard error. A file with errors still gives the scene resolved
//! from what parsed, with exit status 1, as does a run that stopped early; exit status
//! 2 is a usage or I/O error, or input a run cannot use.

pub mod advise;
pub mod export;
pub mod outputs;
pub mod plan;
pub mod preview;
pub mod run;
pub mod scene;

use crate::{Checked, ContactModel, check_bytes, input};
use advise::AdviseArgs;
use clap::{Parser, Subcommand};
use preview::PreviewArgs;
use run::RunArgs;
use walls_diagnostics::Severity;
use walls_model::Options;
use walls_sim::cli::ruled;
use walls_sim::io::par::Rule;

/// The command line of `walls-sim`.
#[allow(missing_docs, reason = "a field's doc comment would show in --help")]
#[derive(Parser)]
#[command(
    name = "walls-sim",
    version,
    about = "Evaluate pkdgrav walls files: the resolved scene, wall motion, runs, and advice for pkdgrav's k_n and timestep.",
    arg_required_else_help = true,
    args_conflicts_with_subcommands = true,
    after_help = "Exit status: 0 success; 1 findings (the walls file has errors: the output is what could be resolved) or a run that stopped early (its JSON says why in \"stopped\"); 2 usage or I/O error, or input a run cannot use."
)]
pub struct SimArgs {
    #[command(subcommand)]
    pub command: Option<SimCommand>,
    /// Print the completion script for SHELL to standard output and exit.
    #[arg(long, value_name = "SHELL", exclusive = true)]
    pub completions: Option<clap_complete::Shell>,
}

/// `walls-sim`'s commands (their doc comments are their help).
#[derive(Subcommand)]
pub enum SimCommand {
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
    /// Write the run (a walls file, particles and run options, or a --par run directory
    /// with options over it) as a pkdgrav run directory: ss.par with every key the run
    /// depends on, walls.dat, initial.ss and a README naming the build and the commands.
    Export(Box<export::ExportArgs>),
    /// Draw the walls (and particles) at a time, or their motion over a span: SVG
    /// (the default), POV-Ray, VTK or an interactive HTML page.
    Preview(Box<PreviewArgs>),
    /// Print the resolved scene as JSON: every wall with the effective value of every
    /// token, in pkdgrav units.
    Scene {
        /// The walls file; `-` reads standard input. Without it, the --par file's
        /// achWallsFile.
        #[arg(
            value_name = "FILE",
            required_unless_present = "par",
            conflicts_with = "par"
        )]
        file: Option<String>,
        /// A pkdgrav run directory's .par file, whose achWallsFile (beside it) is the
        /// walls file when FILE is not given; refused where `run --par` refuses it.
        #[arg(long, value_name = "FILE")]
        par: Option<String>,
        /// The pkdgrav build the --par file is read for, as `run --pkdgrav-build` takes
        /// it (default pkdgrav's own).
        #[arg(long = "pkdgrav-build", value_name = "OPTIONS", value_parser = walls_sim::cli::build, requires = "par")]
        pkdgrav_build: Option<walls_sim::build::Build>,
        /// Also give each wall's `position` at this time (pkdgrav units).
        #[arg(long, value_name = "T", allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
        time: Option<f64>,
        /// The contact model the file is for (it decides which values are errors).
        #[arg(long, value_enum, default_value_t = ContactModel::Ssdem)]
        mode: ContactModel,
    },
}

/// Runs the command `args` name; the exit status.
pub fn dispatch(args: &SimArgs) -> i32 {
    match &args.command {
        Some(SimCommand::Scene {
            file,
            par,
            pkdgrav_build,
            time,
            mode,
        }) => {
            warn_subnormal(time.map(|t| ("--time", t)));
            let file = match (file, par) {
                (Some(file), _) => file.clone(),
                (None, Some(par)) => match run_directory(par, None, pkdgrav_build.clone()) {
                    Ok(RunDirectory { walls: Some(w), .. }) => w,
                    Ok(_) => {
                        return error(format!(
                            "no walls file: name one, or give {par} an achWallsFile line"
                        ));
                    }
                    Err(e) => return error(e),
                },
                (None, None) => return error("no walls file: name one, or give --par"),
            };
            scene::run(&file, *time, *mode)
        }
        Some(SimCommand::Run(args)) => run::run(args),
        Some(SimCommand::Plan(args)) => plan::run(args),
        Some(SimCommand::Preview(args)) => preview::run(args),
        Some(SimCommand::Advise(args)) => advise::run(args),
        Some(SimCommand::Export(args)) => export::run(args),
        // Only for arguments built in code: clap shows the help when no command is given.
        None => error("no command given: scene, run, plan, advise, preview or export"),
    }
}

/// What a run directory's `.par` file names: its walls file and its particles, each
/// beside it.
pub(super) struct RunDirectory {
    pub walls: Option<String>,
    pub particles: Option<std::path::PathBuf>,
}

/// The run directory of the `.par` file at `par`, read as `walls-sim run --par` reads it
/// (refused where pkdgrav's `build`, else its default build, refuses it); `particles`,
/// when given on the command line, stands for its `achInFile`.
pub(super) fn run_directory(
    par: &str,
    particles: Option<String>,
    build: Option<walls_sim::build::Build>,
) -> Result<RunDirectory, String> {
    use walls_sim::config::{self, Flags, Inputs};
    let flags = Flags {
        inputs: Inputs {
            par: Some(par.to_string()),
            particles,
            build,
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let params = config::read_par(&flags).map_err(|e| e.to_string())?;
    Ok(RunDirectory {
        walls: config::walls_file(None, &flags, params.as_ref()),
        particles: config::particle_file(&flags, params.as_ref()).map(Into::into),
    })
}

/// Warns about the options given with a subnormal value (pkdgrav would read them with
/// fewer significant digits), as a run does (W701).
fn warn_subnormal<'a>(options: impl IntoIterator<Item = (&'a str, f64)>) {
    for (option, value) in options {
        if walls_keywords::number::subnormal(value).is_some() {
            let at = option.to_string();
            let w = walls_sim::run::Warning::SubnormalInput { at, value };
            crate::errln!("walls-sim: warning: {w}");
        }
    }
}

/// Reports `e` as an error and gives exit status 2.
fn error(e: impl std::fmt::Display) -> i32 {
    crate::errln!("walls-sim: error: {e}");
    2
}

/// Exit status 1 when the walls file had `errors`, else success.
fn exit_status(errors: usize) -> i32 {
    if errors > 0 { 1 } else { 0 }
}

/// Reads and checks the walls file at `path` in `mode`, with its number of errors;
/// when it has some, says so, and that the command goes on `doing` ("running",
/// "drawing") what could be resolved (`None`: the caller refuses the file, and says so). A length or speed whose squares overflow (C121)
/// stays in the resolved scene, and a run or picture of it would compute infinities
/// and NaN: such a file is refused.
fn read_walls(
    path: &str,
    mode: ContactModel,
    doing: Option<&str>,
) -> Result<(Checked, usize), String> {
    let options = Options {
        mode,
        ..Options::default()
    };
    let read = input::read(path);
    let checked = check_bytes(read.bytes?, &options);
    let errors: Vec<_> = checked
        .diagnostics
        .iter()
        .filter(|d| d.severity == Severity::Error)
        .cloned()
        .collect();
    if !errors.is_empty() {
        // The errors themselves, located, as walls-lint shows them in this mode.
        let report = walls_diagnostics::render::FileReport {
            path: &read.name,
            source: &checked.text,
            diagnostics: &errors,
        };
        let color = crate::console::color_stderr();
        // Standard error is only for people here; if it is gone there is nobody to tell.
        crate::console::err_data(|err| walls_diagnostics::render::human(err, &report, color));
        let overflow = &walls_model::codes::ARITHMETIC_OVERFLOW;
        if let Some(d) = errors.iter().find(|d| d.code.id == overflow.id) {
            return Err(format!(
                "{path}: {} ({}, shown above): nothing can be computed from it",
                d.message, overflow.id
            ));
        }
        let mode = match mode {
            ContactModel::Ssdem => "ssdem",
            ContactModel::Hsdem => "hsdem",
        };
        if let Some(doing) = doing {
            crate::errln!(
                "walls-sim: {path}: {} error(s) for a {mode} run (`walls-lint --mode {mode} {path}` shows them); {doing} what could be resolved",
                errors.len()
            );
        }
    }
    Ok((checked, errors.len()))
}
