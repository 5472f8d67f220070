//! C115 `epst-range`: `epst` is outside its range for the contact model.
//!
//! Checked as the value is read (`ValueRange::TangentialRestitution`), in the mode of
//! the run.

use super::Read;
use crate::ContactModel;
use walls_diagnostics::{Code, Diagnostic};

/// `epst` is outside its range for the contact model.
pub static EPST_RANGE: Code = Code {
    id: "C115",
    name: "epst-range",
    summary: "`epst` is outside its range for the contact model",
    explanation:
        "The tangential coefficient of restitution is −1…1 in HSDEM and 0…1 in SSDEM, or 99 for
the particle's value.

Bad:
```walls
wall type plane
  epst -0.5
```

Good:
```walls
wall type plane
  epst 0.5
```
",
};

/// Reports an `epst` outside the range of the contact model, unless it is 99.
pub(crate) fn check(at: &Read, x: f64, out: &mut Vec<Diagnostic>) {
    let (lo, model) = match at.mode {
        ContactModel::Hsdem => (-1.0, "HSDEM"),
        ContactModel::Ssdem => (0.0, "SSDEM"),
    };
    if x != 99.0 && !(lo..=1.0).contains(&x) {
        out.push(
            Diagnostic::error(
                &EPST_RANGE,
                at.span.clone(),
                format!(
                    "`epst` is {}; in {model} it must be between {lo} and 1, or 99",
                    at.written
                ),
            )
            .with_help("99 means the particle's value"),
        );
    }
}
