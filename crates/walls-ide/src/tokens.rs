//! Semantic tokens: which tokens are keywords, properties, wall types, numbers and
//! comments, for colouring.

use crate::Analysis;
use std::ops::Range;
use walls_keywords::Role;
use walls_syntax::{TokenId, TokenKind};

/// What a coloured token is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HighlightKind {
    /// A keyword that is not a property (`wall`, `defaults`, units, `time`).
    Keyword,
    /// A property keyword.
    Property,
    /// A wall type's name.
    WallType,
    /// A number.
    Number,
    /// A comment.
    Comment,
}

/// One coloured token.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Highlight {
    /// The token.
    pub range: Range<usize>,
    /// What it is.
    pub kind: HighlightKind,
}

/// Every token worth colouring that starts in `range` (a byte range; `0..usize::MAX` for
/// the whole file), in order (whitespace, unknown words and punctuation are not), as
/// they are asked for: the first is found by a binary search, and a caller that wants
/// the first few reads no more.
pub fn semantic_tokens(
    analysis: &Analysis,
    range: Range<usize>,
) -> impl Iterator<Item = Highlight> + '_ {
    let tree = analysis.tree();
    let starts = tree.tokens().starts();
    let first = starts.partition_point(|&s| (s as usize) < range.start);
    let end = starts.partition_point(|&s| (s as usize) < range.end);
    (first..end).filter_map(move |i| {
        let id = TokenId(i as u32);
        let kind = match tree.kind(id) {
            TokenKind::Keyword(k) if k.role() == Role::Property => HighlightKind::Property,
            TokenKind::Keyword(_) => HighlightKind::Keyword,
            TokenKind::TypeName(_) => HighlightKind::WallType,
            TokenKind::Number => HighlightKind::Number,
            TokenKind::Comment | TokenKind::GluedComment => HighlightKind::Comment,
            _ => return None,
        };
        Some(Highlight {
            range: tree.span(id),
            kind,
        })
    })
}
