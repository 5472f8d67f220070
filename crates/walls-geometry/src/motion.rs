//! How walls move (docs/spec.md §1 "Motion", §3 "Contact velocity"): the one place wall
//! motion is computed.
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

type Vec3 = Vector3<f64>;

/// How an oscillating wall's position advances (`--oscillation` of `walls-sim run`:
/// each variant's first paragraph is its help).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum OscillationStepping {
    /// The exact sinusoid of docs/spec.md §1 at every step.
    Exact,
    /// pkdgrav's steps: each moves by the oscillation velocity at its start times dt.
    ///
    /// The default, as runs follow pkdgrav.
    #[default]
    Pkdgrav,
}

/// A wall's oscillation: A·sin(ω·q + 2πφ) along `direction`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oscillation {
    /// `osc-ampl`, A (0: none).
    pub amplitude: f64,
    /// `osc-freq`, ω (radians per unit time).
    pub frequency: f64,
    /// `osc-phase`, φ, a fraction of a cycle as written.
    pub phase: f64,
    /// `osc-vec`, ô (unit, or zero).
    pub direction: Vec3,
}

impl Oscillation {
    /// The phase within one cycle, φ mod 1: only that part of it matters.
    pub fn cycle(&self) -> f64 {
        self.phase.rem_euclid(1.0)
    }
}

/// A wall's motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
    /// Where its origin is at q = 0 (`origin`).
    pub origin: Vec3,
    /// Its linear velocity (`velocity`).
    pub velocity: Vec3,
    /// Its oscillation.
    pub oscillation: Oscillation,
    /// The update interval of its position (`step`; 0 or less: continuous).
    pub step: f64,
    /// The axis of its spin: `orient` (unit, or zero).
    pub spin_axis: Vec3,
    /// Its angular speed about that axis (`ang-speed`).
    pub ang_speed: f64,
}

impl Motion {
    /// Its angular velocity: `ang-speed` about `orient`.
    pub fn spin(&self) -> Vec3 {
        self.spin_axis * self.ang_speed
    }

    /// Whether the wall's origin moves: a velocity or an oscillation.
    pub fn translates(&self) -> bool {
        self.velocity.norm() > 0.0 || self.oscillation.amplitude != 0.0
    }

    /// The fastest its origin moves: |velocity| + |A·ω|.
    pub fn top_speed(&self) -> f64 {
        let o = &self.oscillation;
        self.velocity.norm() + (o.amplitude * o.frequency).abs()
    }

    /// The time the wall's motion is evaluated at: t quantised to whole steps. A step
    /// too small for t/step to be a finite double is no quantisation at all.
    fn quantised_time(&self, t: f64) -> f64 {
        let step = self.step;
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
    pub fn position(&self, t: f64) -> Option<Vec3> {
        let q = self.quantised_time(t);
        let o = &self.oscillation;
        let mut p = self.origin + self.velocity * q;
        if o.amplitude != 0.0 {
            let angle = o.frequency * q + TAU * o.cycle();
            p += o.direction * (o.amplitude * angle.sin());
        }
        p.iter().all(|x| x.is_finite()).then_some(p)
    }

    /// [`Motion::position`], or the origin as written where that overflows: where runs
    /// and previews place the wall.
    pub fn position_or_origin(&self, t: f64) -> Vec3 {
        self.position(t).unwrap_or(self.origin)
    }

    fn phase(&self, t: f64) -> f64 {
        let o = &self.oscillation;
        o.frequency * self.quantised_time(t) + TAU * o.cycle()
    }

    /// The velocity of the wall's origin at time `t`: linear plus oscillation.
    pub fn origin_velocity(&self, t: f64) -> Vec3 {
        let o = &self.oscillation;
        let mut v = self.velocity;
        if o.amplitude != 0.0 {
            v += o.direction * (o.amplitude * o.frequency * self.phase(t).cos());
        }
        v
    }

    /// The velocity of the wall's material at point `q` at time `t`, given where the
    /// origin is then: the origin's velocity plus the spin about `orient` through it.
    pub fn point_velocity(&self, q: &Vec3, origin: &Vec3, t: f64) -> Vec3 {
        self.origin_velocity(t) + self.spin().cross(&(q - origin))
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
            OscillationStepping::Exact => self.position(t + dt),
            OscillationStepping::Pkdgrav => {
                let next = origin + self.origin_velocity(t) * dt;
                next.iter().all(|x| x.is_finite()).then_some(next)
            }
        }
    }
}
