//! Features that help while typing and reading: completion, semantic tokens, inlay
//! hints and go to definition.

use crate::document::Document;
use crate::position::{offset, position, range};
use tower_lsp_server::ls_types::*;
use walls_keywords::{Builtin, Keyword, Role, ValueShape, WallType};
use walls_model::{Place, Source, Value, Wall};
use walls_syntax::{BlockKind, Item, TokenId, TokenKind};

/// The semantic token types, in legend order.
pub const TOKEN_TYPES: [SemanticTokenType; 5] = [
    SemanticTokenType::KEYWORD,
    SemanticTokenType::PROPERTY,
    SemanticTokenType::ENUM_MEMBER,
    SemanticTokenType::NUMBER,
    SemanticTokenType::COMMENT,
];

/// The token at or just before byte `at` (the one the cursor is in or at the end of).
fn token_before(doc: &Document, at: usize) -> Option<TokenId> {
    let starts = doc.parse.tree.tokens().starts();
    let i = starts.partition_point(|&s| (s as usize) < at);
    (i > 0).then(|| TokenId(i as u32 - 1))
}

/// The wall whose block holds byte `at`, or `None` in a defaults block or outside.
fn wall_at(doc: &Document, at: usize) -> Option<&Wall> {
    let tree = &doc.parse.tree;
    let mut wall: Option<usize> = None;
    let mut inside = false;
    for item in tree.items() {
        let start = match item {
            Item::Block(b) => tree.span(tree.head(&b.head)).start,
            Item::Statement(s) | Item::Stray(s) => tree.statement_span(s).start,
        };
        if start > at {
            break;
        }
        inside = matches!(item, Item::Block(b) if b.kind == BlockKind::Wall);
        if inside {
            wall = Some(wall.map_or(0, |w| w + 1));
        }
    }
    wall.filter(|_| inside)
        .and_then(|w| doc.analysis.scene.walls.get(w))
}

/// Completions at a position: type names after `type`, nothing in a comment, otherwise
/// keywords, those the wall's type reads first, each a snippet with its default values.
pub fn completion(doc: &Document, at: Position) -> Vec<CompletionItem> {
    let tree = &doc.parse.tree;
    let text = doc.text();
    let at = offset(&doc.index, text, at);
    let current = token_before(doc, at);
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
                kind: Some(CompletionItemKind::ENUM_MEMBER),
                detail: Some(
                    if t.ssdem_only() {
                        "wall type (SSDEM only)"
                    } else {
                        "wall type"
                    }
                    .into(),
                ),
                ..CompletionItem::default()
            })
            .collect();
    }
    let wall_type = wall_at(doc, at).map(Wall::wall_type);
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
                kind: Some(match k.role() {
                    Role::Property => CompletionItemKind::PROPERTY,
                    _ => CompletionItemKind::KEYWORD,
                }),
                detail: Some(k.shape().describe().into()),
                documentation: Some(Documentation::MarkupContent(MarkupContent {
                    kind: MarkupKind::Markdown,
                    value: k.markdown(),
                })),
                sort_text: Some(format!("{rank}{}", k.name())),
                insert_text: Some(snippet(k)),
                insert_text_format: Some(InsertTextFormat::SNIPPET),
                ..CompletionItem::default()
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

/// Semantic tokens of the whole document, or of the lines of `only`.
pub fn semantic_tokens(doc: &Document, only: Option<Range>) -> Vec<SemanticToken> {
    let tree = &doc.parse.tree;
    let text = doc.text();
    let (first, last) = only.map_or((0, u32::MAX), |r| (r.start.line, r.end.line));
    let mut out = Vec::new();
    let (mut prev_line, mut prev_start) = (0, 0);
    for i in 0..tree.tokens().len() {
        let id = TokenId(i as u32);
        let ty = match tree.kind(id) {
            TokenKind::Keyword(k) if k.role() == Role::Property => 1,
            TokenKind::Keyword(_) => 0,
            TokenKind::TypeName(_) => 2,
            TokenKind::Number => 3,
            TokenKind::Comment | TokenKind::GluedComment => 4,
            _ => continue,
        };
        let span = tree.span(id);
        let start = position(&doc.index, text, span.start);
        if start.line < first || start.line > last {
            continue;
        }
        let length = tree.token_text(id).encode_utf16().count() as u32;
        let delta_start = if start.line == prev_line {
            start.character - prev_start
        } else {
            start.character
        };
        out.push(SemanticToken {
            delta_line: start.line - prev_line,
            delta_start,
            length,
            token_type: ty,
            token_modifiers_bitset: 0,
        });
        (prev_line, prev_start) = (start.line, start.character);
    }
    out
}

/// Hints: what a wall inherits from `defaults`, values the unit tokens scale, and the
/// `k_t` a `k_n` sets.
pub fn inlay_hints(doc: &Document, r: Range) -> Vec<InlayHint> {
    let tree = &doc.parse.tree;
    let text = doc.text();
    let (first, last) = (
        offset(&doc.index, text, r.start),
        offset(&doc.index, text, r.end),
    );
    let mut hints = Vec::new();
    let hint = |at: usize, label: String| InlayHint {
        position: position(&doc.index, text, at),
        label: InlayHintLabel::String(label),
        kind: None,
        text_edits: None,
        tooltip: None,
        padding_left: Some(true),
        padding_right: None,
        data: None,
    };
    let mut walls = doc.analysis.scene.walls.iter();
    for item in tree.items() {
        let Item::Block(b) = item else { continue };
        let header = tree.statement_span(&b.head);
        let wall = (b.kind == BlockKind::Wall).then(|| walls.next()).flatten();
        if header.start > last {
            break;
        }
        let body = tree.body(b);
        let block_end = body
            .last()
            .map_or(header.end, |s| tree.statement_span(s).end);
        if block_end < first {
            continue;
        }
        if let Some(wall) = wall {
            let inherited: Vec<String> = wall
                .settings
                .iter()
                .filter(|(k, s)| {
                    k.applies_to().contains(wall.wall_type())
                        && matches!(
                            s.source,
                            Source::Set {
                                place: Place::Defaults,
                                ..
                            }
                        )
                })
                .map(|(k, s)| format!("{} {}", k.name(), show(&s.value)))
                .collect();
            if !inherited.is_empty() {
                let line_end = body
                    .first()
                    .filter(|s| tree.keyword(s) == Some(Keyword::Type))
                    .map_or(header.end, |s| tree.statement_span(s).end);
                hints.push(hint(line_end, format!("inherits {}", inherited.join(", "))));
            }
        }
        for s in body {
            let (Some(k), Some(&last_value)) = (tree.keyword(s), tree.values(s).last()) else {
                continue;
            };
            let end = tree.span(last_value).end;
            let Some(setting) = wall.and_then(|w| w.setting(k)) else {
                continue;
            };
            // Scaled by units: this token set the value, and it differs from the
            // numbers as written.
            let values = tree.values(s);
            let written = tree.span(values[0]).start..end;
            let raw: Vec<f64> = values
                .iter()
                .filter_map(|&v| tree.token_text(v).parse().ok())
                .collect();
            let scaled: Vec<f64> = match setting.value {
                Value::Number(x) => vec![x],
                Value::Vector(v) => v.iter().copied().collect(),
                _ => Vec::new(),
            };
            let orientation = matches!(k, Keyword::Orient | Keyword::OscVec);
            if setting.source.span() == Some(written)
                && !orientation
                && scaled.len() == raw.len()
                && scaled.iter().zip(&raw).any(|(a, b)| a != b)
            {
                hints.push(hint(
                    end,
                    format!("= {} in pkdgrav units", show(&setting.value)),
                ));
            }
            if matches!(k, Keyword::KN | Keyword::KNOuter | Keyword::KNInner) {
                let kt = match k {
                    Keyword::KN => Keyword::KT,
                    Keyword::KNOuter => Keyword::KTOuter,
                    _ => Keyword::KTInner,
                };
                if let Some(Value::Number(v)) = wall.and_then(|w| w.value(kt)) {
                    hints.push(hint(end, format!("{} = {v}", kt.name())));
                }
            }
        }
    }
    // Only the hints inside the requested range.
    hints.retain(|h| h.position >= r.start && h.position <= r.end);
    hints
}

fn show(v: &Value) -> String {
    match v {
        Value::Number(x) => format!("{x}"),
        Value::Integer(i) => format!("{i}"),
        Value::Vector(v) => format!("{} {} {}", v.x, v.y, v.z),
        Value::Type(t) => t.name().into(),
    }
}

/// Where the value under the cursor comes from: on a property of a wall, the token that
/// set the wall's effective value (its own, or a `defaults` line); on `wall`, every
/// `defaults` value the wall inherits.
pub fn definition(doc: &Document, uri: &Uri, at: Position) -> Vec<Location> {
    let tree = &doc.parse.tree;
    let text = doc.text();
    let at = offset(&doc.index, text, at);
    let Some(wall) = wall_at(doc, at) else {
        return Vec::new();
    };
    let Some(stmt) = tree.statement_containing(at) else {
        return Vec::new();
    };
    let location =
        |span: std::ops::Range<usize>| Location::new(uri.clone(), range(&doc.index, text, &span));
    match tree.keyword(&stmt) {
        Some(Keyword::Wall) => wall
            .settings
            .iter()
            .filter(|(_, s)| {
                matches!(
                    s.source,
                    Source::Set {
                        place: Place::Defaults,
                        ..
                    }
                )
            })
            .filter_map(|(_, s)| s.source.span().map(location))
            .collect(),
        Some(k) => wall
            .setting(k)
            .and_then(|s| s.source.span())
            .map(location)
            .into_iter()
            .collect(),
        None => Vec::new(),
    }
}
