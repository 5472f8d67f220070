//! `walls-sim run`: runs particles against the walls (SSDEM or HSDEM) and reports where
//! they end up, what happened at walls, the energy and pkdgrav's warnings; with `--out`,
//! the trajectory and pkdgrav's reactive-wall files. The settings come from
//! [`walls_sim::config`]; the report from [`walls_sim::report`].

use super::outputs::{Due, Failure, RunOutputs};
use super::{error, exit_status, read_walls};
use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use walls_geometry::Particle;
use walls_geometry::units::System;
use walls_geometry::{Wall, decode};
use walls_sim::config::{Counts, Flags, Inputs, Outputs, Stepping};
use walls_sim::report::OutputError;
use walls_sim::run::{Settings, State};

/// `walls-sim run`: the docs/spec.md §2 command line.
#[derive(clap::Args)]
pub struct RunArgs {
    /// The walls file (default: the --par file's achWallsFile, beside the .par file).
    #[arg(value_name = "FILE")]
    pub file: Option<String>,
    /// `--particles` to `--no-edges`.
    #[command(flatten)]
    pub inputs: Inputs,
    /// Write the trajectory to DIR: particles.csv and walls.csv, at the start and every
    /// --every steps (and at a --par run's last step).
    #[arg(long, value_name = "DIR")]
    pub out: Option<std::path::PathBuf>,
    /// Also write pkdgrav's own outputs in --out at its output steps: `.ss` files named
    /// as pkdgrav names them (the --par file's achOutName and nDigits, else ss.NNNNN),
    /// which pkdgrav's tools read.
    #[arg(long, requires = "out")]
    pub ss_output: bool,
    /// `--oscillation` to `--all-parts`.
    #[command(flatten)]
    pub stepping: Stepping,
    /// Empty pkdgrav's WALLSREACTdata.out and WALLSREACTviz.out in --out first, rather
    /// than appending to them as pkdgrav does.
    #[arg(long)]
    pub fresh: bool,
    /// Replace the outputs of an earlier run in --out (particles.csv, walls.csv, the
    /// .ss outputs): regular files that the run does not read, not read-only, with one
    /// name.
    #[arg(long, requires = "out")]
    pub force: bool,
    /// `--max-steps` and `--every`.
    #[command(flatten)]
    pub counts: Counts,
    /// Print the result as JSON on standard output (always in pkdgrav units).
    #[arg(long)]
    pub json: bool,
    /// The units of the summary's times: pkdgrav's, with the walls file's own beside
    /// them when it sets some (auto); pkdgrav's alone; centimetres-grams-seconds; or SI.
    #[arg(long, value_enum, default_value_t = System::Auto)]
    pub units: System,
}

/// Runs particles as `args` say; the exit status.
pub fn run(args: &RunArgs) -> i32 {
    simulate(args).unwrap_or_else(error)
}

/// What a run needs, read and checked; its particles as `P`s (a run's: the states it
/// starts from).
pub struct Prepared<P = State> {
    /// The walls of the file, checked in the run's mode and decoded.
    pub walls: Vec<Wall>,
    /// The walls file's text.
    pub walls_text: std::sync::Arc<str>,
    /// The `.par` file read, if any.
    pub par: Option<walls_sim::io::par::Params>,
    /// The particles, for a run read straight into the states it starts from (it holds
    /// no second array of them).
    pub particles: Vec<P>,
    /// The settings, from the options, the `.par` file and the defaults.
    pub settings: Settings,
    /// How many errors the walls file has.
    pub errors: usize,
    /// How often the outputs are written, and the `.ss` outputs' names.
    pub outputs: Outputs,
    /// The options that settle the settings.
    pub flags: Flags,
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
/// run's mode), the particles, and the settings from options, `.par` and defaults. A
/// walls file with errors is said to be `doing` ("running") what could be resolved;
/// `None` says nothing of it (the caller refuses it).
pub fn prepare(args: &RunArgs, doing: Option<&str>) -> Result<Prepared, String> {
    prepare_as(args, doing)
}

/// [`prepare`] with the particles read as `P`s: the commands that do not run them keep
/// [`Particle`]s (96 bytes each, not a state's 160).
pub fn prepare_as<P: AsRef<Particle> + From<Particle>>(
    args: &RunArgs,
    doing: Option<&str>,
) -> Result<Prepared<P>, String> {
    use walls_sim::config;
    let flags = Flags {
        inputs: args.inputs.clone(),
        stepping: args.stepping,
        counts: args.counts,
    };
    let par = config::read_par(&flags).map_err(|e| e.to_string())?;
    if let (Some(path), Some(p)) = (&flags.inputs.par, &par) {
        for w in &p.warnings {
            crate::errln!("walls-sim: warning: {path}: {w}");
        }
    }
    let file =
        config::walls_file(args.file.as_deref(), &flags, par.as_ref()).ok_or_else(
            || match &flags.inputs.par {
                Some(path) => {
                    format!("no walls file: give FILE, or an achWallsFile line in {path}")
                }
                None => "no walls file: give FILE, or --par with an achWallsFile line".to_string(),
            },
        )?;
    let (checked, errors) = read_walls(&file, flags.build().contact_model(), doing)?;
    let walls = decode(&checked.scene);
    let readout = walls_geometry::units::Readout::new(args.units, &checked.scene.units);
    let run = config::load_as(&flags, par.as_ref(), &walls).map_err(|e| e.to_string())?;
    if let Some(path) = &flags.inputs.par {
        for w in &run.warnings {
            crate::errln!("walls-sim: warning: {path}: {w}");
        }
    }
    let outputs = config::outputs(&flags, par.as_ref());
    if let (Some(w), Some(path), true) = (&outputs.ss_warning, &flags.inputs.par, args.ss_output) {
        crate::errln!("walls-sim: warning: {path}: {w}");
    }
    let inputs = [
        Some(file.clone()),
        flags.inputs.par.clone(),
        config::particle_file(&flags, par.as_ref()),
        config::cohesion_file(&flags, par.as_ref()),
    ]
    .into_iter()
    .flatten()
    .collect();
    Ok(Prepared {
        walls,
        walls_text: checked.text,
        par,
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

/// The steps after which a run with `settings` outputs its particles, outputs every
/// `every` steps: the multiples of `every` (none when it is 0) and a counted run's last
/// step, as pkdgrav (the trajectory of `--out`, and `walls.run`'s arrays).
pub fn output_step(every: u64, settings: &Settings) -> impl Fn(u64) -> bool + '_ {
    move |step| (every > 0 && step.is_multiple_of(every)) || Some(step) == settings.last_step
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
        outputs: Outputs {
            every, ss, reduced, ..
        },
        inputs,
        readout,
        numbers,
        ..
    } = prepare(args, Some("running"))?;
    let scene = &walls[..];
    let output = output_step(every, &settings);
    let first = settings.start_step;
    // The WALLSREACT lines at the output steps, or, when the `.par` file sets
    // `iRedOutInterval`, at pkdgrav's reduced outputs: the start step and every
    // `iRedOutInterval` steps after it (docs/pkdgrav-physics.md §10).
    let due = |step: u64| Due {
        trajectory: output(step),
        reactive: match reduced {
            Some(n) => (step - first).is_multiple_of(n),
            None => output(step),
        },
    };
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
    let progress = progress_bar(match settings.last_step {
        Some(last) => last.saturating_sub(first),
        None => settings.end_step().saturating_sub(first),
    });
    let mut failure: Option<Failure> = None;
    if let Some(out) = &mut files {
        // The assemblies as the walls file sets them, for pkdgrav's reduced output at
        // the start step.
        let start = reduced.map(|_| walls_sim::dynamics::reactive::assemblies(scene));
        failure = out
            .record_start(
                first,
                settings.t_start(),
                &particles,
                scene,
                start.as_deref(),
            )
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
            let due = due(step);
            let wanted = (due.trajectory || (due.reactive && reactive)) && failure.is_none();
            let Some(out) = files.as_mut().filter(|_| wanted) else {
                return;
            };
            // Only now are the particles looked at (`Snapshot`).
            let (states, assemblies) = snapshot.look();
            failure = out.record((step, t), states, scene, assemblies, due).err();
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
