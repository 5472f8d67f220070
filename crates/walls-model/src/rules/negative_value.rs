//! C107 `negative-value`: `step`, `radius`, `hole-radius`, `length` or `mass` is negative.
//!
//! Checked as the value is read (`ValueRange::NonNegative` on a property).

use super::Read;
use walls_diagnostics::{Code, Diagnostic};

/// `step`, `radius`, `hole-radius`, `length` or `mass` is negative.
pub static NEGATIVE_VALUE: Code = Code {
    id: "C107",
    name: "negative-value",
    summary: "`step`, `radius`, `hole-radius`, `length` or `mass` is negative",
    explanation: "These are sizes, a time step and a mass: none may be negative.

Bad:
```walls
wall type disk
  radius -0.5
```

Good:
```walls
wall type disk
  radius 0.5
```
",
};

/// Reports a negative size, step or mass.
pub(crate) fn check(at: &Read, x: f64, out: &mut Vec<Diagnostic>) {
    if x < 0.0 {
        out.push(Diagnostic::error(
            &NEGATIVE_VALUE,
            at.span.clone(),
            format!(
                "`{}` is {}; it must not be negative",
                at.keyword.name(),
                at.written
            ),
        ));
    }
}
