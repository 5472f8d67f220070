//! Where a byte offset falls: the token at or before it, the top-level item holding it,
//! and the wall whose block holds it (through the walls' block ranges, the source map
//! the resolver records), each by binary search.

use crate::Analysis;
use walls_model::{Value, Wall};
use walls_syntax::{Item, SyntaxTree, TokenId};

/// The token at or just before byte `at` (the one the cursor is in or at the end of).
pub(crate) fn token_before(tree: &SyntaxTree, at: usize) -> Option<TokenId> {
    let starts = tree.tokens().starts();
    let i = starts.partition_point(|&s| (s as usize) < at);
    (i > 0).then(|| TokenId(i as u32 - 1))
}

/// Where an item starts: its first token.
fn item_start(tree: &SyntaxTree, item: &Item) -> usize {
    let head = match item {
        Item::Block(b) => &b.head,
        Item::Statement(s) | Item::Stray(s) => s,
    };
    tree.span(tree.head(head)).start
}

/// The last top-level item starting at or before byte `at`: the block (or statement)
/// that `at`, and the trivia after it up to the next item, belong to.
pub(crate) fn item_at(tree: &SyntaxTree, at: usize) -> Option<&Item> {
    let items = tree.items();
    let i = items.partition_point(|item| item_start(tree, item) <= at);
    items.get(i.checked_sub(1)?)
}

/// The wall whose block holds byte `at`, or `None` in a defaults block or outside: the
/// last wall whose block starts at or before `at`, unless another item starts between
/// its block's end and `at` (the trivia after a block's last statement, up to the next
/// statement, still belongs to the block).
pub(crate) fn wall_at(analysis: &Analysis, at: usize) -> Option<&Wall> {
    let walls = &analysis.scene().walls;
    let i = walls.partition_point(|w| w.block.range().start <= at);
    let wall = walls.get(i.checked_sub(1)?)?;
    let tree = analysis.tree();
    let starts = tree.tokens().starts();
    let start = |t: &TokenId| starts[t.0 as usize] as usize;
    let sig = tree.significant();
    // The first significant token after the block opens the next item.
    let next = sig.partition_point(|t| start(t) < wall.block.range().end);
    match sig.get(next) {
        Some(t) if start(t) <= at => None,
        _ => Some(wall),
    }
}

/// A value as hovers and hints show it.
pub(crate) fn show(v: &Value) -> String {
    match v {
        Value::Number(x) => format!("{x}"),
        Value::Integer(i) => format!("{i}"),
        Value::Vector(v) => format!("{} {} {}", v.x, v.y, v.z),
        Value::Type(t) => t.name().into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use walls_syntax::BlockKind;

    /// The wall at `at` by a scan of the items: the last item starting at or before
    /// `at`, if it is a wall block.
    fn scanned(analysis: &Analysis, at: usize) -> Option<usize> {
        let tree = analysis.tree();
        let mut wall: Option<usize> = None;
        let mut inside = false;
        for item in tree.items() {
            if item_start(tree, item) > at {
                break;
            }
            inside = matches!(item, Item::Block(b) if b.kind == BlockKind::Wall);
            if inside {
                wall = Some(wall.map_or(0, |w| w + 1));
            }
        }
        wall.filter(|_| inside)
    }

    #[test]
    fn the_source_map_agrees_with_a_scan_at_every_offset() {
        for text in [
            "",
            "wall\n",
            "radius 1\nwall type disk\n  radius 1 # r\n\n# after\nwall\nwall type plane",
            "defaults color 3\nwall type disk\nlengthunit 2\n  radius 1\nwall\ndefaults\n  k_n 1\ntime 0\nwall type shell\n  origin 1 2\n3\n",
            "1 2 wall type plane\r  origin 1 1 1\rdefaults\r\nwall  ",
        ] {
            let analysis = Analysis::of_text(text, &walls_model::Options::default());
            for at in 0..=text.len() + 1 {
                assert_eq!(
                    wall_at(&analysis, at).map(|w| w.index),
                    scanned(&analysis, at),
                    "{text:?} at {at}"
                );
            }
        }
    }
}
