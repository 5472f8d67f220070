//! C117 `transparency-range`: `transparency` is outside 0…100.
//!
//! Checked as the value is read (`ValueRange::Transparency`), which also turns a
//! percentage into the fraction stored.

use super::Read;
use crate::scene::Value;
use walls_diagnostics::{Code, Diagnostic};

/// `transparency` is outside 0…100.
pub static TRANSPARENCY_RANGE: Code = Code {
    id: "C117",
    name: "transparency-range",
    summary: "`transparency` is outside 0…100",
    explanation:
        "Transparency is a fraction from 0 to 1, or a percentage above 1 up to 100 (divided by
100).

Bad:
```walls
wall type plane
  transparency 150
```

Good:
```walls
wall type plane
  transparency 50
```
",
};

/// Reports a transparency outside 0…100; returns the value to store, a percentage above
/// 1 divided by 100.
pub(crate) fn check(at: &Read, x: f64, out: &mut Vec<Diagnostic>) -> Value {
    if !(0.0..=100.0).contains(&x) {
        out.push(Diagnostic::error(
            &TRANSPARENCY_RANGE,
            at.span.clone(),
            format!(
                "`transparency` is {}; it must be between 0 and 1, or a percentage up to 100",
                at.written
            ),
        ));
    } else if x > 1.0 {
        return Value::Number(x / 100.0);
    }
    Value::Number(x)
}
