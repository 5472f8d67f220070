//! Where a wall is at time t (SPEC §1 "Motion").
//!
//! With q(t) = t, or ⌊t/step⌋·step when `step` > 0, a wall's origin at time t is
//! origin + velocity·q + osc-ampl·sin(osc-freq·q + 2π·osc-phase)·osc-vec. `ang-speed`
//! does not move the drawn shape.

use crate::scene::{Vec3, Wall};
use std::f64::consts::TAU;
use walls_keywords::Keyword;

/// The time the wall's motion is evaluated at: t quantised to whole steps.
pub fn quantised_time(wall: &Wall, t: f64) -> f64 {
    let step = wall.number(Keyword::Step);
    if step > 0.0 {
        (t / step).floor() * step
    } else {
        t
    }
}

/// The wall's origin displaced by its linear and oscillatory motion at time `t`.
pub fn position(wall: &Wall, t: f64) -> Vec3 {
    let q = quantised_time(wall, t);
    let phase = wall.number(Keyword::OscFreq) * q + TAU * wall.number(Keyword::OscPhase);
    wall.vector(Keyword::Origin)
        + wall.vector(Keyword::Velocity) * q
        + wall.vector(Keyword::OscVec) * (wall.number(Keyword::OscAmpl) * phase.sin())
}
