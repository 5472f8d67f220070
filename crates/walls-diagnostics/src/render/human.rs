//! Reports for people: ariadne snippets with the offending source lines.
//!
//! Each diagnostic becomes one ariadne report: a header with the code, severity and
//! message, the primary span labelled with the message, every secondary label, the
//! help, and the fix's description as a note. Spans are byte offsets
//! ([`ariadne::IndexType::Byte`]), clamped to the text before drawing.
//!
//! Time is linear in the text plus the output. The text is indexed once per file, and
//! a report draws only the lines near its labels: labels more than [`GAP`] lines apart
//! are drawn as separate sections of the report (each with its own `file:line:column`),
//! so a label on the first wall does not make every report walk the whole file. A
//! line longer than [`LONG_LINE`] bytes is never printed whole: a report that touches
//! one shows, for each label, a window of its line around the span with `…` where text
//! is cut ([`long`]), so a 10 MB line prints a few hundred bytes per diagnostic.
//!
//! Nothing from the input reaches the terminal as it is: the path, the messages, the
//! help and the notes are shown through [`terminal::escape`], and a report that touches
//! a line holding a hazard (a control character, a bidirectional override:
//! [`crate::terminal`]) is drawn as a long line's is, with each hazard shown as its
//! escape (`\x1b`) and the underline under the escape. ariadne, which would print such a
//! line as it is (and count a vertical tab or a lone carriage return as a line end), is
//! given the text with every hazard blanked, so that its line numbers stay those of
//! [`LineIndex`]. With colour, the only escape sequences written are ariadne's and ours.

use super::{FileReport, clamp_span};
use crate::terminal::{self, escape};
use crate::{Diagnostic, LineIndex, Severity};
use ariadne::{Cache, Color, Config, IndexType, Label, Report, ReportKind, Source};
use std::borrow::Cow;
use std::fmt;
use std::io::{self, Write};
use std::ops::Range;

mod long;

/// Labels at most this many lines apart share one section of a report.
const GAP: usize = 8;

/// Lines longer than this many bytes are shown as a window around each span.
pub(crate) const LONG_LINE: usize = 400;

/// Writes every diagnostic of `file` as an ariadne report, with ANSI colours when
/// `color` is set.
pub fn human(out: &mut dyn Write, file: &FileReport, color: bool) -> io::Result<()> {
    if file.diagnostics.is_empty() {
        // Indexing the lines of a large clean file would cost more than linting it.
        return Ok(());
    }
    let index = LineIndex::new(file.source);
    let (drawn, hazard_lines) = without_hazards(file.source, &index);
    let path = escape(file.path);
    let mut cache = Shared {
        path: &path,
        source: Source::from(&*drawn),
    };
    for d in file.diagnostics {
        if let Some(record) = d.record {
            write_record(out, &path, d, record, color)?;
            continue;
        }
        let labels = labels(file.source, d);
        let lines: Vec<(usize, usize)> = labels
            .iter()
            .map(|l| {
                (
                    index.line_of(l.span.start),
                    index.line_of(l.span.end.saturating_sub(1).max(l.span.start)),
                )
            })
            .collect();
        // Every line ariadne would print: those of each label (no more than it walks).
        let touches_long_line = lines
            .iter()
            .flat_map(|&(first, last)| first..=last)
            .any(|line| line_len(&index, file.source, line) > LONG_LINE);
        let touches_hazard = lines.iter().any(|&(first, last)| {
            let i = hazard_lines.partition_point(|&line| line < first);
            hazard_lines.get(i).is_some_and(|&line| line <= last)
        });
        if touches_long_line || touches_hazard {
            long::write(out, file, &index, d, &labels, color)?;
        } else {
            report(d, &labels, &lines, color).write(&mut cache, &mut *out)?;
        }
    }
    Ok(())
}

/// A diagnostic at a record of a binary file (a `.ss` file's particle), in ariadne's
/// frame: the header, the path with the record where a text's `line:column` would be,
/// each label's message (it names its own record), then help and fix note.
fn write_record(
    out: &mut dyn Write,
    path: &str,
    d: &Diagnostic,
    record: crate::Record,
    color: bool,
) -> io::Result<()> {
    use ariadne::Fmt;
    let (kind, kind_color) = match d.severity {
        Severity::Error => ("Error", Color::Red),
        Severity::Warning => ("Warning", Color::Yellow),
        Severity::Info => ("Advice", Color::Fixed(147)),
    };
    let header = format!("[{}] {kind}:", d.code.id);
    let header = if color {
        header.fg(kind_color).to_string()
    } else {
        header
    };
    writeln!(out, "{header} {}", escape(&d.message))?;
    writeln!(out, "   ╭─[ {path}: {record} ]")?;
    for label in &d.labels {
        writeln!(out, "   │ ")?;
        writeln!(out, "   │ ─ {}", escape(&label.message))?;
    }
    if let Some(help) = &d.help {
        writeln!(out, "   │ ")?;
        writeln!(out, "   │ Help: {}", escape(help))?;
    }
    if let Some(fix) = &d.fix {
        writeln!(out, "   │ ")?;
        writeln!(out, "   │ Note: fix: {}", escape(&fix.message))?;
    }
    writeln!(out, "───╯")
}

/// The text ariadne is given: `source` with every hazard replaced by as many spaces as it
/// has bytes (offsets and line ends stay), borrowed when there is none; and the sorted
/// 0-based lines that hold a hazard, which ariadne does not draw.
fn without_hazards<'s>(source: &'s str, index: &LineIndex) -> (Cow<'s, str>, Vec<usize>) {
    let mut lines: Vec<usize> = Vec::new();
    let mut drawn = String::new();
    let mut at = 0;
    for run in terminal::runs(source) {
        let line = index.line_of(run.start);
        if lines.last() != Some(&line) {
            lines.push(line);
        }
        drawn.push_str(&source[at..run.start]);
        drawn.extend(std::iter::repeat_n(' ', run.len()));
        at = run.end;
    }
    if lines.is_empty() {
        return (Cow::Borrowed(source), lines);
    }
    drawn.push_str(&source[at..]);
    (Cow::Owned(drawn), lines)
}

/// The length in bytes of 0-based `line`, without its line end.
fn line_len(index: &LineIndex, source: &str, line: usize) -> usize {
    let start = index.line_start(line);
    let end = if line + 1 < index.line_count() {
        index.line_start(line + 1) - 1
    } else {
        source.len()
    };
    end - start
}

/// One label to draw: its span (as shown), its message (escaped) and its colour.
pub(crate) struct Shown<'d> {
    pub span: Range<usize>,
    pub message: Cow<'d, str>,
    pub color: Color,
    pub primary: bool,
}

/// The primary span and the secondary labels of `d`, in source order (ariadne groups
/// labels in the order given; in source order they share one snippet).
fn labels<'d>(source: &str, d: &'d Diagnostic) -> Vec<Shown<'d>> {
    let kind_color = match d.severity {
        Severity::Error => Color::Red,
        Severity::Warning => Color::Yellow,
        Severity::Info => Color::Fixed(147),
    };
    let mut labels: Vec<Shown> = Vec::with_capacity(1 + d.labels.len());
    labels.push(Shown {
        span: display_span(source, &d.span),
        message: escape(&d.message),
        color: kind_color,
        primary: true,
    });
    labels.extend(d.labels.iter().map(|l| Shown {
        span: display_span(source, &l.span),
        message: escape(&l.message),
        color: Color::Blue,
        primary: false,
    }));
    labels.sort_by_key(|l| (l.span.start, l.span.end));
    labels
}

/// The one indexed text of a file, served for every section of a report: a section
/// is a source id (a number) that ariadne draws on its own, over its own lines only.
struct Shared<'a> {
    path: &'a str,
    source: Source<&'a str>,
}

impl<'a> Cache<usize> for Shared<'a> {
    type Storage = &'a str;

    fn fetch(&mut self, _: &usize) -> Result<&Source<Self::Storage>, impl fmt::Debug> {
        Ok::<_, ()>(&self.source)
    }

    fn display<'b>(&self, _: &'b usize) -> Option<impl fmt::Display + 'b> {
        Some(self.path.to_owned())
    }
}
/// The ariadne report of `d`, whose `labels` (in source order) span the 0-based
/// `lines` (first, last): a label more than [`GAP`] lines after the current section's
/// last line opens a new section.
fn report(
    d: &Diagnostic,
    labels: &[Shown],
    lines: &[(usize, usize)],
    color: bool,
) -> Report<'static, (usize, Range<usize>)> {
    let kind = match d.severity {
        Severity::Error => ReportKind::Error,
        Severity::Warning => ReportKind::Warning,
        Severity::Info => ReportKind::Advice,
    };
    let mut sections = Vec::with_capacity(labels.len());
    let mut section = 0;
    let mut section_end: Option<usize> = None;
    for &(first, last) in lines {
        if section_end.is_some_and(|end| first > end + GAP) {
            section += 1;
            section_end = None;
        }
        section_end = Some(section_end.map_or(last, |end| end.max(last)));
        sections.push(section);
    }
    let primary = labels.iter().position(|l| l.primary).unwrap_or(0);
    let mut builder = Report::build(kind, (sections[primary], labels[primary].span.clone()))
        .with_config(
            Config::default()
                .with_index_type(IndexType::Byte)
                .with_color(color),
        )
        .with_code(d.code.id)
        .with_message(escape(&d.message))
        .with_labels(labels.iter().zip(&sections).map(|(l, &section)| {
            let label = Label::new((section, l.span.clone())).with_message(&l.message);
            // ariadne colours labels even with colour off; only ask when wanted.
            if color {
                label.with_color(l.color)
            } else {
                label
            }
        }));
    if let Some(help) = &d.help {
        builder = builder.with_help(escape(help));
    }
    if let Some(fix) = &d.fix {
        builder = builder.with_note(format!("fix: {}", escape(&fix.message)));
    }
    builder.finish()
}

/// The span clamped to the text; an empty span at the very end of a text that ends
/// with a newline moves back before that newline, because ariadne has no empty last
/// line to point into and would show it past the end of the line before.
fn display_span(source: &str, span: &Range<usize>) -> Range<usize> {
    let span = clamp_span(source, span);
    if span.is_empty() && span.start == source.len() {
        let trimmed = source
            .strip_suffix('\n')
            .map(|s| s.strip_suffix('\r').unwrap_or(s));
        if let Some(trimmed) = trimmed {
            return trimmed.len()..trimmed.len();
        }
    }
    span
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::test_support::{SHAPE, SOURCE, UNKNOWN_WORD, diagnostics};

    fn render(source: &str, diags: &[Diagnostic]) -> String {
        let mut out = Vec::new();
        let file = FileReport {
            path: "scene.walls",
            source,
            diagnostics: diags,
        };
        human(&mut out, &file, false).unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn shows_code_message_help_fix_and_line() {
        let text = render(SOURCE, &diagnostics());
        println!("{text}");
        assert!(
            !text.contains('\u{1b}'),
            "no colour codes when colour is off"
        );
        assert!(text.contains("[S101] Error: unknown word `colr`"));
        assert!(text.contains("plane origin 0,0,0 colr 3"));
        assert!(text.contains("in this plane"));
        assert!(text.contains("did you mean `color`?"));
        assert!(text.contains("fix: replace with `color`"));
        assert!(text.contains("[C201] Advice: comment"));
        assert!(text.contains("# μ wall"));
        assert!(text.contains("scene.walls:1:5"), "character column after μ");
        assert!(text.contains("[S102] Error: missing value for `radius`"));
        assert!(text.contains("scene.walls:3:12"));
        assert!(text.contains("[C201] Warning: these walls"));
    }

    #[test]
    fn colour_adds_escape_codes() {
        let mut out = Vec::new();
        let diags = diagnostics();
        let file = FileReport {
            path: "scene.walls",
            source: SOURCE,
            diagnostics: &diags,
        };
        human(&mut out, &file, true).unwrap();
        assert!(String::from_utf8(out).unwrap().contains('\u{1b}'));
    }

    #[test]
    fn odd_spans_do_not_panic() {
        let sources = [
            "",
            "\n",
            "a",
            "plane\n",
            "μ",
            "plane\n\n",
            "x μ\r\ny",
            "a\tμ\n\r\n",
        ];
        for source in sources {
            let far = [(3, 99), (99, 200), (usize::MAX - 1, usize::MAX)];
            let pairs =
                (0..source.len() + 3).flat_map(|s| (0..source.len() + 3).map(move |e| (s, e)));
            for (start, end) in pairs.chain(far) {
                let d = Diagnostic::error(&UNKNOWN_WORD, start..end, "odd")
                    .with_label(end..start, "reversed")
                    .with_label(start..start, "empty");
                let text = render(source, &[d]);
                assert!(
                    text.contains("[S101] Error: odd"),
                    "{source:?} {start}..{end}:\n{text}"
                );
            }
        }
    }

    #[test]
    fn empty_span_at_end_of_file_with_final_newline() {
        let source = "plane radius\n";
        let d = Diagnostic::error(&UNKNOWN_WORD, source.len()..source.len(), "missing value");
        let text = render(source, &[d]);
        println!("{text}");
        assert!(text.contains("missing value"));
        // Shown at the end of the last line, not past it.
        assert!(text.contains("scene.walls:1:13"), "{text}");
        assert_eq!(display_span("a\r\n", &(3..3)), 1..1);
        assert_eq!(display_span("a\n", &(1..2)), 1..2);
        assert_eq!(display_span("", &(0..0)), 0..0);
    }

    #[test]
    fn far_labels_are_separate_sections_with_their_own_lines() {
        let source: String = (1..=40).map(|i| format!("wall type plane {i}\n")).collect();
        let at = source.find("plane 30").unwrap();
        let d =
            Diagnostic::error(&UNKNOWN_WORD, at..at + 5, "late").with_label(10..15, "first wall");
        let text = render(&source, &[d]);
        println!("{text}");
        assert!(text.contains("scene.walls:30:11"), "{text}");
        assert!(text.contains("scene.walls:1:11"), "{text}");
        assert!(text.contains(" 30 │ wall type plane 30"), "{text}");
        assert!(text.contains("  1 │ wall type plane 1"), "{text}");
        assert!(
            !text.contains("plane 2\n") && !text.contains("plane 29"),
            "{text}"
        );
    }

    #[test]
    fn a_long_line_shows_a_window_around_the_span() {
        let source = format!("{} colr {}\n", "a".repeat(1_000_000), "b".repeat(1_000_000));
        let at = source.find("colr").unwrap();
        let d = Diagnostic::error(&UNKNOWN_WORD, at..at + 4, "unknown word `colr`")
            .with_label(0..1, "line starts here")
            .with_help("did you mean `color`?");
        let text = render(&source, &[d]);
        println!("{text}");
        assert!(text.len() < 1000, "{} bytes", text.len());
        assert_eq!(
            text,
            format!(
                "[S101] Error: unknown word `colr`\n   ╭─[ scene.walls:1:1000002 ]\n   │\n \
                 1 │ {a41}…\n   │ ─ line starts here\n \
                 1 │ …{a40} colr {b39}…\n   │ {s41}──── unknown word `colr`\n   │ \n   \
                 │ Help: did you mean `color`?\n───╯\n",
                a41 = "a".repeat(41),
                a40 = "a".repeat(39),
                b39 = "b".repeat(39),
                s41 = " ".repeat(41),
            )
        );
    }

    #[test]
    fn hazards_in_the_source_message_and_path_are_escaped_and_underlined() {
        // OSC 52 (set the clipboard) in a comment, then a word after it on the same line.
        let source = "wall type plane\n# \x1b]52;c;aGk=\x07 colr 3\n";
        let esc = source.find('\x1b').unwrap();
        let colr = source.find("colr").unwrap();
        let diags = [
            Diagnostic::warning(&SHAPE, esc..esc + 1, "control character `\x1b`")
                .with_help("the terminal \x1b[2J"),
            Diagnostic::error(&UNKNOWN_WORD, colr..colr + 4, "unknown word `colr`"),
        ];
        let file = FileReport {
            path: "e\x1b]0;x\x07.walls",
            source,
            diagnostics: &diags,
        };
        for color in [false, true] {
            let mut out = Vec::new();
            human(&mut out, &file, color).unwrap();
            let text = String::from_utf8(out).unwrap();
            println!("{text}");
            // Only the renderer's own colours: every ESC starts an SGR sequence.
            for (i, _) in text.match_indices('\x1b') {
                let sgr = &text[i..];
                let end = sgr.find('m').unwrap();
                assert!(
                    sgr[1..end].starts_with('[')
                        && sgr[2..end].bytes().all(|b| b.is_ascii_digit() || b == b';'),
                    "{:?}",
                    &sgr[..end + 1]
                );
            }
            assert!(!text.contains('\x07'));
            if color {
                continue;
            }
            assert_eq!(
                text,
                "[C201] Warning: control character `\\x1b`\n   ╭─[ e\\x1b]0;x\\x07.walls:2:3 ]\n   │\n \
                 2 │ # \\x1b]52;c;aGk=\\x07 colr 3\n   │   ──── control character `\\x1b`\n   │ \n   \
                 │ Help: the terminal \\x1b[2J\n───╯\n\
                 [S101] Error: unknown word `colr`\n   ╭─[ e\\x1b]0;x\\x07.walls:2:16 ]\n   │\n \
                 2 │ # \\x1b]52;c;aGk=\\x07 colr 3\n   │                      ──── unknown word `colr`\n───╯\n"
            );
        }
    }

    #[test]
    fn a_vertical_tab_or_a_lone_carriage_return_does_not_move_later_lines() {
        // ariadne ends lines at both; pkdgrav and the line index only at `\n`.
        let source = "# a\x0bb\rc\nwall type plane\nwall colr\n";
        let colr = source.find("colr").unwrap();
        let d = Diagnostic::error(&UNKNOWN_WORD, colr..colr + 4, "unknown word `colr`");
        let text = render(source, &[d]);
        println!("{text}");
        assert!(text.contains("scene.walls:3:6"), "{text}");
        assert!(text.contains(" 3 │ wall colr"), "{text}");
    }

    #[test]
    fn a_crlf_line_with_a_hazard_shows_no_carriage_return() {
        let source = "# \u{202e}x\r\nwall\r\n";
        let d = Diagnostic::warning(&SHAPE, 2..5, "override");
        let text = render(source, &[d]);
        assert!(text.contains(" 1 │ # \\u{202e}x\n"), "{text:?}");
        assert!(text.contains("   │   ──────── override\n"), "{text:?}");
    }
}
