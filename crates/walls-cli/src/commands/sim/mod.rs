//! `walls-sim`'s commands, one module each: [`scene`], [`run`], [`plan`], [`advise`] and
//! [`preview`]; and what they share: the value parser of numbers with a range, reading
//! the walls file, and the exit statuses.
//!
//! Diagnostics go to standard error. A file with errors still gives the scene resolved
//! from what parsed, with exit status 1, as does a run that stopped early; exit status
//! 2 is a usage or I/O error, or input a run cannot use.

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
        let x = walls_sim::io::number(s).map_err(|why| format!("`{s}` is {why}"))?;
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
        let mut err = std::io::BufWriter::new(std::io::stderr().lock());
        // Standard error is only for people here; if it is gone there is nobody to tell.
        let _ = walls_diagnostics::render::human(&mut err, &report, color)
            .and_then(|()| std::io::Write::flush(&mut err));
        let mode = match mode {
            ContactModel::Ssdem => "ssdem",
            ContactModel::Hsdem => "hsdem",
        };
        crate::errln!(
            "walls-sim: {path}: {} error(s) for a {mode} run (`walls-lint --mode {mode} {path}` shows them); {doing} what could be resolved",
            errors.len()
        );
    }
    Ok((checked, errors.len()))
}
