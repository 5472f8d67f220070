//! `walls-lsp`: the walls language server over standard input and output (its command
//! line is [`walls_lsp::entry`]'s).

use std::process::ExitCode;

fn main() -> ExitCode {
    ExitCode::from(walls_lsp::entry(std::env::args_os().collect()) as u8)
}
