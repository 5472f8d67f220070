//! C120 `number-too-large`: a value overflows a double once scaled by its unit.
//!
//! Checked as a property's value is read and scaled, before its range; the value is not
//! stored.

use super::Read;
use crate::scene::Value;
use walls_diagnostics::{Code, Diagnostic};

/// A value overflows a double once scaled by its unit.
pub static NUMBER_TOO_LARGE: Code = Code {
    id: "C120",
    name: "number-too-large",
    summary: "a value overflows a double once scaled by its unit",
    explanation:
        "A value such as `1e999`, or a large value times a large unit, is infinite as a double;
the value is ignored.

Bad:
```walls
wall type disk
  radius 1e999
```

Good:
```walls
wall type disk
  radius 1e9
```
",
};

/// Scaled values must stay finite doubles: `1e999`, or a huge value times a unit.
/// Returns whether the value is finite.
#[inline]
pub(crate) fn check(at: &Read, value: Value, out: &mut Vec<Diagnostic>) -> bool {
    let finite = match value {
        Value::Number(x) => x.is_finite(),
        Value::Vector(v) => v.iter().all(|x| x.is_finite()),
        _ => true,
    };
    if !finite {
        out.push(
            Diagnostic::error(
                &NUMBER_TOO_LARGE,
                at.span.clone(),
                format!(
                    "`{}` is too large for a double once scaled ({})",
                    at.keyword.name(),
                    at.keyword.dimension().describe()
                ),
            )
            .with_help("the value is ignored; write it in units that keep it below about 1.8e308"),
        );
    }
    finite
}
