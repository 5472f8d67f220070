//! `walls-fmt`: rewrite walls files in the canonical layout (docs/formatting.md;
//! [`walls_cli::commands::fmt`]).

#![deny(clippy::print_stdout, clippy::print_stderr)]

use clap::Parser;
use std::process::ExitCode;
use walls_cli::commands::fmt::{FmtArgs, run};

/// mimalloc, as in walls-lint.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> ExitCode {
    run(&FmtArgs::parse())
}
