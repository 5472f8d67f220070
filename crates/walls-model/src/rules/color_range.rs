//! C116 `color-range`: `color` is outside 0…255.
//!
//! Checked as the value is read (`ValueRange::Palette`).

use super::Read;
use walls_diagnostics::{Code, Diagnostic};

/// `color` is outside 0…255.
pub static COLOR_RANGE: Code = Code {
    id: "C116",
    name: "color-range",
    summary: "`color` is outside 0…255",
    explanation:
        "Colours are ssdraw's palette indices, 0 to 255 (0 is not drawn, 1–15 named colours,
16–255 greys).

Bad:
```walls
wall type plane
  color 300
```

Good:
```walls
wall type plane
  color 3
```
",
};

/// Reports a `color` outside 0…255.
pub(crate) fn check(at: &Read, c: i64, out: &mut Vec<Diagnostic>) {
    if !(0..=255).contains(&c) {
        out.push(Diagnostic::error(
            &COLOR_RANGE,
            at.span.clone(),
            format!("`color` is {}; it must be between 0 and 255", at.written),
        ));
    }
}
