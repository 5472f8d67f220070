//! R007 `no-output`: output settings under which pkdgrav writes nothing, or only the last
//! step (docs/pkdgrav-physics.md §3; startup_checks.md, "Not checked at start-up").
//!
//! pkdgrav runs steps `iStartStep`+1 … `nSteps` and writes a full output after a step
//! whose number `iOutInterval` divides, and after step `nSteps` always. So
//! `nSteps` ≤ `iStartStep` runs no step and writes nothing (a warning, at `nSteps`); an
//! `iOutInterval` of 0, or longer than the steps run, writes the last step alone (an
//! info, at `iOutInterval`).

use crate::precheck::{Context, Findings};
use walls_diagnostics::{Diagnostic, Severity};

pub use walls_par::run_codes::no_output::NO_OUTPUT;

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
