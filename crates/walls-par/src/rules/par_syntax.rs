//! P001 `par-syntax`: a line pkdgrav's reader refuses (docs/pkdgrav-physics.md §14):
//! pkdgrav stops at start-up with a syntax error.
//!
//! Reported as the lines are read ([`crate::check::File::read`]).

use crate::keys::Key;
use crate::syntax::Problem;
use std::ops::Range;
use walls_diagnostics::{Applicability, Code, Diagnostic, Edit};

/// A line pkdgrav's reader refuses.
pub static PAR_SYNTAX: Code = Code {
    id: "P001",
    name: "par-syntax",
    summary: "a `.par` line pkdgrav's reader refuses: it stops at start-up",
    explanation: concat!(
        "pkdgrav reads a `.par` file line by line and stops with a syntax error at start-up
(exit status 1) on a line that is not blank, not a comment (`#` in the first column) and
not `key = value`: a `!` anywhere (walls files take `!` comments, `.par` files do not), an
indented `#`, a line starting with anything but a letter, a key without `=`, `=` with
nothing after it, and a number key whose value is not a number (`nSteps = yes`).

Bad:
```par\n",
        settled!(),
        "dDelta               = 1e-7 ! seconds in pkdgrav units
nSteps               = 1000
dKn                  = 1e5
iCheckInterval       = 0
```

Good:
```par\n",
        settled!(),
        "dDelta               = 1e-7 # seconds in pkdgrav units
nSteps               = 1000
dKn                  = 1e5
iCheckInterval       = 0
```
"
    ),
};

/// Reports a line the reader refuses, `at` the offending bytes.
pub(crate) fn at_line(text: &str, problem: Problem, at: Range<usize>, out: &mut Vec<Diagnostic>) {
    let mut d = Diagnostic::error(&PAR_SYNTAX, at.clone(), problem.says());
    match problem {
        Problem::Bang => {
            // A `!` after a blank most likely starts a comment: `#` keeps it one (after a
            // number or a string alike, pkdgrav ignores what follows `#`).
            let after_blank = text[..at.start].ends_with([' ', '\t']);
            d = d.with_help("write `#` to begin the comment");
            if after_blank {
                d = d.with_fix(
                    Applicability::Unsafe,
                    "write `#` for `!`",
                    vec![Edit {
                        span: at,
                        replacement: "#".into(),
                    }],
                );
            }
        }
        Problem::IndentedHash => {
            // The blanks before the `#`, from the line's start: removing them makes the
            // comment pkdgrav's (the author's meaning). Not in the rest of a long line,
            // where text precedes them.
            let start = text[..at.start].rfind('\n').map_or(0, |k| k + 1);
            d = d.with_help("start the comment in the first column");
            if text[start..at.start]
                .bytes()
                .all(|b| matches!(b, b' ' | b'\t'))
            {
                d = d.with_fix(
                    Applicability::Safe,
                    "move the comment to the first column",
                    vec![Edit {
                        span: start..at.start,
                        replacement: String::new(),
                    }],
                );
            }
        }
        Problem::NotAKey | Problem::NoEquals | Problem::NoValue => {
            d = d.with_help(
                "write `key = value`, or make the line a comment with `#` in the first column",
            );
        }
    }
    out.push(d);
}

/// Reports a number key whose value is not a number where pkdgrav reads one.
pub(crate) fn not_a_number(key: &Key, value: Range<usize>, text: &str, out: &mut Vec<Diagnostic>) {
    let written = text[value.clone()]
        .split('#')
        .next()
        .unwrap_or("")
        .trim_end();
    let what = match key.kind {
        crate::keys::Kind::Double => "a number",
        _ => "a whole number",
    };
    out.push(
        Diagnostic::error(
            &PAR_SYNTAX,
            value,
            format!(
                "`{}` is {} and `{written}` does not start with one: pkdgrav stops with a syntax error at start-up",
                key.name,
                what,
            ),
        )
        .with_help(format!("write {what} (the key's default is {})", key.default)),
    );
}
