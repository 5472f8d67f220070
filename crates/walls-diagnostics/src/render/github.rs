//! GitHub Actions workflow commands: one `::error …::message` line per diagnostic.
//!
//! ```text
//! ::error file=PATH,line=L,col=C,endLine=EL,endColumn=EC,title=walls-lint (CODE)::MESSAGE
//! ```
//!
//! A file that could not be read is one `::error file=PATH,title=walls-lint::WHY` line,
//! after the diagnostics. Warnings use `::warning` and infos `::notice`. `col` and `endColumn` are left out
//! when the span covers several lines, which Actions rejects. Message data escapes
//! `%`, `\r` and `\n`, so that no input can end the line and start a command of its own;
//! property values also escape `:` and `,`, so that no input can end a property or the
//! properties (`::`). Before that, both show every hazard as its escape (`\x1b`,
//! [`crate::terminal`]): a message is text for people, in a log or a terminal.

use super::{FileReport, Region, Unreadable, message_with_help};
use crate::{LineIndex, Severity};
use std::io::{self, Write};

/// Writes one workflow command line per diagnostic of every file, then one per file
/// that could not be read.
pub fn github(
    out: &mut dyn Write,
    files: &[FileReport],
    unreadable: &[Unreadable],
) -> io::Result<()> {
    for file in files {
        let index = LineIndex::new(file.source);
        for d in file.diagnostics {
            let command = match d.severity {
                Severity::Error => "error",
                Severity::Warning => "warning",
                Severity::Info => "notice",
            };
            let title = format!("walls-lint ({})", d.code.id);
            // At a record of a binary file: no line, the record before the message.
            if let Some(record) = d.record {
                writeln!(
                    out,
                    "::{command} file={},title={}::{}",
                    escape_property(file.path),
                    escape_property(&title),
                    escape_data(&format!("{record}: {}", message_with_help(d)))
                )?;
                continue;
            }
            let r = Region::of(&index, file.source, &d.span);
            let mut props = format!("file={},line={}", escape_property(file.path), r.line);
            if r.line == r.end_line {
                props.push_str(&format!(",col={}", r.column));
            }
            props.push_str(&format!(",endLine={}", r.end_line));
            if r.line == r.end_line {
                props.push_str(&format!(",endColumn={}", r.end_column));
            }
            props.push_str(&format!(",title={}", escape_property(&title)));
            writeln!(
                out,
                "::{command} {props}::{}",
                escape_data(&message_with_help(d))
            )?;
        }
    }
    for u in unreadable {
        let line = u.line.map_or(String::new(), |n| format!(",line={n}"));
        writeln!(
            out,
            "::error file={}{line},title=walls-lint::{}",
            escape_property(u.path),
            escape_data(u.error)
        )?;
    }
    Ok(())
}

/// Escapes a command's message: hazards as their escapes, then `%`, `\r` and `\n`.
fn escape_data(s: &str) -> String {
    crate::terminal::escape(s)
        .replace('%', "%25")
        .replace('\r', "%0D")
        .replace('\n', "%0A")
}

/// Escapes a property value: as [`escape_data`], plus `:` and `,`.
fn escape_property(s: &str) -> String {
    escape_data(s).replace(':', "%3A").replace(',', "%2C")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Diagnostic;
    use crate::render::test_support::{SOURCE, UNKNOWN_WORD, diagnostics};

    fn render(path: &str, diags: &[Diagnostic]) -> String {
        let mut out = Vec::new();
        let file = FileReport {
            path,
            source: SOURCE,
            diagnostics: diags,
        };
        github(&mut out, &[file], &[]).unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn one_line_per_diagnostic() {
        let text = render("dir/a,b:c%.walls", &diagnostics());
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 4);
        assert_eq!(
            lines[0],
            "::error file=dir/a%2Cb%3Ac%25.walls,line=2,col=20,endLine=2,endColumn=24,\
             title=walls-lint (S101)::unknown word `colr`%0Adid you mean `color`?"
        );
        // Characters, not bytes, after `μ`; `%` escaped in data, `,` and `:` kept.
        assert_eq!(
            lines[1],
            "::notice file=dir/a%2Cb%3Ac%25.walls,line=1,col=5,endLine=1,endColumn=9,\
             title=walls-lint (C201)::comment, says 50%25 \"wall\", a:b"
        );
        assert_eq!(
            lines[2],
            "::error file=dir/a%2Cb%3Ac%25.walls,line=3,col=12,endLine=3,endColumn=12,\
             title=walls-lint (S102)::missing value for `radius`"
        );
        // Multi-line: no col / endColumn; newline in the message escaped.
        assert_eq!(
            lines[3],
            "::warning file=dir/a%2Cb%3Ac%25.walls,line=2,endLine=3,\
             title=walls-lint (C201)::these walls%0Ahave no area"
        );
    }

    #[test]
    fn carriage_returns_are_escaped() {
        let d = [Diagnostic::error(&UNKNOWN_WORD, 0..1, "a\r\nb")];
        let text = render("x.walls", &d);
        assert!(text.ends_with("::a%0D%0Ab\n"), "{text}");
        assert_eq!(text.lines().count(), 1);
    }

    #[test]
    fn unreadable_files_are_errors() {
        let mut out = Vec::new();
        let u = Unreadable {
            path: "a,b.walls",
            error: "cannot read a,b.walls: Permission denied",
            line: None,
        };
        github(&mut out, &[], &[u]).unwrap();
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "::error file=a%2Cb.walls,title=walls-lint::cannot read a,b.walls: Permission denied\n"
        );
    }

    #[test]
    fn escaping() {
        assert_eq!(escape_data("50%,a:b\r\n"), "50%25,a:b%0D%0A");
        assert_eq!(escape_property("50%,a:b\r\n"), "50%25%2Ca%3Ab%0D%0A");
        // A lone carriage return (Actions ends a line at it) and the hazards.
        assert_eq!(
            escape_data("a\r::error::x\n\x1b]52;c;aGk=\x07\u{202e}%0A"),
            "a\\x0d::error::x%0A\\x1b]52;c;aGk=\\x07\\u{202e}%250A"
        );
        assert_eq!(
            escape_property("f\x1b.walls::error file=x,line=1::"),
            "f\\x1b.walls%3A%3Aerror file=x%2Cline=1%3A%3A"
        );
    }

    #[test]
    fn a_message_or_a_path_cannot_start_a_command() {
        let d = [Diagnostic::error(
            &UNKNOWN_WORD,
            0..1,
            "unknown word `x\r\n::error file=a::owned\x1b]52;c;aGk=\x07`",
        )];
        let text = render("a\n::warning::b\r,x:y.walls", &d);
        assert_eq!(
            text,
            "::error file=a%0A%3A%3Awarning%3A%3Ab\\x0d%2Cx%3Ay.walls,line=1,col=1,endLine=1,\
             endColumn=2,title=walls-lint (S101)::unknown word `x%0D%0A::error file=a::owned\
             \\x1b]52;c;aGk=\\x07`\n"
        );
    }
}
