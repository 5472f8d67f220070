//! The tools as functions from a command line to an exit status, so that a program that
//! embeds them (a Python wheel) runs them in its own process: [`lint`], [`fmt`] and
//! [`sim`] take the whole argv (argv\[0] is the program's name, as in `std::env::args_os`)
//! and return the status the binary exits with. The binaries are one call of these.
//!
//! A command line clap refuses prints clap's message to standard error and returns 2;
//! `--help` and `--version` print to standard output and return 0. Nothing here ends the
//! process.

use crate::commands::{self, fmt::FmtArgs, lint::LintArgs, sim::SimArgs};
use clap::Parser;
use std::ffi::OsString;

/// `walls-lint` with the command line `argv`; the exit status.
pub fn lint(argv: Vec<OsString>) -> i32 {
    match parse::<LintArgs>(argv) {
        Ok(args) => commands::lint::run(&args),
        Err(status) => status,
    }
}

/// `walls-fmt` with the command line `argv`; the exit status.
pub fn fmt(argv: Vec<OsString>) -> i32 {
    match parse::<FmtArgs>(argv) {
        Ok(args) => commands::fmt::run(&args),
        Err(status) => status,
    }
}

/// `walls-sim` with the command line `argv`; the exit status.
pub fn sim(argv: Vec<OsString>) -> i32 {
    match parse::<SimArgs>(argv) {
        Ok(args) => commands::sim::dispatch(&args),
        Err(status) => status,
    }
}

/// The arguments `argv` gives, or, when clap refuses them or has answered `--help` or
/// `--version`, the exit status after its message is printed.
fn parse<A: Parser>(argv: Vec<OsString>) -> Result<A, i32> {
    A::try_parse_from(argv).map_err(|e| {
        // A closed stream leaves nobody to tell; the status still says what happened.
        let _ = e.print();
        e.exit_code()
    })
}
