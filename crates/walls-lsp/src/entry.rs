//! `walls-lsp`'s command line ([`Args`]) and [`entry`], the server as a function from
//! argv to exit status, so that a program that embeds it (a Python wheel) runs it in its
//! own process; the binary is one call of it.

use clap::{CommandFactory, Parser};
use clap_complete::Shell;
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
    /// Print the completion script for SHELL to standard output and exit.
    #[arg(long, value_name = "SHELL", exclusive = true)]
    pub completions: Option<Shell>,
}

/// Runs the server with the command line `argv` (argv\[0] is the program's name) until
/// the client exits; the exit status: 0, or 2 for a command line clap refuses (its
/// message printed to standard error) or a server that could not start. `--help`,
/// `--version` and `--completions SHELL` print to standard output and return 0.
pub fn entry(argv: Vec<OsString>) -> i32 {
    let args = match Args::try_parse_from(argv) {
        Ok(args) => args,
        Err(e) => {
            // A closed stream leaves nobody to tell; the status still says what happened.
            let _ = e.print();
            return e.exit_code();
        }
    };
    let done = match args.completions {
        Some(shell) => {
            let mut script = Vec::new();
            clap_complete::generate(shell, &mut Args::command(), "walls-lsp", &mut script);
            let mut out = std::io::stdout().lock();
            match out.write_all(&script).and_then(|()| out.flush()) {
                Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
                written => written,
            }
        }
        None => crate::serve_stdio(),
    };
    match done {
        Ok(()) => 0,
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "walls-lsp: {e}");
            2
        }
    }
}
