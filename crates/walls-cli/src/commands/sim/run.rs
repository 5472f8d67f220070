//! `walls-sim run`: runs particles against the walls (SSDEM or HSDEM) and reports where
//! they end up, what happened at walls, the energy and pkdgrav's warnings; with `--out`,
//! the trajectory and pkdgrav's reactive-wall files. The settings come from
//! [`walls_sim::config`]; the report from [`walls_sim::report`].

use super::outputs::{Failure, RunOutputs};
use super::{error, exit_status, read_walls, ruled};
use crate::ContactModel;
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use walls_geometry::Particle;
use walls_geometry::units::System;
use walls_geometry::{Wall, decode};
use walls_sim::OscillationStepping;
use walls_sim::config::Outputs;
use walls_sim::contact::ssdem::Sliding;
use walls_sim::io::par::Rule;
use walls_sim::report::OutputError;
use walls_sim::run::{Integrator, Settings};

/// `walls-sim run`: the docs/spec.md §2 command line.
#[derive(clap::Args)]
pub struct RunArgs {
    /// The walls file (default: the --par file's achWallsFile, beside the .par file).
    #[arg(value_name = "FILE")]
    pub file: Option<String>,
    /// Particles: a CSV file (mass,radius,x,y,z,vx,vy,vz[,wx,wy,wz,color]) or a pkdgrav
    /// .ss file (by the extension .csv or .ss, else by the content); `-` reads standard
    /// input. Without it, nine particles are dropped inside the scene's container
    /// (or onto the scene when it has none).
    #[allow(
        rustdoc::broken_intra_doc_links,
        reason = "the brackets are --help's optional columns"
    )]
    #[arg(long, value_name = "FILE")]
    pub particles: Option<String>,
    /// Run the walls alone, with no particles (instead of the nine dropped onto the
    /// scene, or the --par file's achInFile): oscillating walls move, reactive walls
    /// fall.
    #[arg(long, conflicts_with = "particles")]
    pub no_particles: bool,
    /// A pkdgrav parameter file: timestep, steps, output interval, material, gravity,
    /// and the walls file (achWallsFile) and particle file (achInFile) when not given
    /// here. Keys the evaluator does not follow are warned about.
    #[arg(long, value_name = "FILE")]
    pub par: Option<String>,
    /// The contact model (with --pkdgrav-build, the build's: DEM or not).
    #[arg(long, value_enum, default_value_t = ContactModel::Ssdem)]
    pub method: ContactModel,
    /// The pkdgrav build to follow: its compile options, space or comma separated
    /// (default pkdgrav's own, "DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT"; no DEM:
    /// hard-sphere walls). DEM_COHESION, DEM_TWOLAYERS, DEM_WALLS_REACT and AGGS turn
    /// on their physics.
    #[arg(long, value_name = "OPTIONS", value_parser = build_option, conflicts_with = "method")]
    pub pkdgrav_build: Option<walls_sim::build::Build>,
    /// The timestep (default: π·√(m/(2k_n))/100 for the lightest particle, no more than
    /// lets anything move 2 % of the smallest radius, and shortened so that whole steps
    /// end on --t-end).
    #[arg(long, value_parser = ruled(Rule::Positive))]
    pub dt: Option<f64>,
    /// When to stop (default: three free falls over the scene; without particles, two
    /// oscillation periods).
    #[arg(long, value_parser = ruled(Rule::Positive))]
    pub t_end: Option<f64>,
    /// Uniform gravity.
    #[arg(long, num_args = 3, value_names = ["GX", "GY", "GZ"], allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    pub gravity: Option<Vec<f64>>,
    /// The particles' normal restitution (what walls' 99 means).
    #[arg(long, value_parser = ruled(Rule::Restitution))]
    pub epsn: Option<f64>,
    /// The particles' tangential restitution.
    #[arg(long, value_parser = ruled(Rule::Tangential))]
    pub epst: Option<f64>,
    /// The particles' normal spring constant.
    #[arg(long = "k-n", value_parser = ruled(Rule::Positive))]
    pub k_n: Option<f64>,
    /// The particles' tangential spring constant (default 2/7 of k_n).
    #[arg(long = "k-t", value_parser = ruled(Rule::NonNegative))]
    pub k_t: Option<f64>,
    /// The particles' static friction.
    #[arg(long = "mu-s", value_parser = ruled(Rule::NonNegative))]
    pub mu_s: Option<f64>,
    /// The particles' rolling friction (SSDEM).
    #[arg(long = "mu-r", value_parser = ruled(Rule::NonNegative))]
    pub mu_r: Option<f64>,
    /// The particles' twisting friction (SSDEM).
    #[arg(long = "mu-t", value_parser = ruled(Rule::NonNegative))]
    pub mu_t: Option<f64>,
    /// Particles pass through each other (they still meet walls).
    #[arg(long)]
    pub no_particle_contacts: bool,
    /// HSDEM: only faces and cylinder sides count, not edges, corners and rims
    /// (pkdgrav's bWallsEdgeDetect = 0).
    #[arg(long)]
    pub no_edges: bool,
    /// Write the trajectory to DIR: particles.csv and walls.csv, at the start and every
    /// --every steps (and at a --par run's last step).
    #[arg(long, value_name = "DIR")]
    pub out: Option<std::path::PathBuf>,
    /// Also write pkdgrav's own outputs in --out at its output steps: `.ss` files named
    /// as pkdgrav names them (the --par file's achOutName and nDigits, else ss.NNNNN),
    /// which pkdgrav's tools read.
    #[arg(long, requires = "out")]
    pub ss_output: bool,
    /// How oscillating walls move: step by step as pkdgrav does (the default), or on
    /// the exact sinusoid (for comparison; --integrator pkdgrav always steps SSDEM
    /// walls as pkdgrav does).
    #[arg(long, value_enum, default_value_t = OscillationStepping::Pkdgrav)]
    pub oscillation: OscillationStepping,
    /// SSDEM: the integrator: pkdgrav's own step and contact law (the default); or,
    /// for comparison, kick-drift-kick leapfrog with the summary's contact law, the same
    /// with the dashpot velocity predicted to the step's end, or explicit Euler.
    #[arg(long, value_enum, default_value_t = Integrator::Pkdgrav)]
    pub integrator: Integrator,
    /// SSDEM with --integrator pkdgrav: what the shear spring of a sliding contact does:
    /// pkdgrav's reset (the default), or the Coulomb clamp of LAMMPS and LIGGGHTS (a
    /// sliding contact's friction is exactly μ_s·N). Not a .par key: pkdgrav has none.
    #[arg(long, value_enum, default_value_t = Sliding::Reset)]
    pub sliding: Sliding,
    /// Run every part of the model, whatever the scene needs (for comparison; see
    /// `walls-sim plan`).
    #[arg(long)]
    pub all_parts: bool,
    /// Empty pkdgrav's WALLSREACTdata.out and WALLSREACTviz.out in --out first, rather
    /// than appending to them as pkdgrav does.
    #[arg(long)]
    pub fresh: bool,
    /// Replace the outputs of an earlier run in --out (particles.csv, walls.csv, the
    /// .ss outputs): regular files that the run does not read, not read-only, with one
    /// name.
    #[arg(long, requires = "out")]
    pub force: bool,
    /// The most steps the run may take: a run that would take more is refused before it
    /// starts (a mistyped --dt or --t-end), saying how many it needs.
    #[arg(long, value_name = "N", default_value_t = walls_sim::config::MAX_STEPS)]
    pub max_steps: u64,
    /// Steps between trajectory rows (default: the --par file's iOutInterval, else 100).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    pub every: Option<u64>,
    /// Print the result as JSON on standard output (always in pkdgrav units).
    #[arg(long)]
    pub json: bool,
    /// The units of the summary's times: pkdgrav's, with the walls file's own beside
    /// them when it sets some (auto); pkdgrav's alone; centimetres-grams-seconds; or SI.
    #[arg(long, value_enum, default_value_t = System::Auto)]
    pub units: System,
}

/// `--pkdgrav-build`'s value.
fn build_option(text: &str) -> Result<walls_sim::build::Build, String> {
    walls_sim::build::Build::parse(text).map_err(|e| e.to_string())
}

/// Runs particles as `args` say; the exit status.
pub fn run(args: &RunArgs) -> i32 {
    simulate(args).unwrap_or_else(error)
}

/// What a run needs, read and checked.
pub struct Prepared {
    /// The walls of the file, checked in the run's mode and decoded.
    pub walls: Vec<Wall>,
    /// The particles.
    pub particles: Vec<Particle>,
    /// The settings, from the options, the `.par` file and the defaults.
    pub settings: Settings,
    /// How many errors the walls file has.
    pub errors: usize,
    /// How often the outputs are written, and the `.ss` outputs' names.
    pub outputs: Outputs,
    /// The options that settle the settings.
    pub flags: walls_sim::config::Flags,
    /// The files the run reads: the walls file, the `.par` file, the particles and the
    /// cohesion file, which no output may replace.
    pub inputs: Vec<String>,
    /// How the summary shows times: `--units` for the walls file's units.
    pub readout: walls_geometry::units::Readout,
    /// The subnormal numbers of the inputs (W701), which come before the run's warnings.
    pub numbers: Vec<walls_sim::run::Warning>,
}

/// Reads and checks everything a run needs: the `.par` file (its warnings go to
/// standard error), the walls file (the argument, else the `.par` file's; checked in the
/// run's mode), the particles, and the settings from options, `.par` and defaults.
pub fn prepare(args: &RunArgs) -> Result<Prepared, String> {
    use walls_sim::config;
    let flags = flags(args);
    let par = config::read_par(&flags).map_err(|e| e.to_string())?;
    if let (Some(path), Some(p)) = (&args.par, &par) {
        for w in &p.warnings {
            crate::errln!("walls-sim: warning: {path}: {w}");
        }
    }
    let file =
        config::walls_file(args.file.as_deref(), &flags, par.as_ref()).ok_or_else(
            || match &args.par {
                Some(path) => {
                    format!("no walls file: give FILE, or an achWallsFile line in {path}")
                }
                None => "no walls file: give FILE, or --par with an achWallsFile line".to_string(),
            },
        )?;
    let (checked, errors) = read_walls(&file, flags.build().contact_model(), "running")?;
    let walls = decode(&checked.scene);
    let readout = walls_geometry::units::Readout::new(args.units, &checked.scene.units);
    let run = config::load(&flags, par.as_ref(), &walls).map_err(|e| e.to_string())?;
    if let Some(path) = &args.par {
        for w in &run.warnings {
            crate::errln!("walls-sim: warning: {path}: {w}");
        }
    }
    let outputs = config::outputs(&flags, par.as_ref());
    if let (Some(w), Some(path), true) = (&outputs.ss_warning, &args.par, args.ss_output) {
        crate::errln!("walls-sim: warning: {path}: {w}");
    }
    let inputs = [
        Some(file.clone()),
        args.par.clone(),
        config::particle_file(&flags, par.as_ref()),
        config::cohesion_file(&flags, par.as_ref()),
    ]
    .into_iter()
    .flatten()
    .collect();
    Ok(Prepared {
        walls,
        particles: run.particles,
        settings: run.settings,
        errors,
        outputs,
        inputs,
        readout,
        numbers: run.numbers,
        flags,
    })
}

/// The options of `args` that settle the run's settings.
fn flags(args: &RunArgs) -> walls_sim::config::Flags {
    use walls_sim::run::Planning;
    walls_sim::config::Flags {
        particles: args.particles.clone(),
        no_particles: args.no_particles,
        par: args.par.clone(),
        method: args.method,
        build: args.pkdgrav_build.clone(),
        dt: args.dt,
        t_end: args.t_end,
        gravity: args
            .gravity
            .as_ref()
            .map(|g| nalgebra::Vector3::new(g[0], g[1], g[2])),
        eps_n: args.epsn,
        eps_t: args.epst,
        k_n: args.k_n,
        k_t: args.k_t,
        mu_s: args.mu_s,
        mu_r: args.mu_r,
        mu_t: args.mu_t,
        no_particle_contacts: args.no_particle_contacts,
        no_edges: args.no_edges,
        stepping: args.oscillation,
        integrator: args.integrator,
        sliding: args.sliding,
        planning: if args.all_parts {
            Planning::Everything
        } else {
            Planning::Needed
        },
        max_steps: Some(args.max_steps),
        every: args.every,
    }
}

fn simulate(args: &RunArgs) -> Result<i32, String> {
    use walls_sim::run::run_watched;
    // Before the particles are read: a run keeps less resident in ordinary pages.
    crate::pages::ordinary();
    let Prepared {
        walls,
        particles,
        settings,
        errors,
        outputs: Outputs { every, ss, .. },
        inputs,
        readout,
        numbers,
        ..
    } = prepare(args)?;
    let scene = &walls[..];
    // Outputs at the multiples of `every` and at a counted run's last step, as pkdgrav.
    let output =
        |step: u64| (every > 0 && step.is_multiple_of(every)) || Some(step) == settings.last_step;
    // pkdgrav's reactive-wall files, beside the trajectory, when the run has assemblies
    // (a build with DEM_WALLS_REACT; without it the masses are ignored, W402): appended
    // to as pkdgrav does, unless --fresh.
    let reactive = walls_sim::run::plan::reactive(scene, &settings);
    // Every output is planned, and refused if it must be, before the run starts.
    let mut files = match &args.out {
        Some(dir) => Some(RunOutputs::open(
            dir,
            args.force,
            args.fresh,
            reactive,
            args.ss_output.then(|| ss.clone()),
            &inputs,
        )?),
        None => None,
    };
    let first = settings.start_step;
    let progress = progress_bar(match settings.last_step {
        Some(last) => last.saturating_sub(first),
        None => settings.end_step().saturating_sub(first),
    });
    let mut failure: Option<Failure> = None;
    if let Some(out) = &mut files {
        failure = out
            .record_start(first, settings.t_start(), &particles, scene)
            .err();
    }
    // Ctrl-C (or SIGTERM, SIGHUP) stops the run after the step it is in, so that every
    // output ends on whole rows.
    walls_output::interrupt::install_graceful();
    // A failed write stops the run after its step: nothing more would be written.
    let write_failed = AtomicBool::new(failure.is_some());
    // The parts of the model the report names, from the particles the run is given.
    let model = args
        .json
        .then(|| walls_sim::report::model(scene, &particles, &settings));
    let mut outcome = run_watched(
        scene,
        particles,
        &settings,
        &mut |step, t, snapshot| {
            if let Some(bar) = &progress {
                bar.set_position(step - first);
            }
            // Without `--out` there is nothing to write, and the particles are not looked
            // at (looking gives the kicks owed: a pass over them).
            let Some(out) = files.as_mut().filter(|_| output(step) && failure.is_none()) else {
                return;
            };
            // Only now are the particles looked at (`Snapshot`).
            let (states, assemblies) = snapshot.look();
            failure = out.record(step, t, states, scene, assemblies).err();
            write_failed.store(failure.is_some(), Ordering::Relaxed);
        },
        &|| write_failed.load(Ordering::Relaxed) || walls_output::interrupt::stop_requested(),
    );
    if let Some(bar) = progress {
        bar.finish_and_clear();
    }
    // The inputs' numbers are warned about first, with the run's warnings.
    outcome.warnings.splice(0..0, numbers);
    // Where the outputs end: after a failure, every file cut back to the last output step
    // all of them hold whole.
    let mut written: Option<Written> = None;
    if let Some(mut out) = files {
        let (names, last) = (out.files(), out.last());
        // Nothing is replaced before the first output step is whole.
        if let Some(replaced) = out.replaced().filter(|_| last.is_some()) {
            crate::errln!("walls-sim: replaced {replaced}");
        }
        if failure.is_some() {
            for problem in out.rollback() {
                crate::errln!("walls-sim: error: {problem}");
            }
        } else if let Err(message) = out.finish() {
            failure = Some(Failure {
                step: first + outcome.steps,
                t: outcome.t,
                message,
            });
        }
        written = Some(Written { names, last });
    }
    if let Some(model) = model {
        let report = walls_sim::report::Report::new(model, &settings, &outcome);
        let report = match &written {
            Some(w) => report.with_outputs(&w.names),
            None => report,
        };
        let report = match (&failure, &written) {
            (Some(f), Some(w)) => report.with_output_error(OutputError {
                message: &f.message,
                step: f.step,
                t: f.t,
                whole_until: w.last,
            }),
            _ => report,
        };
        crate::console::out_data(|w| report.write_json(w));
    } else {
        crate::errln!(
            "walls-sim: {}",
            walls_sim::report::summary(&settings, &outcome, &readout)
        );
        for w in &outcome.warnings {
            crate::errln!("walls-sim: warning: {w}");
        }
    }
    if let (Some(f), Some(Written { names, last }), Some(dir)) = (&failure, &written, &args.out) {
        crate::errln!(
            "walls-sim: error: at output step {} (t = {}): {}",
            f.step,
            readout.time(f.t),
            f.message
        );
        match last {
            Some((step, t)) => crate::errln!(
                "walls-sim: the outputs in {} end at output step {step} (t = {}), their last whole one: {}",
                dir.display(),
                readout.time(*t),
                names.join(", ")
            ),
            None => crate::errln!(
                "walls-sim: no output step was written whole: nothing in {} was made or replaced",
                dir.display()
            ),
        }
        return Ok(2);
    }
    let Some(why) = outcome.stopped else {
        return Ok(exit_status(errors));
    };
    crate::errln!(
        "walls-sim: error: the run stopped early, after step {} (t = {}): {why}",
        first + outcome.steps,
        readout.time(outcome.t),
    );
    if let (Some(Written { names, last }), Some(dir)) = (&written, &args.out) {
        let (step, t) = last.unwrap_or((first, settings.t_start()));
        crate::errln!(
            "walls-sim: the outputs in {} end at their last output, step {step} (t = {}), in whole rows: {}",
            dir.display(),
            readout.time(t),
            names.join(", ")
        );
    }
    Ok(1)
}

/// Where a run's outputs end: the files, and the last output step all of them hold whole.
struct Written {
    names: Vec<String>,
    last: Option<(u64, f64)>,
}

/// A progress bar over `steps` steps, when standard error is a terminal.
fn progress_bar(steps: u64) -> Option<indicatif::ProgressBar> {
    if !std::io::stderr().is_terminal() {
        return None;
    }
    let bar = indicatif::ProgressBar::new(steps);
    if let Ok(style) =
        indicatif::ProgressStyle::with_template("walls-sim {bar:40} {pos}/{len} steps, {eta} left")
    {
        bar.set_style(style);
    }
    Some(bar)
}
