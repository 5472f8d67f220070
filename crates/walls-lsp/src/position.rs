//! Byte offsets to LSP positions and back. LSP counts columns in UTF-16 code units by
//! default; inside, everything is byte offsets.

use tower_lsp_server::ls_types::{Position, Range};
use walls_diagnostics::LineIndex;

/// The LSP position of byte `offset` in `text`.
pub fn position(index: &LineIndex, text: &str, offset: usize) -> Position {
    let (line, column) = index.utf16_col(text, offset);
    Position::new(line as u32, column as u32)
}

/// The LSP range of a byte range.
pub fn range(index: &LineIndex, text: &str, span: &std::ops::Range<usize>) -> Range {
    Range::new(
        position(index, text, span.start),
        position(index, text, span.end),
    )
}

/// The byte offset of an LSP position; positions past a line's end or the text's end
/// are clamped to them.
pub fn offset(index: &LineIndex, text: &str, p: Position) -> usize {
    let line = p.line as usize;
    if line >= index.line_count() {
        return text.len();
    }
    let start = index.line_start(line);
    let end = if line + 1 < index.line_count() {
        index.line_start(line + 1)
    } else {
        text.len()
    };
    let mut units = 0;
    for (i, c) in text[start..end].char_indices() {
        if units >= p.character as usize || c == '\n' {
            return start + i;
        }
        units += c.len_utf16();
    }
    end
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf16_round_trip() {
        let text = "# μ𝄞x\nwall\n";
        let index = LineIndex::new(text);
        for offset in [0, 2, 4, 8, 9, 10, 14, text.len()] {
            let p = position(&index, text, offset);
            assert_eq!(super::offset(&index, text, p), offset, "{offset} {p:?}");
        }
        assert_eq!(position(&index, text, 8), Position::new(0, 5));
        assert_eq!(super::offset(&index, text, Position::new(0, 99)), 9);
        assert_eq!(super::offset(&index, text, Position::new(9, 0)), text.len());
    }
}
