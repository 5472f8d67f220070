//! P008 `par-pkdgrav-stops`, P009 `par-pkdgrav-warns`, P010 `par-pkdgrav-changes`,
//! P011 `par-run-differs`: the start-up checks of [`crate::startup`] that hold for the
//! file, each reported as pkdgrav treats it: an error where it stops, a warning where it
//! warns, information where it changes a value without a word, and a warning where it
//! runs without a word and the run is not what the file says.
//!
//! The four codes share this file because they share one check: the table's.

use crate::check::File;
use crate::startup::{CHECKS, Check, Outcome};
use walls_diagnostics::{Code, Diagnostic, Severity};

/// A value pkdgrav stops on.
pub static PKDGRAV_STOPS: Code = Code {
    id: "P008",
    name: "par-pkdgrav-stops",
    summary: "pkdgrav stops on these `.par` values (at start-up, or at its first contact or output)",
    explanation: concat!(
        "pkdgrav checks its parameters when it starts and stops (exit status 1, or an
assertion) on values its build cannot run; a few it does not check stop it later, at the
first contact or the first output. Two of them are defaults that every DEM run must
change: `iForceOverrideOption` (0; DEM needs 2) and `iCheckInterval` (10; DEM takes no
checkpoints, 0). The message names the row of pkdgrav's start-up checks.

Bad:
```par\n",
        settled!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```

Good:
```par\n",
        clean!(),
        "```
"
    ),
};

/// A value pkdgrav warns about.
pub static PKDGRAV_WARNS: Code = Code {
    id: "P009",
    name: "par-pkdgrav-warns",
    summary: "pkdgrav warns about these `.par` values at start-up, and runs",
    explanation: concat!(
        "pkdgrav prints a warning at start-up for values it can run but doubts: a normal spring
constant of 0 (its default), a tangential restitution that does nothing without
friction, `iOutcomes` in a DEM build. Some print only with `bVWarnings` on (the default).

Bad:
```par\n",
        settled!(),
        "dDelta               = 1e-7
nSteps               = 1000
iCheckInterval       = 0
```

Good:
```par\n",
        clean!(),
        "```
"
    ),
};

/// A value pkdgrav changes without a word.
pub static PKDGRAV_CHANGES: Code = Code {
    id: "P010",
    name: "par-pkdgrav-changes",
    summary: "pkdgrav changes a value after reading these `.par` values, without a word (information)",
    explanation: concat!(
        "After reading its parameters pkdgrav changes some values without a word: the most
surprising in a collisions build is `dSoft`, which, given at all (0 too), replaces every
particle's radius.

Bad:
```par\n",
        settled!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
iCheckInterval       = 0
dSoft                = 0
```

Good:
```par\n",
        clean!(),
        "```
"
    ),
};

/// A value pkdgrav runs with, without a word, into a run that is not what the file says.
pub static RUN_DIFFERS: Code = Code {
    id: "P011",
    name: "par-run-differs",
    summary: "pkdgrav runs these `.par` values without a word, and the run is not what they say",
    explanation: concat!(
        "pkdgrav does not check everything: a `dDelta` of 0 (its default) runs steps of no
length, `nSteps` not above `iStartStep` runs nothing and exits with status 0,
`bDoGravity = 0` in a DEM build turns every force off, contacts included.

Bad:
```par\n",
        settled!(),
        "nSteps               = 1000
dKn                  = 1e5
iCheckInterval       = 0
```

Good:
```par\n",
        clean!(),
        "```
"
    ),
};

/// Reports every check of the table that holds for the file in its build; returns the
/// keys of those that hold.
pub(crate) fn check(file: &File, out: &mut Vec<Diagnostic>) -> Vec<&'static str> {
    let warnings_on = file.real("bVWarnings").is_none_or(|x| x != 0.0);
    let mut keys = Vec::new();
    // A row reading a value pkdgrav cannot read (refused at its line) says nothing.
    let unreadable =
        |c: &Check| (c.keys.iter()).any(|k| file.given(k).is_some_and(|e| e.value.is_none()));
    for c in CHECKS {
        if !file.build.meets(c.build)
            || (c.verbose && !warnings_on)
            || unreadable(c)
            || !(c.holds)(file)
        {
            continue;
        }
        keys.extend_from_slice(c.keys);
        out.push(report(file, c));
    }
    keys
}

/// The finding of check `c`, located at the first of its keys the file gives (the
/// file's start when it gives none).
fn report(file: &File, c: &Check) -> Diagnostic {
    let (code, severity) = match c.outcome {
        Outcome::Stops => (&PKDGRAV_STOPS, Severity::Error),
        Outcome::Warns => (&PKDGRAV_WARNS, Severity::Warning),
        Outcome::Changes => (&PKDGRAV_CHANGES, Severity::Info),
        Outcome::Differs => (&RUN_DIFFERS, Severity::Warning),
    };
    let span = c
        .keys
        .iter()
        .find_map(|k| file.given(k))
        .map_or(0..0, |e| e.value_span.clone());
    let values: Vec<String> = c
        .keys
        .iter()
        .filter(|k| crate::keys::registered(k, file.build).is_some())
        .map(|&k| match file.given(k) {
            Some(e) => format!(
                "`{k}` = {} (line {})",
                file.text[e.value_span.clone()]
                    .split('#')
                    .next()
                    .unwrap_or("")
                    .trim_end(),
                e.line
            ),
            None => match crate::keys::registered(k, file.build).and_then(|r| r.default_value()) {
                Some(d) => format!("`{k}` not given (default {d})"),
                None => format!("`{k}` not given"),
            },
        })
        .collect();
    Diagnostic::new(
        code,
        severity,
        span,
        format!("{} [{}]: {}", c.says, c.id, values.join(", ")),
    )
}
