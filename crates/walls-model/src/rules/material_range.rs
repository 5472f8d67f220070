//! C118 `material-range`: a spring constant, friction or cohesion value is negative (and not −1).
//!
//! Checked as the value is read (`ValueRange::ParticleOrNonNegative`).

use super::Read;
use walls_diagnostics::{Code, Diagnostic};

/// A spring constant, friction or cohesion value is negative (and not −1).
pub static MATERIAL_RANGE: Code = Code {
    id: "C118",
    name: "material-range",
    summary: "a spring constant, friction or cohesion value is negative (and not −1)",
    explanation:
        "`k_n`, `k_t`, `mu_s`, `mu_r`, `mu_t`, `beta_s`, `cohesive_coeff` and the two-layer
tokens are −1 (use the particle's value) or at least 0.

Bad:
```walls
wall type plane
  mu_s -0.5
```

Good:
```walls
wall type plane
  mu_s 0.5
```
",
};

/// Reports a negative material value other than −1.
pub(crate) fn check(at: &Read, x: f64, out: &mut Vec<Diagnostic>) {
    if x != -1.0 && x < 0.0 {
        out.push(Diagnostic::error(
            &MATERIAL_RANGE,
            at.span.clone(),
            format!(
                "`{}` is {}; it must be −1 (the particle's value) or at least 0",
                at.keyword.name(),
                at.written
            ),
        ));
    }
}
