//! Lossless lexer and parser for pkdgrav walls files.
//!
//! [`parse`] never fails: it returns a [`SyntaxTree`] that keeps every byte of the input
//! (printing it gives the input back) and the syntax [`Diagnostic`]s, one per mistake,
//! each pointing at the exact offending text. Texts must be under 4 GiB (spans are
//! stored as 32-bit offsets); [`decode`] turns bytes into text or reports where they
//! stop being UTF-8.

pub mod codes;
mod lexer;
mod parser;
mod suggest;
mod tree;
mod validate;

pub use lexer::{Token, TokenKind, Tokens, lex};
use std::sync::Arc;
pub use suggest::{Suggestion, keyword_like, type_like};
pub use tree::{Block, BlockKind, Item, Statement, SyntaxTree, TokenId};
pub use validate::MAX_LINE_BYTES;
use walls_diagnostics::Diagnostic;

/// A parsed file and its syntax diagnostics, sorted by position.
#[derive(Debug, Clone)]
pub struct Parse {
    /// The lossless tree.
    pub tree: SyntaxTree,
    /// Syntax mistakes, sorted by position.
    pub diagnostics: Vec<Diagnostic>,
}

/// Parses a walls file.
pub fn parse(text: impl Into<Arc<str>>) -> Parse {
    let text: Arc<str> = text.into();
    let tokens = lex(&text);
    let mut sig = Vec::with_capacity(tokens.len() / 2);
    let mut sig_kinds = Vec::with_capacity(tokens.len() / 2);
    for (i, &kind) in tokens.kinds().iter().enumerate() {
        if !kind.is_trivia() {
            sig.push(TokenId(i as u32));
            sig_kinds.push(kind);
        }
    }
    let (items, bodies) = parser::items(&sig_kinds);
    let tree = SyntaxTree {
        text,
        tokens,
        sig,
        items,
        bodies,
    };
    let diagnostics = validate::validate(&tree);
    Parse { tree, diagnostics }
}

/// Reads bytes as UTF-8 text, without copying them. On failure, returns the valid
/// prefix and an error whose empty span sits at the first invalid byte (offsets are
/// into the prefix).
pub fn decode(bytes: Vec<u8>) -> Result<String, (String, Box<Diagnostic>)> {
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.into_bytes();
        let prefix = String::from_utf8_lossy(&bytes[..at]).into_owned();
        let diagnostic = Diagnostic::error(
            &codes::INVALID_UTF8,
            at..at,
            format!(
                "the file is not valid UTF-8: byte {at} (0x{:02X}) starts no character",
                bytes[at]
            ),
        )
        .with_help("save the file as UTF-8");
        (prefix, Box::new(diagnostic))
    })
}
