//! R007 `no-output`: output settings under which pkdgrav writes nothing, or only the last
//! step (docs/pkdgrav-physics.md §3; startup_checks.md, "Not checked at start-up").
//!
//! pkdgrav runs steps `iStartStep`+1 … `nSteps` and writes a full output after a step
//! whose number `iOutInterval` divides, and after step `nSteps` always. So
//! `nSteps` ≤ `iStartStep` runs no step and writes nothing (a warning, at `nSteps`); an
//! `iOutInterval` of 0, or longer than the steps run, writes the last step alone (an
//! info, at `iOutInterval`).

use crate::precheck::{Context, Findings};
use walls_diagnostics::{Code, Diagnostic, Severity};

/// Outputs that are never (or only once) written.
pub static NO_OUTPUT: Code = Code {
    id: "R007",
    name: "no-output",
    summary: "pkdgrav runs no step and writes nothing (nSteps ≤ iStartStep), or writes only the last step (iOutInterval 0 or longer than the run)",
    explanation: concat!(
        "`nSteps` is the number of the last step, not a count: pkdgrav runs steps
`iStartStep`+1 to `nSteps` and exits with status 0 without a step, or a word, when
`nSteps` is not above `iStartStep`. It writes a full output after each step whose number
`iOutInterval` divides and after the last step always: an `iOutInterval` of 0, or longer
than the run, leaves the last step's output alone, which may be meant (an info).

Bad:
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
iStartStep           = 1000
dKn                  = 1e5
```

Good:
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 2000
iStartStep           = 1000
dKn                  = 1e5
```
"
    ),
};

/// Reports a run of no step, or with the last step's output alone.
pub(crate) fn check(cx: &Context, out: &mut Findings) {
    let (Some((n_steps, n_span)), Some((start, _))) =
        (cx.par_value("nSteps"), cx.par_value("iStartStep"))
    else {
        return;
    };
    if n_steps <= start {
        out.par.push(
            Diagnostic::warning(
                &NO_OUTPUT,
                n_span,
                format!(
                    "nSteps = {n_steps} is not above iStartStep = {start}: pkdgrav runs no step and writes no output (it exits with status 0)"
                ),
            )
            .with_help("nSteps is the number of the last step: give the start step plus the steps to run"),
        );
        return;
    }
    let Some((interval, i_span)) = cx.par_value("iOutInterval") else {
        return;
    };
    let steps = n_steps - start;
    let why = if interval == 0.0 {
        Some("iOutInterval = 0".to_string())
    } else if interval.abs() > steps {
        Some(format!(
            "iOutInterval = {interval} is longer than the {steps} steps run"
        ))
    } else {
        None
    };
    if let Some(why) = why {
        out.par.push(
            Diagnostic::new(
                &NO_OUTPUT,
                Severity::Info,
                i_span,
                format!("{why}: pkdgrav writes only the last step's output (step {n_steps})"),
            )
            .with_help(
                "set iOutInterval to the steps between outputs if the run is to be followed",
            ),
        );
    }
}
