//! C119 `cohesion-model`: `cohesion_model` is not −1, 0 or 1.
//!
//! Checked as the value is read (`ValueRange::CohesionModel`).

use super::Read;
use walls_diagnostics::{Code, Diagnostic};

/// `cohesion_model` is not −1, 0 or 1.
pub static COHESION_MODEL: Code = Code {
    id: "C119",
    name: "cohesion-model",
    summary: "`cohesion_model` is not −1, 0 or 1",
    explanation:
        "−1 uses the particle's model, 0 is the microscopic contact model, 1 the cohesive bridge
model.

Bad:
```walls
wall type plane
  cohesion_model 2
```

Good:
```walls
wall type plane
  cohesion_model 1
```
",
};

/// Reports a `cohesion_model` other than −1, 0 or 1.
pub(crate) fn check(at: &Read, m: i64, out: &mut Vec<Diagnostic>) {
    if !(-1..=1).contains(&m) {
        out.push(Diagnostic::error(
            &COHESION_MODEL,
            at.span.clone(),
            format!(
                "`cohesion_model` is {}; it must be −1 (particle's), 0 (contact) or 1 (bridge)",
                at.written
            ),
        ));
    }
}
