//! C308 `inertia-off-diagonal`: the inertia tensor has off-diagonal terms.
//!
//! Checked as the value is read (`ValueRange::InertiaRow`, which gives the row).

use super::Read;
use crate::scene::Vec3;
use walls_diagnostics::{Code, Diagnostic};

/// The inertia tensor has off-diagonal terms.
pub static INERTIA_OFF_DIAGONAL: Code = Code {
    id: "C308",
    name: "inertia-off-diagonal",
    summary: "the inertia tensor has off-diagonal terms",
    explanation:
        "pkdgrav uses only the diagonal of the inertia tensor given by `ixj-vec`, `iyj-vec` and
`izj-vec`: give it in the principal frame.

Bad:
```walls
wall type disk
  ixj-vec 0.2 0.1 0
```

Good:
```walls
wall type disk
  ixj-vec 0.2 0 0
```
",
};

/// Warns about a row of the inertia tensor with non-zero terms off the diagonal, which
/// is at index `row`.
pub(crate) fn check(at: &Read, row: usize, v: Vec3, out: &mut Vec<Diagnostic>) {
    if (0..3).any(|j| j != row && v[j] != 0.0) {
        out.push(
            Diagnostic::warning(
                &INERTIA_OFF_DIAGONAL,
                at.span.clone(),
                format!(
                    "`{}` has off-diagonal terms; pkdgrav uses only the diagonal",
                    at.keyword.name()
                ),
            )
            .with_help("give the inertia in the principal frame (pxj-vec, pyj-vec, pzj-vec) so it is diagonal"),
        );
    }
}
