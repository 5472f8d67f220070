//! The lossless syntax tree shared by the checker, the formatter and the LSP server.
//!
//! A walls file is flat: a sequence of items, each a block (`wall` or `defaults` with the
//! statements it owns), a statement outside any block, or stray values before the first
//! keyword. A statement is a keyword and the values after it. The tree keeps every token,
//! trivia included, so [`SyntaxTree`]'s `Display` prints the input back byte for byte;
//! statements refer to tokens by index instead of copying text.

use crate::lexer::{TokenKind, Tokens};
use std::fmt;
use std::ops::Range;
use std::sync::Arc;
use walls_keywords::Keyword;

/// Index of a token in [`SyntaxTree::tokens`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct TokenId(pub u32);

/// A keyword and its values, or a run of stray values: a contiguous range of the
/// file's significant (non-trivia) tokens.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Statement {
    /// Range of significant-token indices (see [`SyntaxTree::significant`]).
    pub(crate) sig: Range<u32>,
}

/// Which block a `wall` or `defaults` keyword opens.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BlockKind {
    /// `wall`: a new wall, a copy of the current defaults.
    Wall,
    /// `defaults`: edits the default wall.
    Defaults,
}

/// A `wall` or `defaults` block: its header statement and the statements it owns.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Block {
    /// Which keyword opened it.
    pub kind: BlockKind,
    /// The `wall`/`defaults` statement itself.
    pub head: Statement,
    /// The statements inside, as indices into the tree's statements (see
    /// [`SyntaxTree::body`]): properties, and for `defaults` also general tokens (units
    /// and `time` close a wall block but not a defaults block).
    pub(crate) body: Range<u32>,
}

/// One top-level element of a file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Item {
    /// A `wall` or `defaults` block.
    Block(Block),
    /// A statement outside any block: a general token (`time`, units), or a wall
    /// property that stands outside any block (an error the validator reports).
    Statement(Statement),
    /// Values with no keyword before them, at the start of the file (an error).
    Stray(Statement),
}

/// A parsed file: its text, every token, and the items.
#[derive(Debug, Clone)]
pub struct SyntaxTree {
    pub(crate) text: Arc<str>,
    pub(crate) tokens: Tokens,
    pub(crate) sig: Vec<TokenId>,
    pub(crate) items: Vec<Item>,
    /// The statements inside blocks, in order; blocks refer to runs of them.
    pub(crate) bodies: Vec<Statement>,
}

impl SyntaxTree {
    /// The source text.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The source text, shared.
    pub fn shared_text(&self) -> &Arc<str> {
        &self.text
    }

    /// Every token, trivia included, in order.
    pub fn tokens(&self) -> &Tokens {
        &self.tokens
    }

    /// The statements inside a block, in order.
    pub fn body(&self, block: &Block) -> &[Statement] {
        &self.bodies[block.body.start as usize..block.body.end as usize]
    }

    /// The top-level items, in order.
    pub fn items(&self) -> &[Item] {
        &self.items
    }

    /// The token ids of the significant (non-trivia) tokens, in order.
    pub fn significant(&self) -> &[TokenId] {
        &self.sig
    }

    /// The kind of a token.
    pub fn kind(&self, id: TokenId) -> TokenKind {
        self.tokens.kinds()[id.0 as usize]
    }

    /// Byte range of a token.
    pub fn span(&self, id: TokenId) -> Range<usize> {
        let i = id.0 as usize;
        let starts = self.tokens.starts();
        let start = starts[i] as usize;
        let end = starts.get(i + 1).map_or(self.text.len(), |&s| s as usize);
        start..end
    }

    /// The text of a token.
    pub fn token_text(&self, id: TokenId) -> &str {
        &self.text[self.span(id)]
    }

    /// The first token of a statement: its keyword, or the first stray value.
    pub fn head(&self, stmt: &Statement) -> TokenId {
        self.sig[stmt.sig.start as usize]
    }

    /// The statement's keyword, if it has one.
    pub fn keyword(&self, stmt: &Statement) -> Option<Keyword> {
        match self.kind(self.head(stmt)) {
            TokenKind::Keyword(k) => Some(k),
            _ => None,
        }
    }

    /// The value tokens after the keyword (every token, for stray values).
    pub fn values(&self, stmt: &Statement) -> &[TokenId] {
        let skip = usize::from(self.keyword(stmt).is_some());
        &self.sig[stmt.sig.start as usize + skip..stmt.sig.end as usize]
    }

    /// Every significant token of the statement: its keyword (if any), then its values.
    pub fn statement_tokens(&self, stmt: &Statement) -> &[TokenId] {
        &self.sig[stmt.sig.start as usize..stmt.sig.end as usize]
    }

    /// Byte range from the statement's first token to the end of its last.
    pub fn statement_span(&self, stmt: &Statement) -> Range<usize> {
        let first = self.sig[stmt.sig.start as usize];
        let last = self.sig[stmt.sig.end as usize - 1];
        self.span(first).start..self.span(last).end
    }

    /// The statement whose keyword starts at byte `offset`: the keyword and the values
    /// up to the next keyword, as the parser groups them.
    pub fn statement_at(&self, offset: usize) -> Option<Statement> {
        let start = self
            .sig
            .partition_point(|&t| (self.tokens.starts()[t.0 as usize] as usize) < offset);
        let head = *self.sig.get(start)?;
        if self.tokens.starts()[head.0 as usize] as usize != offset
            || !matches!(self.kind(head), TokenKind::Keyword(_))
        {
            return None;
        }
        let len = self.sig[start + 1..]
            .iter()
            .take_while(|&&t| !matches!(self.kind(t), TokenKind::Keyword(_)))
            .count();
        Some(Statement {
            sig: start as u32..(start + 1 + len) as u32,
        })
    }

    /// The keyword statement holding the token that starts at byte `offset` (its keyword
    /// or one of its values).
    pub fn statement_containing(&self, offset: usize) -> Option<Statement> {
        let at = self
            .sig
            .partition_point(|&t| (self.tokens.starts()[t.0 as usize] as usize) <= offset);
        let head = self.sig[..at]
            .iter()
            .rposition(|&t| matches!(self.kind(t), TokenKind::Keyword(_)))?;
        self.statement_at(self.tokens.starts()[self.sig[head].0 as usize] as usize)
    }

    /// Every statement of the file in source order, each with the block holding it.
    pub fn statements(&self) -> impl Iterator<Item = (&Statement, Option<&Block>)> + '_ {
        self.items.iter().flat_map(|item| {
            let (first, block, body): (&Statement, Option<&Block>, &[Statement]) = match item {
                Item::Block(b) => (&b.head, Some(b), self.body(b)),
                Item::Statement(s) | Item::Stray(s) => (s, None, &[]),
            };
            std::iter::once((first, block)).chain(body.iter().map(move |s| (s, block)))
        })
    }
}

/// Prints the tree's tokens in order: exactly the text it was parsed from.
impl fmt::Display for SyntaxTree {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for i in 0..self.tokens.len() {
            f.write_str(self.token_text(TokenId(i as u32)))?;
        }
        Ok(())
    }
}
