//! `walls-fmt`: rewrite walls files in the canonical layout (docs/formatting.md;
//! [`walls_cli::commands::fmt`], run by [`walls_cli::entry::fmt`]).

#![deny(clippy::print_stdout, clippy::print_stderr)]

use std::process::ExitCode;

/// mimalloc, as in walls-lint.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    ExitCode::from(walls_cli::entry::fmt(std::env::args_os().collect()) as u8)
}
