//! C106 `rectangle-not-rectangular`: a rectangle's `vertex1` and `vertex2` are not perpendicular.
//!
//! Checked per wall, by its final type; the fix is unsafe.

use crate::check::Checker;
use crate::fix;
use crate::scene::{Place, Setting, Source, Vec3, Wall, direction};
use walls_diagnostics::{Applicability, Code, Diagnostic, Edit};
use walls_keywords::{Keyword, WallType};

/// A rectangle's `vertex1` and `vertex2` are not perpendicular.
pub static RECTANGLE_NOT_RECTANGULAR: Code = Code {
    id: "C106",
    name: "rectangle-not-rectangular",
    summary: "a rectangle's `vertex1` and `vertex2` are not perpendicular",
    explanation:
        "pkdgrav's rectangles have square corners: |cos| of the angle between vertex1 and vertex2
must be at most 0.001. The fix (unsafe: it moves a vertex) replaces the wall's own vertex2
by its part perpendicular to vertex1 (offered when that part is not zero).

Bad:
```walls
wall type rectangle
  vertex1 0.6 0.6 0
  vertex2 0.6 -0.5 0
```

Good:
```walls
wall type rectangle
  vertex1 0.6 0.6 0
  vertex2 0.6 -0.6 0
```
",
};

/// Above this |cos| a rectangle's sides are not perpendicular (docs/spec.md §1).
pub const RECTANGLE_COS_TOLERANCE: f64 = 0.001;

/// Reports a rectangle whose sides are not perpendicular, with a fix that keeps vertex2's
/// part across vertex1.
pub(crate) fn check(cx: &mut Checker, wall: &Wall, t: WallType) {
    if t != WallType::Rectangle {
        return;
    }
    let (v1, v2) = (wall.vector(Keyword::Vertex1), wall.vector(Keyword::Vertex2));
    // Directions, so that vectors too long for a double still compare.
    let Some((d1, d2)) = direction(&v1).zip(direction(&v2)) else {
        return;
    };
    let cos = d1.dot(&d2);
    if cos.abs() <= RECTANGLE_COS_TOLERANCE {
        return;
    }
    let mut d = Diagnostic::error(
        &RECTANGLE_NOT_RECTANGULAR,
        cx.vertices_span(wall),
        format!(
            "rectangle wall {} has vertex1 and vertex2 at {:.3}° (|cos| {:.4} > {RECTANGLE_COS_TOLERANCE})",
            wall.index,
            cos.clamp(-1.0, 1.0).acos().to_degrees(),
            cos.abs()
        ),
    );
    // Only the wall's own vertex2 gets the fix (one from `defaults` is other walls' too),
    // and only where its part across vertex1 is a vertex that reads back square.
    if let Some(Setting {
        source:
            Source::Set {
                values,
                place: Place::Wall,
                ..
            },
        ..
    }) = wall.setting(Keyword::Vertex2)
    {
        // Back to the units vertex2 was written in.
        let unit = wall.units.length;
        let written = fix::vector(&((v2 - d1 * v2.dot(&d1)) / unit));
        let read: Vec<f64> = written
            .split(' ')
            .filter_map(|x| x.parse::<f64>().ok())
            .collect();
        let square = match read[..] {
            [x, y, z] => direction(&(Vec3::new(x, y, z) * unit))
                .is_some_and(|d| d.dot(&d1).abs() <= RECTANGLE_COS_TOLERANCE),
            _ => false,
        };
        if square {
            d = d.with_fix(
                Applicability::Unsafe,
                "make vertex2 perpendicular to vertex1 (keep its part across vertex1)",
                vec![Edit {
                    span: values.range(),
                    replacement: written,
                }],
            );
        }
    }
    cx.push(d);
}
