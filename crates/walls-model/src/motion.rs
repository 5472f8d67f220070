//! Where a wall is at time t (SPEC §1 "Motion").
//!
//! With q(t) = t, or ⌊t/step⌋·step when `step` > 0, a wall's origin at time t is
//! origin + velocity·q + osc-ampl·sin(osc-freq·q + 2π·osc-phase)·osc-vec. `ang-speed`
//! does not move the drawn shape.

use crate::scene::{Vec3, Wall};
use std::f64::consts::TAU;
use walls_keywords::Keyword;

/// The time the wall's motion is evaluated at: t quantised to whole steps. A step too
/// small for t/step to be a finite double is no quantisation at all.
pub fn quantised_time(wall: &Wall, t: f64) -> f64 {
    let step = wall.number(Keyword::Step);
    let steps = (t / step).floor();
    if step > 0.0 && steps.is_finite() {
        steps * step
    } else {
        t
    }
}

/// The wall's origin displaced by its linear and oscillatory motion at time `t`, or
/// `None` when that is not a finite point (values so large that the arithmetic
/// overflows a double).
pub fn position(wall: &Wall, t: f64) -> Option<Vec3> {
    let q = quantised_time(wall, t);
    let amplitude = wall.number(Keyword::OscAmpl);
    let mut p = wall.vector(Keyword::Origin) + wall.vector(Keyword::Velocity) * q;
    if amplitude != 0.0 {
        // The phase is a fraction of a cycle: only its part within one cycle matters.
        let cycle = wall.number(Keyword::OscPhase).rem_euclid(1.0);
        let angle = wall.number(Keyword::OscFreq) * q + TAU * cycle;
        p += wall.vector(Keyword::OscVec) * (amplitude * angle.sin());
    }
    p.iter().all(|x| x.is_finite()).then_some(p)
}
