//! C301 `reactive-type`: a reactive wall (with a mass) is a plane or an infinite cylinder.
//!
//! Checked per reactive wall in SSDEM, by its final type.

use crate::check::Checker;
use crate::scene::Wall;
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::{Types, WallType};

/// A reactive wall (with a mass) is a plane or an infinite cylinder.
pub static REACTIVE_TYPE: Code = Code {
    id: "C301",
    name: "reactive-type",
    summary: "a reactive wall (with a mass) is a plane or an infinite cylinder",
    explanation:
        "Only triangles, rectangles, finite cylinders, disks and shells can have a finite mass and
react to particles.

Bad:
```walls
wall type plane
  mass 1
  assembly 0
```

Good:
```walls
wall type disk
  mass 1
  assembly 0
```
",
};

/// Reports a reactive wall of a type that cannot have a mass.
pub(crate) fn check(cx: &mut Checker, wall: &Wall, t: WallType) {
    if !wall.is_reactive() || Types::REACTIVE.contains(t) {
        return;
    }
    cx.push(Diagnostic::error(
        &REACTIVE_TYPE,
        cx.mass_span(wall),
        format!(
            "wall {} is a {} and cannot have a mass",
            wall.index,
            t.name()
        ),
    ));
}
