//! Renderers: turn [`Diagnostic`]s into text for people and for machines.
//!
//! Every renderer takes one or more [`FileReport`]s (a path, its text and the
//! diagnostics found in it) and produces one output format:
//!
//! * [`human`]: ariadne reports with source snippets, for terminals;
//! * [`json`]: the `walls-lint --format json` object of the command-line contract;
//! * [`sarif`]: a SARIF 2.1.0 log for code-scanning services;
//! * [`github`]: GitHub Actions workflow commands (`::error file=…::…`);
//! * [`gitlab`]: a GitLab Code Quality report (a JSON array of issues).
//!
//! The machine formats also report the files that could not be read ([`Unreadable`]).
//!
//! Text from the input (a path, a message quoting a token) never reaches a terminal as
//! it is: [`human`] and [`github`] show every hazard ([`crate::terminal`]) as its escape
//! (`\x1b`), and the JSON formats ([`json`], [`sarif`], [`gitlab`]) write it as a JSON
//! escape (`\u001b`), which any reader reads back as the character.
//!
//! The machine formats ([`json`], [`sarif`], [`github`], [`gitlab`]) write straight to a
//! [`std::io::Write`] as they go, without building the whole output in memory first;
//! give them a buffered writer.
//!
//! Spans are byte ranges; renderers clamp them to the text (and to character
//! boundaries) first, so a span past the end never panics. Lines and columns are
//! 1-based and columns count characters, as [`LineIndex::line_col`] computes them.

mod github;
mod gitlab;
mod human;
mod json;
mod safe_json;
mod sarif;

pub use github::github;
pub use gitlab::gitlab;
pub use human::human;
pub use json::json;
pub use sarif::sarif;

use crate::{Diagnostic, LineIndex, Severity};
use std::borrow::Cow;
use std::ops::Range;

/// One file's diagnostics with its text.
#[derive(Debug, Clone, Copy)]
pub struct FileReport<'a> {
    /// The path as the user gave it (`-` for standard input).
    pub path: &'a str,
    /// The full text the diagnostics' spans refer to.
    pub source: &'a str,
    /// The findings, in the order they should be shown.
    pub diagnostics: &'a [Diagnostic],
}

/// A file that could not be read: the machine formats report it (JSON: a file entry
/// with an `error`; SARIF: a tool execution notification; GitHub: an `::error` line;
/// GitLab: a `blocker` issue).
#[derive(Debug, Clone, Copy)]
pub struct Unreadable<'a> {
    /// The path as the user gave it.
    pub path: &'a str,
    /// Why it could not be read, for people.
    pub error: &'a str,
    /// The line of the file the error is about (a `.par` file's line naming a file not
    /// followed), if any.
    pub line: Option<usize>,
}

/// Name, version and docs address of the tool, for SARIF.
#[derive(Debug, Clone, Copy)]
pub struct ToolInfo<'a> {
    /// The tool's name, such as `walls-lint`.
    pub name: &'a str,
    /// The tool's version, such as `0.1.0`.
    pub version: &'a str,
    /// Absolute URI of its documentation, when it has a public home.
    pub information_uri: Option<&'a str>,
}

/// How many diagnostics of each severity a set of reports holds.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Summary {
    /// Number of [`Severity::Error`] diagnostics.
    pub errors: usize,
    /// Number of [`Severity::Warning`] diagnostics.
    pub warnings: usize,
    /// Number of [`Severity::Info`] diagnostics.
    pub infos: usize,
}

impl Summary {
    /// Counts one diagnostic of the given severity.
    pub fn add(&mut self, severity: Severity) {
        match severity {
            Severity::Error => self.errors += 1,
            Severity::Warning => self.warnings += 1,
            Severity::Info => self.infos += 1,
        }
    }
}

/// Counts the diagnostics of every file by severity.
pub fn summarize(files: &[FileReport]) -> Summary {
    let mut summary = Summary::default();
    for d in files.iter().flat_map(|f| f.diagnostics) {
        summary.add(d.severity);
    }
    summary
}

/// Clamps `span` to `source`: both ends at most the length, the start moved back and
/// the end moved forward to character boundaries; a span that was empty or reversed
/// becomes empty at its (adjusted) start.
pub(crate) fn clamp_span(source: &str, span: &Range<usize>) -> Range<usize> {
    let mut start = span.start.min(source.len());
    while !source.is_char_boundary(start) {
        start -= 1;
    }
    let mut end = span.end.min(source.len());
    if end <= start || span.end <= span.start {
        return start..start;
    }
    while !source.is_char_boundary(end) {
        end += 1;
    }
    start..end
}

/// A span as 1-based lines and character columns; the end column is exclusive.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Region {
    pub line: usize,
    pub column: usize,
    pub end_line: usize,
    pub end_column: usize,
}

impl Region {
    /// The region of `span` (clamped first) in `source`.
    pub(crate) fn of(index: &LineIndex, source: &str, span: &Range<usize>) -> Self {
        let span = clamp_span(source, span);
        let start = index.line_col(source, span.start);
        let end = index.line_col(source, span.end);
        Region {
            line: start.line,
            column: start.column,
            end_line: end.line,
            end_column: end.column,
        }
    }
}

/// Diagnostic message followed by its help (if any) on a new line; borrowed when
/// there is no help.
pub(crate) fn message_with_help(d: &Diagnostic) -> Cow<'_, str> {
    match &d.help {
        Some(help) => Cow::Owned(format!("{}\n{help}", d.message)),
        None => Cow::Borrowed(&d.message),
    }
}

#[cfg(test)]
pub(crate) mod test_support {
    //! Hand-built diagnostics shared by the renderer tests.

    use crate::{Applicability, Code, Diagnostic, Edit, Severity};

    pub static UNKNOWN_WORD: Code = Code {
        id: "S101",
        name: "unknown-word",
        summary: "A word that is not a walls keyword.",
        explanation: "pkdgrav stops at words it does not know.\n\nBad:\n```walls\nfoo\n```\n\nGood:\n```walls\nplane\n```\n",
    };

    pub static MISSING_VALUE: Code = Code {
        id: "S102",
        name: "missing-value",
        summary: "A token without its value.",
        explanation: "Every token needs a value.",
    };

    pub static SHAPE: Code = Code {
        id: "C201",
        name: "degenerate-shape",
        summary: "A wall with no area.",
        explanation: "A wall of zero size never touches anything.",
    };

    /// Three lines, a `μ` before the first span, no final newline.
    pub const SOURCE: &str = "# μ wall\nplane origin 0,0,0 colr 3\ndisk radius";

    pub fn diagnostics() -> Vec<Diagnostic> {
        let colr = SOURCE.find("colr").unwrap();
        let plane = SOURCE.find("plane").unwrap();
        let wall = SOURCE.find("wall").unwrap();
        vec![
            // Line 2: a help, a secondary label and an unsafe fix.
            Diagnostic::error(&UNKNOWN_WORD, colr..colr + 4, "unknown word `colr`")
                .with_label(plane..plane + 5, "in this plane")
                .with_help("did you mean `color`?")
                .with_fix(
                    Applicability::Unsafe,
                    "replace with `color`",
                    vec![Edit {
                        span: colr..colr + 4,
                        replacement: "color".into(),
                    }],
                ),
            // `wall` after `μ` on line 1: byte column 6, character column 5.
            Diagnostic::new(
                &SHAPE,
                Severity::Info,
                wall..wall + 4,
                "comment, says 50% \"wall\", a:b",
            ),
            // Empty span at the end of a file without final newline: something missing.
            Diagnostic::error(
                &MISSING_VALUE,
                SOURCE.len()..SOURCE.len(),
                "missing value for `radius`",
            )
            .with_fix(
                Applicability::Safe,
                "insert a value",
                vec![Edit {
                    span: SOURCE.len()..SOURCE.len(),
                    replacement: " 1".into(),
                }],
            ),
            // A span over several lines.
            Diagnostic::warning(&SHAPE, plane..SOURCE.len(), "these walls\nhave no area"),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::test_support::{SOURCE, diagnostics};
    use super::*;

    #[test]
    fn clamping() {
        let s = "aμb";
        assert_eq!(clamp_span(s, &(0..99)), 0..4);
        assert_eq!(clamp_span(s, &(2..2)), 1..1);
        assert_eq!(clamp_span(s, &(1..2)), 1..3);
        let (start, end) = (3, 1);
        assert_eq!(clamp_span(s, &(start..end)), 3..3);
        assert_eq!(clamp_span(s, &(usize::MAX..usize::MAX)), 4..4);
        let index = LineIndex::new(s);
        let r = Region::of(&index, s, &(1..3));
        assert_eq!((r.line, r.column, r.end_line, r.end_column), (1, 2, 1, 3));
    }

    #[test]
    fn summary_counts_each_severity() {
        let diags = diagnostics();
        let file = FileReport {
            path: "a.walls",
            source: SOURCE,
            diagnostics: &diags,
        };
        let summary = summarize(&[file, file]);
        assert_eq!(
            summary,
            Summary {
                errors: 4,
                warnings: 2,
                infos: 2
            }
        );
    }
}
