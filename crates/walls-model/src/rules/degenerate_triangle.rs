//! C105 `degenerate-triangle`: a triangle's `vertex1` and `vertex2` are parallel.
//!
//! Checked per wall, by its final type.

use crate::check::Checker;
use crate::scene::{Wall, direction};
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::{Keyword, WallType};

/// A triangle's `vertex1` and `vertex2` are parallel.
pub static DEGENERATE_TRIANGLE: Code = Code {
    id: "C105",
    name: "degenerate-triangle",
    summary: "a triangle's `vertex1` and `vertex2` are parallel",
    explanation:
        "A triangle's normal is vertex1 × vertex2, so the two edges must not be parallel: a
triangle with parallel edges has no area and no normal.

Bad:
```walls
wall type triangle
  vertex1 1 0 0
  vertex2 2 0 0
```

Good:
```walls
wall type triangle
  vertex1 1 0 0
  vertex2 0 1 0
```
",
};

/// Reports a triangle whose edges are parallel (compared as directions, so that vectors
/// too long for a double still compare).
pub(crate) fn check(cx: &mut Checker, wall: &Wall, t: WallType) {
    if t != WallType::Triangle {
        return;
    }
    let (v1, v2) = (wall.vector(Keyword::Vertex1), wall.vector(Keyword::Vertex2));
    let Some((d1, d2)) = direction(&v1).zip(direction(&v2)) else {
        return;
    };
    if d1.cross(&d2).norm() <= 1e-12 {
        let span = cx.vertices_span(wall);
        cx.push(Diagnostic::error(
            &DEGENERATE_TRIANGLE,
            span,
            format!(
                "triangle wall {} has parallel vertex1 and vertex2: no area, no normal",
                wall.index
            ),
        ));
    }
}
