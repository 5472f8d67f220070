//! C201 `ignored-by-type`: a wall sets a token its type does not use.
//!
//! Checked per wall, by its final type, for the wall's own tokens only; the fix is safe.

use crate::check::Checker;
use crate::scene::{Place, Source, Value, Wall};
use walls_diagnostics::{Applicability, Code, Diagnostic};
use walls_keywords::{Keyword, WallType};

/// A wall sets a token its type does not use.
pub static IGNORED_BY_TYPE: Code = Code {
    id: "C201",
    name: "ignored-by-type",
    summary: "a wall sets a token its type does not use",
    explanation:
        "Each wall type reads only some tokens (docs/spec.md §1): a plane has no radius, a triangle
no orient (its normal is vertex1 × vertex2). The value is ignored, which usually means the
type is not the one intended. Judged by the wall's final type; values inherited from
`defaults` are not reported. The fix (safe: the value has no effect) removes the token (every
one the wall's block sets); it is not offered for an `ang-speed` or `orient` that changes how
a triangle or rectangle spins (pkdgrav spins them too, with a warning). A wall whose `type` did not read is judged by no type: this
check is silent on it.

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

/// Reports each token the wall sets itself that its type `t` does not read, with a fix
/// that removes every statement of it in the wall's block (all have no effect).
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
        let statements = cx
            .block_at(wall.span.start)
            .map_or(&[][..], |b| tree.body(b));
        let edits = cx.delete_all(
            statements
                .iter()
                .filter(|s| tree.keyword(s) == Some(*k) && cx.sets(s)),
        );
        if let Some(edits) = edits.filter(|_| !spin_changes(wall, *k)) {
            d = d.with_fix(
                Applicability::Safe,
                format!("remove `{}`, which has no effect", k.name()),
                edits,
            );
        }
        cx.push(d);
    }
}

/// Whether removing the wall's own `k` could change its spin, ang-speed · orient, which
/// pkdgrav applies to every type (it only warns about a spinning triangle or rectangle):
/// the value left is the one from `defaults`, or the built-in one (where another fix
/// removes that default, which no wall takes once this wall sets its own).
fn spin_changes(wall: &Wall, k: Keyword) -> bool {
    if !matches!(k, Keyword::Orient | Keyword::AngSpeed) {
        return false;
    }
    let spin = |left: Option<Value>| {
        let value = |key: Keyword| if key == k { left } else { wall.value(key) };
        match (value(Keyword::Orient), value(Keyword::AngSpeed)) {
            (Some(Value::Vector(o)), Some(Value::Number(w))) => Some(o * w),
            _ => None,
        }
    };
    let now = spin(wall.value(k));
    now != spin(
        wall.settings
            .inherited(k)
            .map(|s| s.value)
            .or(Value::builtin(k)),
    ) || now != spin(Value::builtin(k))
}
