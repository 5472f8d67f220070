//! `walls-fmt`: rewrite walls files in the canonical layout (docs/formatting.md).
//!
//! Files are rewritten in place by [`walls_output::replace`]: only files the user may write, keeping
//! owner, group, mode and hard links, never over an edit made meanwhile, and atomically (a
//! crash or a kill mid-write leaves the original). A file named twice (by any path) is
//! formatted once. `-` formats standard input to standard output. `--check` lists the
//! files that would change and `--diff` shows how, without writing. The report (the files
//! that would change or cannot be formatted, and the summary) goes to standard output, or
//! to standard error when `-` is among the files; the tool's own errors to standard error. Exit status: 0
//! success, 1 a file would change (`--check`, `--diff`) or has syntax errors that prevent
//! formatting, 2 usage or I/O error, or a file not written.

use super::settings::{Resolver, SettingsArgs};
use crate::input;
use clap::Parser;
use rayon::prelude::*;
use std::collections::HashSet;
use std::io::Write;
use std::os::unix::fs::MetadataExt;
use std::path::Path;
use walls_diagnostics::render::{self, FileReport};
use walls_format::FormatOptions;

/// The command line of `walls-fmt`.
#[derive(Parser)]
#[command(
    name = "walls-fmt",
    version,
    about = "Rewrite pkdgrav walls files in the canonical layout, keeping every comment and number.",
    after_help = "Options come from the nearest walls.toml, .walls.toml, pyproject.toml [tool.walls] ([format] table) or .walls-fmt.toml above each file (for -, above the current directory); flags override them (docs/configuration.md).\nExit status: 0 success, 1 a file would change (--check, --diff) or could not be formatted, 2 usage or I/O error, or a file not written (read-only, not yours, hard-linked or changed meanwhile: see docs/formatting.md)."
)]
pub struct FmtArgs {
    /// Files to format in place; `-` formats standard input to standard output.
    #[arg(required = true, value_name = "FILE")]
    pub files: Vec<String>,
    /// Write nothing; list the files that would change and exit 1 if any would.
    #[arg(long)]
    pub check: bool,
    /// Write nothing; print a unified diff of what would change and exit 1 if anything would.
    #[arg(long)]
    pub diff: bool,
    /// Spaces before a statement inside a block.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u8).range(0..=16))]
    pub indent_width: Option<u8>,
    /// Line up the comments after consecutive statements of a block.
    #[arg(long, value_name = "BOOL", num_args = 0..=1, default_missing_value = "true")]
    pub align_trailing_comments: Option<bool>,
    /// Keep one of the blank lines the author wrote between statements.
    #[arg(long, value_name = "BOOL", num_args = 0..=1, default_missing_value = "true")]
    pub keep_blank_lines: Option<bool>,
    /// Print the completion script for SHELL to standard output and exit.
    #[arg(long, value_name = "SHELL", exclusive = true)]
    pub completions: Option<clap_complete::Shell>,
    /// Where the settings come from.
    #[command(flatten)]
    pub settings: SettingsArgs,
}

/// What happened to one file.
enum Outcome {
    Unchanged,
    Changed {
        diff: Option<String>,
    },
    NotFormatted {
        text: String,
        report: Vec<walls_diagnostics::Diagnostic>,
    },
    /// The file (or its `.walls-fmt.toml`) could not be read.
    Unreadable(String),
    /// The file was formatted but not written: refused, or the write failed.
    NotWritten(String),
}

/// Where walls-fmt's report goes (standard output, or standard error beside standard
/// input's formatted text), and the first write to standard output that failed: after it
/// nothing more is written, and the status is 2.
struct Report {
    to_stdout: bool,
    failed: Option<std::io::Error>,
}

impl Report {
    /// Lets `write` write to standard output through a buffer.
    fn stdout(&mut self, write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>) {
        if self.failed.is_none() {
            let mut w = std::io::BufWriter::new(std::io::stdout().lock());
            if let Err(e) = write(&mut w).and_then(|()| w.flush()) {
                self.failed = Some(e);
            }
        }
    }

    /// Lets `write` write to the report's stream.
    fn report(&mut self, write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>) {
        if self.to_stdout {
            self.stdout(write);
        } else {
            let mut w = std::io::BufWriter::new(std::io::stderr().lock());
            // Standard error is for people: if it is gone there is nobody to tell.
            let _ = write(&mut w).and_then(|()| w.flush());
        }
    }

    /// A line of the report, its hazards escaped.
    fn say(&mut self, line: std::fmt::Arguments<'_>) {
        let text = crate::console::escaped(format_args!("{line}\n"));
        self.report(|w| w.write_all(text.as_bytes()));
    }
}

/// Formats the files `args` name and reports on them; the exit status.
pub fn run(args: &FmtArgs) -> i32 {
    let resolver = match Resolver::new(&args.settings) {
        Ok(resolver) => resolver,
        Err(e) => {
            crate::errln!("walls-fmt: error: {e}");
            return 2;
        }
    };
    let outcomes: Vec<(String, Outcome)> = distinct(&args.files)
        .par_iter()
        .map(|f| (input::display_name(f), format_one(f, args, &resolver)))
        .collect();
    // What the files are found to be (would change, cannot be formatted, the summary) is
    // the report, on standard output; standard input's formatted text takes standard
    // output when `-` is among the files, and the report goes to standard error then.
    let to_stdout = !args.files.iter().any(|f| f == "-");
    let mut out = Report {
        to_stdout,
        failed: None,
    };
    let color = if to_stdout {
        crate::console::color_stdout()
    } else {
        crate::console::color_stderr()
    };
    let (mut changed, mut unchanged, mut broken) = (0, 0, 0);
    let (mut unreadable, mut unwritten) = (0, 0);
    for (name, outcome) in &outcomes {
        match outcome {
            Outcome::Unchanged => unchanged += 1,
            Outcome::Changed { diff } => {
                changed += 1;
                match diff {
                    // Escaped where it was made (`unified_diff`).
                    Some(d) => out.stdout(|w| w.write_all(d.as_bytes())),
                    None if args.check => out.say(format_args!("would reformat {name}")),
                    None => {}
                }
            }
            Outcome::NotFormatted { text, report } => {
                broken += 1;
                let file = FileReport {
                    path: name,
                    source: text,
                    diagnostics: report,
                };
                out.report(|w| render::human(w, &file, color));
                out.say(format_args!(
                    "walls-fmt: {name} has syntax errors: not formatted"
                ));
            }
            Outcome::Unreadable(e) => {
                unreadable += 1;
                crate::errln!("walls-fmt: error: {e}");
            }
            Outcome::NotWritten(e) => {
                unwritten += 1;
                crate::errln!("walls-fmt: error: {e}");
            }
        }
    }
    let verb = if args.check || args.diff {
        "would be reformatted"
    } else {
        "reformatted"
    };
    let mut summary = format!(
        "{changed} file{} {verb}, {unchanged} unchanged",
        if changed == 1 { "" } else { "s" }
    );
    for (n, what) in [
        (broken, "not formatted"),
        (unreadable, "could not be read"),
        (unwritten, "not written"),
    ] {
        if n > 0 {
            summary.push_str(&format!(", {n} {what}"));
        }
    }
    out.say(format_args!("{summary}"));
    // A report nobody received is no success: its reader gone (`| head`) or its disk
    // full, the status is 2, as walls-lint's.
    if let Some(e) = out.failed {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            crate::errln!("walls-fmt: error: cannot write the report: {e}");
        }
        return 2;
    }
    if unreadable + unwritten > 0 {
        2
    } else if broken > 0 || ((args.check || args.diff) && changed > 0) {
        1
    } else {
        0
    }
}

/// The files of `files` with duplicates left out: the same file named twice, by any path
/// (`a.walls`, `./a.walls`, a symbolic link to it), is formatted and counted once, under
/// its first name. Files that cannot be looked at stay, to be reported.
fn distinct(files: &[String]) -> Vec<&String> {
    let mut seen = HashSet::new();
    files
        .iter()
        .filter(|f| {
            let identity = if *f == "-" {
                Some(None)
            } else {
                std::fs::metadata(f).ok().map(|m| Some((m.dev(), m.ino())))
            };
            identity.is_none_or(|id| seen.insert(id))
        })
        .collect()
}

/// Formats one file (or standard input) as the arguments ask.
fn format_one(path: &str, args: &FmtArgs, resolver: &Resolver) -> Outcome {
    let stdin = path == "-";
    let options = match resolver.format_options(path) {
        Ok(options) => override_with(options, args),
        Err(e) => return Outcome::Unreadable(e.to_string()),
    };
    let read = if stdin {
        input::read(path).bytes.map(|b| (None, b))
    } else {
        walls_output::replace::read(Path::new(path), input::MAX_FILE_BYTES)
            .map(|(o, b)| (Some(o), b))
    };
    let (original, bytes) = match read {
        Ok(read) => read,
        Err(e) => return Outcome::Unreadable(e),
    };
    let text = match walls_syntax::decode(bytes) {
        Ok(t) => t,
        Err((prefix, d)) => {
            return Outcome::NotFormatted {
                text: prefix,
                report: vec![*d],
            };
        }
    };
    let parsed = walls_syntax::parse(text.as_str());
    let formatted = match walls_format::format(&parsed, &options) {
        Ok(f) => f.text,
        Err(e) => {
            return Outcome::NotFormatted {
                text,
                report: e.diagnostics,
            };
        }
    };
    let changed = formatted != text;
    if args.diff && changed {
        let diff = unified_diff(&input::display_name(path), &text, &formatted);
        return Outcome::Changed { diff: Some(diff) };
    }
    let done = if changed {
        Outcome::Changed { diff: None }
    } else {
        Outcome::Unchanged
    };
    if args.check || args.diff {
        return done;
    }
    let Some(original) = original else {
        let mut out = std::io::stdout().lock();
        return match out
            .write_all(formatted.as_bytes())
            .and_then(|()| out.flush())
        {
            Ok(()) => done,
            Err(e) => Outcome::NotWritten(format!("cannot write standard output: {e}")),
        };
    };
    if !changed {
        return done;
    }
    match original.replace(formatted.as_bytes()) {
        Ok(()) => done,
        Err(e) => Outcome::NotWritten(e.message(path, walls_output::Tool::FORMAT)),
    }
}

/// The unified diff from `old` to `new`, the text of the file shown as `name`, for
/// people (walls-fmt's and walls-lint's `--diff`): its hazards are shown as their
/// escapes (`\x1b`, [`walls_diagnostics::terminal`]), so the diff of a file that holds
/// some shows them but does not apply with `patch`.
pub(crate) fn unified_diff(name: &str, old: &str, new: &str) -> String {
    let diff = similar::TextDiff::from_lines(old, new)
        .unified_diff()
        .header(name, name)
        .to_string();
    walls_diagnostics::terminal::escape(&diff).into_owned()
}

fn override_with(mut options: FormatOptions, args: &FmtArgs) -> FormatOptions {
    if let Some(n) = args.indent_width {
        options.indent_width = n.into();
    }
    if let Some(b) = args.align_trailing_comments {
        options.align_trailing_comments = b;
    }
    if let Some(b) = args.keep_blank_lines {
        options.keep_blank_lines = b;
    }
    options
}
