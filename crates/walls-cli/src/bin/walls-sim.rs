//! `walls-sim`: evaluate a walls file. `walls-sim scene FILE [--time T]` prints the
//! resolved scene as JSON (SPEC §2).
//!
//! Diagnostics go to standard error. A file with errors still gives the scene resolved
//! from what parsed, with exit status 1; exit status 2 is a usage or I/O error.

use clap::{Parser, Subcommand};

/// mimalloc, as in walls-lint: large files cost a few hundred page faults, not thousands.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;
use std::io::{IsTerminal, Write};
use std::process::ExitCode;
use walls_cli::{ModeArg, check_bytes, input};
use walls_diagnostics::Severity;
use walls_diagnostics::render::{self, FileReport};
use walls_model::Options;

#[derive(Parser)]
#[command(
    name = "walls-sim",
    version,
    about = "Evaluate pkdgrav walls files: the resolved scene, wall motion.",
    after_help = "Exit status: 0 success, 1 the file has errors (the output is what could be resolved), 2 usage or I/O error."
)]
struct Args {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Print the resolved scene as JSON: every wall with the effective value of every
    /// token, in pkdgrav units.
    Scene {
        /// The walls file; `-` reads standard input.
        #[arg(value_name = "FILE")]
        file: String,
        /// Also give each wall's `position` at this time (pkdgrav units).
        #[arg(long, value_name = "T", allow_negative_numbers = true, value_parser = finite)]
        time: Option<f64>,
        /// The contact model the file is for (it decides which values are errors).
        #[arg(long, value_enum, default_value_t = ModeArg::Ssdem)]
        mode: ModeArg,
    },
}

fn main() -> ExitCode {
    let args = Args::parse();
    match args.command {
        Command::Scene { file, time, mode } => scene(&file, time, mode),
    }
}

fn scene(path: &str, time: Option<f64>, mode: ModeArg) -> ExitCode {
    let read = input::read(path);
    let bytes = match read.bytes {
        Ok(bytes) => bytes,
        Err(e) => {
            eprintln!("walls-sim: error: {e}");
            return ExitCode::from(2);
        }
    };
    let options = Options {
        mode: mode.into(),
        ..Options::default()
    };
    let checked = check_bytes(bytes, &options);
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let written = walls_model::json::write_scene(&mut out, &checked.scene, &checked.text, time)
        .and_then(|()| out.flush());
    if let Err(e) = written {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            eprintln!("walls-sim: error: cannot write output: {e}");
        }
        return ExitCode::from(2);
    }
    let report = FileReport {
        path: &read.name,
        source: &checked.text,
        diagnostics: &checked.diagnostics,
    };
    let color = std::io::stderr().is_terminal() && std::env::var_os("NO_COLOR").is_none();
    let mut err = std::io::BufWriter::new(std::io::stderr().lock());
    // Standard error is only for people here; if it is gone there is nobody to tell.
    let _ = render::human(&mut err, &report, color).and_then(|()| err.flush());
    if checked
        .diagnostics
        .iter()
        .any(|d| d.severity == Severity::Error)
    {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// A finite real, for `--time`.
fn finite(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        _ => Err(format!("`{s}` is not a finite number")),
    }
}
