//! Go to definition: from a value to the token that set it.

use crate::Analysis;
use crate::locate::wall_at;
use std::ops::Range;
use walls_keywords::Keyword;
use walls_model::{Place, Source};

/// Where the value under byte `at` comes from: on a property of a wall, the values of
/// the token that set the wall's effective value (its own, or a `defaults` line); on
/// `wall`, those of every `defaults` value the wall inherits. Empty elsewhere.
pub fn definition(analysis: &Analysis, at: usize) -> Vec<Range<usize>> {
    let tree = analysis.tree();
    let Some(wall) = wall_at(analysis, at) else {
        return Vec::new();
    };
    let Some(stmt) = tree.statement_containing(at) else {
        return Vec::new();
    };
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
            .filter_map(|(_, s)| s.source.span())
            .collect(),
        Some(k) => wall
            .setting(k)
            .and_then(|s| s.source.span())
            .into_iter()
            .collect(),
        None => Vec::new(),
    }
}
