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
//! both). pkdgrav's soft-sphere build moves its walls otherwise again
//! ([`Motion::soft_sphere_step`], with the velocity of [`Motion::smooth_velocity`];
//! docs/pkdgrav-physics.md §5).
//!
//! [`Moving`] ([`rigid`]) is a wall's motion at one instant, wherever it came from (its
//! [`Motion`], or a reactive assembly): the velocity of its material at a point, a point
//! it holds carried over a step, a vector [`turned`] with its spin.

pub mod rigid;

pub use rigid::{Moving, turned};

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

    /// The velocity of the wall's origin at time `t`: linear plus oscillation.
    pub fn origin_velocity(&self, t: f64) -> Vec3 {
        self.velocity_at(self.quantised_time(t))
    }

    /// The origin's velocity, linear plus A·ω·cos(ω·t + 2πφ) along `osc-vec`, at the
    /// time `t` as given (quantised or not by the caller).
    fn velocity_at(&self, t: f64) -> Vec3 {
        let o = &self.oscillation;
        let mut v = self.velocity;
        if o.amplitude != 0.0 {
            let angle = o.frequency * t + TAU * o.cycle();
            v += o.direction * (o.amplitude * o.frequency * angle.cos());
        }
        v
    }

    /// The velocity of the wall's material at point `q` at time `t`, given where the
    /// origin is then: the origin's velocity plus the spin about `orient` through it.
    pub fn point_velocity(&self, q: &Vec3, origin: &Vec3, t: f64) -> Vec3 {
        self.moving(*origin, self.origin_velocity(t))
            .point_velocity(q)
    }

    /// The wall moving with its origin at `origin` at `velocity`, spinning as its
    /// [`Motion::spin`] says.
    #[inline]
    pub fn moving(&self, origin: Vec3, velocity: Vec3) -> Moving {
        Moving {
            origin,
            velocity,
            spin: self.spin(),
        }
    }

    /// The velocity pkdgrav gives a wall's origin at time `t` (docs/pkdgrav-physics.md
    /// §5): `velocity` plus A·ω·cos(ω·t + 2πφ) along `osc-vec`, with t not quantised to
    /// `step`.
    pub fn smooth_velocity(&self, t: f64) -> Vec3 {
        self.velocity_at(t)
    }

    /// The origin after the step from `t` to `t + dt`, from `origin`, as pkdgrav's
    /// soft-sphere build moves a wall (`msrWallsMove(t + dt/2, dt)`,
    /// docs/pkdgrav-physics.md §5): by the change of the sinusoid and of the linear travel
    /// between the whole steps of `step` (dt when it is 0) that hold t + dt/2 and
    /// t + 3dt/2. `None` when the wall's origin does not move (no velocity, no
    /// oscillation) or the move is not a finite point: the origin stays where it is.
    pub fn soft_sphere_step(&self, origin: &Vec3, t: f64, dt: f64) -> Option<Vec3> {
        if !self.translates() {
            return None;
        }
        let (ta, tb) = (t + 0.5 * dt, t + 1.5 * dt);
        let step = if self.step > 0.0 { self.step } else { dt };
        let (qa, qb) = ((ta / step).floor() * step, (tb / step).floor() * step);
        let osc = &self.oscillation;
        let mut next = *origin + self.velocity * (qb - qa);
        if osc.amplitude != 0.0 {
            let phase = TAU * osc.cycle();
            let swing = (osc.frequency * qb + phase).sin() - (osc.frequency * qa + phase).sin();
            next += osc.direction * (osc.amplitude * swing);
        }
        next.iter().all(|x| x.is_finite()).then_some(next)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A wall moving at `velocity` and oscillating with amplitude 0.2 along x at ω = 3,
    /// φ = 0.1, its position updated every `step`.
    fn wall(velocity: Vec3, step: f64) -> Motion {
        Motion {
            origin: Vec3::new(1.0, 2.0, 3.0),
            velocity,
            oscillation: Oscillation {
                amplitude: 0.2,
                frequency: 3.0,
                phase: 0.1,
                direction: Vec3::x(),
            },
            step,
            spin_axis: Vec3::z(),
            ang_speed: 0.5,
        }
    }

    #[test]
    fn the_smooth_velocity_is_the_exact_one_without_quantising() {
        let m = wall(Vec3::new(0.0, 1.0, 0.0), 0.0);
        for t in [0.0, 0.3, 1.7] {
            assert_eq!(m.smooth_velocity(t), m.origin_velocity(t));
        }
        // With a step, the smooth velocity still follows t, the exact one q(t).
        let stepped = wall(Vec3::new(0.0, 1.0, 0.0), 0.5);
        assert_eq!(stepped.smooth_velocity(0.7), m.origin_velocity(0.7));
        assert_eq!(stepped.origin_velocity(0.7), m.origin_velocity(0.5));
    }

    #[test]
    fn the_soft_sphere_step_moves_by_the_change_between_whole_steps() {
        let dt = 0.01;
        let m = wall(Vec3::new(0.0, 1.0, 0.0), 0.0);
        // Each step moves the origin from the whole step holding t + dt/2 to the one
        // holding t + 3dt/2, from t to t + dt: step after step it lands on the sinusoid.
        let mut o = m.position(0.0).unwrap();
        let mut t = 0.0;
        for _ in 0..100 {
            o = m.soft_sphere_step(&o, t, dt).unwrap();
            t += dt;
        }
        let exact = m.position(t).unwrap();
        assert!((o - exact).norm() < 1e-12, "{o} against {exact}");
        // With a step of 5 dt, the origin moves only at multiples of it.
        let coarse = wall(Vec3::zeros(), 5.0 * dt);
        let moves: Vec<bool> = (0..10)
            .map(|k| {
                let o = Vec3::zeros();
                coarse.soft_sphere_step(&o, k as f64 * dt, dt).unwrap() != o
            })
            .collect();
        assert_eq!(moves.iter().filter(|m| **m).count(), 2, "{moves:?}");
    }

    #[test]
    fn a_wall_that_does_not_translate_or_overflows_stays() {
        let still = Motion {
            velocity: Vec3::zeros(),
            oscillation: Oscillation {
                amplitude: 0.0,
                ..wall(Vec3::zeros(), 0.0).oscillation
            },
            ..wall(Vec3::zeros(), 0.0)
        };
        assert_eq!(still.soft_sphere_step(&Vec3::zeros(), 0.0, 0.1), None);
        let fast = wall(Vec3::new(f64::MAX, 0.0, 0.0), 0.0);
        assert_eq!(
            fast.soft_sphere_step(&Vec3::new(f64::MAX, 0.0, 0.0), 0.0, 10.0),
            None
        );
    }

    #[test]
    fn the_point_velocity_spins_about_the_origin() {
        let m = wall(Vec3::zeros(), 0.0);
        let origin = m.position(0.4).unwrap();
        let q = origin + Vec3::x();
        let v = m.point_velocity(&q, &origin, 0.4);
        assert_eq!(v, m.origin_velocity(0.4) + Vec3::new(0.0, 0.5, 0.0));
        assert_eq!(
            v,
            m.moving(origin, m.origin_velocity(0.4)).point_velocity(&q)
        );
    }
}
