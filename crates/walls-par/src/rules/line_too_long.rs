//! P002 `par-line-too-long`: a line over 127 bytes, which pkdgrav reads as several
//! (docs/pkdgrav-physics.md §14).
//!
//! Reported as the lines are read; the rest of the line is then checked as the line of
//! its own that pkdgrav reads it as.

use crate::syntax::{LINE_LIMIT, Line};
use walls_diagnostics::{Code, Diagnostic};

/// A line over 127 bytes.
pub static LINE_TOO_LONG: Code = Code {
    id: "P002",
    name: "par-line-too-long",
    summary: "a `.par` line over 127 bytes, whose rest pkdgrav reads as a line of its own",
    explanation: concat!(
        "pkdgrav reads a `.par` file 127 bytes at a time (a 128-byte buffer): the rest of a
longer line is read as a new line. That is usually a syntax error or an unknown key
(pkdgrav stops at start-up, naming the line after it), and sometimes worse: a rest that
reads `key = value`, even inside a long comment, sets that key silently. A long trailing
comment is enough.

Bad:
```par\n",
        settled!(),
        "dDelta               = 1e-7 # the timestep: a fiftieth of the contact time of the stiffest pair of the sample; see the notes of the run of 2026-11-29
nSteps               = 1000
dKn                  = 1e5
iCheckInterval       = 0
```

Good:
```par\n",
        settled!(),
        "# dDelta, the timestep: a fiftieth of the contact time of the stiffest pair of the
# sample; see the notes of the run of 2026-11-29
dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
iCheckInterval       = 0
```
"
    ),
};

/// Reports `line` if pkdgrav reads it in more than one piece.
pub(crate) fn check(text: &str, line: &Line, out: &mut Vec<Diagnostic>) {
    let [first, rest @ ..] = &line.reads[..] else {
        return;
    };
    // A rest of blanks (the `\r` of a CRLF line of 127 bytes), or one that starts with
    // `#`, is a blank line or a comment to pkdgrav: nothing is lost.
    let harmless = |r: &crate::syntax::Read| {
        matches!(
            r.kind,
            crate::syntax::Kind::Blank | crate::syntax::Kind::Comment
        )
    };
    if rest.iter().all(harmless) {
        return;
    }
    let bytes = line.span.len();
    let shown: String = text[first.span.end..line.span.end]
        .chars()
        .take(40)
        .collect();
    out.push(
        Diagnostic::error(
            &LINE_TOO_LONG,
            first.span.end..line.span.end,
            format!(
                "the line is {bytes} bytes long: pkdgrav reads its first {LINE_LIMIT} and then the rest, `{shown}`, as a line of its own"
            ),
        )
        .with_help(format!(
            "keep each line, comments included, to {LINE_LIMIT} bytes: put a long comment on lines of its own"
        )),
    );
}
