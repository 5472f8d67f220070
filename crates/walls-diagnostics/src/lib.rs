//! Diagnostics as data, rendered at the edge.
//!
//! A [`Diagnostic`] is a plain value: a stable [`Code`], a [`Severity`], a primary byte
//! span, secondary [`Label`]s, a message, optional help and an optional [`Fix`]. Stages
//! that find problems (lexer, parser, checker) build them; the [`render`] module turns
//! them into text for people (ariadne) or for machines (JSON, SARIF 2.1.0, GitHub
//! workflow annotations, GitLab Code Quality). Spans are byte ranges everywhere;
//! [`LineIndex`] turns them into
//! 1-based lines and character columns only when rendering. [`terminal`] is the one
//! definition of the characters a terminal would act on, and of how human output shows
//! them.

mod line_index;
pub mod render;
pub mod terminal;

pub use line_index::{LineCol, LineIndex};
use std::collections::BTreeMap;
use std::ops::Range;

/// The most secondary places one diagnostic lists: a mistake repeated over thousands of
/// walls stays one readable report (its message gives the full count).
pub const MAX_LABELS: usize = 10;

/// How serious a finding is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// pkdgrav would reject or misread the file.
    Error,
    /// Legal, but very likely not what the author meant.
    Warning,
    /// Worth knowing; never fails a lint.
    Info,
}

impl Severity {
    /// The lower-case name used by every output format.
    pub const fn as_str(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info => "info",
        }
    }
}

/// A stable diagnostic code with its documentation, defined once by the stage that
/// emits it. The same text serves `--explain`, editor hovers and `docs/diagnostics.md`.
#[derive(Debug, PartialEq, Eq, Hash)]
pub struct Code {
    /// Stable identifier such as `S101`; never reused for another meaning.
    pub id: &'static str,
    /// Kebab-case name such as `unknown-word`.
    pub name: &'static str,
    /// One line saying what the code is about.
    pub summary: &'static str,
    /// Markdown: why it matters, then a bad example and a good example, each in a
    /// fenced `walls` code block preceded by a line `Bad:` or `Good:`.
    pub explanation: &'static str,
}

/// A place in a binary file that has no lines: one of its records, such as particle 17 of
/// a pkdgrav `.ss` file. A diagnostic there keeps the record's bytes as its span; every
/// renderer shows the record (`particle 17`) where a text file's place would be its line
/// and column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Record {
    /// What the file's records are, singular: `particle`.
    pub kind: &'static str,
    /// The record's index in the file, from 0.
    pub index: usize,
}

impl std::fmt::Display for Record {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} {}", self.kind, self.index)
    }
}

/// A secondary span with a note, such as "the vector starts here".
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Label {
    /// Byte range in the source.
    pub span: Range<usize>,
    /// What this place has to do with the problem.
    pub message: String,
}

/// Whether a fix may be applied without a person looking at it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Applicability {
    /// Keeps what the author evidently meant; fine to apply automatically.
    Safe,
    /// A guess (a spelling suggestion, say): offer it, never apply it unasked.
    Unsafe,
}

impl Applicability {
    /// The lower-case name used by the machine formats.
    pub const fn as_str(self) -> &'static str {
        match self {
            Applicability::Safe => "safe",
            Applicability::Unsafe => "unsafe",
        }
    }
}

/// Replace the bytes of `span` with `replacement` (an empty span inserts).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Edit {
    /// Byte range to replace.
    pub span: Range<usize>,
    /// The new text.
    pub replacement: String,
}

/// A way to repair the problem: text edits that do not overlap.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Fix {
    /// What the fix does, in the imperative ("insert a space before `#`").
    pub message: String,
    /// Whether it may be applied unasked.
    pub applicability: Applicability,
    /// The edits, in source order.
    pub edits: Vec<Edit>,
}

/// One finding about one place in one file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Diagnostic {
    /// The stable code and its documentation.
    pub code: &'static Code,
    /// How serious it is.
    pub severity: Severity,
    /// Byte range of the exact offending text (empty where something is missing).
    pub span: Range<usize>,
    /// What is wrong, in one sentence.
    pub message: String,
    /// Other places that explain the problem.
    pub labels: Vec<Label>,
    /// How to put it right, when a sentence helps.
    pub help: Option<String>,
    /// An automatic repair, when one exists.
    pub fix: Option<Fix>,
    /// In a binary file, the record it is about (its span is the record's bytes): shown
    /// in place of a line and column.
    pub record: Option<Record>,
}

impl Diagnostic {
    /// An error with no labels, help or fix yet.
    pub fn error(code: &'static Code, span: Range<usize>, message: impl Into<String>) -> Self {
        Self::new(code, Severity::Error, span, message)
    }

    /// A warning with no labels, help or fix yet.
    pub fn warning(code: &'static Code, span: Range<usize>, message: impl Into<String>) -> Self {
        Self::new(code, Severity::Warning, span, message)
    }

    /// A diagnostic of any severity with no labels, help or fix yet.
    pub fn new(
        code: &'static Code,
        severity: Severity,
        span: Range<usize>,
        message: impl Into<String>,
    ) -> Self {
        Diagnostic {
            code,
            severity,
            span,
            message: message.into(),
            labels: Vec::new(),
            help: None,
            fix: None,
            record: None,
        }
    }

    /// Adds a secondary label.
    pub fn with_label(mut self, span: Range<usize>, message: impl Into<String>) -> Self {
        self.labels.push(Label {
            span,
            message: message.into(),
        });
        self
    }

    /// Places it at a record of a binary file (its span the record's bytes).
    pub fn in_record(mut self, kind: &'static str, index: usize) -> Self {
        self.record = Some(Record { kind, index });
        self
    }

    /// Sets the help sentence.
    pub fn with_help(mut self, help: impl Into<String>) -> Self {
        self.help = Some(help.into());
        self
    }

    /// Sets the fix.
    pub fn with_fix(
        mut self,
        applicability: Applicability,
        message: impl Into<String>,
        edits: Vec<Edit>,
    ) -> Self {
        self.fix = Some(Fix {
            message: message.into(),
            applicability,
            edits,
        });
        self
    }
}

/// Applies every fix of the given applicability (and, with `Unsafe`, the safe ones too)
/// whose edits do not overlap an edit already taken; returns the new text.
pub fn apply_fixes(source: &str, diagnostics: &[Diagnostic], level: Applicability) -> String {
    apply_fixes_counted(source, diagnostics, level).0
}

/// [`apply_fixes`], with the number of fixes it applied. A fix whose own edits overlap is
/// malformed and never applied. Linear in the number of edits (up to a logarithm).
pub fn apply_fixes_counted(
    source: &str,
    diagnostics: &[Diagnostic],
    level: Applicability,
) -> (String, usize) {
    // The edits taken, by start (no two share one): end and edit.
    let mut taken: BTreeMap<usize, (usize, &Edit)> = BTreeMap::new();
    let mut applied = 0;
    for fix in diagnostics.iter().filter_map(|d| d.fix.as_ref()) {
        if level == Applicability::Safe && fix.applicability == Applicability::Unsafe {
            continue;
        }
        let mut own: Vec<&Edit> = fix.edits.iter().collect();
        own.sort_by_key(|e| (e.span.start, e.span.end));
        let malformed = own.windows(2).any(|w| edits_overlap(w[0], w[1]));
        if malformed || own.iter().any(|e| overlaps_taken(&taken, e)) {
            continue;
        }
        for e in own {
            taken.insert(e.span.start, (e.span.end, e));
        }
        applied += 1;
    }
    let mut out = String::with_capacity(source.len());
    let mut at = 0;
    for (_, (_, e)) in taken {
        out.push_str(&source[at..e.span.start]);
        out.push_str(&e.replacement);
        at = e.span.end;
    }
    out.push_str(&source[at..]);
    (out, applied)
}

/// Whether `e` conflicts with an edit already taken (see [`edits_overlap`]): the one that
/// starts last at or before it, or one that starts inside it.
fn overlaps_taken(taken: &BTreeMap<usize, (usize, &Edit)>, e: &Edit) -> bool {
    let before = taken
        .range(..=e.span.start)
        .next_back()
        .is_some_and(|(&start, &(end, _))| start == e.span.start || end > e.span.start);
    before
        || (e.span.end > e.span.start + 1
            && taken.range(e.span.start + 1..e.span.end).next().is_some())
}

/// Two edits conflict when their ranges share a byte, or both insert at one place.
fn edits_overlap(a: &Edit, b: &Edit) -> bool {
    (a.span.start < b.span.end && b.span.start < a.span.end) || a.span.start == b.span.start
}

#[cfg(test)]
mod tests {
    use super::*;

    const CODE: Code = Code {
        id: "T001",
        name: "test",
        summary: "a test",
        explanation: "",
    };

    fn fixed(span: Range<usize>, applicability: Applicability, with: &str) -> Diagnostic {
        let edit = Edit {
            span: span.clone(),
            replacement: with.into(),
        };
        Diagnostic::warning(&CODE, span, "m").with_fix(applicability, "f", vec![edit])
    }

    #[test]
    fn fixes_are_counted_the_first_of_overlapping_ones_taken_unsafe_ones_only_if_asked() {
        use Applicability::{Safe, Unsafe};
        // Each case: fixes, level, what is left, how many were applied. Two edits that
        // start at one place conflict (the first wins); one that starts where another
        // ends does not.
        let cases = [
            (
                vec![
                    fixed(0..1, Safe, "A"),
                    fixed(0..2, Safe, "overlaps the first"),
                    fixed(2..3, Unsafe, "C"),
                    fixed(3..3, Safe, "+"),
                ],
                [(Safe, "Abc+", 2), (Unsafe, "AbC+", 3)],
            ),
            (
                vec![
                    fixed(1..2, Safe, "B"),
                    fixed(1..1, Safe, "<"),
                    fixed(2..2, Safe, ">"),
                    fixed(0..3, Safe, "whole"),
                    fixed(2..2, Safe, "again"),
                ],
                [(Safe, "aB>c", 2), (Unsafe, "aB>c", 2)],
            ),
        ];
        for (diagnostics, levels) in cases {
            for (level, left, applied) in levels {
                assert_eq!(
                    apply_fixes_counted("abc", &diagnostics, level),
                    (left.to_string(), applied)
                );
                assert_eq!(apply_fixes("abc", &diagnostics, level), left);
            }
        }
    }

    #[test]
    fn a_fix_whose_own_edits_overlap_is_never_applied() {
        let edit = |span: Range<usize>, with: &str| Edit {
            span,
            replacement: with.into(),
        };
        let malformed = Diagnostic::warning(&CODE, 0..2, "m").with_fix(
            Applicability::Safe,
            "f",
            vec![edit(0..2, "X"), edit(1..3, "Y")],
        );
        let fine = fixed(2..3, Applicability::Safe, "Z");
        assert_eq!(
            apply_fixes_counted("abc", &[malformed, fine], Applicability::Safe),
            ("abZ".to_string(), 1)
        );
    }
}
