//! The chumsky grammar over significant tokens.
//!
//! The grammar is total: every sequence of tokens parses, because every mistake has a
//! place in the tree (a statement with too many or too few values, a property outside a
//! block, stray values). The validator then reports each mistake once, with its code,
//! which is how recovery "resumes at the next keyword": a broken statement extends to
//! the next keyword and no further.
//!
//! ```text
//! file      = item*
//! item      = wall-block | defaults-block | general | property | stray
//! wall-block     = "wall" value* property*
//! defaults-block = "defaults" value* (property | general)*
//! general   = (time | lengthunit | massunit | timeunit) value*
//! property  = wall-token value*
//! stray     = value+
//! value     = number | word | type-name
//! ```

use crate::lexer::TokenKind;
use crate::tree::{Block, BlockKind, Item, Statement};
use chumsky::prelude::*;
use walls_keywords::{Keyword, Role};

type Input<'a> = &'a [TokenKind];
type Extra = extra::Default;

/// A top-level element as the grammar sees it: a block only counts its statements,
/// which [`items`] then lays out flat (no allocation per block).
enum Parsed {
    Block(BlockKind, Statement, usize),
    Item(Item),
}

/// Parses the significant tokens into items, and the statements inside blocks.
pub(crate) fn items(sig: &[TokenKind]) -> (Vec<Item>, Vec<Statement>) {
    let parsed = file().parse(sig).into_output().unwrap_or_default();
    let mut items = Vec::with_capacity(parsed.len());
    let mut bodies = Vec::new();
    for p in parsed {
        match p {
            Parsed::Item(item) => items.push(item),
            Parsed::Block(kind, head, count) => {
                // A statement is a keyword and the values up to the next keyword.
                let first = bodies.len() as u32;
                let mut at = head.sig.end as usize;
                for _ in 0..count {
                    let len = 1 + sig[at + 1..]
                        .iter()
                        .take_while(|k| !matches!(k, TokenKind::Keyword(_)))
                        .count();
                    bodies.push(Statement {
                        sig: at as u32..(at + len) as u32,
                    });
                    at += len;
                }
                items.push(Item::Block(Block {
                    kind,
                    head,
                    body: first..bodies.len() as u32,
                }));
            }
        }
    }
    (items, bodies)
}

fn file<'a>() -> impl Parser<'a, Input<'a>, Vec<Parsed>, Extra> {
    let value = select! {
        TokenKind::Number => (),
        TokenKind::Word => (),
        TokenKind::TypeName(_) => (),
    };
    let values = value.repeated();
    let statement = |role: Role| {
        select! { TokenKind::Keyword(k) if k.role() == role => () }
            .then(values)
            .map_with(|_, e| statement_at(e.span()))
    };
    let property = statement(Role::Property);
    let general = statement(Role::General);
    let head = |k: Keyword| {
        just(TokenKind::Keyword(k))
            .then(values)
            .map_with(|_, e| statement_at(e.span()))
    };
    let wall = head(Keyword::Wall)
        .then(property.repeated().count())
        .map(|(head, count)| Parsed::Block(BlockKind::Wall, head, count));
    let defaults = head(Keyword::Defaults)
        .then(choice((property, general)).repeated().count())
        .map(|(head, count)| Parsed::Block(BlockKind::Defaults, head, count));
    let stray = value
        .repeated()
        .at_least(1)
        .map_with(|_, e| Parsed::Item(Item::Stray(statement_at(e.span()))));
    choice((
        wall,
        defaults,
        general.map(|s| Parsed::Item(Item::Statement(s))),
        property.map(|s| Parsed::Item(Item::Statement(s))),
        stray,
    ))
    .repeated()
    .collect()
    .then_ignore(end())
}

fn statement_at(span: SimpleSpan) -> Statement {
    Statement {
        sig: span.start as u32..span.end as u32,
    }
}
