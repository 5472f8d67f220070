//! The rigid-body rotation of reactive assemblies (`walls_sim::dynamics::rigid`): torque-free
//! periods of I = (1, 2, 3) (the notes' T = 6.3101 and the intermediate-axis flip's
//! 13.9530), the invariants 2E and |L|, a symmetric top's precession, a constant torque's
//! L = τ·t and the document's spinning tetrahedron, for both integrators.

use nalgebra::Vector3;
use walls_sim::dynamics::rigid::{Rotation, RotationIntegrator, step, torque_free_period};

type Vec3 = Vector3<f64>;

const BOTH: [RotationIntegrator; 2] = [
    RotationIntegrator::AdaptiveRk,
    RotationIntegrator::LieSplitting,
];

/// Integrates torque-free for `n` steps of `dt`, calling `each` with the time and state
/// after every step.
fn run(
    omega: Vec3,
    inertia: Vec3,
    dt: f64,
    n: usize,
    how: RotationIntegrator,
    mut each: impl FnMut(f64, &Rotation),
) -> Rotation {
    let mut rot = Rotation::new(omega);
    for k in 1..=n {
        step(&mut rot, &inertia, &Vec3::zeros(), dt, how);
        each(k as f64 * dt, &rot);
    }
    rot
}

/// The mean period of ω₂ from its upward zero crossings (linearly interpolated) over
/// `periods` periods of about `t_guess`.
fn measured_period(
    omega: Vec3,
    dt: f64,
    t_guess: f64,
    periods: usize,
    how: RotationIntegrator,
) -> f64 {
    let inertia = Vec3::new(1.0, 2.0, 3.0);
    let n = ((periods as f64 + 0.5) * t_guess / dt) as usize;
    let mut crossings = Vec::new();
    let mut last = (0.0, omega.y);
    run(omega, inertia, dt, n, how, |t, r| {
        let w2 = r.omega.y;
        if last.1 < 0.0 && w2 >= 0.0 {
            crossings.push(last.0 + (t - last.0) * (-last.1) / (w2 - last.1));
        }
        last = (t, w2);
    });
    assert!(
        crossings.len() >= 2,
        "{how:?}: {} crossings",
        crossings.len()
    );
    (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64
}

#[test]
fn exact_periods_match_the_notes() {
    let inertia = Vec3::new(1.0, 2.0, 3.0);
    let t1 = torque_free_period(&inertia, &Vec3::new(0.3, 0.2, 1.0)).unwrap();
    let t2 = torque_free_period(&inertia, &Vec3::new(0.1, 2.0, 0.1)).unwrap();
    assert!((t1 - 6.3101).abs() < 5e-5, "{t1}");
    assert!((t2 - 13.9530).abs() < 5e-5, "{t2}");
}

#[test]
fn periods_of_the_asymmetric_body() {
    for how in BOTH {
        for (omega, expected) in [
            (Vec3::new(0.3, 0.2, 1.0), 6.3101),
            (Vec3::new(0.1, 2.0, 0.1), 13.9530),
        ] {
            let period = measured_period(omega, 1e-3, expected, 5, how);
            assert!(
                ((period - expected) / expected).abs() < 1e-4,
                "{how:?} ω₀ = {omega:?}: period {period}, expected {expected}"
            );
        }
    }
}

#[test]
fn omega_returns_after_one_period() {
    let inertia = Vec3::new(1.0, 2.0, 3.0);
    for how in BOTH {
        for omega in [Vec3::new(0.3, 0.2, 1.0), Vec3::new(0.1, 2.0, 0.1)] {
            let period = torque_free_period(&inertia, &omega).unwrap();
            let n = 10_000;
            let rot = run(omega, inertia, period / n as f64, n, how, |_, _| {});
            let error = (rot.omega - omega).norm() / omega.norm();
            assert!(error < 1e-3, "{how:?} ω₀ = {omega:?}: {error}");
        }
    }
}

/// The largest relative deviations of 2E and |L| from their start, in the first and the
/// last tenth of the run.
fn invariants(omega: Vec3, dt: f64, n: usize, how: RotationIntegrator) -> [f64; 4] {
    let inertia = Vec3::new(1.0, 2.0, 3.0);
    let start = Rotation::new(omega);
    let (e0, l0) = (
        start.twice_energy(&inertia),
        start.momentum_world(&inertia).norm(),
    );
    let mut out = [0.0f64; 4];
    let mut k = 0;
    run(omega, inertia, dt, n, how, |_, r| {
        k += 1;
        let de = ((r.twice_energy(&inertia) - e0) / e0).abs();
        let dl = ((r.momentum_world(&inertia).norm() - l0) / l0).abs();
        if k <= n / 10 {
            out[0] = out[0].max(de);
            out[1] = out[1].max(dl);
        }
        if k > n - n / 10 {
            out[2] = out[2].max(de);
            out[3] = out[3].max(dl);
        }
        assert!(r.orthonormality_error() < 1e-13);
    });
    out
}

#[test]
fn adaptive_rk_keeps_energy_and_momentum() {
    for omega in [Vec3::new(0.3, 0.2, 1.0), Vec3::new(0.1, 2.0, 0.1)] {
        let [e_first, l_first, e_last, l_last] =
            invariants(omega, 1e-3, 100_000, RotationIntegrator::AdaptiveRk);
        for v in [e_first, l_first, e_last, l_last] {
            assert!(v < 1e-6, "{omega:?}: {v}");
        }
    }
}

#[test]
fn splitting_keeps_momentum_exactly_and_energy_bounded() {
    for omega in [Vec3::new(0.3, 0.2, 1.0), Vec3::new(0.1, 2.0, 0.1)] {
        // 1,000 time units: about 160 and 70 periods.
        let [e_first, l_first, e_last, l_last] =
            invariants(omega, 1e-2, 100_000, RotationIntegrator::LieSplitting);
        assert!(
            l_first < 1e-13 && l_last < 1e-13,
            "{omega:?}: |L| {l_first} {l_last}"
        );
        // Bounded: as large in the first tenth as in the last (no drift), and small.
        assert!(
            e_first < 1e-3 && e_last < 1e-3,
            "{omega:?}: 2E {e_first} {e_last}"
        );
        assert!(
            e_last < 1.5 * e_first,
            "{omega:?}: 2E drifts {e_first} → {e_last}"
        );
    }
}

#[test]
fn symmetric_top_precesses() {
    // I₁ = I₂: (ω₁, ω₂) turns at Ω = (I₃ − I₁)ω₃/I₁ in the body frame.
    let inertia = Vec3::new(1.0, 1.0, 2.5);
    let omega = Vec3::new(0.2, 0.0, 0.8);
    let rate = (inertia.z - inertia.x) * omega.z / inertia.x;
    let t = 5.0;
    for how in BOTH {
        let n = 5_000;
        let rot = run(omega, inertia, t / n as f64, n, how, |_, _| {});
        let exact = Vec3::new(0.2 * (rate * t).cos(), 0.2 * (rate * t).sin(), 0.8);
        let error = (rot.omega - exact).norm();
        assert!(error < 1e-6, "{how:?}: {error}");
    }
}

#[test]
fn constant_torque_changes_momentum_by_torque_times_time() {
    let inertia = Vec3::new(1.0, 2.0, 3.0);
    let torque = Vec3::new(0.3, -0.2, 0.5);
    for how in BOTH {
        let mut rot = Rotation::new(Vec3::zeros());
        let (dt, n) = (1e-3, 2_000);
        for _ in 0..n {
            step(&mut rot, &inertia, &torque, dt, how);
        }
        let l = rot.momentum_world(&inertia);
        let expected = torque * (dt * n as f64);
        let error = (l - expected).norm() / expected.norm();
        assert!(
            error < 1e-9,
            "{how:?}: L = {l:?}, expected {expected:?}: {error}"
        );
    }
}

#[test]
fn document_tetrahedron_spins_about_z() {
    // Section 7's sample: a regular tetrahedron, I = 0.2 about every axis, rot-vec 0 0 1.
    let inertia = Vec3::new(0.2, 0.2, 0.2);
    for how in BOTH {
        let mut rot = Rotation::new(Vec3::new(0.0, 0.0, 1.0));
        let dt = 0.01;
        for k in 1..=1_000 {
            step(&mut rot, &inertia, &Vec3::zeros(), dt, how);
            let t = k as f64 * dt;
            assert!(
                (rot.omega - Vec3::new(0.0, 0.0, 1.0)).norm() < 1e-12,
                "{how:?}"
            );
            let x = Vec3::new(t.cos(), t.sin(), 0.0);
            let y = Vec3::new(-t.sin(), t.cos(), 0.0);
            assert!(
                (rot.axes[0] - x).norm() < 1e-9,
                "{how:?} t = {t}: {:?}",
                rot.axes[0]
            );
            assert!((rot.axes[1] - y).norm() < 1e-9, "{how:?} t = {t}");
            assert!((rot.axes[2] - Vec3::z()).norm() < 1e-12, "{how:?} t = {t}");
        }
    }
}
