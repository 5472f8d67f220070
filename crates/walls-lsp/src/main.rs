//! `walls-lsp`: the walls language server over standard input and output.

use clap::Parser;
use std::process::ExitCode;

/// The walls language server: speaks LSP over standard input and output (editors start
/// it; see docs/editors.md).
#[derive(Parser)]
#[command(version, about)]
struct Args {
    /// Talk over standard input and output (the only way, and the default; accepted
    /// because editors pass it).
    #[arg(long)]
    stdio: bool,
}

fn main() -> ExitCode {
    Args::parse();
    match walls_lsp::serve_stdio() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("walls-lsp: {e}");
            ExitCode::from(2)
        }
    }
}
