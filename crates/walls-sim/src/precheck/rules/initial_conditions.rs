//! R009 `initial-conditions-start-up`: what pkdgrav checks of the `.ss` file when it
//! starts (docs/pkdgrav-startup-checks.md A127, B44–B46): an aggregate of one particle
//! (an `AGGS` build) stops it, and a header time other than `iStartStep`·`dDelta` is
//! reset to it, with a warning.

use crate::precheck::{Context, Findings};
use walls_diagnostics::{Diagnostic, Severity};

pub use walls_par::run_codes::initial_conditions::INITIAL_CONDITIONS;

/// Reports an aggregate of one particle at it, and a header time pkdgrav resets at
/// `iStartStep`.
pub(crate) fn check(cx: &Context, out: &mut Findings) {
    let Some(ss) = cx.particles() else { return };
    if cx.run.par.build.has("AGGS") {
        let mut count: std::collections::BTreeMap<i32, (usize, usize)> = Default::default();
        for (k, p) in ss.particles.iter().enumerate() {
            if p.index < 0 {
                let e = count.entry(p.index).or_insert((0, k));
                e.0 += 1;
            }
        }
        for (&org, &(n, k)) in &count {
            if n == 1 {
                out.particles.push(
                    Diagnostic::new(
                        &INITIAL_CONDITIONS,
                        Severity::Error,
                        ss.span(k),
                        format!(
                            "particle {k} is the only member of aggregate {} (org_idx {org}): pkdgrav stops at start-up (exit status 1) on an aggregate of one particle",
                            -1 - i64::from(org)
                        ),
                    )
                    .in_record("particle", k)
                    .with_help("give the aggregate a second member, or the particle an org_idx of 0 or more"),
                );
            }
        }
    }
    let (Some((start, span)), Some((dt, _))) = (cx.par_value("iStartStep"), cx.par_value("dDelta"))
    else {
        return;
    };
    let t = ss.time;
    let t0 = start * dt;
    let says = if t == 0.0 && start > 0.0 {
        format!(
            "the initial conditions' time is 0 and iStartStep = {start}: pkdgrav resets it to iStartStep·dDelta = {t0:e}, with a warning that prints 0 (B44)"
        )
    } else if t > 0.0 && start == 0.0 {
        format!(
            "the initial conditions' time is {t:e} and iStartStep = 0: pkdgrav resets it to 0, with a warning (B45)"
        )
    } else if t != t0 {
        format!(
            "the initial conditions' time is {t:e}, not iStartStep·dDelta = {t0:e}: pkdgrav resets it, with a warning that the clocks may be inconsistent (B46)"
        )
    } else {
        return;
    };
    out.par.push(
        Diagnostic::new(&INITIAL_CONDITIONS, Severity::Warning, span, says).with_help(
            "write the .ss file's time as iStartStep·dDelta (walls-sim export does), or set iStartStep to the step it was written at",
        ),
    );
}
