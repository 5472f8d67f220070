//! `walls-lsp`'s command line ([`Args`]) and [`entry`], the server as a function from
//! argv to exit status, so that a program that embeds it (a Python wheel) runs it in its
//! own process; the binary is one call of it.

use clap::Parser;
use std::ffi::OsString;
use std::io::Write;

/// The walls language server: speaks LSP over standard input and output (editors start
/// it; see docs/editors.md).
#[derive(Parser)]
#[command(name = "walls-lsp", version, about)]
pub struct Args {
    /// Talk over standard input and output (the only way, and the default; accepted
    /// because editors pass it).
    #[arg(long)]
    pub stdio: bool,
}

/// Runs the server with the command line `argv` (argv\[0] is the program's name) until
/// the client exits; the exit status: 0, or 2 for a command line clap refuses (its
/// message printed to standard error) or a server that could not start. `--help` and
/// `--version` print to standard output and return 0.
pub fn entry(argv: Vec<OsString>) -> i32 {
    if let Err(e) = Args::try_parse_from(argv) {
        // A closed stream leaves nobody to tell; the status still says what happened.
        let _ = e.print();
        return e.exit_code();
    }
    match crate::serve_stdio() {
        Ok(()) => 0,
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "walls-lsp: {e}");
            2
        }
    }
}
