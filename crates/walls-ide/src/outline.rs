//! The outline (each wall and defaults block with its statements, and the statements
//! outside blocks) and the folding ranges of blocks.
//!
//! An outline has at most the number of entries its caller asks for, whatever the file,
//! so that its size (and an editor's memory for it) has a bound: a mesh of 100,000 walls
//! is not 400,000 entries. Its shape is chosen by what fits: every block with its
//! statements; else the blocks and statements of the top level alone; else runs of them
//! as groups (`walls 0–99`), each run a power of ten long, the shortest whose groups
//! fit. A statement's detail (its values) is cut after [`MAX_DETAIL`] bytes.

use crate::Analysis;
use std::ops::Range;
use walls_model::Wall;
use walls_syntax::{BlockKind, Item, Statement, SyntaxTree};

/// The most bytes of values a statement's detail shows before `…`.
pub const MAX_DETAIL: usize = 80;

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
    /// A run of blocks and statements of the top level, in an outline too long to list
    /// them one by one.
    Group,
}

/// One outline entry.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Symbol {
    /// `wall 3: disk`, `defaults`, the statement's keyword, or a group's `walls 0–99`.
    pub name: String,
    /// A statement's values as written (the first [`MAX_DETAIL`] bytes of them).
    pub detail: Option<String>,
    /// What it is.
    pub kind: SymbolKind,
    /// The whole block, statement or run.
    pub range: Range<usize>,
    /// Its keyword (a group's: its first entry's).
    pub selection_range: Range<usize>,
    /// A block's statements (empty for statements and groups, and for blocks when the
    /// outline lists the top level alone).
    pub children: Vec<Symbol>,
}

/// One entry of the top level: a block or a statement with a keyword.
struct Top<'a> {
    item: &'a Item,
    /// The wall a wall block made, if the resolver made one.
    wall: Option<&'a Wall>,
    range: Range<usize>,
    selection_range: Range<usize>,
}

/// The entries of the top level, in order, with the walls their blocks made.
fn tops(analysis: &Analysis) -> impl Iterator<Item = Top<'_>> {
    let tree = analysis.tree();
    let mut walls = analysis.scene().walls.iter();
    tree.items().iter().filter_map(move |item| {
        let (head, wall, end) = match item {
            Item::Block(b) => {
                let wall = (b.kind == BlockKind::Wall).then(|| walls.next()).flatten();
                let end = tree.body(b).last().unwrap_or(&b.head);
                (&b.head, wall, end)
            }
            Item::Statement(s) if tree.keyword(s).is_some() => (s, None, s),
            _ => return None,
        };
        Some(Top {
            item,
            wall,
            range: tree.statement_span(head).start..tree.statement_span(end).end,
            selection_range: tree.span(tree.head(head)),
        })
    })
}

/// A statement's values as written, the first [`MAX_DETAIL`] bytes of them.
fn detail(tree: &SyntaxTree, stmt: &Statement) -> Option<String> {
    let mut out = String::new();
    for &v in tree.values(stmt) {
        if out.len() >= MAX_DETAIL {
            out.push_str(" …");
            break;
        }
        if !out.is_empty() {
            out.push(' ');
        }
        out.push_str(tree.token_text(v));
    }
    (!out.is_empty()).then_some(out)
}

impl Top<'_> {
    /// Its entry, with a block's statements when `children` says so.
    fn symbol(&self, tree: &SyntaxTree, children: bool) -> Symbol {
        let property = |s: &Statement| {
            let k = tree.keyword(s)?;
            Some(Symbol {
                name: k.name().into(),
                detail: detail(tree, s),
                kind: SymbolKind::Property,
                range: tree.statement_span(s),
                selection_range: tree.span(tree.head(s)),
                children: Vec::new(),
            })
        };
        let (name, detail, kind, children) = match self.item {
            Item::Block(b) => {
                let children = match children {
                    true => tree.body(b).iter().filter_map(property).collect(),
                    false => Vec::new(),
                };
                match (b.kind, self.wall) {
                    (BlockKind::Wall, Some(w)) => {
                        let name = format!("wall {}: {}", w.index, w.wall_type().name());
                        (name, None, SymbolKind::Wall, children)
                    }
                    (BlockKind::Wall, None) => ("wall".into(), None, SymbolKind::Wall, children),
                    (BlockKind::Defaults, _) => {
                        ("defaults".into(), None, SymbolKind::Defaults, children)
                    }
                }
            }
            Item::Statement(s) => {
                let name = tree.keyword(s).map_or("", |k| k.name()).into();
                (name, detail(tree, s), SymbolKind::Statement, Vec::new())
            }
            // Never among the entries of the top level.
            Item::Stray(_) => (String::new(), None, SymbolKind::Statement, Vec::new()),
        };
        Symbol {
            name,
            detail,
            kind,
            range: self.range.clone(),
            selection_range: self.selection_range.clone(),
            children,
        }
    }
}

/// The outline, in order, in at most `max` entries (at least one): each wall
/// (`wall 3: disk`) and defaults block with its statements, and the statements outside
/// blocks; when they are more than `max`, the blocks without their statements; when the
/// top level alone is more than `max`, runs of 10, 100, … of its entries (the shortest
/// runs that fit), each a [`SymbolKind::Group`] named by its walls (`walls 0–99`).
pub fn symbols(analysis: &Analysis, max: usize) -> Vec<Symbol> {
    let tree = analysis.tree();
    let max = max.max(1);
    let (mut top, mut inner) = (0usize, 0usize);
    for item in tree.items() {
        match item {
            Item::Block(b) => {
                top += 1;
                inner += tree
                    .body(b)
                    .iter()
                    .filter(|s| tree.keyword(s).is_some())
                    .count();
            }
            Item::Statement(s) if tree.keyword(s).is_some() => top += 1,
            _ => {}
        }
    }
    if top <= max {
        let children = top + inner <= max;
        return tops(analysis).map(|t| t.symbol(tree, children)).collect();
    }
    let mut run = 10;
    while top.div_ceil(run) > max {
        run *= 10;
    }
    let mut out = Vec::with_capacity(top.div_ceil(run));
    let mut entries = tops(analysis);
    while let Some(first) = entries.next() {
        let (mut last, mut walls) = (first.range.end, first.wall.map(|w| (w.index, w.index)));
        let mut count = 1;
        while count < run {
            let Some(t) = entries.next() else { break };
            last = t.range.end;
            if let Some(w) = t.wall {
                walls = Some(walls.map_or((w.index, w.index), |(a, _)| (a, w.index)));
            }
            count += 1;
        }
        let name = match walls {
            Some((a, b)) if a == b => format!("wall {a}"),
            Some((a, b)) => format!("walls {a}–{b}"),
            None => format!("{} …", first.symbol(tree, false).name),
        };
        out.push(Symbol {
            name,
            detail: None,
            kind: SymbolKind::Group,
            range: first.range.start..last,
            selection_range: first.selection_range,
            children: Vec::new(),
        });
    }
    out
}

/// Every block with statements, from its keyword to the end of its last statement
/// (editors fold those that span several lines), in order.
pub fn folding(analysis: &Analysis) -> impl Iterator<Item = Range<usize>> + '_ {
    let tree = analysis.tree();
    tree.items().iter().filter_map(move |item| {
        let Item::Block(b) = item else { return None };
        let last = tree.body(b).last()?;
        Some(tree.statement_span(&b.head).start..tree.statement_span(last).end)
    })
}
