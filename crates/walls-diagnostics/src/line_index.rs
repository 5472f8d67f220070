//! Byte offsets to lines and columns, computed only at the edge.
//!
//! Lines are split at `\n` only, as pkdgrav reads them (`fgets`; a lone `\r` is white
//! space to it and to the lexer), so that a report's line is the line pkdgrav and the
//! syntax check count. Columns count Unicode scalar values (characters), as the
//! command-line contract asks. The language server counts lines as editors do (`\n`,
//! `\r\n` or a lone `\r`) and columns in UTF-16: it has its own index, `walls_ide::Lines`.
//!
//! Every query costs at most one block of [`BLOCK`] bytes, however long the line: the
//! index keeps the number of characters before each block, so that a hundred thousand
//! diagnostics on one 10 MB line take linear time, not the line's length each.

/// A 1-based line and 1-based character column.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub struct LineCol {
    /// 1-based line number.
    pub line: usize,
    /// 1-based column, counted in characters.
    pub column: usize,
}

/// The bytes per block of the character-count table.
const BLOCK: usize = 4096;

/// The start offset of every line of a text, and the number of characters before every
/// block of [`BLOCK`] bytes.
#[derive(Debug, Clone)]
pub struct LineIndex {
    starts: Vec<usize>,
    chars_before_block: Vec<usize>,
}

impl LineIndex {
    /// Indexes `text`.
    pub fn new(text: &str) -> Self {
        let mut starts = vec![0];
        starts.extend(memchr::memchr_iter(b'\n', text.as_bytes()).map(|i| i + 1));
        // One entry per block, and one for the end: any offset up to the length has one.
        let chars_before_block = std::iter::once(0)
            .chain(text.as_bytes().chunks(BLOCK).scan(0, |chars, block| {
                *chars += count_chars(block);
                Some(*chars)
            }))
            .collect();
        LineIndex {
            starts,
            chars_before_block,
        }
    }

    /// The number of characters of `text` before byte `offset` (at most the text's length).
    fn chars_before(&self, text: &str, offset: usize) -> usize {
        let block = offset / BLOCK;
        self.chars_before_block[block] + count_chars(&text.as_bytes()[block * BLOCK..offset])
    }

    /// The 0-based line holding byte `offset` (offsets past the end map to the last line).
    pub fn line_of(&self, offset: usize) -> usize {
        self.starts.partition_point(|&s| s <= offset) - 1
    }

    /// Byte offset where 0-based `line` starts.
    pub fn line_start(&self, line: usize) -> usize {
        self.starts[line]
    }

    /// Number of lines (a final newline opens one more, empty line).
    pub fn line_count(&self) -> usize {
        self.starts.len()
    }

    /// 1-based line and character column of byte `offset` in `text`. An offset inside a
    /// multi-byte character counts as that character's start.
    pub fn line_col(&self, text: &str, offset: usize) -> LineCol {
        let offset = offset.min(text.len());
        let line = self.line_of(offset);
        let start = self.starts[line];
        let column = self.chars_before(text, offset) - self.chars_before(text, start);
        LineCol {
            line: line + 1,
            column: column + 1,
        }
    }
}

/// The number of bytes of `bytes` that start a character.
fn count_chars(bytes: &[u8]) -> usize {
    bytes.iter().filter(|&&b| (b as i8) >= -0x40).count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_count_characters() {
        let text = "ab\nμx\n";
        let idx = LineIndex::new(text);
        assert_eq!(idx.line_col(text, 0), LineCol { line: 1, column: 1 });
        assert_eq!(idx.line_col(text, 3), LineCol { line: 2, column: 1 });
        assert_eq!(idx.line_col(text, 5), LineCol { line: 2, column: 2 });
        assert_eq!(idx.line_col(text, 7), LineCol { line: 3, column: 1 });
        assert_eq!(idx.line_col(text, 99), LineCol { line: 3, column: 1 });
    }

    #[test]
    fn columns_across_blocks() {
        let text = format!("x\n{}{}", "μ".repeat(BLOCK), "ab".repeat(BLOCK));
        let idx = LineIndex::new(&text);
        for offset in [
            0,
            1,
            2,
            4,
            BLOCK,
            BLOCK + 2,
            2 * BLOCK + 2,
            text.len() - 1,
            text.len(),
        ] {
            let naive = text.as_bytes()[..offset].iter().rposition(|&b| b == b'\n');
            let start = naive.map_or(0, |i| i + 1);
            let expected = count_chars(&text.as_bytes()[start..offset]) + 1;
            assert_eq!(idx.line_col(&text, offset).column, expected, "at {offset}");
        }
        // A text that ends on a block's end: its end is in the table too.
        let text = "μ".repeat(BLOCK / 2);
        let end = LineIndex::new(&text).line_col(&text, text.len());
        assert_eq!(
            end,
            LineCol {
                line: 1,
                column: BLOCK / 2 + 1
            }
        );
    }
}
