//! C207 `unused-default`: a `defaults` value that no later wall inherits.
//!
//! Checked once per file, after the walls; the fix is safe.

use crate::check::Checker;
use crate::scene::{Place, Scene, Source};
use std::collections::HashSet;
use walls_diagnostics::{Applicability, Code, Diagnostic};
use walls_keywords::Keyword;

/// A `defaults` value that no later wall inherits.
pub static UNUSED_DEFAULT: Code = Code {
    id: "C207",
    name: "unused-default",
    summary: "a `defaults` value that no later wall inherits",
    explanation:
        "A default reaches only the walls created after it, and only those that do not set the
token themselves. One that no wall inherits has no effect: it comes after the last wall,
every later wall overrides it, or another default replaces it first. The fix (safe)
removes it, with the statements of the same token before it in its block (which it
overrides).

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
/// that inherits it and whose type reads it, or whose type is unknown (a wall judged by
/// no type); `orient` and `ang-speed`, which give the spin pkdgrav applies to a triangle
/// or rectangle too, by any wall that inherits them.
pub(crate) fn check(cx: &mut Checker, scene: &Scene) {
    let used: HashSet<usize> = scene
        .walls
        .iter()
        .flat_map(|w| {
            let t = w.known_type();
            w.settings.iter().filter(move |(k, _)| {
                t.is_none_or(|t| k.applies_to().contains(t))
                    || matches!(k, Keyword::Orient | Keyword::AngSpeed)
            })
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
        // The statement and the earlier ones of its block with the same keyword, which
        // it overrides: removing it alone would bring back the one before it.
        let statements = cx.block_at(span.start).map_or(&[][..], |b| tree.body(b));
        let edits = cx.delete_all(statements.iter().filter(|s| {
            tree.keyword(s) == Some(*k) && cx.sets(s) && tree.span(tree.head(s)).start <= span.start
        }));
        if let Some(edits) = edits {
            d = d.with_fix(Applicability::Safe, "remove the unused default", edits);
        }
        cx.push(d);
    }
}
