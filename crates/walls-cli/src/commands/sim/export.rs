//! `walls-sim export`: writes a run (a walls file, particles and the run's options, or a
//! `.par` file with options over it) as a pkdgrav run directory: `ss.par`, `walls.dat`,
//! `initial.ss`, the cohesion file if the run reads one, `README.md` and `walls.toml` (the
//! build, for walls-lint). The settings are `run`'s ([`super::run::prepare`]); what the
//! `.par` file says is [`walls_sim::export`]'s; every file is planned (and refused if it
//! must be) before any is written, and all are written before any takes its name.

use super::error;
use super::run::{Prepared, RunArgs, prepare_as};
use std::path::{Path, PathBuf};
use walls_geometry::Particle;
use walls_output::{Outputs, Tool, WriteError};
use walls_sim::config::{Counts, Inputs, Stepping};
use walls_sim::export::{Names, Source};

/// `walls-sim export`'s command line.
#[derive(clap::Args)]
pub struct ExportArgs {
    /// The walls file (default: the --par file's achWallsFile, beside the .par file).
    #[arg(value_name = "FILE")]
    pub file: Option<String>,
    /// `--particles` to `--no-edges`, as `run` takes them.
    #[command(flatten)]
    pub inputs: Inputs,
    /// Steps between pkdgrav's outputs (iOutInterval; default: the --par file's, else
    /// 100).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    pub every: Option<u64>,
    /// The run directory to write (made if missing): ss.par, walls.dat, initial.ss,
    /// README.md, walls.toml (and cohesion.txt when the run reads a cohesion file).
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
    /// Replace the files of an earlier export in DIR (regular files the export does not
    /// read).
    #[arg(long)]
    pub force: bool,
}

/// The names of the files written, as the `.par` file names them.
const NAMES: Names<'static> = Names {
    par: "ss.par",
    walls: "walls.dat",
    particles: "initial.ss",
    cohesion: None,
};

/// The cohesion file's name in the directory.
const COHESION: &str = "cohesion.txt";

/// Writes the run directory `args` describe; the exit status.
pub fn run(args: &ExportArgs) -> i32 {
    export(args).unwrap_or_else(error)
}

fn export(args: &ExportArgs) -> Result<i32, String> {
    let run_args = RunArgs {
        file: args.file.clone(),
        inputs: args.inputs.clone(),
        out: None,
        ss_output: false,
        stepping: Stepping::default(),
        fresh: false,
        force: false,
        counts: Counts {
            // Nothing is run: pkdgrav's own limit is checked below.
            max_steps: u64::MAX,
            every: args.every,
        },
        json: false,
        units: walls_geometry::units::System::Pkdgrav,
    };
    let prepared: Prepared<Particle> = prepare_as(&run_args, None)?;
    let Prepared {
        walls_text,
        par,
        particles,
        settings,
        errors,
        outputs,
        flags,
        inputs,
        ..
    } = &prepared;
    if *errors > 0 {
        crate::errln!(
            "walls-sim: error: {}: {errors} error(s) (shown above): pkdgrav would refuse or misread it; nothing is exported",
            inputs.first().map_or("the walls file", String::as_str)
        );
        return Ok(1);
    }
    if particles.is_empty() {
        return Err(
            "no particles to export: pkdgrav starts from a .ss file with at least one; give --particles"
                .into(),
        );
    }
    let steps = settings.end_step().saturating_sub(settings.start_step);
    if steps == 0 {
        return Err(format!(
            "the run takes no step: it starts at t = {:e} (step {}) and ends at t = {:e}; pkdgrav would run none and write nothing: give a later --t-end",
            settings.t_start(),
            settings.start_step,
            settings.t_end
        ));
    }
    if settings.end_step() > i32::MAX as u64 {
        return Err(format!(
            "the run would take {steps} steps of {:e} to t = {:e}, and pkdgrav counts steps in an int (nSteps at most {}): give a longer --dt or a shorter --t-end",
            settings.dt,
            settings.t_end,
            i32::MAX
        ));
    }
    let par_build = walls_par::Build::parse(&settings.build.names())
        .map_err(|e| format!("the build's option {} is not pkdgrav's", e.name))?;
    // The `.par` file the run came from, read again for its lines.
    let source_text = match &flags.inputs.par {
        Some(path) => {
            let bytes = crate::input::read(path).bytes?;
            // Lines are copied as text: a byte that is not UTF-8 would change in the copy.
            let text = String::from_utf8(bytes).map_err(|e| {
                let at = e.utf8_error().valid_up_to();
                let line = 1 + e.as_bytes()[..at].iter().filter(|&&b| b == b'\n').count();
                format!("{path}: line {line} is not UTF-8 text: the export copies the file's lines as text, and would change it")
            })?;
            Some((path.as_str(), text))
        }
        None => None,
    };
    let mut ignored = Vec::new();
    let source_file = source_text
        .as_ref()
        .map(|(_, text)| walls_par::check::File::read(text, &par_build, &mut ignored));
    let source = match (&source_text, &source_file) {
        (Some((path, _)), Some(file)) => Some(Source {
            path: Path::new(path)
                .file_name()
                .and_then(|n| n.to_str())
                .unwrap_or(path),
            file,
        }),
        _ => None,
    };
    let cohesion = walls_sim::config::cohesion_file(flags, par.as_ref())
        .filter(|_| walls_sim::run::optional::cohesion_on(settings));
    let names = Names {
        cohesion: cohesion.as_ref().map(|_| COHESION),
        ..NAMES
    };
    let exported = walls_sim::export::par_file(flags, source.as_ref(), settings, outputs, &names)?;
    // What pkdgrav would refuse in the file written is a fault of the export's: say so
    // rather than write it.
    let refused: Vec<String> = walls_par::check(&exported.par, &par_build)
        .into_iter()
        .filter(|d| d.severity == walls_diagnostics::Severity::Error)
        .map(|d| format!("{}: {}", d.code.id, d.message))
        .collect();
    if !refused.is_empty() {
        return Err(format!(
            "the .par file to be written would stop pkdgrav: {}",
            refused.join("; ")
        ));
    }
    let mut walls = walls_text.to_string();
    if !walls.ends_with('\n') {
        // pkdgrav aborts on a last line without a newline; one changes nothing else.
        walls.push('\n');
    }
    let ss = walls_sim::io::particles::write_ss(settings.t_start(), particles);
    for w in &exported.warnings {
        crate::errln!("walls-sim: warning: {w}");
    }
    let readme = walls_sim::export::readme(&exported, &names, particles.len(), outputs);
    let settings_file = walls_sim::export::settings_file(&exported);
    let cohesion_bytes = match &cohesion {
        Some(path) => Some(std::fs::read(path).map_err(|e| format!("cannot read {path}: {e}"))?),
        None => None,
    };
    let mut files: Vec<(&str, &[u8])> = vec![
        (names.par, exported.par.as_bytes()),
        (names.walls, walls.as_bytes()),
        (names.particles, &ss),
        ("README.md", readme.as_bytes()),
        ("walls.toml", settings_file.as_bytes()),
    ];
    if let Some(bytes) = &cohesion_bytes {
        files.push((COHESION, bytes));
    }
    write_all(&args.out, args.force, inputs, &files)?;
    crate::errln!(
        "walls-sim: exported {} particle(s), {} step(s) of {:e}, to {}: {} (build: {}); check it with `walls-lint {}`",
        particles.len(),
        exported.last_step.saturating_sub(settings.start_step),
        settings.dt,
        args.out.display(),
        files.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", "),
        exported.build.names(),
        args.out.display(),
    );
    Ok(0)
}

/// Writes `files` in the folder `out` (made if missing), each planned first: nothing is
/// written if one of them may not be (it exists without `force`, or is an input, a link,
/// not a regular file). Each is written whole to a new file without a name first, and
/// they take their names only when all are written: a full disk leaves what was there.
fn write_all(
    out: &Path,
    force: bool,
    inputs: &[String],
    files: &[(&str, &[u8])],
) -> Result<(), String> {
    let mut outputs = Outputs::new(Tool::EXPORT, force);
    for input in inputs {
        outputs.reads(input);
    }
    let shown = |name: &str| walls_output::path_in(out, Path::new(name));
    let message =
        |name: &str, e: &WriteError| e.message(&shown(name).display().to_string(), Tool::EXPORT);
    let folder = outputs
        .folder(out, true)
        .map_err(|e| e.message(&out.display().to_string(), Tool::EXPORT))?;
    let mut targets = Vec::new();
    for (name, _) in files {
        let target = folder
            .plan(Path::new(name))
            .map_err(|e| message(name, &e))?;
        targets.push(target);
    }
    let mut streams = Vec::new();
    for ((_, bytes), target) in files.iter().zip(&targets) {
        let mut stream = target.stream().map_err(|e| target.message(&e))?;
        std::io::Write::write_all(&mut stream, bytes)
            .and_then(|()| std::io::Write::flush(&mut stream))
            .map_err(|e| target.message(&e.into()))?;
        streams.push(stream);
    }
    let mut placed = Vec::new();
    for ((name, _), (stream, target)) in files.iter().zip(streams.into_iter().zip(&targets)) {
        if let Err(e) = stream.finish() {
            let done = if placed.is_empty() {
                String::new()
            } else {
                format!(" ({} written before it)", placed.join(", "))
            };
            return Err(format!("{}{done}", target.message(&e.into())));
        }
        placed.push(*name);
    }
    Ok(())
}
