//! Where each line of a text starts, as editors count lines: a line ends at `\n`,
//! `\r\n` or a lone `\r`. Also the UTF-16 column (LSP's default unit) at regular marks
//! along every line, so that converting any offset to a column, or back, reads at most
//! 256 (`MARK_EVERY`) bytes: in any order, for any number of conversions, in time linear in
//! their number however long the line (a 10 MB line with 100k tokens is as quick as
//! 100k short lines).

/// The most bytes between two marks of a line (a mark falls on the first character
/// boundary at or after each multiple past the line's start or the previous mark).
const MARK_EVERY: usize = 256;

/// The start offset of every line of a text, and marks of known UTF-16 columns.
#[derive(Debug, Clone)]
pub struct Lines {
    starts: Vec<usize>,
    /// `(offset, UTF-16 column)` in offset order; every line start is one (column 0).
    marks: Vec<(usize, usize)>,
}

/// A known point of a line: its byte offset and its UTF-16 column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mark {
    /// The byte offset (a character boundary).
    pub offset: usize,
    /// The column there, in UTF-16 code units from the line's start.
    pub utf16_column: usize,
}

impl Lines {
    /// Indexes `text` (one pass).
    pub fn new(text: &str) -> Self {
        let b = text.as_bytes();
        let mut starts = vec![0];
        let mut marks = vec![(0, 0)];
        let mut column = 0;
        let mut last_mark = 0;
        for (i, c) in text.char_indices() {
            let ends = c == '\n' || (c == '\r' && b.get(i + 1) != Some(&b'\n'));
            if ends {
                starts.push(i + 1);
                marks.push((i + 1, 0));
                last_mark = i + 1;
                column = 0;
                continue;
            }
            if i - last_mark >= MARK_EVERY {
                marks.push((i, column));
                last_mark = i;
            }
            column += c.len_utf16();
        }
        Lines { starts, marks }
    }

    /// The 0-based line holding byte `offset` (offsets past the end are on the last).
    pub fn line_of(&self, offset: usize) -> usize {
        self.starts.partition_point(|&s| s <= offset) - 1
    }

    /// Where 0-based `line` starts, if the text has that line.
    pub fn line_start(&self, line: usize) -> Option<usize> {
        self.starts.get(line).copied()
    }

    /// The last mark at or before `offset`: on `offset`'s line, at most 256 (`MARK_EVERY`)
    /// bytes (plus one character) before it.
    pub fn mark_before(&self, offset: usize) -> Mark {
        let i = self.marks.partition_point(|&(o, _)| o <= offset) - 1;
        let (offset, utf16_column) = self.marks[i];
        Mark {
            offset,
            utf16_column,
        }
    }

    /// The last mark of 0-based `line` whose column is at most `utf16_column`, if the
    /// text has that line.
    pub fn mark_at_column(&self, line: usize, utf16_column: usize) -> Option<Mark> {
        let start = self.line_start(line)?;
        let end = self.line_start(line + 1).unwrap_or(usize::MAX);
        let first = self.marks.partition_point(|&(o, _)| o < start);
        let last = self.marks.partition_point(|&(o, _)| o < end);
        let line_marks = &self.marks[first..last];
        let i = line_marks.partition_point(|&(_, c)| c <= utf16_column) - 1;
        let (offset, utf16_column) = line_marks[i];
        Some(Mark {
            offset,
            utf16_column,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::{Lines, MARK_EVERY};

    #[test]
    fn every_line_ending_counts() {
        let lines = Lines::new("a\rb\r\nc\nd");
        assert_eq!(
            (0..4).map(|l| lines.line_start(l)).collect::<Vec<_>>(),
            [Some(0), Some(2), Some(5), Some(7)]
        );
        assert_eq!(lines.line_start(4), None);
        assert_eq!(lines.line_of(3), 1);
        assert_eq!(lines.line_of(99), 3);
    }

    #[test]
    fn marks_hold_the_utf16_column_on_long_lines() {
        let line = "μ𝄞x ".repeat(200);
        let text = format!("{line}\r{line}\n");
        let lines = Lines::new(&text);
        let second = line.len() + 1;
        for offset in (0..text.len()).filter(|&o| text.is_char_boundary(o)) {
            let mark = lines.mark_before(offset);
            let start = if offset < second { 0 } else { second };
            assert!(mark.offset <= offset && mark.offset >= start, "{offset}");
            assert!(offset - mark.offset <= MARK_EVERY + 4, "{offset}");
            let column: usize = text[start..mark.offset].encode_utf16().count();
            assert_eq!(mark.utf16_column, column, "{offset}");
        }
        let mark = lines.mark_at_column(1, 500).unwrap();
        assert!(mark.offset >= second && mark.utf16_column <= 500);
        assert!(500 - mark.utf16_column <= MARK_EVERY);
        assert_eq!(lines.mark_at_column(2, 9).unwrap().offset, text.len());
        assert_eq!(lines.mark_at_column(3, 0), None);
    }
}
