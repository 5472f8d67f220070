//! M001 `not-in-hsdem`: a wall type or token that pkdgrav's hard-sphere (HSDEM) code does not implement.
//!
//! Checked per wall in HSDEM, by its final type: the type, then a finite cylinder's taper.

use crate::check::Checker;
use crate::scene::Wall;
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::{Keyword, WallType};

/// A wall type or token that pkdgrav's hard-sphere (HSDEM) code does not implement.
pub static NOT_IN_HSDEM: Code = Code {
    id: "M001",
    name: "not-in-hsdem",
    summary: "a wall type or token that pkdgrav's hard-sphere (HSDEM) code does not implement",
    explanation:
        "pkdgrav implements triangle and shell walls, and the `taper` of finite cylinders, only
in its soft-sphere (SSDEM) code; a hard-sphere run refuses them. Judged per wall, by its
final type, with `--mode hsdem`.

Bad (with `--mode hsdem`):
```walls
defaults epsn 0.9 epst 1
wall type triangle
```

Good:
```walls
defaults epsn 0.9 epst 1
wall type rectangle
```
",
};

/// Reports a wall of a type, or a finite cylinder with a taper, that the hard-sphere
/// code does not implement.
pub(crate) fn check(cx: &mut Checker, wall: &Wall, t: WallType) {
    if t.ssdem_only() {
        let span = cx
            .span_of(wall, Keyword::Type)
            .unwrap_or_else(|| wall.span.clone());
        cx.push(
            Diagnostic::error(
                &NOT_IN_HSDEM,
                span,
                format!("pkdgrav's hard-sphere code has no {} walls", t.name()),
            )
            .with_help("run with SSDEM, or build the shape from rectangles, disks and cylinders"),
        );
    }
    if t == WallType::CylinderFinite && wall.number(Keyword::Taper) != 0.0 {
        let span = cx
            .span_of(wall, Keyword::Taper)
            .unwrap_or_else(|| wall.span.clone());
        cx.push(
            Diagnostic::error(
                &NOT_IN_HSDEM,
                span,
                "pkdgrav's hard-sphere code does not implement `taper`",
            )
            .with_help("remove `taper`, or run with SSDEM"),
        );
    }
}
