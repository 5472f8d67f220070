//! P004 `par-read-as`: a value pkdgrav reads otherwise than it is written
//! (docs/pkdgrav-physics.md §14, docs/pkdgrav-startup-checks.md C1): an integer or a switch with a
//! fraction or an exponent (`nSteps = 1e5` is 1), or text after a number that is not a
//! comment, which pkdgrav ignores without a word.
//!
//! Reported as the values are read.

use crate::keys::{Key, Kind};
use crate::value::Value;
use std::ops::Range;
use walls_diagnostics::{Code, Diagnostic};

/// A value pkdgrav reads otherwise than it is written.
pub static READ_AS: Code = Code {
    id: "P004",
    name: "par-read-as",
    summary: "a `.par` value pkdgrav reads otherwise than it is written (`nSteps = 1e5` is 1)",
    explanation: concat!(
        "pkdgrav reads an integer or a switch as C's `%d` does: the leading whole number, the
rest ignored, so `nSteps = 1e5` runs 1 step and `iOutInterval = 0.5` is 0. After any
number it ignores the rest of the line, so `dDelta = 1e-7 s` is read as 1e-7 with no
word about the `s`. Write the value as pkdgrav reads it, and comments after `#`.

Bad:
```par\n",
        settled!(),
        "dDelta               = 1e-7
nSteps               = 1e5
dKn                  = 1e5
iCheckInterval       = 0
```

Good:
```par\n",
        settled!(),
        "dDelta               = 1e-7
nSteps               = 100000
dKn                  = 1e5
iCheckInterval       = 0
```
"
    ),
};

/// Reports `key`'s value (`read` of it read as `value`, `ignored` passed over) when what
/// pkdgrav reads is not what `span` says.
pub(crate) fn check(
    key: &Key,
    read: &str,
    value: &Value,
    ignored: &str,
    span: Range<usize>,
    out: &mut Vec<Diagnostic>,
) {
    if let Value::Str(s) = value
        && s.len() >= 2
        && s.starts_with('"')
        && s.ends_with('"')
        && !crate::value::UNQUOTED.contains(&key.name)
    {
        out.push(
            Diagnostic::warning(
                &READ_AS,
                span.clone(),
                format!(
                    "pkdgrav keeps the quotes of `{}`: it reads {s}, quotes included (only the walls, cohesion, uniform-gravity and special-particles file names lose theirs)",
                    key.name
                ),
            )
            .with_help("write the value without quotes"),
        );
    }
    if ignored.is_empty() {
        return;
    }
    let shown = match value {
        Value::Int(x) => x.to_string(),
        Value::Double(_) => read.to_string(),
        Value::Str(s) => {
            out.push(
                Diagnostic::warning(
                    &READ_AS,
                    span,
                    format!(
                        "pkdgrav reads `{}` as `{s}`: a NUL byte ends the line it reads, and `{ignored}` is lost",
                        key.name
                    ),
                )
                .with_help("take the NUL byte out"),
            );
            return;
        }
    };
    let message = match key.kind {
        Kind::Int | Kind::Bool => format!(
            "`{}` is an integer: pkdgrav reads the leading whole number {shown} and ignores `{ignored}`",
            key.name
        ),
        _ => format!(
            "pkdgrav reads `{}` as {shown} and ignores `{ignored}`",
            key.name
        ),
    };
    out.push(
        Diagnostic::warning(&READ_AS, span, message)
            .with_help("write the value as pkdgrav reads it; comments go after `#`"),
    );
}
