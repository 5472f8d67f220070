//! C112 `osc-phase-range`: `osc-phase` is outside 0…1.
//!
//! Checked as the value is read (`ValueRange::Phase`).

use super::Read;
use crate::fix;
use walls_diagnostics::{Code, Diagnostic};

/// `osc-phase` is outside 0…1.
pub static OSC_PHASE_RANGE: Code = Code {
    id: "C112",
    name: "osc-phase-range",
    summary: "`osc-phase` is outside 0…1",
    explanation:
        "The phase is a fraction of a cycle, from 0 to 1 (0.75 starts the wall at the bottom of
its cycle).

Bad:
```walls
wall type plane
  osc-ampl 0.1
  osc-freq 2
  osc-phase 1.25
```

Good:
```walls
wall type plane
  osc-ampl 0.1
  osc-freq 2
  osc-phase 0.25
```
",
};

/// Reports an `osc-phase` outside 0…1, with the same phase within one cycle.
pub(crate) fn check(at: &Read, x: f64, out: &mut Vec<Diagnostic>) {
    if !(0.0..=1.0).contains(&x) {
        out.push(
            Diagnostic::error(
                &OSC_PHASE_RANGE,
                at.span.clone(),
                format!(
                    "`osc-phase` is {}; it is a fraction of a cycle, between 0 and 1",
                    at.written
                ),
            )
            .with_help(format!(
                "the same phase within one cycle is {}",
                fix::number(x.rem_euclid(1.0))
            )),
        );
    }
}
