//! C304 `mass-without-assembly`: a wall has a mass but no assembly (an error).
//!
//! Checked over the reactive walls in SSDEM: walls are gathered by the token that gave
//! them their mass, and each token is reported once, after every wall. A mass from a
//! `defaults` line is reported on that line, with the walls it reaches as labels (the
//! first [`MAX_LABELS`]; the message gives their count).

use super::{ByPlace, walls_named};
use crate::check::Checker;
use crate::scene::{Place, Source, Wall};
use walls_diagnostics::{Applicability, Code, Diagnostic, Edit, MAX_LABELS};
use walls_keywords::Keyword;

/// A wall has a mass but no assembly.
pub static MASS_WITHOUT_ASSEMBLY: Code = Code {
    id: "C304",
    name: "mass-without-assembly",
    summary: "a wall has a mass but no assembly",
    explanation: "A wall with a mass reacts to the particles that hit it, and pkdgrav keeps the
motion of reactive walls per assembly. A wall with a mass but no `assembly` keeps the
assembly −1, and pkdgrav then writes its per-assembly arrays at index −1, memory it does
not own: the run is silently corrupted. Give every inertial wall an assembly, 0 or 1. A
`mass` on a `defaults` line reaches every later wall that does not set its own: the
diagnostic is on that line and lists the walls. The fix (unsafe: check that the walls
belong together) adds `assembly 0` after the `mass`.

Bad:
```walls
wall type disk
  mass 1
```

Good:
```walls
wall type disk
  mass 1
  assembly 0
```
",
};

/// The reactive walls with no assembly, by the start of the `mass` values that gave
/// them their mass.
#[derive(Default)]
pub(crate) struct NoAssembly<'w>(ByPlace<'w, usize>);

impl<'w> NoAssembly<'w> {
    /// Notes `wall`, a reactive wall, if it has no assembly.
    pub(crate) fn note(&mut self, wall: &'w Wall) {
        if wall.integer(Keyword::Assembly) >= 0 {
            return;
        }
        let key = wall
            .setting(Keyword::Mass)
            .and_then(|s| s.source.span())
            .map_or(wall.span.start, |s| s.start);
        self.0.add(key, wall);
    }

    /// Reports each `mass` token, in the order of its first wall.
    pub(crate) fn report(self, cx: &mut Checker) {
        for (_, walls) in self.0.into_groups() {
            report(cx, &walls);
        }
    }
}

/// One error for the `mass` token that gave `walls` their mass.
fn report(cx: &mut Checker, walls: &[&Wall]) {
    let first = walls[0];
    let setting = first.setting(Keyword::Mass);
    let from_defaults = matches!(
        setting.as_ref().map(|s| &s.source),
        Some(Source::Set {
            place: Place::Defaults,
            ..
        })
    );
    let span = cx.mass_span(first);
    let mut d = if from_defaults {
        let mut d = Diagnostic::error(
            &MASS_WITHOUT_ASSEMBLY,
            span.clone(),
            format!(
                "this `defaults` mass gives {} a mass but no assembly",
                walls_named(walls)
            ),
        );
        for w in walls.iter().take(MAX_LABELS) {
            d = d.with_label(w.span.clone(), format!("wall {} has this mass", w.index));
        }
        d
    } else {
        Diagnostic::error(
            &MASS_WITHOUT_ASSEMBLY,
            span.clone(),
            format!("wall {} has a mass but no assembly", first.index),
        )
    };
    d = d.with_help(
        "pkdgrav would index its per-assembly arrays at -1 and corrupt the run: give every inertial wall an assembly, 0 or 1",
    );
    if setting.is_some() {
        d = d.with_fix(
            Applicability::Unsafe,
            "add `assembly 0` after the mass",
            vec![Edit {
                span: span.end..span.end,
                replacement: " assembly 0".into(),
            }],
        );
    }
    cx.push_about(d, Some(Keyword::Mass));
}
