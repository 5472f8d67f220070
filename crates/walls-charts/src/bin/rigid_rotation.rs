//! Rigid-body rotation integrators compared on what a reactive assembly asks of one
//! (`walls_sim::dynamics::rigid`): the torque-free asymmetric body I = (1, 2, 3) started at
//! ω₀ = (0.3, 0.2, 1) (period T = 6.3101, precession about the major axis) and at
//! ω₀ = (0.1, 2, 0.1) (T = 13.9530, the intermediate-axis flip).
//!
//! Methods: `adaptive RK` — pkdgrav's Dormand–Prince 5(4) on Euler's equations, relative
//! accuracy 10⁻⁶ and, to see what the tolerance buys, 10⁻¹²; `Lie splitting` —
//! the symmetric splitting into exact rotations about the principal axes. Each runs 10
//! periods at 25 to 6,400 steps a period (dt = T/N, so the run ends exactly at 10T).
//!
//! Measures: the error, |ω(10T) − ω₀|/|ω₀| (the body-frame ω is periodic with the exact
//! period T, from the Jacobi elliptic solution, `rigid::torque_free_period`); the largest
//! relative deviations of 2E = Σ Iᵢωᵢ² and of |L| = |Σ Iᵢωᵢp̂ᵢ| over the run; the cost,
//! ns of one thread per unit of simulated time (median of 5 timed runs, without the
//! invariant bookkeeping). Errors at rounding are drawn at 10⁻¹⁷.
//!
//! Charts: `rigid_rotation` (error against cost, with each case's Pareto front dashed)
//! and `rigid_rotation_invariants` (2E and |L| errors against cost).

use nalgebra::Vector3;
use std::hint::black_box;
use std::time::Instant;
use walls_charts::{Chart, Mark, Series, out_dir, pareto_front, write};
use walls_sim::dynamics::rigid::{Rotation, RotationIntegrator, step, step_rk, torque_free_period};

type Vec3 = Vector3<f64>;

/// The floor errors at rounding are drawn at.
const FLOOR: f64 = 1e-17;

/// A method: its name and one step.
#[derive(Clone, Copy)]
enum Method {
    Rk(f64),
    Lie,
}

impl Method {
    fn name(self) -> String {
        match self {
            Method::Rk(1e-6) => "adaptive RK 1e-6 (pkdgrav)".into(),
            Method::Rk(tol) => format!("adaptive RK {tol:e}"),
            Method::Lie => "Lie splitting".into(),
        }
    }

    fn step(self, rot: &mut Rotation, inertia: &Vec3, dt: f64) {
        let zero = Vec3::zeros();
        match self {
            Method::Rk(tol) => {
                step_rk(rot, inertia, &zero, dt, tol);
            }
            Method::Lie => {
                step(rot, inertia, &zero, dt, RotationIntegrator::LieSplitting);
            }
        }
    }
}

/// One measured run.
struct Run {
    error: f64,
    energy: f64,
    momentum: f64,
    ns_per_time: f64,
}

fn measure(method: Method, omega: Vec3, inertia: Vec3, period: f64, per_period: usize) -> Run {
    let n = 10 * per_period;
    let dt = period / per_period as f64;
    let start = Rotation::new(omega);
    let (e0, l0) = (
        start.twice_energy(&inertia),
        start.momentum_world(&inertia).norm(),
    );
    let mut rot = start;
    let (mut energy, mut momentum) = (0.0f64, 0.0f64);
    for _ in 0..n {
        method.step(&mut rot, &inertia, dt);
        energy = energy.max(((rot.twice_energy(&inertia) - e0) / e0).abs());
        momentum = momentum.max(((rot.momentum_world(&inertia).norm() - l0) / l0).abs());
    }
    let error = (rot.omega - omega).norm() / omega.norm();
    let mut times = Vec::new();
    for _ in 0..5 {
        let mut rot = start;
        let begin = Instant::now();
        for _ in 0..n {
            method.step(black_box(&mut rot), &inertia, dt);
        }
        black_box(&rot);
        times.push(begin.elapsed().as_nanos() as f64 / (10.0 * period));
    }
    times.sort_by(f64::total_cmp);
    Run {
        error: error.max(FLOOR),
        energy: energy.max(FLOOR),
        momentum: momentum.max(FLOOR),
        ns_per_time: times[2],
    }
}

fn main() -> std::io::Result<()> {
    let inertia = Vec3::new(1.0, 2.0, 3.0);
    let cases = [
        ("ω₀=(0.3,0.2,1)", Vec3::new(0.3, 0.2, 1.0)),
        ("flip ω₀=(0.1,2,0.1)", Vec3::new(0.1, 2.0, 0.1)),
    ];
    let methods = [Method::Rk(1e-6), Method::Rk(1e-12), Method::Lie];
    let per_period = [25, 50, 100, 200, 400, 800, 1600, 3200, 6400];
    let mut errors = Vec::new();
    let mut invariants = Vec::new();
    let mut fronts = Vec::new();
    println!(
        "case | method | steps/T | ω error after 10T | max 2E error | max |L| error | ns per unit time"
    );
    for (label, omega) in cases {
        let period = torque_free_period(&inertia, &omega).expect("asymmetric body");
        println!("{label}: exact period {period:.6}");
        let mut all = Vec::new();
        for method in methods {
            let mut e = Vec::new();
            let (mut en, mut mo) = (Vec::new(), Vec::new());
            for &k in &per_period {
                let run = measure(method, omega, inertia, period, k);
                println!(
                    "{label} | {} | {k} | {:.3e} | {:.3e} | {:.3e} | {:.0}",
                    method.name(),
                    run.error,
                    run.energy,
                    run.momentum,
                    run.ns_per_time
                );
                e.push((run.ns_per_time, run.error));
                en.push((run.ns_per_time, run.energy));
                mo.push((run.ns_per_time, run.momentum));
            }
            all.extend(e.iter().copied());
            errors.push(Series::new(
                format!("{} {label}", method.name()),
                e,
                Mark::Line,
            ));
            if matches!(method, Method::Lie) || matches!(method, Method::Rk(t) if t == 1e-6) {
                let short = match method {
                    Method::Lie => "Lie",
                    Method::Rk(_) => "RK 1e-6",
                };
                invariants.push(Series::new(format!("{short} 2E {label}"), en, Mark::Line));
                invariants.push(Series::new(format!("{short} |L| {label}"), mo, Mark::Line));
            }
        }
        fronts.push(Series::new(
            format!("Pareto front {label}"),
            pareto_front(&all),
            Mark::Dashed,
        ));
    }
    errors.extend(fronts);
    write(
        &out_dir(),
        &Chart {
            name: "rigid_rotation".into(),
            title: "Torque-free rigid body I=(1,2,3): error after 10 periods against cost".into(),
            x_label: "ns per unit of simulated time".into(),
            y_label: "|ω(10T) − ω₀| / |ω₀|".into(),
            log_x: true,
            log_y: true,
        },
        &errors,
    )?;
    write(
        &out_dir(),
        &Chart {
            name: "rigid_rotation_invariants".into(),
            title: "Torque-free rigid body I=(1,2,3): largest 2E and |L| errors over 10 periods"
                .into(),
            x_label: "ns per unit of simulated time".into(),
            y_label: "relative error (1e-17 = rounding)".into(),
            log_x: true,
            log_y: true,
        },
        &invariants,
    )
}
