//! `walls-sim`: evaluate a walls file. `walls-sim scene FILE [--time T]` prints the
//! resolved scene as JSON (SPEC §2); `walls-sim run` runs particles against it;
//! `walls-sim advise` suggests dKn, dKt and dDelta for the real pkdgrav run. The command
//! line and its commands are [`walls_cli::commands::sim`], run by
//! [`walls_cli::entry::sim`].
//!
//! Diagnostics go to standard error. A file with errors still gives the scene resolved
//! from what parsed, with exit status 1, as does a run that stopped early; exit status
//! 2 is a usage or I/O error, or input a run cannot use.

#![deny(clippy::print_stdout, clippy::print_stderr)]

use std::process::ExitCode;

/// mimalloc, as in walls-lint: large files cost a few hundred page faults, not thousands.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    ExitCode::from(walls_cli::entry::sim(std::env::args_os().collect()) as u8)
}
