//! C101 `unit-not-positive`: a unit token is zero or negative.
//!
//! Checked as a unit token is read (`ValueRange::Positive`); the unit in force is kept.

use super::Read;
use walls_diagnostics::{Code, Diagnostic};

/// A unit token is zero or negative.
pub static UNIT_NOT_POSITIVE: Code = Code {
    id: "C101",
    name: "unit-not-positive",
    summary: "a unit token is zero or negative",
    explanation:
        "`lengthunit`, `massunit` and `timeunit` multiply the values read after them and must be
positive. The unit in force is kept when one is not.

Bad:
```walls
lengthunit 0
wall type plane
```

Good:
```walls
lengthunit 6.68458e-14
wall type plane
```
",
};

/// Reports a unit that is not a positive finite number; returns whether the unit may be
/// used.
pub(crate) fn check(at: &Read, x: f64, out: &mut Vec<Diagnostic>) -> bool {
    if x.is_finite() && x > 0.0 {
        return true;
    }
    out.push(Diagnostic::error(
        &UNIT_NOT_POSITIVE,
        at.span.clone(),
        format!(
            "`{}` must be positive, not {x}; the unit in force is kept",
            at.keyword.name()
        ),
    ));
    false
}
