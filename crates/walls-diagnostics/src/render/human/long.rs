//! Reports that touch a line longer than [`LONG_LINE`](super::LONG_LINE) bytes, or a
//! line that holds a hazard ([`crate::terminal`]).
//!
//! ariadne prints every line it shows in full, and as it is, so these reports are drawn
//! here, in
//! ariadne's frame: the header, a `file:line:column` box, then for each label (in
//! source order) its line cut to a window of at most [`BEFORE`] characters before the
//! span, [`SPAN`] of the span and [`AFTER`] after it, with `…` where text is cut, and a
//! line underlining the span followed by the label's message; then help and fix note.
//! In the window, a hazard is shown as its escape (`\x1b`: [`terminal::escape`]), with
//! the underline under the escape, and a tab as a space, so the underline stays aligned;
//! the path, the message, the help and the note are escaped too.

use super::Shown;
use crate::render::FileReport;
use crate::terminal::{self, escape};
use crate::{Diagnostic, LineIndex, Severity};
use ariadne::{Color, Fmt};
use std::io::{self, Write};

/// Characters shown before a span.
const BEFORE: usize = 40;
/// Characters of a span shown at most.
const SPAN: usize = 80;
/// Characters shown after a span.
const AFTER: usize = 40;

/// Writes the report of `d`, whose `labels` are in source order.
pub(super) fn write(
    out: &mut dyn Write,
    file: &FileReport,
    index: &LineIndex,
    d: &Diagnostic,
    labels: &[Shown],
    color: bool,
) -> io::Result<()> {
    let paint = |text: &str, c: Color| -> String {
        if color {
            text.fg(c).to_string()
        } else {
            text.to_owned()
        }
    };
    let (kind, kind_color) = match d.severity {
        Severity::Error => ("Error", Color::Red),
        Severity::Warning => ("Warning", Color::Yellow),
        Severity::Info => ("Advice", Color::Fixed(147)),
    };
    writeln!(
        out,
        "{} {}",
        paint(&format!("[{}] {kind}:", d.code.id), kind_color),
        escape(&d.message)
    )?;
    let source = file.source;
    let last_line = labels
        .iter()
        .map(|l| index.line_of(l.span.start) + 1)
        .max()
        .unwrap_or(1);
    let width = last_line.to_string().len();
    let pad = " ".repeat(width + 2);
    let bar = "│";
    let at = labels
        .iter()
        .find(|l| l.primary)
        .map_or(0, |l| l.span.start);
    let start = index.line_col(source, at);
    writeln!(
        out,
        "{pad}╭─[ {}:{}:{} ]",
        escape(file.path),
        start.line,
        start.column
    )?;
    writeln!(out, "{pad}{bar}")?;
    for label in labels {
        let line = index.line_of(label.span.start);
        let line_start = index.line_start(line);
        let line_end = line_start + super::line_len(index, source, line);
        // A carriage return that ends the line is its line end, not shown.
        let line_end = if source[..line_end].ends_with('\r') && source[line_end..].starts_with('\n')
        {
            line_end - 1
        } else {
            line_end
        };
        let span_end = label.span.end.min(line_end).max(label.span.start);
        let before = back_chars(source, line_start, label.span.start, BEFORE);
        let shown_end = forward_chars(source, label.span.start, span_end, SPAN);
        let after = forward_chars(source, span_end, line_end, AFTER);
        let mut text = String::new();
        if before > line_start {
            text.push('…');
        }
        text.push_str(&visible(&source[before..label.span.start]));
        let underline_at = text.chars().count();
        text.push_str(&visible(&source[label.span.start..shown_end]));
        if shown_end < span_end {
            text.push('…');
        }
        let underline_len = text.chars().count() - underline_at;
        if shown_end == span_end {
            text.push_str(&visible(&source[span_end..after]));
            if after < line_end {
                text.push('…');
            }
        }
        let number = format!("{:>width$}", line + 1);
        writeln!(out, " {number} {bar} {text}")?;
        writeln!(
            out,
            "{pad}{bar} {}{} {}",
            " ".repeat(underline_at),
            paint(&"─".repeat(underline_len.max(1)), label.color),
            label.message
        )?;
    }
    if let Some(help) = &d.help {
        writeln!(out, "{pad}{bar} ")?;
        writeln!(out, "{pad}{bar} Help: {}", escape(help))?;
    }
    if let Some(fix) = &d.fix {
        writeln!(out, "{pad}{bar} ")?;
        writeln!(out, "{pad}{bar} Note: fix: {}", escape(&fix.message))?;
    }
    writeln!(out, "{}╯", "─".repeat(width + 2))
}

/// The offset `n` characters before `to`, but not before `from`.
fn back_chars(source: &str, from: usize, to: usize, n: usize) -> usize {
    source[from..to]
        .char_indices()
        .rev()
        .nth(n.saturating_sub(1))
        .map_or(from, |(i, _)| from + i)
}

/// The offset `n` characters after `from`, but not after `to`.
fn forward_chars(source: &str, from: usize, to: usize, n: usize) -> usize {
    source[from..to]
        .char_indices()
        .nth(n)
        .map_or(to, |(i, _)| from + i)
}

/// `text` (part of one line) with every hazard shown as its escape and every other
/// control character (a tab) as a space: one column each.
fn visible(text: &str) -> String {
    terminal::escape(text)
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect()
}
