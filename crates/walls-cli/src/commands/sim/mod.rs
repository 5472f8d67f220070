//! `walls-sim`'s commands, one module each: [`scene`], [`run`], [`plan`], [`advise`] and
//! [`preview`]; and what they share: the value parser of numbers with a range, reading
//! the walls file, and the exit statuses.
//!
//! Diagnostics go to standard error. A file with errors still gives the scene resolved
//! from what parsed, with exit status 1; exit status 2 is a usage or I/O error.

pub mod advise;
pub mod plan;
pub mod preview;
pub mod run;
pub mod scene;

use crate::{Checked, ContactModel, check_bytes, input};
use std::process::ExitCode;
use walls_diagnostics::Severity;
use walls_geometry::units::System;
use walls_model::Options;
use walls_sim::io::par::Rule;

/// A value parser for a number that must obey `rule`, as the `.par` file's values must.
pub fn ruled(rule: Rule) -> impl Fn(&str) -> Result<f64, String> + Clone {
    move |s| {
        let x = s
            .parse::<f64>()
            .map_err(|_| format!("`{s}` is not a number"))?;
        rule.check(x).map_err(|says| format!("it must be {says}"))
    }
}

/// `--units` of `run` and `preview` (docs/units.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum UnitsArg {
    /// pkdgrav's units, and the walls file's own beside them when it sets some.
    Auto,
    /// pkdgrav's units alone (AU, solar masses, 1/k days).
    Pkdgrav,
    /// Centimetres, grams, seconds.
    Cgs,
    /// Metres, kilograms, seconds.
    Si,
}

impl From<UnitsArg> for System {
    fn from(u: UnitsArg) -> System {
        match u {
            UnitsArg::Auto => System::Auto,
            UnitsArg::Pkdgrav => System::Pkdgrav,
            UnitsArg::Cgs => System::Cgs,
            UnitsArg::Si => System::Si,
        }
    }
}

/// Reports `e` as an error and gives exit status 2.
fn error(e: impl std::fmt::Display) -> ExitCode {
    crate::errln!("walls-sim: error: {e}");
    ExitCode::from(2)
}

/// Exit status 1 when the walls file had `errors`, else success.
fn exit_status(errors: usize) -> ExitCode {
    if errors > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// Reads and checks the walls file at `path` in `mode`, with its number of errors;
/// when it has some, says so, and that the command goes on `doing` ("running",
/// "drawing") what could be resolved.
fn read_walls(path: &str, mode: ContactModel, doing: &str) -> Result<(Checked, usize), String> {
    let options = Options {
        mode,
        ..Options::default()
    };
    let checked = check_bytes(input::read(path).bytes?, &options);
    let errors = checked
        .diagnostics
        .iter()
        .filter(|d| d.severity == Severity::Error)
        .count();
    if errors > 0 {
        crate::errln!(
            "walls-sim: {path}: {errors} error(s); {doing} what could be resolved (see walls-lint)"
        );
    }
    Ok((checked, errors))
}
