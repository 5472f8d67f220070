//! C305 `invalid-assembly`: `assembly` is not 0 or 1.
//!
//! Checked as the value is read (`ValueRange::Assembly`).

use super::Read;
use walls_diagnostics::{Code, Diagnostic};

/// `assembly` is not 0 or 1.
pub static INVALID_ASSEMBLY: Code = Code {
    id: "C305",
    name: "invalid-assembly",
    summary: "`assembly` is not 0 or 1",
    explanation:
        "pkdgrav allows two assemblies (MAX_NUM_WALL_ASSEMBLIES is 2), numbered 0 and 1. The
default −1 (no assembly) cannot be written explicitly: leave `assembly` out instead.

Bad:
```walls
wall type disk
  mass 1
  assembly 2
```

Good:
```walls
wall type disk
  mass 1
  assembly 1
```
",
};

/// Reports an `assembly` other than 0 or 1.
pub(crate) fn check(at: &Read, a: i64, out: &mut Vec<Diagnostic>) {
    if (0..=1).contains(&a) {
        return;
    }
    let message = if a == -1 {
        "`assembly -1` cannot be written: pkdgrav reads only 0 or 1".to_string()
    } else {
        format!(
            "`assembly` is {}; pkdgrav allows 2 assemblies, numbered 0 and 1",
            at.written
        )
    };
    out.push(
        Diagnostic::error(&INVALID_ASSEMBLY, at.span.clone(), message)
            .with_help("a wall that is in no assembly simply leaves `assembly` out"),
    );
}
