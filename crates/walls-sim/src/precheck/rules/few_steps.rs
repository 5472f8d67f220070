//! R004 `few-steps-per-contact`: `dDelta` too long for the stiffest contact of the
//! lightest particle.
//!
//! The contact of mass μ and spring k lasts π·√(μ/k) undamped (μ = m/2 between two equal
//! particles, m against a wall: [`crate::advise`]); the stiffest is that of the lightest
//! particle, between two of them with `dKn`, against each wall with its `k_n` (−1:
//! `dKn`). Fewer than [`crate::advise::MIN_STEPS_PER_CONTACT`] steps per contact is the
//! rule of `walls-sim advise` and of the evaluator's W202; a step of 2/ω or more
//! (ω = √(k/μ)) is beyond the leapfrog's stability limit (W201) and is said so.

use crate::advise::{MIN_STEPS_PER_CONTACT, significant};
use crate::precheck::{Context, Findings};
use walls_diagnostics::Diagnostic;

pub use walls_par::run_codes::few_steps::FEW_STEPS;

/// Warns at `dDelta` when the stiffest contact has too few steps.
pub(crate) fn check(cx: &Context, out: &mut Findings) {
    let Some(ss) = cx.particles() else { return };
    if !cx.dem {
        return;
    }
    let (Some((dt, dt_span)), Some((k_n, k_span))) = (cx.par_value("dDelta"), cx.par_value("dKn"))
    else {
        return;
    };
    if !(dt > 0.0 && dt.is_finite() && k_n >= 0.0 && k_n.is_finite()) {
        return;
    }
    // The mass a contact moves: the particle's, or with AGGS its aggregate's (members
    // move as one body, docs/pkdgrav-physics.md §9).
    let aggs = cx.run.par.build.has("AGGS");
    let mut aggregates: std::collections::HashMap<i32, f64> = std::collections::HashMap::new();
    if aggs {
        for p in ss.particles.iter().filter(|p| p.index < 0) {
            *aggregates.entry(p.index).or_default() += p.mass;
        }
    }
    let body = |p: &walls_geometry::Particle| match aggregates.get(&p.index) {
        Some(m) if aggs && p.index < 0 => *m,
        _ => p.mass,
    };
    let Some((k, lightest)) = (ss.particles.iter().enumerate())
        .map(|(k, p)| (k, body(p)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
    else {
        return;
    };
    let who = match ss.particles[k].index {
        i if aggs && i < 0 => format!("aggregate {} (particle {k}'s, m = {lightest:e})", -1 - i),
        _ => format!("particle {k} (m = {lightest:e})"),
    };
    // The stiffest contact, as ω = √(k/μ), with what it is.
    let mut stiffest: Option<(f64, String)> = None;
    let mut consider = |omega: f64, what: String| {
        if omega.is_finite() && omega > 0.0 && stiffest.as_ref().is_none_or(|(o, _)| omega > *o) {
            stiffest = Some((omega, what));
        }
    };
    // Members of one aggregate never meet (AGGS): a run of one aggregate has no pairs.
    let first = ss.particles.first().map_or(0, |p| p.index);
    let one_aggregate =
        cx.run.par.build.has("AGGS") && first < 0 && ss.particles.iter().all(|p| p.index == first);
    if ss.particles.len() > 1 && !one_aggregate {
        consider(
            (2.0 * k_n / lightest).sqrt(),
            format!("two bodies as light as {who} with dKn = {k_n:e}"),
        );
    }
    for (w, wall) in cx.walls.iter().enumerate() {
        let k_w = if wall.material.k_n < 0.0 {
            k_n
        } else {
            wall.material.k_n
        };
        consider(
            (k_w / lightest).sqrt(),
            format!("{who} against {} (k_n = {k_w:e})", cx.wall_name(w)),
        );
    }
    let Some((omega, what)) = stiffest else {
        return;
    };
    let steps = std::f64::consts::PI / omega / dt;
    if steps >= MIN_STEPS_PER_CONTACT {
        return;
    }
    let unstable = dt >= 2.0 / omega;
    let message = format!(
        "dDelta = {dt:e} gives {} steps per contact for the stiffest contact, {what}; fewer than {MIN_STEPS_PER_CONTACT}{}",
        significant(steps, 3),
        if unstable {
            format!(
                ", and the step is beyond the leapfrog's stability limit 2/ω = {:e}: the run gains energy",
                2.0 / omega
            )
        } else {
            ": the rebound's restitution is off by several per cent".to_string()
        }
    );
    let mut d = Diagnostic::warning(&FEW_STEPS, dt_span, message);
    if cx.run.par.given("dKn").is_some() {
        d = d.with_label(k_span, "the spring constant");
    }
    out.par.push(
        d.with_help(format!(
                "a dDelta of {} or less gives 30 steps a contact (walls-sim advise gives dKn and dDelta from the particles' size and speed)",
                significant(std::f64::consts::PI / omega / 30.0, 3)
            )),
    );
}
