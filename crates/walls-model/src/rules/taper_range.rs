//! C109 `taper-range`: `taper` is outside 0…1.
//!
//! Checked as the value is read (`ValueRange::Fraction`).

use super::Read;
use walls_diagnostics::{Code, Diagnostic};

/// `taper` is outside 0…1.
pub static TAPER_RANGE: Code = Code {
    id: "C109",
    name: "taper-range",
    summary: "`taper` is outside 0…1",
    explanation:
        "`taper` is the fraction by which a finite cylinder narrows towards +orient: 0 is a plain
cylinder, 1 comes to a point.

Bad:
```walls
wall type cylinder-finite
  taper 1.5
```

Good:
```walls
wall type cylinder-finite
  taper 0.5
```
",
};

/// Reports a `taper` outside 0…1.
pub(crate) fn check(at: &Read, x: f64, out: &mut Vec<Diagnostic>) {
    if !(0.0..=1.0).contains(&x) {
        out.push(
            Diagnostic::error(
                &TAPER_RANGE,
                at.span.clone(),
                format!("`taper` is {}; it must be between 0 and 1", at.written),
            )
            .with_help("0 is a plain cylinder, 1 narrows it to a point at the +orient end"),
        );
    }
}
