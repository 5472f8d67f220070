//! C114 `epsn-range`: `epsn` is above 1 (and not 99).
//!
//! Checked as the value is read (`ValueRange::NormalRestitution`).

use super::Read;
use walls_diagnostics::{Code, Diagnostic};

/// `epsn` is above 1 (and not 99).
pub static EPSN_RANGE: Code = Code {
    id: "C114",
    name: "epsn-range",
    summary: "`epsn` is above 1 (and not 99)",
    explanation:
        "The normal coefficient of restitution is at most 1 (elastic); 0 sticks, a negative value
removes the particle, and 99 means \"use the particle's value\".

Bad:
```walls
wall type plane
  epsn 1.2
```

Good:
```walls
wall type plane
  epsn 0.8
```
",
};

/// Reports an `epsn` above 1 that is not 99.
pub(crate) fn check(at: &Read, x: f64, out: &mut Vec<Diagnostic>) {
    if x != 99.0 && x > 1.0 {
        out.push(
            Diagnostic::error(
                &EPSN_RANGE,
                at.span.clone(),
                format!("`epsn` is {}; it must be at most 1, or 99", at.written),
            )
        .with_help("99 means the particle's value; 1 is elastic, 0 sticks, negative removes the particle"),
        );
    }
}
