//! C206 `sticky-wall-order`: a sticky wall (`epsn 0`) comes after a non-sticky one.
//!
//! Checked over the walls in order.

use crate::check::Checker;
use crate::scene::Wall;
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::Keyword;

/// A sticky wall (`epsn 0`) comes after a non-sticky one.
pub static STICKY_WALL_ORDER: Code = Code {
    id: "C206",
    name: "sticky-wall-order",
    summary: "a sticky wall (`epsn 0`) comes after a non-sticky one",
    explanation:
        "pkdgrav stores the index of the wall a particle sticks to. If the number or order of
walls before a sticky wall changes between runs, stuck particles end up on the wrong wall,
so the document asks for sticky walls to be listed first.

Bad:
```walls
wall type plane
  epsn 0.5
wall type disk
  epsn 0
```

Good:
```walls
wall type disk
  epsn 0
wall type plane
  epsn 0.5
```
",
};

/// The walls seen so far, as far as stickiness goes.
#[derive(Default)]
pub(crate) struct StickyOrder<'w> {
    /// The first wall that is not sticky.
    non_sticky: Option<&'w Wall>,
}

impl<'w> StickyOrder<'w> {
    /// Reports `wall` if it is sticky and a non-sticky wall came before; walls are
    /// given in order.
    pub(crate) fn check(&mut self, cx: &mut Checker, wall: &'w Wall) {
        let epsn = wall.number(Keyword::Epsn);
        match self.non_sticky {
            Some(first) if epsn == 0.0 => {
                let mut d = Diagnostic::warning(
                    &STICKY_WALL_ORDER,
                    wall.span.clone(),
                    format!(
                        "sticky wall {} (epsn 0) comes after non-sticky wall {}",
                        wall.index, first.index
                    ),
                )
                .with_label(first.span.clone(), format!("wall {} is not sticky", first.index))
                .with_help("list sticky walls first and keep their order: pkdgrav stores the index of the wall a particle sticks to");
                if let Some(span) = cx.span_of(wall, Keyword::Epsn) {
                    d = d.with_label(span, "epsn 0 makes it sticky");
                }
                cx.push(d);
            }
            None if epsn != 0.0 => self.non_sticky = Some(wall),
            _ => {}
        }
    }
}
