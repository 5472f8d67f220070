//! Diagnostics as data, rendered at the edge.
//!
//! A [`Diagnostic`] is a plain value: a stable [`Code`], a [`Severity`], a primary byte
//! span, secondary [`Label`]s, a message, optional help and an optional [`Fix`]. Stages
//! that find problems (lexer, parser, checker) build them; the [`render`] module turns
//! them into text for people (ariadne) or for machines (JSON, SARIF 2.1.0, GitHub
//! workflow annotations, GitLab Code Quality). Spans are byte ranges everywhere;
//! [`LineIndex`] turns them into
//! 1-based lines and character columns only when rendering.

mod line_index;
pub mod render;

pub use line_index::{LineCol, LineIndex};
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

/// [`apply_fixes`], with the number of fixes it applied. In time `n log n` in the fixes:
/// the edits taken are kept by where they start, and an edit can only overlap the one
/// taken that starts last at or before it, or the one that starts first after it (the
/// edits taken never overlap one another).
pub fn apply_fixes_counted(
    source: &str,
    diagnostics: &[Diagnostic],
    level: Applicability,
) -> (String, usize) {
    let mut edits: Vec<&Edit> = Vec::new();
    // Where each run of edits taken starts, and where the furthest of them ends.
    let mut taken: std::collections::BTreeMap<usize, usize> = std::collections::BTreeMap::new();
    let mut applied = 0;
    for fix in diagnostics.iter().filter_map(|d| d.fix.as_ref()) {
        if level == Applicability::Safe && fix.applicability == Applicability::Unsafe {
            continue;
        }
        let overlaps = fix.edits.iter().any(|e| overlaps_taken(&taken, e));
        if !overlaps {
            for e in &fix.edits {
                let end = taken.entry(e.span.start).or_insert(e.span.end);
                *end = (*end).max(e.span.end);
            }
            edits.extend(fix.edits.iter());
            applied += 1;
        }
    }
    (splice(source, edits), applied)
}

/// `source` with `edits` (which do not overlap) made.
fn splice(source: &str, mut edits: Vec<&Edit>) -> String {
    edits.sort_by_key(|e| (e.span.start, e.span.end));
    let mut out = String::with_capacity(source.len());
    let mut at = 0;
    for e in edits {
        out.push_str(&source[at..e.span.start]);
        out.push_str(&e.replacement);
        at = e.span.end;
    }
    out.push_str(&source[at..]);
    out
}

/// Whether `e` conflicts with an edit `taken` holds (start to end): two edits conflict
/// when their ranges share a byte, or both start at one place.
fn overlaps_taken(taken: &std::collections::BTreeMap<usize, usize>, e: &Edit) -> bool {
    let Range { start, end } = e.span;
    let before = taken.range(..=start).next_back();
    let after = taken.range(start + 1..).next();
    before.is_some_and(|(&s, &t_end)| s == start || start < t_end)
        || after.is_some_and(|(&s, _)| s < end)
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
        let diagnostics = [
            fixed(0..1, Applicability::Safe, "A"),
            fixed(0..2, Applicability::Safe, "overlaps the first"),
            fixed(2..3, Applicability::Unsafe, "C"),
            fixed(3..3, Applicability::Safe, "+"),
        ];
        assert_eq!(
            apply_fixes_counted("abc", &diagnostics, Applicability::Safe),
            ("Abc+".to_string(), 2)
        );
        assert_eq!(
            apply_fixes_counted("abc", &diagnostics, Applicability::Unsafe),
            ("AbC+".to_string(), 3)
        );
        assert_eq!(
            apply_fixes("abc", &diagnostics, Applicability::Safe),
            "Abc+"
        );
    }

    /// Two edits conflict when their ranges share a byte, or both insert at one place:
    /// the rule, edit against edit.
    fn edits_overlap(a: &Edit, b: &Edit) -> bool {
        (a.span.start < b.span.end && b.span.start < a.span.end) || a.span.start == b.span.start
    }

    /// What was applied before, comparing each fix with every edit taken.
    fn quadratic(source: &str, diagnostics: &[Diagnostic]) -> (String, usize) {
        let mut edits: Vec<&Edit> = Vec::new();
        let mut applied = 0;
        for fix in diagnostics.iter().filter_map(|d| d.fix.as_ref()) {
            let overlaps = fix
                .edits
                .iter()
                .any(|e| edits.iter().any(|t| edits_overlap(e, t)));
            if !overlaps {
                edits.extend(fix.edits.iter());
                applied += 1;
            }
        }
        (splice(source, edits), applied)
    }

    #[test]
    fn the_edits_taken_are_those_the_edit_against_edit_rule_takes() {
        let source = "abcdefghijklmnopqrstuvwxyz".repeat(4);
        // A small generator, the same every run.
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = |n: usize| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % n as u64) as usize
        };
        for _ in 0..200 {
            let diagnostics: Vec<Diagnostic> = (0..40)
                .map(|_| {
                    // One or two edits, each empty or a few bytes, apart from each other.
                    let mut edits = Vec::new();
                    let mut at = next(source.len() - 8);
                    for _ in 0..1 + next(2) {
                        let len = next(4);
                        edits.push(Edit {
                            span: at..at + len,
                            replacement: "+".into(),
                        });
                        at += len + 1 + next(3);
                        if at + 4 > source.len() {
                            break;
                        }
                    }
                    Diagnostic::warning(&CODE, 0..0, "m").with_fix(Applicability::Safe, "f", edits)
                })
                .collect();
            assert_eq!(
                apply_fixes_counted(&source, &diagnostics, Applicability::Safe),
                quadratic(&source, &diagnostics)
            );
        }
    }
}
