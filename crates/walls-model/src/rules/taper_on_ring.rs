//! C110 `taper-on-ring`: a tapered finite cylinder has length 0.
//!
//! Checked per wall, by its final type.

use crate::check::Checker;
use crate::scene::Wall;
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::{Keyword, WallType};

/// A tapered finite cylinder has length 0.
pub static TAPER_ON_RING: Code = Code {
    id: "C110",
    name: "taper-on-ring",
    summary: "a tapered finite cylinder has length 0",
    explanation: "A finite cylinder of length 0 is a ring, which cannot taper.

Bad:
```walls
wall type cylinder-finite
  length 0
  taper 0.5
```

Good:
```walls
wall type cylinder-finite
  length 1
  taper 0.5
```
",
};

/// Reports a finite cylinder of length 0 with a taper.
pub(crate) fn check(cx: &mut Checker, wall: &Wall, t: WallType) {
    if t != WallType::CylinderFinite {
        return;
    }
    let taper = wall.number(Keyword::Taper);
    if taper != 0.0 && wall.number(Keyword::Length) == 0.0 {
        let span = cx
            .span_of(wall, Keyword::Taper)
            .unwrap_or_else(|| wall.span.clone());
        let mut d = Diagnostic::error(
            &TAPER_ON_RING,
            span,
            format!(
                "finite cylinder wall {} has length 0 (a ring), which cannot taper",
                wall.index
            ),
        );
        if let Some(l) = cx.span_of(wall, Keyword::Length) {
            d = d.with_label(l, "length 0");
        }
        cx.push(d);
    }
}
