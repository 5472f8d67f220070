//! `walls-fmt`: rewrite walls files in the canonical layout (docs/formatting.md).
//!
//! Files are rewritten in place, atomically (a temporary file beside the original,
//! given the original's permissions, then renamed over it): a crash or a kill mid-write
//! leaves the original. `-` formats standard input to standard output. `--check` lists
//! the files that would change and `--diff` shows how, without writing. Exit status: 0
//! success, 1 a file would change (`--check`, `--diff`) or has syntax errors that
//! prevent formatting, 2 usage or I/O error.

use crate::input;
use clap::Parser;
use rayon::prelude::*;
use std::io::{Read, Write};
use std::path::Path;
use std::process::ExitCode;
use walls_diagnostics::render::{self, FileReport};
use walls_format::{FormatOptions, discover};

/// The command line of `walls-fmt`.
#[derive(Parser)]
#[command(
    name = "walls-fmt",
    version,
    about = "Rewrite pkdgrav walls files in the canonical layout, keeping every comment and number.",
    after_help = "Options come from the nearest .walls-fmt.toml above each file (for -, above the current directory); flags override it.\nExit status: 0 success, 1 a file would change (--check, --diff) or could not be formatted, 2 usage or I/O error."
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
    Failed(String),
}

/// Formats the files `args` name and reports on them; the exit status.
pub fn run(args: &FmtArgs) -> ExitCode {
    let outcomes: Vec<(String, Outcome)> = args
        .files
        .par_iter()
        .map(|f| (display(f), format_one(f, args)))
        .collect();
    let color = crate::console::color_stderr();
    let mut err = std::io::BufWriter::new(std::io::stderr().lock());
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let (mut changed, mut unchanged, mut broken, mut failed) = (0, 0, 0, 0);
    for (name, outcome) in &outcomes {
        // Standard error is for people: if it is gone there is nobody to tell.
        let _ = match outcome {
            Outcome::Unchanged => {
                unchanged += 1;
                Ok(())
            }
            Outcome::Changed { diff } => {
                changed += 1;
                match diff {
                    Some(d) => write!(out, "{d}"),
                    None if args.check => writeln!(err, "would reformat {name}"),
                    None => Ok(()),
                }
            }
            Outcome::NotFormatted { text, report } => {
                broken += 1;
                let file = FileReport {
                    path: name,
                    source: text,
                    diagnostics: report,
                };
                render::human(&mut err, &file, color).and_then(|()| {
                    writeln!(err, "walls-fmt: {name} has syntax errors: not formatted")
                })
            }
            Outcome::Failed(e) => {
                failed += 1;
                writeln!(err, "walls-fmt: error: {e}")
            }
        };
    }
    let verb = if args.check || args.diff {
        "would be reformatted"
    } else {
        "reformatted"
    };
    let _ = writeln!(
        err,
        "{changed} file{} {verb}, {unchanged} unchanged{}",
        if changed == 1 { "" } else { "s" },
        if broken > 0 {
            format!(", {broken} not formatted")
        } else {
            String::new()
        }
    );
    if out.flush().is_err() || err.flush().is_err() {
        return ExitCode::from(2);
    }
    if failed > 0 {
        ExitCode::from(2)
    } else if broken > 0 || ((args.check || args.diff) && changed > 0) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

fn display(path: &str) -> String {
    if path == "-" {
        "<stdin>".into()
    } else {
        path.into()
    }
}

/// Formats one file (or standard input) as the arguments ask.
fn format_one(path: &str, args: &FmtArgs) -> Outcome {
    let stdin = path == "-";
    let dir = if stdin {
        std::env::current_dir().unwrap_or_default()
    } else {
        Path::new(path)
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or_default()
    };
    let dir = if dir.as_os_str().is_empty() {
        ".".into()
    } else {
        dir
    };
    let options = match discover(&dir) {
        Ok((options, _)) => override_with(options, args),
        Err(e) => return Outcome::Failed(e.to_string()),
    };
    let read = if stdin {
        let mut bytes = Vec::new();
        std::io::stdin()
            .lock()
            .take(input::MAX_FILE_BYTES + 1)
            .read_to_end(&mut bytes)
            .map(|_| bytes)
            .map_err(|e| format!("cannot read standard input: {e}"))
    } else {
        input::read(path).bytes
    };
    let bytes = match read {
        Ok(b) => b,
        Err(e) => return Outcome::Failed(e),
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
    if stdin && !args.check && !args.diff {
        let mut out = std::io::stdout().lock();
        return match out
            .write_all(formatted.as_bytes())
            .and_then(|()| out.flush())
        {
            Ok(()) if formatted == text => Outcome::Unchanged,
            Ok(()) => Outcome::Changed { diff: None },
            Err(e) => Outcome::Failed(format!("cannot write standard output: {e}")),
        };
    }
    if formatted == text {
        return Outcome::Unchanged;
    }
    if args.diff {
        let name = display(path);
        let diff = similar::TextDiff::from_lines(&text, &formatted)
            .unified_diff()
            .header(&name, &name)
            .to_string();
        return Outcome::Changed { diff: Some(diff) };
    }
    if args.check {
        return Outcome::Changed { diff: None };
    }
    match write_atomically(Path::new(path), &formatted) {
        Ok(()) => Outcome::Changed { diff: None },
        Err(e) => Outcome::Failed(format!("cannot write {path}: {e}")),
    }
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

/// Replaces `path` with `text`: a temporary file in the same folder, with the original's
/// permissions, renamed over it, so that the original survives any failure before that.
/// A symbolic link is followed: its target is rewritten and the link stays.
fn write_atomically(path: &Path, text: &str) -> std::io::Result<()> {
    let path = &std::fs::canonicalize(path)?;
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let permissions = std::fs::metadata(path)?.permissions();
    let mut tmp = tempfile::Builder::new()
        .prefix(".walls-fmt")
        .tempfile_in(dir)?;
    tmp.write_all(text.as_bytes())?;
    tmp.as_file().sync_all()?;
    tmp.as_file().set_permissions(permissions)?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}
