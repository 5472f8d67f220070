//! P006 `par-duplicate-key`: a key given twice; pkdgrav takes the last silently
//! (docs/pkdgrav-physics.md §14).
//!
//! Checked once the file is read.

use crate::check::File;
use walls_diagnostics::{Applicability, Code, Diagnostic, Edit};

/// A key given twice.
pub static DUPLICATE_KEY: Code = Code {
    id: "P006",
    name: "par-duplicate-key",
    summary: "a `.par` key given twice: pkdgrav takes the last without a word",
    explanation: concat!(
        "pkdgrav reads every line and the last value of a key wins, silently: an early line
that looks like the run's setting is not. The fix deletes the lines that do not count.

Bad:
```par\n",
        settled!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
iCheckInterval       = 0
dDelta               = 2e-7
```

Good:
```par\n",
        settled!(),
        "dDelta               = 2e-7
nSteps               = 1000
dKn                  = 1e5
iCheckInterval       = 0
```
"
    ),
};

/// Reports every entry a later one of the same key overrides.
pub(crate) fn check(file: &File, out: &mut Vec<Diagnostic>) {
    for entry in &file.entries {
        if file.wins(entry) {
            continue;
        }
        let Some(last) = file.given(entry.key.name) else {
            continue;
        };
        // A line read whole (its rest, if any, blanks: a CRLF line of 127 bytes) can go
        // whole.
        let whole = file.lines.get(entry.line - 1).is_some_and(|l| {
            l.reads[1..]
                .iter()
                .all(|r| r.kind == crate::syntax::Kind::Blank)
        });
        let mut d = Diagnostic::warning(
            &DUPLICATE_KEY,
            entry.key_span.clone(),
            format!(
                "`{}` is given again on line {}, which pkdgrav takes: this value does nothing",
                entry.key.name, last.line
            ),
        )
        .with_label(last.key_span.clone(), "the value pkdgrav takes");
        if whole {
            d = d.with_fix(
                Applicability::Safe,
                "delete the line pkdgrav overrides",
                vec![Edit {
                    span: entry.line_span.clone(),
                    replacement: String::new(),
                }],
            );
        }
        out.push(d);
    }
}
