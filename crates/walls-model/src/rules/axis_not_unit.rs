//! C306 `axis-not-unit`: a principal axis is not a unit vector.
//!
//! Checked as the value is read (`ValueRange::UnitVector`); the fix is unsafe.

use super::Read;
use crate::fix;
use crate::scene::{Vec3, direction};
use walls_diagnostics::{Applicability, Code, Diagnostic, Edit};

/// A principal axis is not a unit vector.
pub static AXIS_NOT_UNIT: Code = Code {
    id: "C306",
    name: "axis-not-unit",
    summary: "a principal axis is not a unit vector",
    explanation:
        "`pxj-vec`, `pyj-vec` and `pzj-vec` must each have length 1 ± 0.001. The fix (unsafe)
normalises the axis.

Bad:
```walls
wall type disk
  pxj-vec 2 0 0
```

Good:
```walls
wall type disk
  pxj-vec 1 0 0
```
",
};

/// A principal axis may differ from unit length by this much.
pub const AXIS_LENGTH_TOLERANCE: f64 = 0.001;

/// Reports a principal axis that is not a unit vector, with a fix that normalises it.
pub(crate) fn check(at: &Read, v: Vec3, out: &mut Vec<Diagnostic>) {
    if (v.norm() - 1.0).abs() <= AXIS_LENGTH_TOLERANCE {
        return;
    }
    let mut d = Diagnostic::error(
        &AXIS_NOT_UNIT,
        at.span.clone(),
        format!(
            "principal axis `{}` has length {:.6}; it must be 1 ± {AXIS_LENGTH_TOLERANCE}",
            at.keyword.name(),
            v.norm()
        ),
    );
    if let Some(n) = direction(&v) {
        d = d.with_fix(
            Applicability::Unsafe,
            "normalise the axis",
            vec![Edit {
                span: at.span.clone(),
                replacement: fix::vector(&n),
            }],
        );
    }
    out.push(d);
}
