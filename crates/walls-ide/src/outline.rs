//! The outline (each wall and defaults block with its statements, and the statements
//! outside blocks) and the folding ranges of blocks.

use crate::Analysis;
use std::ops::Range;
use walls_syntax::{BlockKind, Item, Statement};

/// What an outline entry is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SymbolKind {
    /// A wall block.
    Wall,
    /// A `defaults` block.
    Defaults,
    /// A statement inside a block.
    Property,
    /// A statement outside any block.
    Statement,
}

/// One outline entry.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Symbol {
    /// `wall 3: disk`, `defaults`, or the statement's keyword.
    pub name: String,
    /// A statement's values as written.
    pub detail: Option<String>,
    /// What it is.
    pub kind: SymbolKind,
    /// The whole block or statement.
    pub range: Range<usize>,
    /// Its keyword.
    pub selection_range: Range<usize>,
    /// A block's statements (always empty for statements).
    pub children: Vec<Symbol>,
}

/// The outline: each wall (`wall 3: disk`) and defaults block with its statements, and
/// the statements outside blocks, in order.
pub fn symbols(analysis: &Analysis) -> Vec<Symbol> {
    let tree = analysis.tree();
    let symbol = |name: String, detail: Option<String>, kind, stmt: &Statement, children| Symbol {
        name,
        detail,
        kind,
        range: tree.statement_span(stmt),
        selection_range: tree.span(tree.head(stmt)),
        children,
    };
    let values = |stmt: &Statement| {
        let v: Vec<&str> = tree
            .values(stmt)
            .iter()
            .map(|&t| tree.token_text(t))
            .collect();
        (!v.is_empty()).then(|| v.join(" "))
    };
    let mut walls = analysis.scene().walls.iter();
    let mut out = Vec::new();
    for item in tree.items() {
        match item {
            Item::Block(b) => {
                let children: Vec<Symbol> = tree
                    .body(b)
                    .iter()
                    .filter_map(|s| {
                        let k = tree.keyword(s)?;
                        Some(symbol(
                            k.name().into(),
                            values(s),
                            SymbolKind::Property,
                            s,
                            Vec::new(),
                        ))
                    })
                    .collect();
                let (name, kind) = match b.kind {
                    BlockKind::Wall => {
                        let w = walls.next();
                        let name = w.map_or("wall".into(), |w| {
                            format!("wall {}: {}", w.index, w.wall_type().name())
                        });
                        (name, SymbolKind::Wall)
                    }
                    BlockKind::Defaults => ("defaults".into(), SymbolKind::Defaults),
                };
                let mut s = symbol(name, None, kind, &b.head, children);
                if let Some(last) = tree.body(b).last() {
                    s.range.end = tree.statement_span(last).end;
                }
                out.push(s);
            }
            Item::Statement(s) => {
                if let Some(k) = tree.keyword(s) {
                    out.push(symbol(
                        k.name().into(),
                        values(s),
                        SymbolKind::Statement,
                        s,
                        Vec::new(),
                    ));
                }
            }
            Item::Stray(_) => {}
        }
    }
    out
}

/// Every block with statements, from its keyword to the end of its last statement
/// (editors fold those that span several lines).
pub fn folding(analysis: &Analysis) -> Vec<Range<usize>> {
    let tree = analysis.tree();
    tree.items()
        .iter()
        .filter_map(|item| {
            let Item::Block(b) = item else { return None };
            let last = tree.body(b).last()?;
            Some(tree.statement_span(&b.head).start..tree.statement_span(last).end)
        })
        .collect()
}
