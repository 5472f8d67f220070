//! C204 `lone-oscillation`: a wall has an oscillation amplitude but no frequency, or the reverse.
//!
//! Checked per wall.

use crate::check::Checker;
use crate::scene::Wall;
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::Keyword;

/// A wall has an oscillation amplitude but no frequency, or the reverse.
pub static LONE_OSCILLATION: Code = Code {
    id: "C204",
    name: "lone-oscillation",
    summary: "a wall has an oscillation amplitude but no frequency, or the reverse",
    explanation: "The wall moves by A·sin(ωt + 2πφ): with A or ω zero it does not oscillate at all.

Bad:
```walls
wall type plane
  osc-ampl 0.1
```

Good:
```walls
wall type plane
  osc-ampl 0.1
  osc-freq 2
```
",
};

/// Reports a wall with an oscillation amplitude and no frequency, or the reverse.
pub(crate) fn check(cx: &mut Checker, wall: &Wall) {
    let (a, w) = (wall.number(Keyword::OscAmpl), wall.number(Keyword::OscFreq));
    if (a != 0.0) == (w != 0.0) {
        return;
    }
    let (set, missing) = if a != 0.0 {
        (Keyword::OscAmpl, Keyword::OscFreq)
    } else {
        (Keyword::OscFreq, Keyword::OscAmpl)
    };
    let span = cx.span_of(wall, set).unwrap_or_else(|| wall.span.clone());
    cx.push(
        Diagnostic::warning(
            &LONE_OSCILLATION,
            span,
            format!(
                "wall {} has `{}` but no `{}`, so it does not oscillate",
                wall.index,
                set.name(),
                missing.name()
            ),
        )
        .with_help("the wall moves by osc-ampl · sin(osc-freq · t + 2π · osc-phase)"),
    );
}
