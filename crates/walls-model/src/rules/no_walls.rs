//! C208 `no-walls`: the file defines no wall.
//!
//! Checked once per file.

use crate::check::Checker;
use crate::scene::Scene;
use walls_diagnostics::{Code, Diagnostic};

/// The file defines no wall.
pub static NO_WALLS: Code = Code {
    id: "C208",
    name: "no-walls",
    summary: "the file defines no wall",
    explanation:
        "A walls file without a `wall` token gives pkdgrav nothing to do; usually the file is
empty or was cut short.

Bad:
```walls
lengthunit 2
```

Good:
```walls
wall type plane
```
",
};

/// Reports a file without walls, at its start.
pub(crate) fn check(cx: &mut Checker, scene: &Scene) {
    if scene.walls.is_empty() {
        cx.push(Diagnostic::warning(
            &NO_WALLS,
            0..0,
            "the file defines no wall",
        ));
    }
}
