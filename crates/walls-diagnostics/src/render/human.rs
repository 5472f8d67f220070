//! Reports for people: ariadne snippets with the offending source lines.
//!
//! Each diagnostic becomes one ariadne report: a header with the code, severity and
//! message, the primary span labelled with the message, every secondary label, the
//! help, and the fix's description as a note. Spans are byte offsets
//! ([`ariadne::IndexType::Byte`]), clamped to the text before drawing.

use super::{FileReport, clamp_span};
use crate::{Diagnostic, Severity};
use ariadne::{Color, Config, IndexType, Label, Report, ReportKind, Source};
use std::io::{self, Write};
use std::ops::Range;

/// Writes every diagnostic of `file` as an ariadne report, with ANSI colours when
/// `color` is set.
pub fn human(out: &mut dyn Write, file: &FileReport, color: bool) -> io::Result<()> {
    if file.diagnostics.is_empty() {
        // Indexing the lines of a large clean file would cost more than linting it.
        return Ok(());
    }
    let source = Source::from(file.source);
    for d in file.diagnostics {
        report(file, d, color).write((file.path, &source), &mut *out)?;
    }
    Ok(())
}

fn report<'a>(
    file: &FileReport<'a>,
    d: &Diagnostic,
    color: bool,
) -> Report<'static, (&'a str, Range<usize>)> {
    let (kind, kind_color) = match d.severity {
        Severity::Error => (ReportKind::Error, Color::Red),
        Severity::Warning => (ReportKind::Warning, Color::Yellow),
        Severity::Info => (ReportKind::Advice, Color::Fixed(147)),
    };
    let span = display_span(file.source, &d.span);

    // ariadne groups labels in the order given; give them in source order so that
    // one file's labels share one snippet.
    let mut labels: Vec<(Range<usize>, &str, Color)> = Vec::with_capacity(1 + d.labels.len());
    labels.push((span.clone(), d.message.as_str(), kind_color));
    labels.extend(d.labels.iter().map(|l| {
        (
            display_span(file.source, &l.span),
            l.message.as_str(),
            Color::Blue,
        )
    }));
    labels.sort_by_key(|(s, _, _)| (s.start, s.end));

    let mut builder = Report::build(kind, (file.path, span))
        .with_config(
            Config::default()
                .with_index_type(IndexType::Byte)
                .with_color(color),
        )
        .with_code(d.code.id)
        .with_message(&d.message)
        .with_labels(labels.into_iter().map(|(s, msg, c)| {
            let label = Label::new((file.path, s)).with_message(msg);
            // ariadne colours labels even with colour off; only ask when wanted.
            if color { label.with_color(c) } else { label }
        }));
    if let Some(help) = &d.help {
        builder = builder.with_help(help);
    }
    if let Some(fix) = &d.fix {
        builder = builder.with_note(format!("fix: {}", fix.message));
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
    use crate::render::test_support::{SOURCE, UNKNOWN_WORD, diagnostics};

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
}
