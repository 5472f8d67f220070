//! P007 `par-not-modelled`: a key the build registers whose value walls-sim does not
//! follow ([`crate::evaluator`]): a key it does not model, physics not modelled yet, or
//! a value other than the one it follows. Information, never a failure: pkdgrav runs
//! the file; walls-sim's preview of the run differs there.
//!
//! Checked once the file is read, on the lines that win, and on the keys the file
//! leaves at a default walls-sim does not follow (unless pkdgrav stops on that default,
//! which `par-pkdgrav-stops` reports).

use crate::check::File;
use crate::evaluator::{KEYS, Use, use_of};
use walls_diagnostics::{Code, Diagnostic, Severity};

/// A key walls-sim does not follow.
pub static NOT_MODELLED: Code = Code {
    id: "P007",
    name: "par-not-modelled",
    summary: "a `.par` key pkdgrav follows and walls-sim does not (information)",
    explanation: concat!(
        "walls-sim reads the `.par` keys of wall runs and follows them as pkdgrav does. A key it
does not model (tree gravity, periodic boxes, hard-sphere overlap options), or a value
other than the one it follows, is pkdgrav's alone: the real run does it, walls-sim's
preview of the run does not. Nothing is wrong with the file; this says where the preview
and the job part ways.

Bad:
```par\n",
        settled!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
iCheckInterval       = 0
bDoSelfGravity       = 1
```

Good:
```par\n",
        clean!(),
        "```
"
    ),
};

/// Reports the keys walls-sim does not follow; `stopped` names the keys whose default
/// pkdgrav stops on (reported there, not again here).
pub(crate) fn check(file: &File, stopped: &[&str], out: &mut Vec<Diagnostic>) {
    let dem = file.build.has("DEM");
    for entry in file.entries.iter().filter(|e| file.wins(e)) {
        let name = entry.key.name;
        if !crate::evaluator::follows_alone(name, dem) {
            continue;
        }
        let message = match use_of(name) {
            None => format!(
                "walls-sim does not model `{name}`: pkdgrav follows it, walls-sim's run of this file does not"
            ),
            Some(Use::NotYet(why)) => format!("`{name}`: {why}"),
            Some(Use::Only { value, why, .. }) => {
                let Some(x) = file.real(name) else { continue };
                let same = if name.starts_with('b') {
                    (x != 0.0) == (value != 0.0)
                } else {
                    x == value
                };
                if same {
                    continue;
                }
                format!("`{name}` = {x} is not modelled: {why}")
            }
            Some(Use::Read | Use::NoEffect) => continue,
        };
        out.push(Diagnostic::new(
            &NOT_MODELLED,
            Severity::Info,
            entry.key_span.clone(),
            message,
        ));
    }
    for &(name, u) in KEYS {
        let Use::Only {
            value,
            default,
            why,
        } = u
        else {
            continue;
        };
        if default == value
            || file.given(name).is_some()
            || stopped.contains(&name)
            || crate::keys::registered(name, file.build).is_none()
            || !crate::evaluator::follows_alone(name, dem)
        {
            continue;
        }
        out.push(Diagnostic::new(
            &NOT_MODELLED,
            Severity::Info,
            0..0,
            format!("`{name}` is not given, so pkdgrav takes its default {default}: {why}"),
        ));
    }
}
