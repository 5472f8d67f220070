//! M003 `hsdem-particle-value`: in HSDEM, a wall leaves `epsn` or `epst` at 99.
//!
//! Checked over the walls in HSDEM: walls are gathered by the place that leaves the
//! coefficient at 99, and each place is reported once, after every wall.

use super::{ByPlace, walls_named};
use crate::check::Checker;
use crate::scene::Wall;
use walls_diagnostics::{Code, Diagnostic, MAX_LABELS};
use walls_keywords::Keyword;

/// In HSDEM, a wall leaves `epsn` or `epst` at 99.
pub static HSDEM_PARTICLE_VALUE: Code = Code {
    id: "M003",
    name: "hsdem-particle-value",
    summary: "in HSDEM, a wall leaves `epsn` or `epst` at 99",
    explanation:
        "99 means \"use the particle's value\" in SSDEM, but pkdgrav's hard-sphere code never
substitutes it: 99 is used as the coefficient itself. Every wall of a hard-sphere run
needs real `epsn` and `epst` values (a `defaults` line is the easy way).

Bad (with `--mode hsdem`):
```walls
wall type plane
```

Good:
```walls
defaults epsn 0.9 epst 1
wall type plane
```
",
};

/// The walls that leave `epsn` or `epst` at 99, by keyword and by the start of the
/// token that set 99 (none for the built-in value).
#[derive(Default)]
pub(crate) struct AtNinetyNine<'w>(ByPlace<'w, (Keyword, Option<usize>)>);

impl<'w> AtNinetyNine<'w> {
    /// Notes `wall` if it leaves a coefficient at 99.
    pub(crate) fn note(&mut self, wall: &'w Wall) {
        for k in [Keyword::Epsn, Keyword::Epst] {
            if wall.number(k) == 99.0 {
                let key = wall
                    .setting(k)
                    .and_then(|s| s.source.span())
                    .map(|s| s.start);
                self.0.add((k, key), wall);
            }
        }
    }

    /// Reports each place, in the order of its first wall.
    pub(crate) fn report(self, cx: &mut Checker) {
        for ((k, source), walls) in self.0.into_groups() {
            report(cx, k, source.is_some(), &walls);
        }
    }
}

/// One diagnostic per place that leaves the coefficient at 99 for the walls listed.
fn report(cx: &mut Checker, k: Keyword, from_token: bool, walls: &[&Wall]) {
    let first = walls[0];
    let verb = if walls.len() == 1 { "leaves" } else { "leave" };
    let which = format!("{} {verb}", walls_named(walls));
    let span = if from_token {
        cx.span_of(first, k).unwrap_or_else(|| first.span.clone())
    } else {
        first.span.clone()
    };
    let mut d = Diagnostic::error(
        &HSDEM_PARTICLE_VALUE,
        span,
        format!(
            "{which} `{}` at 99, which pkdgrav's hard-sphere code uses as the coefficient itself",
            k.name()
        ),
    )
    .with_help(format!(
        "set `{}` for every wall, for instance once in a `defaults` block at the top",
        k.name()
    ));
    if !from_token {
        for w in walls[1..].iter().take(MAX_LABELS) {
            d = d.with_label(w.span.clone(), format!("wall {} too", w.index));
        }
    }
    cx.push_about(d, Some(k));
}
