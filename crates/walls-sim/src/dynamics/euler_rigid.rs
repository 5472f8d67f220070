//! pkdgrav's integration of a rigid body's rotation over one step
//! (docs/pkdgrav-physics.md §9.3 and §10): the body-frame angular velocity ω and the
//! principal axes, integrated together by Euler's equations with the body-frame torque
//! held fixed, by the adaptive Cash–Karp Runge–Kutta of Numerical Recipes (`odeint`
//! driving `rkqs` and `rkck`).
//!
//! This is the integrator of both pkdgrav's reactive wall assemblies (`DEM_WALLS_REACT`)
//! and its aggregates (`AGGS`): [`integrate`] advances a [`Rotation`] over `dt` given the
//! principal moments and the torque in the body frame. Aggregates re-orthonormalise the
//! axes afterwards (§9.3); reactive walls do not say so, and this function leaves the
//! axes as the integrator leaves them.
//!
//! # The equations
//!
//! The state is y = (ω₁, ω₂, ω₃, p̂₁, p̂₂, p̂₃): ω in the body (principal) frame and the
//! three principal axes in the space frame (p̂₁ = `pxj`, p̂₂ = `pyj`, p̂₃ = `pzj`), twelve
//! numbers. With principal moments Iᵢ and body torque τᵢ:
//!
//! - I₁ω̇₁ = τ₁ + (I₂ − I₃)ω₂ω₃, and cyclically;
//! - ṗ̂₁ = ω₃p̂₂ − ω₂p̂₃, ṗ̂₂ = ω₁p̂₃ − ω₃p̂₁, ṗ̂₃ = ω₂p̂₁ − ω₁p̂₂, componentwise (the
//!   axes turn with the space angular velocity Σωᵢp̂ᵢ, written linearly in the axes).
//!
//! # The integrator (Numerical Recipes, 2nd ed., §16.2)
//!
//! - `odeint`: from t = 0 to dt, first trial step h = dt; before each step the scale
//!   yscalᵢ = |yᵢ| + |h·ẏᵢ| + 10⁻¹⁵ and, if the step would pass dt, h = dt − t.
//! - `rkqs`: one Cash–Karp step (`rkck`); errmax = maxᵢ |errᵢ/yscalᵢ| / tolerance; while
//!   errmax > 1, h ← sign(h)·max(0.9|h|·errmax^−¼, 0.1|h|) and retry; on success the next
//!   h is 0.9·h·errmax^−⅕ when errmax > 1.89·10⁻⁴, else 5h.
//! - pkdgrav's tolerance is 10⁻⁶ and its minimum step 10⁻³·dt (docs/pkdgrav-physics.md
//!   §17). Numerical Recipes stops with an error when the next step would be that small;
//!   pkdgrav only warns and goes on. Here the step is held at the minimum (and a step at
//!   the minimum is taken whatever its error), and [`Cost::floor`] says the minimum was
//!   reached, for the run's warning.
//! - pkdgrav exits (status 1) on a step underflow (a step too small to move the clock) or
//!   after more than [`MAX_STEPS`] steps: [`Cost::failure`] says so, the rotation is left
//!   where the last step took it, and the run stops. With the minimum step of 10⁻³·dt
//!   neither can happen to finite numbers (at most about 1,000 steps are taken).
//!
//! For pkdgrav's reactive walls one step of the order of the particles' contact time is
//! a rotation of well under a degree, and one Cash–Karp step of dt is accepted.

use crate::dynamics::rigid::{Rotation, State};
use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// pkdgrav's relative accuracy.
pub const TOLERANCE: f64 = 1e-6;
/// pkdgrav's minimum step, as a fraction of the whole step.
pub const MIN_STEP_FRACTION: f64 = 1e-3;
/// The floor added to each scale (pkdgrav's `TINY`).
pub const TINY: f64 = 1e-15;
/// The most steps one integration takes (Numerical Recipes' and pkdgrav's `MAXSTP`).
pub const MAX_STEPS: u32 = 10_000;

/// What an integration cost, and whether it reached the minimum step or failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Cost {
    /// Cash–Karp steps accepted.
    pub accepted: u32,
    /// Cash–Karp steps rejected and retried smaller.
    pub rejected: u32,
    /// Whether the minimum step was reached: a step (or a retry) the accuracy asked to
    /// be smaller was held at the minimum, or a step at the minimum was taken with its
    /// error above the tolerance (pkdgrav warns, and goes on).
    pub floor: bool,
    /// Why the integration did not reach the step's end, where pkdgrav exits.
    pub failure: Option<Failure>,
}

/// Why an adaptive integration could not finish a step: where pkdgrav exits with status
/// 1 (docs/pkdgrav-physics.md §17).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Failure {
    /// A step too small to move the clock (Numerical Recipes' "stepsize underflow").
    Underflow,
    /// More than [`MAX_STEPS`] steps.
    TooManySteps,
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::Underflow => f.write_str("a substep too small to move the clock (underflow)"),
            Failure::TooManySteps => write!(f, "more than {MAX_STEPS} substeps"),
        }
    }
}

/// Advances `rot` (body ω and space axes) over `dt` by Euler's equations with principal
/// moments `inertia` (all > 0) and the body-frame torque `torque_body` held fixed:
/// pkdgrav's Cash–Karp integration with its tolerance ([`TOLERANCE`]).
pub fn integrate(rot: &mut Rotation, inertia: &Vec3, torque_body: &Vec3, dt: f64) -> Cost {
    integrate_with(rot, inertia, torque_body, dt, TOLERANCE)
}

/// [`integrate`] with relative accuracy `tolerance`.
pub fn integrate_with(
    rot: &mut Rotation,
    inertia: &Vec3,
    torque_body: &Vec3,
    dt: f64,
    tolerance: f64,
) -> Cost {
    let limits = Limits {
        tolerance,
        min_step_fraction: MIN_STEP_FRACTION,
        max_steps: MAX_STEPS,
    };
    integrate_within(rot, inertia, torque_body, dt, limits)
}

/// An integration's accuracy and bounds: pkdgrav's are [`TOLERANCE`],
/// [`MIN_STEP_FRACTION`] and [`MAX_STEPS`].
#[derive(Debug, Clone, Copy)]
struct Limits {
    tolerance: f64,
    min_step_fraction: f64,
    max_steps: u32,
}

/// [`integrate`] within `limits`.
fn integrate_within(
    rot: &mut Rotation,
    inertia: &Vec3,
    torque_body: &Vec3,
    dt: f64,
    limits: Limits,
) -> Cost {
    let mut cost = Cost::default();
    if dt == 0.0 {
        return cost;
    }
    let tolerance = limits.tolerance;
    let f = |y: &State| derivative(y, inertia, torque_body);
    let (x1, x2) = (0.0, dt);
    let h_min = limits.min_step_fraction * dt.abs();
    let mut y = rot.packed();
    let mut x = x1;
    let mut h = dt;
    let mut done = false;
    for _ in 0..limits.max_steps {
        let dydx = f(&y);
        let mut yscal = State::zeros();
        for i in 0..12 {
            yscal[i] = y[i].abs() + (dydx[i] * h).abs() + TINY;
        }
        if (x + h - x2) * (x + h - x1) > 0.0 {
            h = x2 - x;
        }
        // rkqs
        let mut hh = h;
        let (y_new, h_next) = loop {
            let (y_try, err) = cash_karp(&y, &dydx, hh, &f);
            let mut errmax = 0.0f64;
            for i in 0..12 {
                errmax = errmax.max((err[i] / yscal[i]).abs());
            }
            errmax /= tolerance;
            let at_minimum = hh.abs() <= h_min;
            if errmax <= 1.0 || at_minimum || !errmax.is_finite() {
                cost.accepted += 1;
                cost.floor |= errmax > 1.0 && errmax.is_finite();
                let next = if errmax > 1.89e-4 {
                    0.9 * hh * errmax.powf(-0.2)
                } else {
                    5.0 * hh
                };
                break (y_try, next);
            }
            cost.rejected += 1;
            let htemp = 0.9 * hh * errmax.powf(-0.25);
            hh = if hh >= 0.0 {
                htemp.max(0.1 * hh)
            } else {
                htemp.min(0.1 * hh)
            };
            if hh.abs() < h_min {
                hh = h_min * dt.signum();
                cost.floor = true;
            }
        };
        if x + hh == x {
            cost.failure = Some(Failure::Underflow);
            break;
        }
        x += hh;
        y = y_new;
        if (x - x2) * (x2 - x1) >= 0.0 {
            done = true;
            break;
        }
        h = if h_next.abs() <= h_min {
            cost.floor = true;
            h_min * dt.signum()
        } else {
            h_next
        };
    }
    if !done && cost.failure.is_none() {
        cost.failure = Some(Failure::TooManySteps);
    }
    rot.unpack(&y);
    cost
}

/// The right-hand side: Euler's equations and the axes' turn.
fn derivative(y: &State, inertia: &Vec3, torque: &Vec3) -> State {
    let (w1, w2, w3) = (y[0], y[1], y[2]);
    let (i1, i2, i3) = (inertia.x, inertia.y, inertia.z);
    let mut d = State::zeros();
    d[0] = (torque.x + (i2 - i3) * w2 * w3) / i1;
    d[1] = (torque.y + (i3 - i1) * w3 * w1) / i2;
    d[2] = (torque.z + (i1 - i2) * w1 * w2) / i3;
    for c in 0..3 {
        let (p1, p2, p3) = (y[3 + c], y[6 + c], y[9 + c]);
        d[3 + c] = w3 * p2 - w2 * p3;
        d[6 + c] = w1 * p3 - w3 * p1;
        d[9 + c] = w2 * p1 - w1 * p2;
    }
    d
}

/// One Cash–Karp step (Numerical Recipes' `rkck`): the fifth-order result and the
/// error estimate.
fn cash_karp(y: &State, dydx: &State, h: f64, f: &impl Fn(&State) -> State) -> (State, State) {
    const B21: f64 = 0.2;
    const B31: f64 = 3.0 / 40.0;
    const B32: f64 = 9.0 / 40.0;
    const B41: f64 = 0.3;
    const B42: f64 = -0.9;
    const B43: f64 = 1.2;
    const B51: f64 = -11.0 / 54.0;
    const B52: f64 = 2.5;
    const B53: f64 = -70.0 / 27.0;
    const B54: f64 = 35.0 / 27.0;
    const B61: f64 = 1631.0 / 55296.0;
    const B62: f64 = 175.0 / 512.0;
    const B63: f64 = 575.0 / 13824.0;
    const B64: f64 = 44275.0 / 110592.0;
    const B65: f64 = 253.0 / 4096.0;
    const C1: f64 = 37.0 / 378.0;
    const C3: f64 = 250.0 / 621.0;
    const C4: f64 = 125.0 / 594.0;
    const C6: f64 = 512.0 / 1771.0;
    const DC1: f64 = C1 - 2825.0 / 27648.0;
    const DC3: f64 = C3 - 18575.0 / 48384.0;
    const DC4: f64 = C4 - 13525.0 / 55296.0;
    const DC5: f64 = -277.0 / 14336.0;
    const DC6: f64 = C6 - 0.25;
    let mut t = State::zeros();
    for i in 0..12 {
        t[i] = y[i] + B21 * h * dydx[i];
    }
    let ak2 = f(&t);
    for i in 0..12 {
        t[i] = y[i] + h * (B31 * dydx[i] + B32 * ak2[i]);
    }
    let ak3 = f(&t);
    for i in 0..12 {
        t[i] = y[i] + h * (B41 * dydx[i] + B42 * ak2[i] + B43 * ak3[i]);
    }
    let ak4 = f(&t);
    for i in 0..12 {
        t[i] = y[i] + h * (B51 * dydx[i] + B52 * ak2[i] + B53 * ak3[i] + B54 * ak4[i]);
    }
    let ak5 = f(&t);
    for i in 0..12 {
        t[i] =
            y[i] + h * (B61 * dydx[i] + B62 * ak2[i] + B63 * ak3[i] + B64 * ak4[i] + B65 * ak5[i]);
    }
    let ak6 = f(&t);
    let mut out = State::zeros();
    let mut err = State::zeros();
    for i in 0..12 {
        out[i] = y[i] + h * (C1 * dydx[i] + C3 * ak3[i] + C4 * ak4[i] + C6 * ak6[i]);
        err[i] = h * (DC1 * dydx[i] + DC3 * ak3[i] + DC4 * ak4[i] + DC5 * ak5[i] + DC6 * ak6[i]);
    }
    (out, err)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_constant_torque_about_a_principal_axis_spins_it_up_linearly() {
        let mut rot = Rotation::new(Vec3::zeros());
        let inertia = Vec3::new(2.0, 3.0, 4.0);
        integrate(&mut rot, &inertia, &Vec3::new(0.0, 0.0, 8.0), 0.5);
        assert!((rot.omega.z - 1.0).abs() < 1e-15);
        // The body turns by ½·α·t² = 0.25 rad about z.
        let angle = rot.axes[0].y.atan2(rot.axes[0].x);
        assert!((angle - 0.25).abs() < 1e-6, "{angle}");
    }

    /// A body tumbling about no principal axis, and its moments.
    fn tumbling() -> (Rotation, Vec3) {
        (
            Rotation::new(Vec3::new(1.0, 2.0, 3.0)),
            Vec3::new(1.0, 2.0, 3.0),
        )
    }

    #[test]
    fn a_step_of_many_turns_reaches_the_minimum_step_and_goes_on() {
        // 200 rad/s for a step of 1: at dt/1000 a turn of 0.2 rad, too coarse for 10⁻⁶.
        let (mut rot, inertia) = tumbling();
        rot.omega *= 60.0;
        let cost = integrate(&mut rot, &inertia, &Vec3::zeros(), 1.0);
        assert!(cost.floor, "{cost:?}");
        assert_eq!(cost.failure, None);
        // Most of them held at the minimum: about a thousand steps.
        assert!((900..=1100).contains(&cost.accepted), "{cost:?}");
        // A slow one does not.
        let (mut rot, inertia) = tumbling();
        let cost = integrate(&mut rot, &inertia, &Vec3::zeros(), 0.01);
        assert!(!cost.floor && cost.failure.is_none(), "{cost:?}");
    }

    #[test]
    fn more_steps_than_allowed_fail_and_leave_the_rotation_where_the_last_took_it() {
        let (mut rot, inertia) = tumbling();
        let limits = Limits {
            tolerance: TOLERANCE,
            min_step_fraction: MIN_STEP_FRACTION,
            max_steps: 3,
        };
        let cost = integrate_within(&mut rot, &inertia, &Vec3::zeros(), 1.0, limits);
        assert_eq!(cost.failure, Some(Failure::TooManySteps));
        assert_eq!(cost.accepted, 3);
        assert!(rot.omega != Vec3::new(1.0, 2.0, 3.0));
    }
}
