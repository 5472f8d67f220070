//! C201 `ignored-by-type`: a wall sets a token its type does not use.
//!
//! Checked per wall, by its final type, for the wall's own tokens only; the fix is safe.

use crate::check::Checker;
use crate::scene::{Place, Source, Wall};
use walls_diagnostics::{Applicability, Code, Diagnostic};
use walls_keywords::WallType;

/// A wall sets a token its type does not use.
pub static IGNORED_BY_TYPE: Code = Code {
    id: "C201",
    name: "ignored-by-type",
    summary: "a wall sets a token its type does not use",
    explanation:
        "Each wall type reads only some tokens (docs/spec.md §1): a plane has no radius, a triangle
no orient (its normal is vertex1 × vertex2). The value is ignored, which usually means the
type is not the one intended. Judged by the wall's final type; values inherited from
`defaults` are not reported. The fix (safe: the value has no effect) removes the token.

Bad:
```walls
wall type plane
  radius 2
```

Good:
```walls
wall type disk
  radius 2
```
",
};

/// Reports each token the wall sets itself that its type `t` does not read.
pub(crate) fn check(cx: &mut Checker, wall: &Wall, t: WallType) {
    let tree = cx.tree;
    for (k, setting) in wall.settings.iter() {
        let Source::Set {
            place: Place::Wall,
            values,
            derived_from: None,
        } = &setting.source
        else {
            continue;
        };
        if k.applies_to().contains(t) {
            continue;
        }
        let Some(stmt) = tree.statement_containing(values.range().start) else {
            continue;
        };
        let keyword = tree.span(tree.head(&stmt));
        let mut d = Diagnostic::warning(
            &IGNORED_BY_TYPE,
            keyword.clone(),
            format!(
                "a {} wall ignores `{}`",
                t.name(),
                &tree.text()[keyword.clone()]
            ),
        )
        .with_help(format!(
            "`{}` applies to {}",
            k.name(),
            k.applies_to().names().join(", ")
        ));
        d = d.with_fix(
            Applicability::Safe,
            format!("remove `{}`, which has no effect", k.name()),
            vec![cx.delete(&stmt)],
        );
        cx.push(d);
    }
}
