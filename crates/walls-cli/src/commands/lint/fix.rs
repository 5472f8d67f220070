//! `walls-lint --fix`, `--unsafe-fixes` and `--diff`: applying the fixes the diagnostics
//! carry (docs/diagnostics.md, "Fixing").
//!
//! The fixes of the level asked for (safe ones; unsafe ones too with `--unsafe-fixes`) are
//! applied in rounds, each new text checked again ([`walls_ide::fix_rounds`], the rounds
//! the editor's "fix all" makes too). The diagnostics reported are those of the fixed text.
//!
//! A file is replaced through [`walls_output::replace`], as walls-fmt replaces one (kept
//! owner, group, mode and links, atomic, never over an edit made meanwhile); a file not
//! written is reported with the diagnostics of its unchanged text and an error. Standard input's fixed text goes to
//! standard output. `--diff` writes nothing: it prints what the fixes would change.

use super::{Format, Language, LintArgs, Linted, Report, plural};
use crate::commands::fmt::unified_diff;
use crate::input;
use clap::ValueEnum;
use std::io::Write;
use std::path::Path;
use walls_diagnostics::{Applicability, Diagnostic};
use walls_ide::fix_rounds;
use walls_model::Options;

/// What the command line asks of the fixes.
#[derive(Clone, Copy)]
pub(super) struct Fixing {
    /// Safe fixes only, or unsafe ones too.
    pub level: Applicability,
    /// Print a diff instead of writing.
    pub diff: bool,
}

impl Fixing {
    /// The fixing `args` ask for, if any: `--fix`, `--unsafe-fixes` or `--diff`.
    pub(super) fn asked(args: &LintArgs) -> Option<Fixing> {
        (args.fix || args.unsafe_fixes || args.diff).then_some(Fixing {
            level: if args.unsafe_fixes {
                Applicability::Unsafe
            } else {
                Applicability::Safe
            },
            diff: args.diff,
        })
    }

    /// Why fixing `files` cannot be reported in `format`: standard input's fixed text
    /// and a machine format's report would both go to standard output.
    pub(super) fn output_clash(self, format: Format, files: &[String]) -> Option<String> {
        let machine = !matches!(format, Format::Human);
        (machine && !self.diff && files.iter().any(|f| f == "-")).then(|| {
            let format = format.to_possible_value().map(|v| v.get_name().to_string());
            format!(
                "--fix on standard input writes the fixed text to standard output, where \
                 --format {} writes its report too: use --format human (it goes to standard \
                 error) or --diff",
                format.unwrap_or_default()
            )
        })
    }
}

/// What fixing one file did.
#[derive(Default)]
pub(super) struct FileFixes {
    /// How many fixes were applied (with `--diff`: would be).
    pub fixed: usize,
    /// What goes to standard output: the diff, or standard input's fixed text.
    pub output: Option<String>,
    /// Why the fixed file could not be written.
    pub not_written: Option<String>,
}

/// Reads the file at `path` (`-`: standard input), checks it in its `language` (`keep`
/// drops the diagnostics its settings ignore, after every check), applies its fixes as
/// `fixing` says and writes the result (or makes its diff).
pub(super) fn lint(
    path: &str,
    language: &Language,
    keep: &dyn Fn(&mut Vec<Diagnostic>),
    fixing: Fixing,
) -> (Linted, FileFixes) {
    let (name, read) = if path == "-" {
        let read = input::read(path);
        (read.name, read.bytes.map(|bytes| (None, bytes)))
    } else {
        let read = walls_output::replace::read(Path::new(path), input::MAX_FILE_BYTES);
        (
            path.to_string(),
            read.map(|(file, bytes)| (Some(file), bytes)),
        )
    };
    let (file, bytes) = match read {
        Ok(read) => read,
        Err(e) => {
            let outcome = Err(e);
            return (Linted::new(name, outcome), FileFixes::default());
        }
    };
    // Bytes that are not UTF-8 give only the encoding error, which has no fix: such a file
    // is never written.
    let mut checked = language.check_bytes(bytes);
    keep(&mut checked.diagnostics);
    let after = fix(&checked, language, keep, fixing.level);
    let mut fixes = FileFixes {
        fixed: after.as_ref().map_or(0, |(_, fixed)| *fixed),
        ..FileFixes::default()
    };
    let kept = if fixing.diff {
        fixes.output = after.map(|(after, _)| unified_diff(&name, &checked.text, &after.text));
        checked
    } else if let Some(file) = file {
        match after.map(|(after, _)| (file.replace(after.text.as_bytes()), after)) {
            None => checked,
            Some((Ok(()), after)) => after,
            Some((Err(e), _)) => {
                fixes.fixed = 0;
                fixes.not_written = Some(e.message(path, walls_output::Tool::FIX));
                checked
            }
        }
    } else {
        let after = after.map_or(checked, |(after, _)| after);
        fixes.output = Some(after.text.to_string());
        after
    };
    let outcome = Ok((kept.text, kept.diagnostics));
    (Linted::new(name, outcome), fixes)
}

/// The text of `first` with the fixes of `level` applied ([`fix_rounds`]), each new text
/// checked in `language` less what `keep` drops, and how many fixes were applied; `None`
/// if there was nothing to apply.
fn fix(
    first: &Report,
    language: &Language,
    keep: &dyn Fn(&mut Vec<Diagnostic>),
    level: Applicability,
) -> Option<(Report, usize)> {
    fix_rounds(first, level, &|text| {
        let mut checked = language.check_text(text);
        keep(&mut checked.diagnostics);
        checked
    })
}

/// The text `walls-lint --fix` (with `Unsafe`: `--unsafe-fixes`) makes of `text` with no
/// settings file, and how many fixes it applied: the same rounds as a file's.
pub fn fix_text(text: &str, options: &Options, level: Applicability) -> (String, usize) {
    let language = Language::Walls(options.clone());
    let checked = language.check_text(text.to_string());
    match fix(&checked, &language, &|_| {}, level) {
        Some((fixed, count)) => (fixed.text.to_string(), count),
        None => (text.to_string(), 0),
    }
}

/// Writes to standard output what fixing gave for it, file after file: the diffs, or
/// standard input's fixed text.
pub(super) fn write_outputs(fixes: &[FileFixes]) -> std::io::Result<()> {
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    for text in fixes.iter().filter_map(|f| f.output.as_deref()) {
        out.write_all(text.as_bytes())?;
    }
    out.flush()
}

/// `--diff`'s summary on standard error: how many fixes the diffs hold, in how many files.
pub(super) fn write_diff_summary(fixes: &[FileFixes]) -> std::io::Result<()> {
    let fixed: usize = fixes.iter().map(|f| f.fixed).sum();
    let files = fixes.iter().filter(|f| f.fixed > 0).count();
    writeln!(
        std::io::stderr().lock(),
        "{fixed} fix{} would be applied to {files} file{}",
        if fixed == 1 { "" } else { "es" },
        plural(files)
    )
}
