//! Hover: the keyword's documentation, with the value it has where the cursor is and
//! where that value came from.

use crate::Analysis;
use crate::locate::{item_at, show, wall_at};
use std::ops::Range;
use walls_keywords::{Keyword, Role};
use walls_model::{Place, Source, Value};
use walls_syntax::{BlockKind, Item, Statement};

/// What a hover shows.
#[derive(Debug, Clone, PartialEq)]
pub struct Hover {
    /// The text, in Markdown.
    pub markdown: String,
    /// The statement it is about.
    pub range: Range<usize>,
}

/// The documentation of the keyword of the statement holding byte `offset`, with the
/// value it has there; `None` past the statement's end or on stray values.
pub fn hover(analysis: &Analysis, offset: usize) -> Option<Hover> {
    let tree = analysis.tree();
    let stmt = tree.statement_containing(offset)?;
    let keyword = tree.keyword(&stmt)?;
    let span = tree.statement_span(&stmt);
    if offset > span.end {
        return None;
    }
    let mut markdown = keyword.markdown();
    if let Some(note) = effective_value(analysis, &stmt, keyword) {
        markdown.push('\n');
        markdown.push_str(&note);
    }
    Some(Hover {
        markdown,
        range: span,
    })
}

/// For a property in a wall block: the wall's effective value and where it came from;
/// for one in a `defaults` block, what that means. Nothing for statements outside blocks.
fn effective_value(analysis: &Analysis, stmt: &Statement, keyword: Keyword) -> Option<String> {
    let tree = analysis.tree();
    let start = tree.statement_span(stmt).start;
    let Some(Item::Block(block)) = item_at(tree, start) else {
        return None;
    };
    if keyword.role() != Role::Property {
        return None;
    }
    if block.kind == BlockKind::Defaults {
        return Some("Sets the default for the walls created after this block.".into());
    }
    let wall = wall_at(analysis, start)?;
    let setting = wall.setting(keyword)?;
    let values = tree.values(stmt);
    let here = match (values.first(), values.last()) {
        (Some(&a), Some(&b)) => Some(tree.span(a).start..tree.span(b).end),
        _ => None,
    };
    let line = |at: usize| analysis.lines.line_of(at) + 1;
    let from = match &setting.source {
        Source::Builtin => "the built-in default".to_string(),
        Source::Set {
            derived_from: Some(k),
            values,
            ..
        } => format!(
            "the `{}` on line {} (2/7 of it)",
            k.name(),
            line(values.range().start)
        ),
        Source::Set { values, .. } if Some(values.range()) == here => "this token".to_string(),
        Source::Set {
            place: Place::Wall,
            values,
            ..
        } => format!(
            "the `{}` on line {}, which wins",
            keyword.name(),
            line(values.range().start)
        ),
        Source::Set {
            place: Place::Defaults,
            values,
            ..
        } => format!("`defaults` on line {}", line(values.range().start)),
    };
    let shown = show(&setting.value);
    // What happened to the number as written: unit scaling, or a percentage.
    let written = match (&setting.source, setting.value) {
        (
            Source::Set {
                values,
                derived_from: None,
                ..
            },
            Value::Number(x),
        ) if Some(values.range()) == here => analysis.text()[values.range()]
            .parse::<f64>()
            .ok()
            .filter(|&raw| raw != x),
        _ => None,
    };
    let note = match written {
        Some(raw) if keyword == Keyword::Transparency => {
            format!(" Written as {raw}, a percentage.")
        }
        Some(raw) => format!(" Written as {raw}, scaled by the units in force."),
        None => String::new(),
    };
    Some(format!(
        "In wall {}: **{shown}** (pkdgrav units), from {from}.{note}",
        wall.index
    ))
}
