//! C303 `assembly-without-mass`: a wall in an assembly has no mass.
//!
//! Checked per wall in SSDEM.

use crate::check::Checker;
use crate::scene::Wall;
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::Keyword;

/// A wall in an assembly has no mass.
pub static ASSEMBLY_WITHOUT_MASS: Code = Code {
    id: "C303",
    name: "assembly-without-mass",
    summary: "a wall in an assembly has no mass",
    explanation: "Every wall of an assembly needs a mass; the assembly's mass is their sum.

Bad:
```walls
wall type disk
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

/// Reports a wall that is in an assembly but has no mass.
pub(crate) fn check(cx: &mut Checker, wall: &Wall) {
    let assembly = wall.integer(Keyword::Assembly);
    if wall.is_reactive() || assembly < 0 {
        return;
    }
    let span = cx
        .span_of(wall, Keyword::Assembly)
        .unwrap_or_else(|| wall.span.clone());
    cx.push(Diagnostic::error(
        &ASSEMBLY_WITHOUT_MASS,
        span,
        format!(
            "wall {} is in assembly {assembly} but has no mass",
            wall.index
        ),
    ));
}
