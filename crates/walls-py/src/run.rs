//! `walls.run`: a run of `walls-sim run`, with the particles at every output step.
//!
//! The keywords are `walls-sim run`'s options by their long names (`--t-end` is
//! `t_end`), made into its command line and parsed by its own parser ([`SimArgs`]), so
//! that every option has the command's meaning, default and checks. The run is read and
//! checked by the command's `prepare`, outputs after the steps its
//! [`run::output_step`] says (as the trajectory of `--out`), and is reported as `--json`
//! reports it ([`walls_sim::report::Report`]). The files of the run are paths here:
//! `python/walls/_analysis.py` writes a walls text or a particles array to a temporary
//! file first.

use crate::{args, diagnostics, ss};
use clap::{ArgAction, CommandFactory, Parser};
use pyo3::exceptions::{PyKeyboardInterrupt, PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyString};
use std::ffi::OsString;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use walls_cli::commands::sim::run::{self, Prepared, RunArgs};
use walls_cli::commands::sim::{SimArgs, SimCommand};
use walls_geometry::Particle;
use walls_model::Options;

/// Adds the functions of this file to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_run, m)?)
}

/// The options of `walls-sim run` that are not keywords of `walls.run`, by their ids:
/// the files it is given as arguments (FILE, `--particles`, `--par`) and those of the
/// command's outputs and summary, which `walls.run` returns instead.
const NOT_KEYWORDS: &[&str] = &[
    "file",
    "particles",
    "par",
    "out",
    "ss_output",
    "fresh",
    "force",
    "json",
    "units",
    "help",
];

/// How often a run asks Python whether Ctrl-C was pressed: every so many steps.
const SIGNAL_STEPS: u64 = 1024;

/// The keyword of an option: its long name with `_` for `-`.
fn keyword(long: &str) -> String {
    long.replace('-', "_")
}

/// The options of `walls-sim run` that `walls.run` takes, each with its keyword.
fn options(run: &clap::Command) -> Vec<(&clap::Arg, String)> {
    run.get_arguments()
        .filter(|a| !NOT_KEYWORDS.contains(&a.get_id().as_str()))
        .filter_map(|a| Some((a, keyword(a.get_long()?))))
        .collect()
}

/// A value of an option as its command line gives it: a `str` as it is, an integer
/// exactly, a real as the shortest decimal of its double (read back exactly).
fn value_text(value: &Bound<'_, PyAny>, name: args::Name<'_>) -> PyResult<String> {
    if value.is_instance_of::<PyString>() {
        return args::word(value, name);
    }
    if let Ok(n) = args::integer(value, name, i128::MIN..=i128::MAX) {
        return Ok(n.to_string());
    }
    args::number(value, name).map(|x| format!("{x:?}"))
}

/// The command line of `walls-sim run` for the walls file `walls`, the particles file
/// `particles`, the `.par` file `par` and the keywords `given` (None keeps an option's
/// default, as leaving it out does).
fn command_line(
    walls: Option<OsString>,
    particles: Option<OsString>,
    par: Option<OsString>,
    given: &Bound<'_, PyDict>,
) -> PyResult<Vec<OsString>> {
    let command = SimArgs::command();
    let run = command
        .find_subcommand("run")
        .expect("walls-sim has a run command");
    let options = options(run);
    let mut argv: Vec<OsString> = vec!["walls-sim".into(), "run".into()];
    for (key, value) in given.iter() {
        let key: String = key.extract()?;
        let Some((arg, _)) = options.iter().find(|(_, k)| *k == key) else {
            let names: Vec<&str> = options.iter().map(|(_, k)| k.as_str()).collect();
            return Err(PyTypeError::new_err(format!(
                "walls.run() got an unexpected keyword argument '{key}' (its options are walls-sim run's: {})",
                names.join(", ")
            )));
        };
        if value.is_none() {
            continue;
        }
        let long = arg
            .get_long()
            .expect("an option with a keyword has a long name");
        let name: args::Name<'_> = &key;
        if matches!(arg.get_action(), ArgAction::SetTrue) {
            if args::flag(&value, name)? {
                argv.push(format!("--{long}").into());
            }
        } else if arg.get_num_args().is_some_and(|n| n.min_values() == 3) {
            let vector: [f64; 3] = args::row(&value, name, "numbers", args::number)?;
            argv.push(format!("--{long}").into());
            argv.extend(vector.iter().map(|x| format!("{x:?}").into()));
        } else {
            argv.push(format!("--{long}={}", value_text(&value, name)?).into());
        }
    }
    let mut path = |option: &str, value: Option<OsString>| {
        if let Some(value) = value {
            let mut arg = OsString::from(format!("--{option}="));
            arg.push(value);
            argv.push(arg);
        }
    };
    path("particles", particles);
    path("par", par);
    if let Some(walls) = walls {
        argv.push("--".into());
        argv.push(walls);
    }
    Ok(argv)
}

/// `walls-sim run`'s arguments from its command line, refused (`ValueError`) as the
/// command refuses them, with its message.
fn parse(argv: Vec<OsString>) -> PyResult<RunArgs> {
    let refused = |message: String| {
        let first = message.lines().next().unwrap_or_default();
        PyValueError::new_err(format!(
            "walls.run: {}",
            first.strip_prefix("error: ").unwrap_or(first)
        ))
    };
    match SimArgs::try_parse_from(argv) {
        Ok(SimArgs {
            command: Some(SimCommand::Run(args)),
            ..
        }) => Ok(*args),
        Ok(_) => Err(refused("not a run".into())),
        Err(e) => Err(refused(e.render().to_string())),
    }
}

/// A `WallsError` with the errors of the walls file of a run that has some, found by
/// the check `prepare` made (in the run's contact model).
fn walls_errors(py: Python<'_>, prepared: &Prepared) -> PyErr {
    let options = Options {
        mode: prepared.flags.build().contact_model(),
        ..Options::default()
    };
    let checked = walls_ide::check_text(prepared.walls_text.to_string(), &options);
    diagnostics::error(
        py,
        "the walls file has errors",
        &checked.text,
        &checked.errors(),
    )
}

/// Appends each particle's position, velocity and spin (nine doubles; NaN for one no
/// longer in the run) to `out`.
fn push_states<'a>(out: &mut Vec<f64>, particles: impl Iterator<Item = Option<&'a Particle>>) {
    for p in particles {
        match p {
            Some(p) => out.extend(p.pos.iter().chain(&p.vel).chain(&p.spin)),
            None => out.extend([f64::NAN; 9]),
        }
    }
}

/// What `_run` returns: the report, the times, the states and the particles at the start.
type Ran<'py> = (
    Bound<'py, PyAny>,
    Bound<'py, PyBytes>,
    Bound<'py, PyBytes>,
    Bound<'py, PyBytes>,
);

/// Runs `walls-sim run` on the walls file `walls` (None: the `.par` file's
/// achWallsFile), the particles file `particles` (None: the command's default) and the
/// `.par` file `par`, with `options` its keywords. Returns the report `--json` prints,
/// the times of the outputs (native doubles), each output's particles (position,
/// velocity and spin, nine native doubles each, NaN for one the run deleted) and the
/// run's particles at the start as records of `walls.SS_DTYPE`.
///
/// Raises `ValueError` for an option the command refuses, `TypeError` for an unknown
/// keyword or a value of the wrong kind, `WallsError` for input the command cannot run
/// (with the diagnostics of a walls file with errors), and `KeyboardInterrupt` after
/// Ctrl-C.
#[pyfunction]
#[pyo3(signature = (walls, particles, par, options))]
fn _run<'py>(
    py: Python<'py>,
    walls: Option<&Bound<'py, PyAny>>,
    particles: Option<&Bound<'py, PyAny>>,
    par: Option<&Bound<'py, PyAny>>,
    options: &Bound<'py, PyDict>,
) -> PyResult<Ran<'py>> {
    let path = |v: Option<&Bound<'py, PyAny>>| -> PyResult<Option<OsString>> {
        Ok(args::optional(v, args::path)?.map(Into::into))
    };
    let argv = command_line(path(walls)?, path(particles)?, path(par)?, options)?;
    let args = parse(argv)?;
    // The command's warnings about its inputs (a `.par` file's), which it prints, as
    // Python warnings (a notebook shows them under the cell); a walls file's errors are
    // the `WallsError`'s diagnostics.
    let (prepared, said) =
        py.detach(|| walls_cli::console::capturing(|| run::prepare(&args, None)));
    for line in said.lines() {
        if let Some(warning) = line.strip_prefix("walls-sim: warning: ") {
            let message = std::ffi::CString::new(warning.replace('\0', "\\0"))
                .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
            let category = py.get_type::<pyo3::exceptions::PyUserWarning>();
            PyErr::warn(py, &category, &message, 2)?;
        }
    }
    let prepared = prepared.map_err(|e| diagnostics::plain(py, e))?;
    if prepared.errors > 0 {
        return Err(walls_errors(py, &prepared));
    }
    let Prepared {
        walls,
        particles,
        settings,
        outputs,
        numbers,
        ..
    } = prepared;
    let interrupted = AtomicBool::new(false);
    let steps = AtomicU64::new(0);
    let stop = || {
        if steps.fetch_add(1, Ordering::Relaxed) % SIGNAL_STEPS == SIGNAL_STEPS - 1
            && Python::attach(|py| py.check_signals().is_err())
        {
            interrupted.store(true, Ordering::Relaxed);
        }
        interrupted.load(Ordering::Relaxed)
    };
    let (json, times, states, initial) = py.detach(|| {
        let output = run::output_step(outputs.every, &settings);
        let model = walls_sim::report::model(&walls, &particles, &settings);
        let initial = ss::records(&particles);
        let mut times = vec![settings.t_start()];
        let mut states = Vec::new();
        push_states(&mut states, particles.iter().map(|s| Some(&s.particle)));
        let mut outcome = walls_sim::run::run_watched(
            &walls,
            particles,
            &settings,
            &mut |step, t, snapshot| {
                if output(step) {
                    let (now, _) = snapshot.look();
                    times.push(t);
                    push_states(
                        &mut states,
                        now.iter().map(|s| s.alive.then_some(&s.particle)),
                    );
                }
            },
            &stop,
        );
        // The inputs' numbers are warned about first, as the command warns.
        outcome.warnings.splice(0..0, numbers);
        let mut json = Vec::new();
        let written =
            walls_sim::report::Report::new(model, &settings, &outcome).write_json(&mut json);
        (written.map(|()| json), times, states, initial)
    });
    if interrupted.load(Ordering::Relaxed) {
        return Err(PyKeyboardInterrupt::new_err("walls.run was interrupted"));
    }
    let json = json.map_err(|e| PyRuntimeError::new_err(format!("writing the report: {e}")))?;
    let bytes = |values: &[f64]| {
        let raw: Vec<u8> = values.iter().flat_map(|x| x.to_ne_bytes()).collect();
        PyBytes::new(py, &raw)
    };
    Ok((
        diagnostics::from_json(py, &json)?,
        bytes(&times),
        bytes(&states),
        PyBytes::new(py, &initial),
    ))
}
