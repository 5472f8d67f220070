//! C207 `unused-default`: a `defaults` value that no later wall inherits.
//!
//! Checked once per file, after the walls; the fix is safe.

use crate::check::Checker;
use crate::scene::{Place, Scene, Source};
use std::collections::HashSet;
use walls_diagnostics::{Applicability, Code, Diagnostic};

/// A `defaults` value that no later wall inherits.
pub static UNUSED_DEFAULT: Code = Code {
    id: "C207",
    name: "unused-default",
    summary: "a `defaults` value that no later wall inherits",
    explanation:
        "A default reaches only the walls created after it, and only those that do not set the
token themselves. One that no wall inherits has no effect: it comes after the last wall,
every later wall overrides it, or another default replaces it first. The fix (safe)
removes it.

Bad:
```walls
wall type plane
defaults color 3
```

Good:
```walls
defaults color 3
wall type plane
```
",
};

/// Reports each `defaults` value that no later wall inherits; a default is used by a wall
/// that inherits it and whose type reads it.
pub(crate) fn check(cx: &mut Checker, scene: &Scene) {
    let used: HashSet<usize> = scene
        .walls
        .iter()
        .flat_map(|w| {
            let t = w.wall_type();
            w.settings
                .iter()
                .filter(move |(k, _)| k.applies_to().contains(t))
        })
        .filter_map(|(_, s)| match &s.source {
            Source::Set {
                place: Place::Defaults,
                values,
                ..
            } => Some(values.range().start),
            _ => None,
        })
        .collect();
    let tree = cx.tree;
    for (k, span) in &scene.defaults {
        let values = tree
            .statement_at(span.start)
            .and_then(|s| tree.values(&s).first().map(|&v| tree.span(v).start));
        if values.is_some_and(|v| used.contains(&v)) {
            continue;
        }
        let mut d = Diagnostic::warning(
            &UNUSED_DEFAULT,
            span.clone(),
            format!("no wall inherits this default `{}`", k.name()),
        )
        .with_help(
            "a default reaches only walls created after it that do not set the token themselves",
        );
        if let Some(stmt) = tree.statement_at(span.start) {
            d = d.with_fix(
                Applicability::Safe,
                "remove the unused default",
                vec![cx.delete(&stmt)],
            );
        }
        cx.push(d);
    }
}
