//! The formatter: the canonical layout of a walls file (docs/formatting.md).
//!
//! One statement per line; a block's `type` on its `wall` (or `defaults`) line and its
//! other statements indented beneath; a blank line between multi-line walls; keywords in
//! lower case; `,` and `=` written as single spaces; every value on its keyword's line
//! (which repairs pkdgrav's same-line rule); at most one blank line in a row; a final
//! newline. Comments are kept exactly: one on its own line stays on its own line, at the
//! indentation of what follows; one after a statement stays after it. The text of every
//! number is kept byte for byte, so formatting never changes what a file means.
//!
//! The formatter works on the lossless tree. A file whose statements do not parse (an
//! unknown word, a short vector, …) is not formatted: [`format`] returns the blocking
//! diagnostics instead, and nothing is lost. The syntax errors formatting repairs (values
//! off their keyword's line, a missing final newline, a comment glued to a word) do not
//! block it, nor does any warning: control characters (S006) are kept byte for byte in a
//! comment and between words replaced by the canonical space as any other white space,
//! and a subnormal number (S110) is read as written and its text kept.

mod config;
mod layout;

pub use config::{FormatTable, MAX_INDENT_WIDTH};
use std::ops::Range;
use walls_diagnostics::{Diagnostic, Edit, Severity};
use walls_syntax::Parse;

/// How the canonical layout may vary (`.walls-fmt.toml`, the `[format]` table of `walls.toml`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FormatOptions {
    /// Spaces before a statement inside a block.
    pub indent_width: usize,
    /// Line up the comments after consecutive statements of a block.
    pub align_trailing_comments: bool,
    /// Keep (one of) the blank lines the author wrote between statements.
    pub keep_blank_lines: bool,
}

impl Default for FormatOptions {
    fn default() -> Self {
        FormatOptions {
            indent_width: 2,
            align_trailing_comments: false,
            keep_blank_lines: true,
        }
    }
}

/// Why a file was not formatted.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NotFormatted {
    /// The syntax errors that leave the file's statements unclear.
    pub diagnostics: Vec<Diagnostic>,
}

/// A formatted file, with where each top-level item came from and went to, so that a
/// range of it can be formatted alone.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Formatted {
    /// The canonical text.
    pub text: String,
    /// For each top-level item: its source byte range and its output byte range. The
    /// ranges tile both texts.
    pub(crate) pieces: Vec<(Range<usize>, Range<usize>)>,
}

/// The syntax errors whose statements the formatter cannot lay out safely: every error
/// but those it repairs. A warning never blocks: its statement parsed.
fn blocks_formatting(d: &Diagnostic) -> bool {
    use walls_syntax::codes::*;
    d.severity == Severity::Error
        && ![
            &MISSING_FINAL_NEWLINE,
            &LINE_TOO_LONG,
            &GLUED_COMMENT,
            &VALUE_ON_OTHER_LINE,
        ]
        .iter()
        .any(|c| std::ptr::eq(*c, d.code))
}

/// Formats a parsed file, or says which syntax errors prevent it.
pub fn format(parse: &Parse, options: &FormatOptions) -> Result<Formatted, NotFormatted> {
    let blocking: Vec<Diagnostic> = parse
        .diagnostics
        .iter()
        .filter(|d| blocks_formatting(d))
        .cloned()
        .collect();
    if !blocking.is_empty() {
        return Err(NotFormatted {
            diagnostics: blocking,
        });
    }
    Ok(layout::format(&parse.tree, options))
}

/// Whether [`format`] formats `parse` (no syntax error leaves its statements unclear),
/// without listing the errors: a caller that only needs to know allocates nothing.
pub fn can_format(parse: &Parse) -> bool {
    !parse.diagnostics.iter().any(blocks_formatting)
}

/// Formats a text (convenience for [`format`] on a fresh parse).
pub fn format_text(text: &str, options: &FormatOptions) -> Result<String, NotFormatted> {
    format(&walls_syntax::parse(text), options).map(|f| f.text)
}

/// The edit that formats only the top-level items (blocks, statements, with their
/// comments) that `range` touches; `None` when they are already formatted.
pub fn format_range(
    parse: &Parse,
    range: Range<usize>,
    options: &FormatOptions,
) -> Result<Option<Edit>, NotFormatted> {
    let formatted = format(parse, options)?;
    let touched: Vec<&(Range<usize>, Range<usize>)> = formatted
        .pieces
        .iter()
        .filter(|(src, _)| {
            if range.is_empty() {
                // A cursor touches the item it stands in (or the last, at the very end).
                src.start <= range.start
                    && (range.start < src.end || src.end == parse.tree.text().len())
            } else {
                src.start < range.end && range.start < src.end
            }
        })
        .collect();
    let (Some(first), Some(last)) = (touched.first(), touched.last()) else {
        return Ok(None);
    };
    let source = first.0.start..last.0.end;
    let replacement = &formatted.text[first.1.start..last.1.end];
    Ok(
        (&parse.tree.text()[source.clone()] != replacement).then(|| Edit {
            span: source,
            replacement: replacement.to_string(),
        }),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_warning_does_not_block_formatting() {
        // S110 is a warning for a subnormal and an error for a number that reads as 0.
        let options = FormatOptions::default();
        assert_eq!(
            format_text("wall type disk\nradius   1e-320\n", &options).unwrap(),
            "wall type disk\n  radius 1e-320\n"
        );
        let not = format_text("wall type disk\nradius 1e-400\n", &options).unwrap_err();
        assert_eq!(not.diagnostics.len(), 1);
        assert_eq!(not.diagnostics[0].code.id, "S110");
        assert_eq!(not.diagnostics[0].severity, Severity::Error);
    }
}
