//! C302 `reactive-spinning`: a reactive wall has an `ang-speed`.
//!
//! Checked per reactive wall in SSDEM.

use crate::check::Checker;
use crate::scene::Wall;
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::Keyword;

/// A reactive wall has an `ang-speed`.
pub static REACTIVE_SPINNING: Code = Code {
    id: "C302",
    name: "reactive-spinning",
    summary: "a reactive wall has an `ang-speed`",
    explanation: "A reactive wall's rotation comes from `rot-vec` and the torques on its assembly;
`ang-speed` must be 0.

Bad:
```walls
wall type disk
  mass 1
  assembly 0
  ang-speed 2
```

Good:
```walls
wall type disk
  mass 1
  assembly 0
  rot-vec 0 0 2
```
",
};

/// Reports a reactive wall with a non-zero `ang-speed`.
pub(crate) fn check(cx: &mut Checker, wall: &Wall) {
    if !wall.is_reactive() || wall.number(Keyword::AngSpeed) == 0.0 {
        return;
    }
    let span = cx
        .span_of(wall, Keyword::AngSpeed)
        .unwrap_or_else(|| wall.span.clone());
    cx.push(
        Diagnostic::error(
            &REACTIVE_SPINNING,
            span,
            format!("reactive wall {} has an ang-speed", wall.index),
        )
        .with_help("a reactive wall turns through rot-vec and the torques on its assembly"),
    );
}
