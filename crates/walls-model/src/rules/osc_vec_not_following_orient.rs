//! C205 `osc-vec-not-following-orient`: an oscillating wall still shakes along +z although its normal is not +z.
//!
//! Checked per wall that oscillates (amplitude and frequency both set); the fix is unsafe.

use crate::check::Checker;
use crate::fix;
use crate::scene::{Place, Source, Wall};
use walls_diagnostics::{Applicability, Code, Diagnostic};
use walls_keywords::{Keyword, Types, WallType};

/// An oscillating wall still shakes along +z although its normal is not +z.
pub static OSC_VEC_NOT_FOLLOWING_ORIENT: Code = Code {
    id: "C205",
    name: "osc-vec-not-following-orient",
    summary: "an oscillating wall still shakes along +z although its normal is not +z",
    explanation:
        "`osc-vec` defaults to the *initial* orient, 0 0 1, and does not follow a later `orient`
(or a triangle's or rectangle's normal). A wall tilted away from z that oscillates without
an `osc-vec` therefore shakes along z. The fix (unsafe: you may want z) sets `osc-vec` to
the wall's normal, after the wall's own `orient` (for an `orient` from `defaults`, which
other walls share, the help says what to add).

Bad:
```walls
wall type plane
  orient 1 0 0
  osc-ampl 0.1
  osc-freq 2
```

Good:
```walls
wall type plane
  orient 1 0 0
  osc-vec 1 0 0
  osc-ampl 0.1
  osc-freq 2
```
",
};

/// Reports an oscillating wall without `osc-vec` whose normal is not ±z.
pub(crate) fn check(cx: &mut Checker, wall: &Wall, t: WallType) {
    let (a, w) = (wall.number(Keyword::OscAmpl), wall.number(Keyword::OscFreq));
    if a == 0.0 || w == 0.0 || wall.settings.get(Keyword::OscVec).is_some() {
        return;
    }
    let normal = wall.normal();
    if normal.norm() == 0.0 || normal.z.abs() > 1.0 - 1e-9 {
        return;
    }
    let polygon = Types::POLYGON.contains(t);
    let orient = (!polygon).then(|| wall.setting(Keyword::Orient)).flatten();
    let mut d = Diagnostic::warning(
        &OSC_VEC_NOT_FOLLOWING_ORIENT,
        orient
            .as_ref()
            .and_then(|s| s.source.span())
            .unwrap_or_else(|| wall.span.clone()),
        format!(
            "wall {} oscillates along 0 0 1 although its normal is {}: osc-vec does not follow orient",
            wall.index,
            fix::vector(&normal)
        ),
    );
    if let Some(span) = cx.span_of(wall, Keyword::OscAmpl) {
        d = d.with_label(span, "it oscillates");
    }
    // Only the wall's own `orient` gets the fix: an `osc-vec` added to `defaults` would
    // reach other walls too.
    let written = fix::vector(&normal);
    d = match orient.map(|s| s.source) {
        Some(Source::Set {
            values,
            place: Place::Wall,
            ..
        }) if fix::normal_numbers(&written) => d.with_fix(
            Applicability::Unsafe,
            "oscillate along the normal: set osc-vec to orient",
            vec![fix::append(
                cx.tree.text(),
                values.range().end,
                format!(" osc-vec {written}"),
            )],
        ),
        _ => d.with_help(format!(
            "add `osc-vec {}` to oscillate along the normal",
            fix::vector(&normal)
        )),
    };
    cx.push(d);
}
