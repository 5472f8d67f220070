//! C304 `mass-without-assembly`: a wall has a mass but no assembly.
//!
//! Checked per reactive wall in SSDEM.

use crate::check::Checker;
use crate::scene::Wall;
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::Keyword;

/// A wall has a mass but no assembly.
pub static MASS_WITHOUT_ASSEMBLY: Code = Code {
    id: "C304",
    name: "mass-without-assembly",
    summary: "a wall has a mass but no assembly",
    explanation: "The document asks every inertial wall to be given an assembly, 0 or 1.

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

/// Reports a reactive wall in no assembly.
pub(crate) fn check(cx: &mut Checker, wall: &Wall) {
    if !wall.is_reactive() || wall.integer(Keyword::Assembly) >= 0 {
        return;
    }
    cx.push(
        Diagnostic::warning(
            &MASS_WITHOUT_ASSEMBLY,
            cx.mass_span(wall),
            format!("wall {} has a mass but no assembly", wall.index),
        )
        .with_help("give every inertial wall an assembly, 0 or 1"),
    );
}
