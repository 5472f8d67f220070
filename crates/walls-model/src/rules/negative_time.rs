//! C102 `negative-time`: `time` is negative.
//!
//! Checked as `time` is read (`ValueRange::NonNegative` on a general token).

use super::Read;
use walls_diagnostics::{Code, Diagnostic};

/// `time` is negative.
pub static NEGATIVE_TIME: Code = Code {
    id: "C102",
    name: "negative-time",
    summary: "`time` is negative",
    explanation:
        "`time` must not be negative (pkdgrav ignores its value, but refuses a negative one).

Bad:
```walls
time -1
wall type plane
```

Good:
```walls
wall type plane
```
",
};

/// Reports a negative `time`; returns whether it did.
pub(crate) fn check(at: &Read, x: f64, out: &mut Vec<Diagnostic>) -> bool {
    let negative = x < 0.0;
    if negative {
        out.push(Diagnostic::error(
            &NEGATIVE_TIME,
            at.span.clone(),
            format!("`time` is {x}; it must not be negative"),
        ));
    }
    negative
}
