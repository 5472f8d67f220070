//! Inlay hints: what a wall inherits from `defaults`, values the unit tokens scale, and
//! the `k_t` a `k_n` sets.

use crate::Analysis;
use crate::locate::show;
use std::ops::Range;
use walls_keywords::Keyword;
use walls_model::{Place, Source, Value};
use walls_syntax::{BlockKind, Item};

/// A note shown inline.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InlayHint {
    /// Where it goes: the byte it follows.
    pub offset: usize,
    /// What it says.
    pub label: String,
}

/// The hints at offsets within `range` (both ends included), in order of the blocks; the
/// first `max` of them.
pub fn inlay_hints(analysis: &Analysis, range: Range<usize>, max: usize) -> Vec<InlayHint> {
    let tree = analysis.tree();
    let (first, last) = (range.start, range.end);
    let mut hints = Vec::new();
    let hint = |hints: &mut Vec<InlayHint>, offset: usize, label: String| {
        if (first..=last).contains(&offset) {
            hints.push(InlayHint { offset, label });
        }
    };
    let mut walls = analysis.scene().walls.iter();
    for item in tree.items() {
        if hints.len() >= max {
            break;
        }
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
                hint(
                    &mut hints,
                    line_end,
                    format!("inherits {}", inherited.join(", ")),
                );
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
            let scaled: Vec<f64> = match setting.value {
                Value::Number(x) => vec![x],
                Value::Vector(v) => v.iter().copied().collect(),
                _ => Vec::new(),
            };
            // One more than the value has is enough to tell the counts apart: a line of
            // a million numbers is not read into a million.
            let raw: Vec<f64> = values
                .iter()
                .filter_map(|&v| tree.token_text(v).parse().ok())
                .take(scaled.len() + 1)
                .collect();
            let orientation = matches!(k, Keyword::Orient | Keyword::OscVec);
            if setting.source.span() == Some(written)
                && !orientation
                && scaled.len() == raw.len()
                && scaled.iter().zip(&raw).any(|(a, b)| a != b)
            {
                hint(
                    &mut hints,
                    end,
                    format!("= {} in pkdgrav units", show(&setting.value)),
                );
            }
            if matches!(k, Keyword::KN | Keyword::KNOuter | Keyword::KNInner) {
                let kt = match k {
                    Keyword::KN => Keyword::KT,
                    Keyword::KNOuter => Keyword::KTOuter,
                    _ => Keyword::KTInner,
                };
                if let Some(Value::Number(v)) = wall.and_then(|w| w.value(kt)) {
                    hint(&mut hints, end, format!("{} = {v}", kt.name()));
                }
            }
        }
    }
    hints.truncate(max);
    hints
}
