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

/// Parses the significant tokens into items.
pub(crate) fn items(sig: &[TokenKind]) -> Vec<Item> {
    file().parse(sig).into_output().unwrap_or_default()
}

fn file<'a>() -> impl Parser<'a, Input<'a>, Vec<Item>, Extra> {
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
        .then(property.repeated().collect::<Vec<_>>())
        .map(|(head, body)| {
            Item::Block(Block {
                kind: BlockKind::Wall,
                head,
                body,
            })
        });
    let defaults = head(Keyword::Defaults)
        .then(choice((property, general)).repeated().collect::<Vec<_>>())
        .map(|(head, body)| {
            Item::Block(Block {
                kind: BlockKind::Defaults,
                head,
                body,
            })
        });
    let stray = value
        .repeated()
        .at_least(1)
        .map_with(|_, e| Item::Stray(statement_at(e.span())));
    choice((
        wall,
        defaults,
        general.map(Item::Statement),
        property.map(Item::Statement),
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
