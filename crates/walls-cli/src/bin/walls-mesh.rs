//! `walls-mesh`: an STL or OBJ mesh as pkdgrav triangle walls (docs/meshes.md;
//! [`walls_cli::commands::mesh`], run by [`walls_cli::entry::mesh`]).

#![deny(clippy::print_stdout, clippy::print_stderr)]

use std::process::ExitCode;

fn main() -> ExitCode {
    ExitCode::from(walls_cli::entry::mesh(std::env::args_os().collect()) as u8)
}
