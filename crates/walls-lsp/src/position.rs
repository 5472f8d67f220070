//! Byte offsets to LSP positions and back. LSP counts columns in UTF-16 code units by
//! default and ends lines at `\n`, `\r\n` and a lone `\r`; inside, everything is byte
//! offsets.

use tower_lsp_server::ls_types::{Position, Range};
pub use walls_ide::Lines;

/// The LSP position of byte `offset` in `text` (an offset inside a character counts as
/// that character's start). Reads at most a mark's worth of the line
/// (256 bytes), however long the line.
pub fn position(lines: &Lines, text: &str, offset: usize) -> Position {
    let offset = offset.min(text.len());
    let line = lines.line_of(offset);
    let mark = lines.mark_before(offset);
    let column: usize = text[mark.offset..]
        .char_indices()
        .take_while(|&(i, _)| mark.offset + i < offset)
        .map(|(_, c)| c.len_utf16())
        .sum();
    Position::new(line as u32, (mark.utf16_column + column) as u32)
}

/// The LSP range of a byte range.
pub fn range(lines: &Lines, text: &str, span: &std::ops::Range<usize>) -> Range {
    Range::new(
        position(lines, text, span.start),
        position(lines, text, span.end),
    )
}

/// The byte offset of an LSP position; positions past a line's end or the text's end
/// are clamped to them. Reads at most a mark's worth of the line.
pub fn offset(lines: &Lines, text: &str, p: Position) -> usize {
    let line = p.line as usize;
    let Some(mark) = lines.mark_at_column(line, p.character as usize) else {
        return text.len();
    };
    let end = lines.line_start(line + 1).unwrap_or(text.len());
    let mut units = mark.utf16_column;
    for (i, c) in text[mark.offset..end].char_indices() {
        if units >= p.character as usize || c == '\n' || c == '\r' {
            return mark.offset + i;
        }
        units += c.len_utf16();
    }
    end
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lone_carriage_returns_end_lines() {
        let text = "wall\rtype\r\nplane\n";
        let lines = Lines::new(text);
        assert_eq!(position(&lines, text, 5), Position::new(1, 0));
        assert_eq!(position(&lines, text, 11), Position::new(2, 0));
        assert_eq!(super::offset(&lines, text, Position::new(1, 9)), 9);
    }

    #[test]
    fn utf16_round_trip() {
        let text = "# μ𝄞x\nwall\n";
        let index = Lines::new(text);
        for offset in [0, 2, 4, 8, 9, 10, 14, text.len()] {
            let p = position(&index, text, offset);
            assert_eq!(super::offset(&index, text, p), offset, "{offset} {p:?}");
        }
        assert_eq!(position(&index, text, 8), Position::new(0, 5));
        assert_eq!(super::offset(&index, text, Position::new(0, 99)), 9);
        assert_eq!(super::offset(&index, text, Position::new(9, 0)), text.len());
    }
}
