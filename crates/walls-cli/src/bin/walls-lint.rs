//! `walls-lint`: check walls files for everything pkdgrav would reject or misread
//! ([`walls_cli::commands::lint`], run by [`walls_cli::entry::lint`]).

#![deny(clippy::print_stdout, clippy::print_stderr)]

use std::process::ExitCode;

/// mimalloc: it maps memory in large chunks, so a large file's tokens and walls cost a
/// few hundred page faults instead of twenty thousand (measured in docs/performance-history.md, "Targets").
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    ExitCode::from(walls_cli::entry::lint(std::env::args_os().collect()) as u8)
}
