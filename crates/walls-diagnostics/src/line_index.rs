//! Byte offsets to lines and columns, computed only at the edge.
//!
//! Lines are split at `\n`. Columns count Unicode scalar values (characters), as the
//! command-line contract asks; [`LineIndex::utf16_col`] serves the LSP.
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
        starts.extend(memchr_newlines(text.as_bytes()));
        let mut chars_before_block = Vec::with_capacity(text.len() / BLOCK + 1);
        let mut chars = 0;
        for block in text.as_bytes().chunks(BLOCK) {
            chars_before_block.push(chars);
            chars += count_chars(block);
        }
        LineIndex {
            starts,
            chars_before_block,
        }
    }

    /// The number of characters of `text` before byte `offset` (at most the text's length).
    fn chars_before(&self, text: &str, offset: usize) -> usize {
        let block = offset / BLOCK;
        match self.chars_before_block.get(block) {
            Some(&before) => before + count_chars(&text.as_bytes()[block * BLOCK..offset]),
            None => {
                self.chars_before_block.last().copied().unwrap_or(0)
                    + count_chars(&text.as_bytes()[(block.max(1) - 1) * BLOCK..offset])
            }
        }
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

    /// 0-based line and UTF-16 column of byte `offset`, as the LSP counts them.
    pub fn utf16_col(&self, text: &str, offset: usize) -> (usize, usize) {
        let offset = offset.min(text.len());
        let line = self.line_of(offset);
        let start = self.starts[line];
        let prefix = text.get(start..offset).unwrap_or_default();
        (line, prefix.encode_utf16().count())
    }
}

/// The number of bytes of `bytes` that start a character.
fn count_chars(bytes: &[u8]) -> usize {
    bytes.iter().filter(|&&b| (b as i8) >= -0x40).count()
}

fn memchr_newlines(bytes: &[u8]) -> impl Iterator<Item = usize> + '_ {
    bytes
        .iter()
        .enumerate()
        .filter(|&(_, &b)| b == b'\n')
        .map(|(i, _)| i + 1)
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
        assert_eq!(idx.utf16_col(text, 5), (1, 1));
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
    }
}
