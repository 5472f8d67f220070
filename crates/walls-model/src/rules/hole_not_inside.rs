//! C108 `hole-not-inside`: a disk's `hole-radius` is not smaller than its `radius`.
//!
//! Checked per wall, by its final type.

use crate::check::Checker;
use crate::scene::Wall;
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::{Keyword, WallType};

/// A disk's `hole-radius` is not smaller than its `radius`.
pub static HOLE_NOT_INSIDE: Code = Code {
    id: "C108",
    name: "hole-not-inside",
    summary: "a disk's `hole-radius` is not smaller than its `radius`",
    explanation: "A disk's hole must be smaller than the disk (both may be 0, a point).

Bad:
```walls
wall type disk
  radius 0.5
  hole-radius 0.5
```

Good:
```walls
wall type disk
  radius 0.5
  hole-radius 0.2
```
",
};

/// Reports a disk whose hole is not smaller than the disk (negative sizes are C107's).
pub(crate) fn check(cx: &mut Checker, wall: &Wall, t: WallType) {
    if t != WallType::Disk {
        return;
    }
    let (r, h) = (
        wall.number(Keyword::Radius),
        wall.number(Keyword::HoleRadius),
    );
    if !(h < r || (h == 0.0 && r == 0.0)) && r >= 0.0 && h >= 0.0 {
        let span = cx
            .span_of(wall, Keyword::HoleRadius)
            .or_else(|| cx.span_of(wall, Keyword::Radius))
            .unwrap_or_else(|| wall.span.clone());
        cx.push(Diagnostic::error(
            &HOLE_NOT_INSIDE,
            span,
            format!(
                "disk wall {} has hole-radius {h} not smaller than its radius {r}",
                wall.index
            ),
        ));
    }
}
