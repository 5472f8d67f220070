//! Completion: type names after `type`, nothing in a comment, otherwise every keyword,
//! those the wall's type reads first, each a snippet with its default values.

use crate::Analysis;
use crate::locate::{token_before, wall_at};
use walls_keywords::{Builtin, Keyword, Role, ValueShape, WallType};
use walls_model::Wall;
use walls_syntax::TokenKind;

/// What a completion item completes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CompletionKind {
    /// A wall type's name, after `type`.
    WallType,
    /// A keyword that sets a wall property.
    Property,
    /// Any other keyword (blocks, units, `time`).
    Keyword,
}

/// One completion.
#[derive(Debug, Clone, PartialEq)]
pub struct CompletionItem {
    /// The word offered.
    pub label: String,
    /// What it is.
    pub kind: CompletionKind,
    /// A short description: what values it takes, or what it names.
    pub detail: String,
    /// Its documentation, in Markdown.
    pub documentation: Option<String>,
    /// The key to sort by, where the label's order is not the one wanted.
    pub sort_text: Option<String>,
    /// The text to insert as a snippet (`${1:default}` tab stops), instead of the label.
    pub snippet: Option<String>,
}

/// The completions at byte `at`.
pub fn completion(analysis: &Analysis, at: usize) -> Vec<CompletionItem> {
    let tree = analysis.tree();
    let current = token_before(tree, at);
    if let Some(t) = current {
        let kind = tree.kind(t);
        let span = tree.span(t);
        if matches!(kind, TokenKind::Comment | TokenKind::GluedComment) && span.end >= at {
            return Vec::new();
        }
    }
    // The significant token before the word being typed.
    let typing = current.filter(|&t| !tree.kind(t).is_trivia() && tree.span(t).end == at);
    let before = tree
        .significant()
        .iter()
        .rev()
        .find(|&&t| tree.span(t).end <= at && Some(t) != typing)
        .copied();
    if before.is_some_and(|t| tree.kind(t) == TokenKind::Keyword(Keyword::Type)) {
        return WallType::SPELLINGS
            .iter()
            .map(|&(name, t)| CompletionItem {
                label: name.into(),
                kind: CompletionKind::WallType,
                detail: if t.ssdem_only() {
                    "wall type (SSDEM only)"
                } else {
                    "wall type"
                }
                .into(),
                documentation: None,
                sort_text: None,
                snippet: None,
            })
            .collect();
    }
    let wall_type = wall_at(analysis, at).map(Wall::wall_type);
    Keyword::ALL
        .iter()
        .map(|&k| {
            let rank = match (k.role(), wall_type) {
                (Role::Property, Some(t)) if k.applies_to().contains(t) => 0,
                (Role::Property, Some(_)) => 2,
                (Role::Property, None) => 1,
                (Role::Block, _) => 1,
                (Role::General, _) => 3,
            };
            CompletionItem {
                label: k.name().into(),
                kind: match k.role() {
                    Role::Property => CompletionKind::Property,
                    _ => CompletionKind::Keyword,
                },
                detail: k.shape().describe().into(),
                documentation: Some(k.markdown()),
                sort_text: Some(format!("{rank}{}", k.name())),
                snippet: Some(snippet(k)),
            }
        })
        .collect()
}

/// The keyword with tab stops for its values, prefilled with the built-in defaults.
fn snippet(k: Keyword) -> String {
    let n = |x: f64| format!("{x}");
    match (k.shape(), k.builtin()) {
        (ValueShape::Vector, Builtin::Vector([x, y, z])) => {
            format!(
                "{} ${{1:{}}} ${{2:{}}} ${{3:{}}}",
                k.name(),
                n(x),
                n(y),
                n(z)
            )
        }
        (ValueShape::Number, Builtin::Number(x)) => format!("{} ${{1:{}}}", k.name(), n(x)),
        (ValueShape::Integer, Builtin::Integer(i)) => format!("{} ${{1:{i}}}", k.name()),
        (ValueShape::TypeName, _) => {
            let names: Vec<&str> = WallType::ALL.iter().map(|t| t.name()).collect();
            format!("{} ${{1|{}|}}", k.name(), names.join(","))
        }
        _ => k.name().into(),
    }
}
