//! The tools as functions from a command line to an exit status, so that a program that
//! embeds them (a Python wheel) runs them in its own process: [`lint`], [`fmt`], [`sim`]
//! and [`mesh`] take the whole argv (argv\[0] is the program's name, as in `std::env::args_os`)
//! and return the status the binary exits with. The binaries are one call of these.
//!
//! A command line clap refuses prints clap's message to standard error and returns 2
//! (quoting the arguments with their hazards escaped, `\x1b`: clap would quote them as
//! they are);
//! `--help` and `--version` print to standard output and return 0, as does
//! `--completions SHELL` (the shell's completion script, from the clap definitions).
//! Nothing here ends the process; what the commands share can, as the binaries expect:
//! a standard output closed by its reader ends it with status 0, one that fails with 2
//! ([`crate::console`]), and a signal while `walls-sim run` runs, or while a file is
//! written through a named temporary file, with 128 + the signal ([`walls_output::interrupt`]).

use crate::commands::{self, fmt::FmtArgs, lint::LintArgs, mesh::MeshArgs, sim::SimArgs};
use clap::Parser;
use clap_complete::Shell;
use std::ffi::OsString;
use std::io::Write;
use walls_diagnostics::terminal;

/// `walls-lint` with the command line `argv`; the exit status.
pub fn lint(argv: Vec<OsString>) -> i32 {
    tool::<LintArgs>(argv)
}

/// `walls-fmt` with the command line `argv`; the exit status.
pub fn fmt(argv: Vec<OsString>) -> i32 {
    tool::<FmtArgs>(argv)
}

/// `walls-sim` with the command line `argv`; the exit status.
pub fn sim(argv: Vec<OsString>) -> i32 {
    tool::<SimArgs>(argv)
}

/// `walls-mesh` with the command line `argv`; the exit status.
pub fn mesh(argv: Vec<OsString>) -> i32 {
    tool::<MeshArgs>(argv)
}

/// A tool's command line: what it runs, and the `--completions` every tool has.
trait Tool: Parser {
    /// The shell whose completion script `--completions` asks for.
    fn completions(&self) -> Option<Shell>;
    /// Runs the tool; the exit status.
    fn run(&self) -> i32;
}

impl Tool for LintArgs {
    fn completions(&self) -> Option<Shell> {
        self.completions
    }
    fn run(&self) -> i32 {
        commands::lint::run(self)
    }
}

impl Tool for FmtArgs {
    fn completions(&self) -> Option<Shell> {
        self.completions
    }
    fn run(&self) -> i32 {
        commands::fmt::run(self)
    }
}

impl Tool for SimArgs {
    fn completions(&self) -> Option<Shell> {
        self.completions
    }
    fn run(&self) -> i32 {
        commands::sim::dispatch(self)
    }
}

impl Tool for MeshArgs {
    fn completions(&self) -> Option<Shell> {
        self.completions
    }
    fn run(&self) -> i32 {
        commands::mesh::run(self)
    }
}

/// Parses `argv` as `T`'s command line and runs it, or prints clap's answer, or the
/// completion script; the exit status.
fn tool<T: Tool>(argv: Vec<OsString>) -> i32 {
    // clap quotes a refused argument as it is: the same command line with its hazards
    // escaped is refused the same way, quoting them escaped.
    let escaped: Option<Vec<OsString>> = argv
        .iter()
        .any(|a| terminal::find(&a.to_string_lossy(), 0).is_some())
        .then(|| {
            argv.iter()
                .map(|a| terminal::escape(&a.to_string_lossy()).into_owned().into())
                .collect()
        });
    let args = match T::try_parse_from(argv) {
        Ok(args) => args,
        Err(e) => {
            let shown = match escaped.map(T::try_parse_from) {
                Some(Err(shown)) => shown,
                // Escaped, it parses: clap's plain message (which drops the escape
                // sequences it quoted), through the console, which escapes the rest.
                Some(Ok(_)) => {
                    crate::console::err(format_args!("{}", e.render()));
                    return e.exit_code();
                }
                None => e,
            };
            // A closed stream leaves nobody to tell; the status still says what happened.
            let _ = shown.print();
            return shown.exit_code();
        }
    };
    match args.completions() {
        Some(shell) => completions(shell, T::command()),
        None => args.run(),
    }
}

/// Prints the completion script of `command` for `shell` to standard output; the exit
/// status.
fn completions(shell: Shell, mut command: clap::Command) -> i32 {
    let name = command.get_name().to_string();
    let mut script = Vec::new();
    clap_complete::generate(shell, &mut command, name, &mut script);
    let mut out = std::io::stdout().lock();
    match out.write_all(&script).and_then(|()| out.flush()) {
        Ok(()) => 0,
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => 0,
        Err(e) => {
            crate::errln!("error: cannot write standard output: {e}");
            2
        }
    }
}
