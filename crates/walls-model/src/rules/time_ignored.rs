//! C103 `time-ignored`: a non-zero `time`, which pkdgrav ignores.
//!
//! Checked as `time` is read, when it is not negative (C102 reports that).

use super::Read;
use walls_diagnostics::{Code, Diagnostic, Severity};

/// A non-zero `time`, which pkdgrav ignores.
pub static TIME_IGNORED: Code = Code {
    id: "C103",
    name: "time-ignored",
    summary: "a non-zero `time`, which pkdgrav ignores",
    explanation:
        "pkdgrav reads `time` but does not use it: to place moving walls at a time, change the
time in the particle (ss) file. This is information, not a mistake.

Bad:
```walls
time 10
wall type plane
```

Good:
```walls
wall type plane
```
",
};

/// Notes a non-zero `time`.
pub(crate) fn check(at: &Read, x: f64, out: &mut Vec<Diagnostic>) {
    if x != 0.0 {
        out.push(
            Diagnostic::new(
                &TIME_IGNORED,
                Severity::Info,
                at.span.clone(),
                "pkdgrav ignores `time`",
            )
            .with_help("to place moving walls at a time, set the time in the particle (ss) file"),
        );
    }
}
