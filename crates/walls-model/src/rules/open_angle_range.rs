//! C111 `open-angle-range`: `open-angle` is outside 0…180 degrees.
//!
//! Checked as the value is read (`ValueRange::HalfTurn`).

use super::Read;
use walls_diagnostics::{Code, Diagnostic};

/// `open-angle` is outside 0…180 degrees.
pub static OPEN_ANGLE_RANGE: Code = Code {
    id: "C111",
    name: "open-angle-range",
    summary: "`open-angle` is outside 0…180 degrees",
    explanation:
        "A shell's opening is a cap of half-angle `open-angle` degrees centred on +orient: 0 is a
closed sphere, 90 a hemisphere, 180 nothing left.

Bad:
```walls
wall type shell
  open-angle 270
```

Good:
```walls
wall type shell
  open-angle 90
```
",
};

/// Reports an `open-angle` outside 0…180.
pub(crate) fn check(at: &Read, x: f64, out: &mut Vec<Diagnostic>) {
    if !(0.0..=180.0).contains(&x) {
        out.push(Diagnostic::error(
            &OPEN_ANGLE_RANGE,
            at.span.clone(),
            format!(
                "`open-angle` is {}; it must be between 0 and 180 degrees",
                at.written
            ),
        ));
    }
}
