//! How walls move (SPEC §1 "Motion", §3 "Contact velocity").
//!
//! A wall's origin at time t is origin + velocity·q + A·sin(ω·q + 2πφ)·ô, with q = t or,
//! when `step` > 0, t quantised to whole steps. A point q of the wall moves at
//! velocity + A·ω·cos(ω·q(t) + 2πφ)·ô + (Ω·orient) × (q − origin(t)); the spin changes
//! only what a contact feels, never where the wall is.
//!
//! pkdgrav itself moves an oscillating wall step by step, each step by the oscillation
//! velocity at its start times dt ([`OscillationStepping::Pkdgrav`]). That runs half a
//! step behind the exact sinusoid and half a step's travel above it: over a cycle of N
//! steps the largest gap is A·ω·dt = 2πA/N (0.31 A at 20 steps a cycle, 0.063 A at 100),
//! and after each whole cycle the two agree again: nothing accumulates (the tests measure
//! both).

use nalgebra::Vector3;
use std::f64::consts::TAU;
use walls_keywords::Keyword;
use walls_model::Wall;
use walls_model::motion::quantised_time;

type Vec3 = Vector3<f64>;

/// How an oscillating wall's position advances.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OscillationStepping {
    /// The exact sinusoid of SPEC §1 at every time.
    #[default]
    Exact,
    /// pkdgrav's way: each step adds the oscillation velocity at its start times dt.
    Pkdgrav,
}

/// A wall's motion.
#[derive(Debug, Clone, Copy)]
pub struct Motion<'w> {
    wall: &'w Wall,
}

impl<'w> Motion<'w> {
    /// The motion of `wall`.
    pub fn new(wall: &'w Wall) -> Self {
        Motion { wall }
    }

    fn phase(&self, t: f64) -> f64 {
        let w = self.wall;
        w.number(Keyword::OscFreq) * quantised_time(w, t)
            + TAU * w.number(Keyword::OscPhase).rem_euclid(1.0)
    }

    /// The velocity of the wall's origin at time `t`: linear plus oscillation.
    pub fn origin_velocity(&self, t: f64) -> Vec3 {
        let w = self.wall;
        let a = w.number(Keyword::OscAmpl);
        let mut v = w.vector(Keyword::Velocity);
        if a != 0.0 {
            v += w.vector(Keyword::OscVec) * (a * w.number(Keyword::OscFreq) * self.phase(t).cos());
        }
        v
    }

    /// The velocity of the wall's material at point `q` at time `t`, given where the
    /// origin is then: the origin's velocity plus the spin about `orient` through it.
    pub fn point_velocity(&self, q: &Vec3, origin: &Vec3, t: f64) -> Vec3 {
        let spin = self.wall.vector(Keyword::Orient) * self.wall.number(Keyword::AngSpeed);
        self.origin_velocity(t) + spin.cross(&(q - origin))
    }

    /// The origin after one step of `dt` from `origin` at time `t`.
    pub fn step(
        &self,
        origin: &Vec3,
        t: f64,
        dt: f64,
        stepping: OscillationStepping,
    ) -> Option<Vec3> {
        match stepping {
            OscillationStepping::Exact => walls_model::motion::position(self.wall, t + dt),
            OscillationStepping::Pkdgrav => {
                let next = origin + self.origin_velocity(t) * dt;
                next.iter().all(|x| x.is_finite()).then_some(next)
            }
        }
    }
}
