//! The rotation of a rigid body with diagonal principal inertia under a torque given in
//! the world frame, as a reactive wall assembly turns (docs/spec.md §3 "Reactive walls").
//!
//! The state is the body-frame angular velocity ω and the principal axes p̂₁, p̂₂, p̂₃ in
//! the world frame; the world angular velocity is Σ ωᵢ p̂ᵢ and the world angular momentum
//! L = Σ Iᵢ ωᵢ p̂ᵢ. Two integrators ([`RotationIntegrator`]):
//!
//! - [`RotationIntegrator::AdaptiveRk`], pkdgrav's way: Euler's equations in the body
//!   frame, Iᵢ ω̇ᵢ = (Iⱼ − Iₖ) ωⱼ ωₖ + τ·p̂ᵢ (i, j, k cyclic), with dp̂ᵢ/dt = ω_world × p̂ᵢ,
//!   integrated by the embedded Dormand–Prince 5(4) pair with an adaptive substep:
//!   relative accuracy 10⁻⁶ (on the norm of ω, scaled like Numerical Recipes' `rkqs` by
//!   |ω| + h|ω̇|, and on the unit axes), first substep dt, minimum substep 10⁻³·dt (a
//!   substep that small is accepted whatever its error, and [`Steps::floor`] says the
//!   minimum was reached); a substep too small to move the clock, or more than
//!   [`MAX_STEPS`] substeps, end the step where it is ([`Steps::failure`]), as pkdgrav's
//!   integrator exits there (docs/pkdgrav-physics.md §17). It conserves neither 2E nor |L|
//!   exactly: both drift, slowly, at the accuracy asked for.
//! - [`RotationIntegrator::LieSplitting`], symplectic and Lie–Poisson: half a kick of the
//!   world angular momentum, L += τ·dt/2; the free body split into its three exact
//!   rotations about the principal axes (McLachlan 1993; Reich 1994; Dullweber, Leimkuhler
//!   & McLachlan 1997), each sub-flow turning the body about p̂ᵢ by (L·p̂ᵢ/Iᵢ)·h, composed
//!   symmetrically (Strang) as 1(dt/2) 2(dt/2) 3(dt) 2(dt/2) 1(dt/2); the other half kick.
//!   Second order, time-reversible; the sub-flows leave L untouched, so |L| is kept to
//!   rounding and a constant torque changes L by exactly τ·t; the energy oscillates by
//!   O(dt²) without drift.
//!
//! Both keep the axes orthonormal: after each step, if the largest |p̂ᵢ·p̂ⱼ − δᵢⱼ| exceeds
//! 10⁻¹⁵, they are replaced by the nearest orthonormal frame (the polar factor, by
//! Newton–Schulz iterations, which treat the three axes alike). The splitting's rotations
//! are orthogonal, so only rounding ever triggers that; the Runge–Kutta substeps drift at
//! their truncation error and are corrected nearly every step. The body-frame ω is left as
//! it is: the splitting carries the body components of L, turned with the axes.

pub use crate::dynamics::euler_rigid::{Failure, MAX_STEPS};
use nalgebra::{Matrix3, SVector, Vector3};

type Vec3 = Vector3<f64>;
/// A rotation as twelve numbers: ω, then p̂₁, p̂₂, p̂₃ (the integrators' state).
pub(crate) type State = SVector<f64, 12>;

/// A rigid body's rotation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rotation {
    /// The angular velocity in the body (principal) frame.
    pub omega: Vec3,
    /// The principal axes p̂₁, p̂₂, p̂₃ in the world frame (orthonormal, right-handed).
    pub axes: [Vec3; 3],
}

impl Rotation {
    /// The rotation as the integrators' state vector: ω, then p̂₁, p̂₂, p̂₃.
    pub(crate) fn packed(&self) -> State {
        let mut y = State::zeros();
        y.fixed_rows_mut::<3>(0).copy_from(&self.omega);
        for i in 0..3 {
            y.fixed_rows_mut::<3>(3 + 3 * i).copy_from(&self.axes[i]);
        }
        y
    }

    /// Takes the rotation back from a state vector ([`Rotation::packed`]).
    pub(crate) fn unpack(&mut self, y: &State) {
        self.omega = y.fixed_rows::<3>(0).into_owned();
        for i in 0..3 {
            self.axes[i] = y.fixed_rows::<3>(3 + 3 * i).into_owned();
        }
    }

    /// A body with body-frame angular velocity `omega` whose principal axes are the world
    /// axes.
    pub fn new(omega: Vec3) -> Rotation {
        Rotation {
            omega,
            axes: [Vec3::x(), Vec3::y(), Vec3::z()],
        }
    }

    /// The angular velocity in the world frame, Σ ωᵢ p̂ᵢ.
    pub fn omega_world(&self) -> Vec3 {
        self.axes[0] * self.omega.x + self.axes[1] * self.omega.y + self.axes[2] * self.omega.z
    }

    /// The angular momentum in the world frame, Σ Iᵢ ωᵢ p̂ᵢ.
    pub fn momentum_world(&self, inertia: &Vec3) -> Vec3 {
        self.axes[0] * (inertia.x * self.omega.x)
            + self.axes[1] * (inertia.y * self.omega.y)
            + self.axes[2] * (inertia.z * self.omega.z)
    }

    /// Twice the kinetic energy, Σ Iᵢ ωᵢ².
    pub fn twice_energy(&self, inertia: &Vec3) -> f64 {
        inertia.component_mul(&self.omega).dot(&self.omega)
    }

    /// The largest |p̂ᵢ·p̂ⱼ − δᵢⱼ|: how far the axes are from orthonormal.
    pub fn orthonormality_error(&self) -> f64 {
        let a = self.axes_matrix();
        (a.transpose() * a - Matrix3::identity()).amax()
    }

    /// The axes as the columns of a matrix (body to world).
    pub fn axes_matrix(&self) -> Matrix3<f64> {
        Matrix3::from_columns(&self.axes)
    }
}

/// How [`step`] integrates the rotation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RotationIntegrator {
    /// pkdgrav's: Euler's equations by embedded Dormand–Prince 5(4), relative accuracy
    /// 10⁻⁶, minimum substep 10⁻³·dt.
    #[default]
    AdaptiveRk,
    /// The symmetric splitting of the free body into exact rotations about the principal
    /// axes, between two half kicks of the angular momentum by the torque.
    LieSplitting,
}

/// What a step cost.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Steps {
    /// Substeps accepted (1 for the splitting).
    pub substeps: u32,
    /// Substeps rejected and retried smaller.
    pub rejected: u32,
    /// Evaluations of the right-hand side (the splitting: its five axis rotations).
    pub evaluations: u32,
    /// Whether the axes were re-orthonormalised after the step.
    pub reorthonormalised: bool,
    /// [`RotationIntegrator::AdaptiveRk`]: whether the minimum substep was reached (a
    /// substep the accuracy asked to be smaller held at the minimum).
    pub floor: bool,
    /// [`RotationIntegrator::AdaptiveRk`]: why the step did not reach its end.
    pub failure: Option<Failure>,
}

/// pkdgrav's relative accuracy for the rotation.
pub const PKDGRAV_TOLERANCE: f64 = 1e-6;
/// pkdgrav's minimum substep, as a fraction of the step.
pub const MIN_SUBSTEP_FRACTION: f64 = 1e-3;
/// The orthonormality error above which the axes are re-orthonormalised.
pub const ORTHONORMALITY_LIMIT: f64 = 1e-15;

/// Advances `rot` by `dt` under `torque_world` (constant over the step) with the
/// principal moments `inertia` (all > 0).
pub fn step(
    rot: &mut Rotation,
    inertia: &Vec3,
    torque_world: &Vec3,
    dt: f64,
    how: RotationIntegrator,
) -> Steps {
    match how {
        RotationIntegrator::AdaptiveRk => {
            step_rk(rot, inertia, torque_world, dt, PKDGRAV_TOLERANCE)
        }
        RotationIntegrator::LieSplitting => step_splitting(rot, inertia, torque_world, dt),
    }
}

/// [`RotationIntegrator::AdaptiveRk`] with relative accuracy `tolerance` instead of
/// pkdgrav's 10⁻⁶ (the minimum substep stays 10⁻³·dt).
pub fn step_rk(
    rot: &mut Rotation,
    inertia: &Vec3,
    torque_world: &Vec3,
    dt: f64,
    tolerance: f64,
) -> Steps {
    let mut steps = Steps::default();
    if dt == 0.0 {
        return steps;
    }
    let h_min = MIN_SUBSTEP_FRACTION * dt.abs();
    let mut y = rot.packed();
    let mut t = 0.0;
    let mut h = dt;
    let mut k1 = derivative(&y, inertia, torque_world);
    steps.evaluations += 1;
    while (dt - t) * dt.signum() > 0.0 {
        let remaining = dt - t;
        if h.abs() >= remaining.abs() {
            h = remaining;
        }
        let (y_new, k7, err) = dormand_prince(&y, &k1, h, inertia, torque_world);
        steps.evaluations += 6;
        let scale_omega = y.fixed_rows::<3>(0).norm() + h.abs() * k1.fixed_rows::<3>(0).norm();
        let e_omega = err.fixed_rows::<3>(0).norm();
        let e_axes = err.fixed_rows::<9>(3).amax();
        let ratio_omega = if e_omega == 0.0 {
            0.0
        } else {
            e_omega / (tolerance * scale_omega)
        };
        let ratio = ratio_omega.max(e_axes / tolerance);
        // A state that is not finite has no error to control: take the step as it is
        // rather than shrink h to NaN and never advance.
        let at_minimum = h.abs() <= h_min * (1.0 + 1e-12)
            || h.abs() < remaining.abs() * 1e-12
            || !ratio.is_finite();
        if t + h == t {
            steps.failure = Some(Failure::Underflow);
            break;
        }
        if ratio <= 1.0 || at_minimum {
            steps.floor |= ratio > 1.0 && ratio.is_finite();
            if steps.substeps == MAX_STEPS {
                steps.failure = Some(Failure::TooManySteps);
                break;
            }
            t += h;
            y = y_new;
            k1 = k7;
            steps.substeps += 1;
            let grow = if ratio == 0.0 {
                5.0
            } else {
                (0.9 * ratio.powf(-0.2)).clamp(0.2, 5.0)
            };
            h *= grow;
        } else {
            steps.rejected += 1;
            h *= (0.9 * ratio.powf(-0.25)).clamp(0.1, 0.5);
        }
        if h.abs() < h_min {
            h = h_min * dt.signum();
            // (Not for the step's last substep, cut short to end on dt.)
            steps.floor |= (dt - t) * dt.signum() > 0.0;
        }
    }
    rot.unpack(&y);
    steps.reorthonormalised = reorthonormalise(rot);
    steps
}

/// [`RotationIntegrator::LieSplitting`]. The angular momentum is carried in body
/// components mᵢ = L·p̂ᵢ = Iᵢωᵢ: a kick adds h·τ·p̂ᵢ to each, and a turn of the body by θ
/// about p̂ᵢ turns (mⱼ, mₖ) by the same plane rotation as (p̂ⱼ, p̂ₖ), so that L = Σ mᵢ p̂ᵢ
/// stays what it was without ever being recomputed from the axes.
fn step_splitting(rot: &mut Rotation, inertia: &Vec3, torque_world: &Vec3, dt: f64) -> Steps {
    let half = 0.5 * dt;
    let kick = |m: &mut Vec3, axes: &[Vec3; 3]| {
        for i in 0..3 {
            m[i] += torque_world.dot(&axes[i]) * half;
        }
    };
    let mut m = inertia.component_mul(&rot.omega);
    kick(&mut m, &rot.axes);
    for (axis, h) in [(0, half), (1, half), (2, dt), (1, half), (0, half)] {
        let angle = m[axis] / inertia[axis] * h;
        turn_about_axis(&mut rot.axes, &mut m, axis, angle);
    }
    kick(&mut m, &rot.axes);
    rot.omega = m.component_div(inertia);
    let reorthonormalised = reorthonormalise(rot);
    Steps {
        substeps: 1,
        rejected: 0,
        evaluations: 5,
        reorthonormalised,
        floor: false,
        failure: None,
    }
}

/// Turns the body by `angle` about its principal axis `axis` (right-handed): the other two
/// axes rotate in their plane, and the body components `m` of the (fixed) world angular
/// momentum turn with them, (mⱼ, mₖ) = (L·p̂ⱼ, L·p̂ₖ).
fn turn_about_axis(axes: &mut [Vec3; 3], m: &mut Vec3, axis: usize, angle: f64) {
    let (j, k) = ((axis + 1) % 3, (axis + 2) % 3);
    let (s, c) = angle.sin_cos();
    let (pj, pk) = (axes[j], axes[k]);
    // p̂ᵢ × p̂ⱼ = p̂ₖ and p̂ᵢ × p̂ₖ = −p̂ⱼ for a right-handed frame.
    axes[j] = pj * c + pk * s;
    axes[k] = pk * c - pj * s;
    let (mj, mk) = (m[j], m[k]);
    m[j] = mj * c + mk * s;
    m[k] = mk * c - mj * s;
}

/// Replaces the axes by the nearest orthonormal frame when they are further from one than
/// [`ORTHONORMALITY_LIMIT`]; says whether it did.
fn reorthonormalise(rot: &mut Rotation) -> bool {
    if rot.orthonormality_error() <= ORTHONORMALITY_LIMIT {
        return false;
    }
    let mut a = rot.axes_matrix();
    for _ in 0..8 {
        let gram = a.transpose() * a;
        if (gram - Matrix3::identity()).amax() <= 4e-16 {
            break;
        }
        // Newton–Schulz: converges quadratically to the polar factor near a rotation.
        a = a * (Matrix3::identity() * 3.0 - gram) * 0.5;
    }
    for i in 0..3 {
        rot.axes[i] = a.column(i).into_owned();
    }
    true
}

/// Euler's equations in the body frame with the axes carried along.
fn derivative(y: &State, inertia: &Vec3, torque_world: &Vec3) -> State {
    let w: Vec3 = y.fixed_rows::<3>(0).into_owned();
    let p = [
        y.fixed_rows::<3>(3).into_owned(),
        y.fixed_rows::<3>(6).into_owned(),
        y.fixed_rows::<3>(9).into_owned(),
    ];
    let w_world: Vec3 = p[0] * w.x + p[1] * w.y + p[2] * w.z;
    let mut d = State::zeros();
    for i in 0..3 {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        d[i] = ((inertia[j] - inertia[k]) * w[j] * w[k] + torque_world.dot(&p[i])) / inertia[i];
        d.fixed_rows_mut::<3>(3 + 3 * i)
            .copy_from(&w_world.cross(&p[i]));
    }
    d
}

/// One Dormand–Prince 5(4) substep from `y` (derivative `k1`) over `h`: the fifth-order
/// result, its derivative (the next substep's k1) and the error estimate.
fn dormand_prince(
    y: &State,
    k1: &State,
    h: f64,
    inertia: &Vec3,
    torque: &Vec3,
) -> (State, State, State) {
    let f = |s: &State| derivative(s, inertia, torque);
    let k2 = f(&(y + k1 * (h / 5.0)));
    let k3 = f(&(y + (k1 * (3.0 / 40.0) + k2 * (9.0 / 40.0)) * h));
    let k4 = f(&(y + (k1 * (44.0 / 45.0) - k2 * (56.0 / 15.0) + k3 * (32.0 / 9.0)) * h));
    let k5 = f(&(y
        + (k1 * (19372.0 / 6561.0) - k2 * (25360.0 / 2187.0) + k3 * (64448.0 / 6561.0)
            - k4 * (212.0 / 729.0))
            * h));
    let k6 = f(&(y
        + (k1 * (9017.0 / 3168.0) - k2 * (355.0 / 33.0)
            + k3 * (46732.0 / 5247.0)
            + k4 * (49.0 / 176.0)
            - k5 * (5103.0 / 18656.0))
            * h));
    let y_new = y
        + (k1 * (35.0 / 384.0) + k3 * (500.0 / 1113.0) + k4 * (125.0 / 192.0)
            - k5 * (2187.0 / 6784.0)
            + k6 * (11.0 / 84.0))
            * h;
    let k7 = f(&y_new);
    let err = (k1 * (71.0 / 57600.0) - k3 * (71.0 / 16695.0) + k4 * (71.0 / 1920.0)
        - k5 * (17253.0 / 339200.0)
        + k6 * (22.0 / 525.0)
        - k7 * (1.0 / 40.0))
        * h;
    (y_new, k7, err)
}

/// The period of the body-frame ω of a torque-free body with principal moments `inertia`
/// (distinct) started at `omega`: 4K(k)/λ from the Jacobi elliptic solution (Landau &
/// Lifshitz §37), K by the arithmetic–geometric mean. `None` on a separatrix or for a
/// body with equal moments.
pub fn torque_free_period(inertia: &Vec3, omega: &Vec3) -> Option<f64> {
    // Order the moments I_a < I_b < I_c.
    let mut idx = [0usize, 1, 2];
    idx.sort_by(|&a, &b| inertia[a].total_cmp(&inertia[b]));
    let (i1, i2, i3) = (inertia[idx[0]], inertia[idx[1]], inertia[idx[2]]);
    if !(i1 < i2 && i2 < i3) {
        return None;
    }
    let l2 = inertia.component_mul(omega).norm_squared();
    let e2 = inertia.component_mul(omega).dot(omega);
    let (k2, rate2) = if l2 > e2 * i2 {
        (
            (i2 - i1) * (e2 * i3 - l2) / ((i3 - i2) * (l2 - e2 * i1)),
            (i3 - i2) * (l2 - e2 * i1) / (i1 * i2 * i3),
        )
    } else if l2 < e2 * i2 {
        (
            (i3 - i2) * (l2 - e2 * i1) / ((i2 - i1) * (e2 * i3 - l2)),
            (i2 - i1) * (e2 * i3 - l2) / (i1 * i2 * i3),
        )
    } else {
        return None;
    };
    if !(0.0..1.0).contains(&k2) || rate2 <= 0.0 {
        return None;
    }
    let (mut a, mut b) = (1.0f64, (1.0 - k2).sqrt());
    for _ in 0..64 {
        if (a - b).abs() <= 1e-16 * a {
            break;
        }
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    let k = std::f64::consts::PI / (2.0 * a);
    Some(4.0 * k / rate2.sqrt())
}
