//! `walls-mesh`: an STL or OBJ mesh as pkdgrav triangle walls (docs/meshes.md;
//! [`walls_cli::commands::mesh`]).

#![deny(clippy::print_stdout, clippy::print_stderr)]

use clap::Parser;
use std::process::ExitCode;
use walls_cli::commands::mesh::{MeshArgs, run};

fn main() -> ExitCode {
    run(&MeshArgs::parse())
}
