//! R008 `step-wider-than-ndigits`: the last step's number has more digits than
//! `nDigits`, so output names stop sorting (docs/pkdgrav-physics.md §3:
//! `achOutName.%0<nDigits>d`).

use crate::precheck::{Context, Findings};
use walls_diagnostics::Diagnostic;

pub use walls_par::run_codes::wide_steps::WIDE_STEPS;

/// Warns when the last step needs more digits than `nDigits`.
pub(crate) fn check(cx: &Context, out: &mut Findings) {
    let (Some((n_steps, n_span)), Some((digits, d_span)), Some((start, _))) = (
        cx.par_value("nSteps"),
        cx.par_value("nDigits"),
        cx.par_value("iStartStep"),
    ) else {
        return;
    };
    if !(n_steps > start && n_steps >= 1.0 && n_steps.is_finite() && digits >= 1.0) {
        return;
    }
    let width = (n_steps as u64).to_string().len();
    if (width as f64) <= digits {
        return;
    }
    let given = cx.run.par.given("nDigits").is_some();
    let at = if given { d_span } else { n_span.clone() };
    let mut d = Diagnostic::warning(
        &WIDE_STEPS,
        at,
        format!(
            "nSteps = {n_steps} has {width} digits, more than nDigits = {digits}{}: the last outputs' names are wider than the first ones' and sort before them",
            if given { "" } else { " (the default)" }
        ),
    )
    .with_help(format!("set nDigits = {width}"));
    if given {
        d = d.with_label(n_span, "the last step");
    }
    out.par.push(d);
}
