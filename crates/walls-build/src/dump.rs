//! Writing walls as a whole file: a leading comment, the units, the defaults block and
//! the walls, laid out by the formatter and checked as `walls-lint` checks a file.

use crate::value::number;
use crate::wall::{Units, Wall};
use std::fmt::{self, Write as _};
use walls_diagnostics::{Diagnostic, LineIndex, Severity};
use walls_format::FormatOptions;
use walls_model::Options;

/// What [`dumps`] writes besides the walls, and how it checks the file.
#[derive(Debug, Clone, Default)]
pub struct DumpOptions {
    /// The unit tokens, written first.
    pub units: Units,
    /// The defaults block, written before the walls (nothing when `None` or empty).
    pub defaults: Option<Wall>,
    /// A comment for the top of the file; each of its lines becomes a `#` line.
    pub comment: Option<String>,
    /// The run the file is checked for: contact model, pkdgrav's MAX_NUM_WALLS.
    pub check: Options,
    /// The layout (walls-fmt's default unless given).
    pub format: FormatOptions,
}

/// A file [`dumps`] wrote: its text, and the warnings `walls-lint` gives it.
#[derive(Debug, Clone)]
pub struct Dumped {
    /// The file, in the canonical layout.
    pub text: String,
    /// Warnings (and notes): legal, but maybe not what was meant.
    pub warnings: Vec<Diagnostic>,
}

/// Walls that make a file pkdgrav would reject or misread: the text and every
/// diagnostic of it (errors and warnings, by position).
#[derive(Debug, Clone)]
pub struct DumpError {
    /// The text as it would have been written.
    pub text: String,
    /// Every diagnostic, at least one an error.
    pub diagnostics: Vec<Diagnostic>,
}

impl fmt::Display for DumpError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let errors = self
            .diagnostics
            .iter()
            .filter(|d| d.severity == Severity::Error)
            .count();
        writeln!(
            f,
            "the walls make a file with {errors} error{}:",
            if errors == 1 { "" } else { "s" }
        )?;
        f.write_str(&describe(&self.text, &self.diagnostics))
    }
}

impl std::error::Error for DumpError {}

/// Diagnostics of `text` as lines `LINE:COLUMN: SEVERITY[CODE]: MESSAGE`, with the text of
/// each line they point at, for messages outside a terminal (Python's exceptions and
/// warnings).
pub fn describe(text: &str, diagnostics: &[Diagnostic]) -> String {
    let index = LineIndex::new(text);
    let mut out = String::new();
    for d in diagnostics {
        let at = index.line_col(text, d.span.start);
        let line = text.lines().nth(at.line - 1).unwrap_or_default().trim();
        let _ = writeln!(
            out,
            "{}:{}: {}[{}]: {} (`{line}`)",
            at.line,
            at.column,
            d.severity.as_str(),
            d.code.id,
            d.message
        );
    }
    out
}

/// Writes `walls` as a whole walls file: the comment, the units, the defaults and each
/// wall, in walls-fmt's canonical layout, with every number the shortest decimal that
/// reads back exactly. The file is then checked as `walls-lint` checks it: any error
/// fails the dump ([`DumpError`]); warnings come back beside the text.
pub fn dumps(walls: &[Wall], options: &DumpOptions) -> Result<Dumped, DumpError> {
    let mut raw = String::new();
    if let Some(comment) = &options.comment {
        for line in comment.lines() {
            let line = line.trim_end();
            if line.is_empty() {
                raw.push_str("#\n");
            } else {
                let _ = writeln!(raw, "# {line}");
            }
        }
    }
    for (name, x) in options.units.tokens() {
        let _ = writeln!(raw, "{name} {}", number(x));
    }
    // A blank line after the header (comment and units) and after the defaults.
    let blank = |raw: &mut String| {
        if !raw.is_empty() {
            raw.push('\n');
        }
    };
    blank(&mut raw);
    if let Some(defaults) = options.defaults.as_ref().filter(|d| !d.is_empty()) {
        block(&mut raw, "defaults", defaults);
        blank(&mut raw);
    }
    for wall in walls {
        block(&mut raw, "wall", wall);
    }
    let text = match walls_format::format_text(&raw, &options.format) {
        Ok(text) => text,
        Err(not) => {
            return Err(DumpError {
                text: raw,
                diagnostics: not.diagnostics,
            });
        }
    };
    let checked = walls_ide::check_text(text.as_str(), &options.check);
    if checked
        .diagnostics
        .iter()
        .any(|d| d.severity == Severity::Error)
    {
        Err(DumpError {
            text,
            diagnostics: checked.diagnostics,
        })
    } else {
        Ok(Dumped {
            text,
            warnings: checked.diagnostics,
        })
    }
}

/// A block, one token a line (the formatter lays it out).
fn block(out: &mut String, head: &str, wall: &Wall) {
    out.push_str(head);
    out.push('\n');
    for (name, value) in wall.tokens() {
        let _ = writeln!(out, "{name} {value}");
    }
}
