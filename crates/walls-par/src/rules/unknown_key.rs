//! P003 `par-unknown-key`: a key the build does not register (docs/pkdgrav-physics.md
//! §14, §18): pkdgrav prints "Unrecognized command" and stops at start-up.
//!
//! Reported as the lines are read.

use crate::keys;
use crate::options::Build;
use std::ops::Range;
use walls_diagnostics::{Applicability, Code, Diagnostic, Edit};

/// A key the build does not register.
pub static UNKNOWN_KEY: Code = Code {
    id: "P003",
    name: "par-unknown-key",
    summary: "a `.par` key the pkdgrav build does not register: it stops at start-up",
    explanation: concat!(
        "pkdgrav registers its `.par` keys at start-up, each only in the builds whose compile
options it needs (`iCohesionModel` needs `DEM_COHESION`, `dBetaS` needs
`DEM_ROTATION_DASHPOT`). A key the build does not register, a misspelt one or one of
another build, stops pkdgrav at start-up (exit status 1): keys are case-sensitive. The
build is the one `--pkdgrav-build` names (or the settings file's `[run] pkdgrav-build`);
by default pkdgrav's default soft-sphere build with walls.

Bad:
```par\n",
        settled!(),
        "dDelta               = 1e-7
nStep                = 1000
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

/// Takes back the rename a finding offers when the file already sets that key: the
/// renamed line would override the file's own (the help says where it is).
pub(crate) fn no_rename_to_a_key_given(file: &crate::check::File, out: &mut [Diagnostic]) {
    for d in out
        .iter_mut()
        .filter(|d| std::ptr::eq(d.code, &UNKNOWN_KEY))
    {
        let Some(fix) = &d.fix else { continue };
        let Some(given) = fix.edits.first().and_then(|e| file.given(&e.replacement)) else {
            continue;
        };
        d.help = Some(format!(
            "did you mean `{}`? The file sets it on line {}: renaming this line would override that one",
            given.key.name, given.line
        ));
        d.fix = None;
    }
}

/// Reports `name` at `span`, which `build` does not register.
pub(crate) fn check(name: &str, span: Range<usize>, build: &Build, out: &mut Vec<Diagnostic>) {
    let elsewhere: Vec<&str> = keys::any(name).map(|k| k.condition).collect();
    let mut d = Diagnostic::error(
        &UNKNOWN_KEY,
        span.clone(),
        format!(
            "`{name}` is not a key this pkdgrav build registers: pkdgrav stops at start-up (\"Unrecognized command\")"
        ),
    );
    if !elsewhere.is_empty() {
        d = d.with_help(format!(
            "pkdgrav registers `{name}` only in builds with {}; this build is {}: name the job's build with --pkdgrav-build, or leave the key out",
            elsewhere.join(", or "),
            build.names()
        ));
    } else if let Some(near) = keys::nearest(name, build) {
        d = d.with_help(format!("did you mean `{near}`?")).with_fix(
            Applicability::Unsafe,
            format!("write `{near}`"),
            vec![Edit {
                span,
                replacement: near.to_string(),
            }],
        );
    } else {
        d = d.with_help("leave the line out, or make it a comment with `#` in the first column");
    }
    out.push(d);
}
