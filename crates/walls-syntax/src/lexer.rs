//! The lexer: text to a lossless token stream.
//!
//! Every byte of the input belongs to exactly one token, trivia included (spaces,
//! separators, newlines, comments), so concatenating the tokens gives back the input.
//! Words are split at pkdgrav's separators (C's white space: space, tab, newline,
//! vertical tab, form feed, carriage return; and `,`, `=`); a word is a
//! keyword, a wall type name, a number, or an unknown word. A `#` or `!` at the start
//! of a word begins a comment to the end of the line; one glued to the end of a word is
//! a [`TokenKind::GluedComment`], which pkdgrav does not treat as a comment at all.

use logos::Logos;
use walls_keywords::{Keyword, WallType};

/// What a token is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TokenKind {
    /// Spaces, tabs, vertical tabs, form feeds and carriage returns; also a UTF-8
    /// byte-order mark, which pkdgrav reads as part of a word (the syntax check reports
    /// it as `S005`, so that the word after it is still read as the author meant).
    Whitespace,
    /// A run of `,` and `=`, which pkdgrav also reads as whitespace.
    Separator,
    /// `\n` or `\r\n`.
    Newline,
    /// A comment from a word-initial `#` or `!` to the end of the line.
    Comment,
    /// A `#` or `!` comment glued to the end of a word (`1#x`): not a comment to pkdgrav.
    GluedComment,
    /// A decimal real as docs/spec.md §1 defines it.
    Number,
    /// A keyword, matched regardless of case.
    Keyword(Keyword),
    /// A wall type name (or the alias `disc`), matched regardless of case.
    TypeName(WallType),
    /// Any other word: unknown words, malformed numbers, `nan`, `inf`, hex floats.
    Word,
}

impl TokenKind {
    /// Whether the token means nothing to the reader (it only separates or comments).
    pub const fn is_trivia(self) -> bool {
        matches!(
            self,
            TokenKind::Whitespace
                | TokenKind::Separator
                | TokenKind::Newline
                | TokenKind::Comment
                | TokenKind::GluedComment
        )
    }
}

/// One token: its kind and the byte offset where it starts. It ends where the next
/// token starts (or at the end of the text).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Token {
    /// What the token is.
    pub kind: TokenKind,
    /// Byte offset of its first byte.
    pub start: u32,
}

/// Every token of a text, in order, stored as two arrays (kinds, starts): six bytes a
/// token, and scans of kinds alone stay in cache.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Tokens {
    kinds: Vec<TokenKind>,
    starts: Vec<u32>,
}

impl Tokens {
    /// How many tokens there are.
    pub fn len(&self) -> usize {
        self.kinds.len()
    }

    /// Whether there are none (the text is empty).
    pub fn is_empty(&self) -> bool {
        self.kinds.is_empty()
    }

    /// The kinds, in order.
    pub fn kinds(&self) -> &[TokenKind] {
        &self.kinds
    }

    /// The start offsets, in order.
    pub fn starts(&self) -> &[u32] {
        &self.starts
    }

    /// The `i`-th token.
    pub fn get(&self, i: usize) -> Option<Token> {
        Some(Token {
            kind: *self.kinds.get(i)?,
            start: self.starts[i],
        })
    }

    /// Every token, in order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = Token> + '_ {
        self.kinds
            .iter()
            .zip(&self.starts)
            .map(|(&kind, &start)| Token { kind, start })
    }
}

/// The logos automaton. Keyword variants carry their [`Keyword`] through callbacks so
/// the table in `walls-keywords` stays the single list of names (a test checks that
/// every row lexes to itself).
#[derive(Logos, Debug, Clone, Copy, PartialEq, Eq)]
enum Raw {
    #[regex(r"[ \t\r\x0B\x0C]+")]
    Whitespace,
    #[regex("\u{FEFF}+")]
    ByteOrderMark,
    #[regex(r"[,=]+")]
    Separator,
    #[regex(r"\r?\n")]
    Newline,
    // To the end of the line: a lone `\r` is part of the comment (pkdgrav only ends
    // lines at `\n`), a `\r` before the `\n` is the line end's.
    #[regex(r"[#!]([^\n]*[^\r\n])?", allow_greedy = true)]
    Comment,
    #[regex(r"[+-]?([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][+-]?[0-9]+)?", priority = 5)]
    Number,
    #[regex(r"[^ \t\r\n\x0B\x0C,=#!\u{FEFF}]+", priority = 1)]
    Word,
    #[token("time", |_| Keyword::Time, ignore(case))]
    #[token("lengthunit", |_| Keyword::LengthUnit, ignore(case))]
    #[token("massunit", |_| Keyword::MassUnit, ignore(case))]
    #[token("timeunit", |_| Keyword::TimeUnit, ignore(case))]
    #[token("defaults", |_| Keyword::Defaults, ignore(case))]
    #[token("wall", |_| Keyword::Wall, ignore(case))]
    #[token("type", |_| Keyword::Type, ignore(case))]
    #[token("origin", |_| Keyword::Origin, ignore(case))]
    #[token("orient", |_| Keyword::Orient, ignore(case))]
    #[token("vertex1", |_| Keyword::Vertex1, ignore(case))]
    #[token("vertex2", |_| Keyword::Vertex2, ignore(case))]
    #[token("velocity", |_| Keyword::Velocity, ignore(case))]
    #[token("step", |_| Keyword::Step, ignore(case))]
    #[token("osc-ampl", |_| Keyword::OscAmpl, ignore(case))]
    #[token("osc-freq", |_| Keyword::OscFreq, ignore(case))]
    #[token("osc-phase", |_| Keyword::OscPhase, ignore(case))]
    #[token("osc-vec", |_| Keyword::OscVec, ignore(case))]
    #[token("radius", |_| Keyword::Radius, ignore(case))]
    #[token("hole-radius", |_| Keyword::HoleRadius, ignore(case))]
    #[token("length", |_| Keyword::Length, ignore(case))]
    #[token("taper", |_| Keyword::Taper, ignore(case))]
    #[token("open-angle", |_| Keyword::OpenAngle, ignore(case))]
    #[token("ang-speed", |_| Keyword::AngSpeed, ignore(case))]
    #[token("epsn", |_| Keyword::Epsn, ignore(case))]
    #[token("epst", |_| Keyword::Epst, ignore(case))]
    #[token("color", |_| Keyword::Color, ignore(case))]
    #[token("transparency", |_| Keyword::Transparency, ignore(case))]
    #[token("k_n", |_| Keyword::KN, ignore(case))]
    #[token("k_t", |_| Keyword::KT, ignore(case))]
    #[token("mu_s", |_| Keyword::MuS, ignore(case))]
    #[token("mu_r", |_| Keyword::MuR, ignore(case))]
    #[token("mu_t", |_| Keyword::MuT, ignore(case))]
    #[token("beta_s", |_| Keyword::BetaS, ignore(case))]
    #[token("cohesion_model", |_| Keyword::CohesionModel, ignore(case))]
    #[token("cohesive_coeff", |_| Keyword::CohesiveCoeff, ignore(case))]
    #[token("inner_overlap_boundary", |_| Keyword::InnerOverlapBoundary, ignore(case))]
    #[token("k_n_outer", |_| Keyword::KNOuter, ignore(case))]
    #[token("k_t_outer", |_| Keyword::KTOuter, ignore(case))]
    #[token("k_n_inner", |_| Keyword::KNInner, ignore(case))]
    #[token("k_t_inner", |_| Keyword::KTInner, ignore(case))]
    #[token("mass", |_| Keyword::Mass, ignore(case))]
    #[token("cog", |_| Keyword::Cog, ignore(case))]
    #[token("rot-vec", |_| Keyword::RotVec, ignore(case))]
    #[token("ixj-vec", |_| Keyword::IxjVec, ignore(case))]
    #[token("iyj-vec", |_| Keyword::IyjVec, ignore(case))]
    #[token("izj-vec", |_| Keyword::IzjVec, ignore(case))]
    #[token("pxj-vec", |_| Keyword::PxjVec, ignore(case))]
    #[token("pyj-vec", |_| Keyword::PyjVec, ignore(case))]
    #[token("pzj-vec", |_| Keyword::PzjVec, ignore(case))]
    #[token("assembly", |_| Keyword::Assembly, ignore(case))]
    Keyword(Keyword),
    #[token("plane", |_| WallType::Plane, ignore(case))]
    #[token("triangle", |_| WallType::Triangle, ignore(case))]
    #[token("rectangle", |_| WallType::Rectangle, ignore(case))]
    #[token("disk", |_| WallType::Disk, ignore(case))]
    #[token("disc", |_| WallType::Disk, ignore(case))]
    #[token("cylinder-infinite", |_| WallType::CylinderInfinite, ignore(case))]
    #[token("cylinder-finite", |_| WallType::CylinderFinite, ignore(case))]
    #[token("shell", |_| WallType::Shell, ignore(case))]
    TypeName(WallType),
}

/// Splits `text` into tokens covering every byte, in order.
pub fn lex(text: &str) -> Tokens {
    let mut tokens = Tokens {
        kinds: Vec::with_capacity(text.len() / 3),
        starts: Vec::with_capacity(text.len() / 3),
    };
    let mut lexer = Raw::lexer(text);
    let mut prev_end_of_word: Option<usize> = None;
    while let Some(raw) = lexer.next() {
        let span = lexer.span();
        let kind = match raw {
            Ok(Raw::Whitespace | Raw::ByteOrderMark) => TokenKind::Whitespace,
            Ok(Raw::Separator) => TokenKind::Separator,
            Ok(Raw::Newline) => TokenKind::Newline,
            Ok(Raw::Comment) if prev_end_of_word == Some(span.start) => TokenKind::GluedComment,
            Ok(Raw::Comment) => TokenKind::Comment,
            Ok(Raw::Number) => TokenKind::Number,
            Ok(Raw::Keyword(k)) => TokenKind::Keyword(k),
            Ok(Raw::TypeName(t)) => TokenKind::TypeName(t),
            // Every byte sequence matches some pattern; an error can only be a stray
            // byte the patterns do not cover, and it reads as an unknown word.
            Ok(Raw::Word) | Err(()) => TokenKind::Word,
        };
        prev_end_of_word = (!kind.is_trivia()).then_some(span.end);
        tokens.kinds.push(kind);
        tokens.starts.push(span.start as u32);
    }
    tokens
}
