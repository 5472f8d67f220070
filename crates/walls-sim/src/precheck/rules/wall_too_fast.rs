//! R005 `wall-too-fast-for-particles`: a wall that moves more than a tenth of the smallest particle's
//! radius in one step (or one jump of its `step`), the evaluator's W203 rule: a contact
//! can then start deep, or be stepped over.

use crate::precheck::{Context, Findings};
use crate::run::stability::WALL_TRAVEL_FRACTION;
use walls_diagnostics::Diagnostic;

pub use walls_par::run_codes::wall_too_fast::WALL_TOO_FAST;

/// Warns at each wall that moves too far in a step.
pub(crate) fn check(cx: &Context, out: &mut Findings) {
    if cx.particles().is_none() {
        return;
    }
    let Some((dt, _)) = cx.par_value("dDelta") else {
        return;
    };
    let Some((k, smallest)) =
        (cx.radii.iter().copied().enumerate()).min_by(|a, b| a.1.total_cmp(&b.1))
    else {
        return;
    };
    for (w, wall) in cx.walls.iter().enumerate() {
        let speed = wall.motion.top_speed();
        let interval = wall.motion.step.max(dt);
        let travel = speed * interval;
        if !(travel.is_finite() && travel > WALL_TRAVEL_FRACTION * smallest) {
            continue;
        }
        out.walls.push(
            Diagnostic::warning(
                &WALL_TOO_FAST,
                cx.wall_span(w),
                format!(
                    "{} moves up to {travel:e} in one step ({speed:e} × {interval:e}), more than a tenth of the smallest particle's radius {smallest:e} (particle {k}): contacts start deep or are stepped over",
                    cx.wall_name(w)
                ),
            )
            .with_help("shorten dDelta (or the wall's step), or slow the wall"),
        );
    }
}
