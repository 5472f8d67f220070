//! A `.par` file's lines as pkdgrav's reader sees them (docs/pkdgrav-physics.md §14):
//! each read takes at most [`LINE_LIMIT`] bytes, so a longer line is read as several;
//! a line whose first column is `#` is a comment; a blank line is nothing; anything else
//! must be `key = value`, a key being a letter followed by letters, digits, `_` or `$`.
//! An indented `#`, a `!` anywhere in such a line, a line that starts with anything but
//! a letter or a blank, a key without `=`, and `=` with nothing after it (or only a
//! comment) are syntax errors: pkdgrav stops at start-up.
//!
//! Every read keeps its byte span in the file, so that each finding is located exactly.

use std::ops::Range;

/// The most bytes pkdgrav reads as one line (its 128-byte buffer, `PRM_LINE_SIZE`, less
/// the terminating zero): a longer line's rest is read as a line of its own.
pub const LINE_LIMIT: usize = 127;

/// One line of the file, as written (without its line break).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Line {
    /// The line's number, from 1.
    pub number: usize,
    /// Its bytes in the file, without the line break (`\n` or `\r\n`).
    pub span: Range<usize>,
    /// What pkdgrav reads in it: one read, or several when it is over [`LINE_LIMIT`]
    /// bytes.
    pub reads: Vec<Read>,
}

/// One read of pkdgrav's reader: a line, or a piece of a long one.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Read {
    /// Its bytes in the file.
    pub span: Range<usize>,
    /// What it is.
    pub kind: Kind,
}

/// What a read is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Kind {
    /// Nothing but blanks.
    Blank,
    /// A `#` in the first column: the rest is a comment.
    Comment,
    /// `key = value`: the key's bytes and the value's (to the end of the read, a comment
    /// included; [`crate::value`] reads it as the key's type).
    Entry {
        /// The key.
        key: Range<usize>,
        /// The value and what follows it on the line.
        value: Range<usize>,
    },
    /// A syntax error at `at`.
    Error {
        /// What is wrong.
        problem: Problem,
        /// The offending bytes (empty where something is missing).
        at: Range<usize>,
    },
}

/// A syntax error of pkdgrav's reader.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Problem {
    /// A `!` (pkdgrav's comments are `#` in the first column only).
    Bang,
    /// A `#` after blanks at the start of the line.
    IndentedHash,
    /// The line starts with something that is not a letter, a blank or `#`.
    NotAKey,
    /// The key is not followed by `=`.
    NoEquals,
    /// `=` is followed by nothing, or by a comment only.
    NoValue,
}

impl Problem {
    /// What is wrong, in words.
    pub fn says(self) -> &'static str {
        match self {
            Problem::Bang => {
                "`!` is not a comment in a .par file: pkdgrav stops with a syntax error at start-up"
            }
            Problem::IndentedHash => {
                "a `#` comment must start in the first column: indented, pkdgrav stops with a syntax error at start-up"
            }
            Problem::NotAKey => {
                "a line must start with a key (a letter), a blank or `#`: pkdgrav stops with a syntax error at start-up"
            }
            Problem::NoEquals => {
                "the key is not followed by `=`: pkdgrav stops with a syntax error at start-up"
            }
            Problem::NoValue => {
                "`=` has no value after it: pkdgrav stops with a syntax error at start-up"
            }
        }
    }
}

/// The blanks pkdgrav skips around a key, `=` and a value.
fn blank(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | b'\x0b' | b'\x0c')
}

/// The lines of `text`, each with pkdgrav's reads of it.
pub fn lines(text: &str) -> Vec<Line> {
    let mut out = Vec::new();
    let mut start = 0;
    for (i, raw) in text.split('\n').enumerate() {
        let end = start + raw.len();
        // A final empty piece after the last line break is no line.
        if !(raw.is_empty() && end == text.len() && i > 0) {
            let content = raw.strip_suffix('\r').map_or(end, |r| start + r.len());
            out.push(Line {
                number: i + 1,
                span: start..content,
                reads: reads(text, start..end),
            });
        }
        start = end + 1;
    }
    out
}

/// pkdgrav's reads of the line at `span` (its carriage return included: pkdgrav reads
/// it as a byte of the line, and as a blank).
fn reads(text: &str, span: Range<usize>) -> Vec<Read> {
    let mut out = Vec::new();
    let mut at = span.start;
    loop {
        let mut end = (at + LINE_LIMIT).min(span.end);
        // A read ends at a character's boundary here (pkdgrav's ends at the 127th byte:
        // the spans of a multi-byte character astride it go with the next read).
        while !text.is_char_boundary(end) {
            end -= 1;
        }
        if end == at && at < span.end {
            // A single character wider than the rest of the read.
            end = text[at..]
                .char_indices()
                .nth(1)
                .map_or(span.end, |(k, _)| at + k);
        }
        out.push(Read {
            span: at..end,
            kind: kind(text, at..end),
        });
        if end >= span.end {
            return out;
        }
        at = end;
    }
}

/// What the read at `span` is.
fn kind(text: &str, span: Range<usize>) -> Kind {
    // A NUL byte ends the C string pkdgrav reads the line into.
    let b = &text.as_bytes()[span.clone()];
    let b = &b[..b.iter().position(|&c| c == 0).unwrap_or(b.len())];
    let span = span.start..span.start + b.len();
    let at = |k: usize| span.start + k;
    if b.iter().all(|&c| blank(c)) {
        return Kind::Blank;
    }
    if b[0] == b'#' {
        return Kind::Comment;
    }
    let first = b.iter().position(|&c| !blank(c)).unwrap_or(0);
    if b[first] == b'#' {
        return error(Problem::IndentedHash, at(first)..at(first + 1));
    }
    if let Some(k) = b.iter().position(|&c| c == b'!') {
        return error(Problem::Bang, at(k)..at(k + 1));
    }
    if !b[first].is_ascii_alphabetic() {
        let width = text[at(first)..].chars().next().map_or(1, char::len_utf8);
        return error(Problem::NotAKey, at(first)..at(first) + width);
    }
    let key_end = first
        + b[first..]
            .iter()
            .position(|&c| !(c.is_ascii_alphanumeric() || c == b'_' || c == b'$'))
            .unwrap_or(b.len() - first);
    let eq = key_end + b[key_end..].iter().take_while(|&&c| blank(c)).count();
    if eq >= b.len() || b[eq] != b'=' {
        let width = text[at(eq)..span.end]
            .chars()
            .next()
            .map_or(0, char::len_utf8);
        return error(Problem::NoEquals, at(eq)..at(eq) + width);
    }
    let value = eq + 1 + b[eq + 1..].iter().take_while(|&&c| blank(c)).count();
    if value >= b.len() || b[value] == b'#' {
        return error(Problem::NoValue, at(eq)..at(eq + 1));
    }
    // The value runs to the end of the read, less trailing blanks.
    let value_end = b.len() - b.iter().rev().take_while(|&&c| blank(c)).count();
    Kind::Entry {
        key: at(first)..at(key_end),
        value: at(value)..at(value_end),
    }
}

fn error(problem: Problem, at: Range<usize>) -> Kind {
    Kind::Error { problem, at }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(text: &str) -> Vec<Kind> {
        lines(text)
            .into_iter()
            .flat_map(|l| l.reads)
            .map(|r| r.kind)
            .collect()
    }

    #[test]
    fn lines_are_read_as_pkdgrav_reads_them() {
        let text = "# c\n\n  \ndDelta = 1e-5 # s\n  # no\nnSteps = 5 ! no\n1x = 2\nkey 3\nkey =\nk = # c\n";
        assert_eq!(
            kinds(text),
            [
                Kind::Comment,
                Kind::Blank,
                Kind::Blank,
                Kind::Entry {
                    key: 8..14,
                    value: 17..25
                },
                error(Problem::IndentedHash, 28..29),
                error(Problem::Bang, 44..45),
                error(Problem::NotAKey, 49..50),
                error(Problem::NoEquals, 60..61),
                error(Problem::NoValue, 66..67),
                error(Problem::NoValue, 70..71),
            ]
        );
        // The last line without a line break is a line; a CRLF line ends before `\r`.
        let l = lines("a = 1\r\nb = 2");
        assert_eq!((l[0].span.clone(), l[1].span.clone()), (0..5, 7..12));
        assert_eq!(lines("").len(), 1);
    }

    #[test]
    fn a_long_line_is_read_in_pieces_of_127_bytes() {
        let text = format!("achOutName = {}\n", "x".repeat(200));
        let l = &lines(&text)[0];
        let spans: Vec<_> = l.reads.iter().map(|r| r.span.clone()).collect();
        assert_eq!(spans, [0..127, 127..213]);
        // The rest starts with `x`: a key without `=`.
        assert!(matches!(
            l.reads[1].kind,
            Kind::Error {
                problem: Problem::NoEquals,
                ..
            }
        ));
        // A multi-byte character astride byte 127 goes with the next read.
        let text = format!("s = {}é", "x".repeat(122));
        let l = &lines(&text)[0];
        assert_eq!(l.reads[0].span, 0..126);
    }
}
