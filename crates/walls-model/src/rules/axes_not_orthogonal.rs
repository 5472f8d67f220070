//! C307 `axes-not-orthogonal`: a reactive wall's principal axes are not mutually orthogonal.
//!
//! Checked per reactive wall in SSDEM.

use crate::check::Checker;
use crate::scene::Wall;
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::Keyword;

/// A reactive wall's principal axes are not mutually orthogonal.
pub static AXES_NOT_ORTHOGONAL: Code = Code {
    id: "C307",
    name: "axes-not-orthogonal",
    summary: "a reactive wall's principal axes are not mutually orthogonal",
    explanation:
        "The principal axes should form an orthonormal basis; checked for reactive walls, with
|cos| above 0.001 reported.

Bad:
```walls
wall type disk
  mass 1
  assembly 0
  pyj-vec 0.6 0.8 0
```

Good:
```walls
wall type disk
  mass 1
  assembly 0
  pyj-vec 0 1 0
```
",
};

/// Principal axes with |cos| above this are not orthogonal.
pub const AXES_COS_TOLERANCE: f64 = 0.001;

/// Reports each pair of a reactive wall's principal axes that are not orthogonal.
pub(crate) fn check(cx: &mut Checker, wall: &Wall) {
    if !wall.is_reactive() {
        return;
    }
    let axes = [Keyword::PxjVec, Keyword::PyjVec, Keyword::PzjVec];
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        let (a, b) = (wall.vector(axes[i]), wall.vector(axes[j]));
        if a.norm() == 0.0 || b.norm() == 0.0 {
            continue;
        }
        let cos = a.dot(&b) / (a.norm() * b.norm());
        if cos.abs() > AXES_COS_TOLERANCE {
            let span = cx
                .span_of(wall, axes[j])
                .or_else(|| cx.span_of(wall, axes[i]))
                .unwrap_or_else(|| wall.span.clone());
            cx.push(Diagnostic::warning(
                &AXES_NOT_ORTHOGONAL,
                span,
                format!(
                    "principal axes `{}` and `{}` are not orthogonal (|cos| {:.4})",
                    axes[i].name(),
                    axes[j].name(),
                    cos.abs()
                ),
            ));
        }
    }
}
