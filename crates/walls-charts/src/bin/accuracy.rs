//! Error against cost for the evaluator's contact methods (issue 8, chart a).
//!
//! A particle (m = 1, R = 0.1) meets a plane head-on at speed 1, gravity off, against
//! k_n = 10⁴. The soft-sphere model runs at dt = t_c/N for N from 1.4 to 200 with four
//! integrators: pkdgrav's own step (the default: docs/pkdgrav-physics.md §2, the force
//! evaluation at t₀, the dashpot at v_n + a_n·dt), kick-drift-kick leapfrog, the same
//! with the dashpot velocity predicted to the step's end, and explicit Euler; the
//! hard-sphere model is exact at any step. Errors are against the analytic answers:
//! - restitution: |e_measured − ε|/ε at ε = 0.5 (the rebound speed over the impact's);
//! - peak overlap: against the damped oscillator's x_max = (v/ω_d)·e^(−βt*)·sin(ω_d t*),
//!   t* = atan(ω_d/β)/ω_d, β = C/2m, at ε = 0.5;
//! - energy: |E_after/E_before − 1| at ε = 1.
//!
//! Each error is the worst over 8 phases of the steps at which the contact begins and
//! ends (N + j/8 steps per contact, started at different points of a step). Cost
//! is the measured time per simulated contact: 1,000 independent particles each
//! make one contact (particle contacts off), timed as a whole, the median of 5 runs.
//! Writes `accuracy_restitution`, `accuracy_overlap`, `accuracy_energy` and the table
//! `accuracy.csv` (method, N, errors, ns per contact) to docs/charts.

use nalgebra::Vector3;
use std::time::Instant;
use walls_charts::{Chart, Mark, Series, out_dir, pareto_front, write};
use walls_geometry::Particle;
use walls_geometry::Wall;
use walls_sim::contact::ssdem::damping;
use walls_sim::run::{ContactModel, Integrator, ParticleMaterial, Settings, run, run_observed};

type Vec3 = Vector3<f64>;

const MASS: f64 = 1.0;
const RADIUS: f64 = 0.1;
const K_N: f64 = 1e4;
const PARTICLES: usize = 1000;

/// The soft-sphere integrators compared.
const INTEGRATORS: [(&str, Integrator); 4] = [
    ("pkdgrav's step (default)", Integrator::Pkdgrav),
    ("leapfrog (KDK)", Integrator::Leapfrog),
    ("KDK, dashpot at predicted v", Integrator::LeapfrogPredicted),
    ("explicit Euler", Integrator::ExplicitEuler),
];

/// One method at one step: its errors and cost.
struct Point {
    method: &'static str,
    n: f64,
    restitution: f64,
    overlap: f64,
    energy: f64,
    ns_per_contact: f64,
}

fn scene() -> Vec<Wall> {
    walls_test_support::scene("wall type plane\n")
}

/// `count` particles touching the plane z = 0 and moving into it at speed 1, spaced
/// far apart along x.
fn particles(count: usize) -> Vec<Particle> {
    (0..count)
        .map(|i| Particle {
            mass: MASS,
            radius: RADIUS,
            pos: Vec3::new(i as f64, 0.0, RADIUS),
            vel: Vec3::new(0.0, 0.0, -1.0),
            spin: Vec3::zeros(),
            color: 3,
            index: i as i32,
        })
        .collect()
}

/// The contact's analytic duration π/ω_d and peak overlap at restitution `eps`.
fn analytic(eps: f64) -> (f64, f64) {
    let c = damping(eps, K_N, MASS);
    let beta = c / (2.0 * MASS);
    let omega = (K_N / MASS - beta * beta).sqrt();
    let t_peak = (omega / beta).atan() / omega;
    let peak = (1.0 / omega) * (-beta * t_peak).exp() * (omega * t_peak).sin();
    (std::f64::consts::PI / omega, peak)
}

fn settings(
    method: ContactModel,
    integrator: Integrator,
    eps: f64,
    dt: f64,
    t_end: f64,
) -> Settings {
    Settings {
        build: walls_sim::build::Build::default_for(method),
        integrator,
        particle_contacts: false,
        ..Settings::new(
            dt,
            t_end,
            ParticleMaterial {
                eps_n: eps,
                eps_t: 1.0,
                k_n: K_N,
                k_t: 2.0 / 7.0 * K_N,
                mu_s: 0.0,
                mu_r: 0.0,
                mu_t: 0.0,
                beta_s: walls_geometry::BETA_S_DEFAULT,
            },
        )
    }
}

/// The errors of one method at `dt`: the worst over 8 phases of the step at which the
/// contact begins and ends (errors depend on where in a step the contact starts and
/// ends; a single phase can flatter a method by an order of magnitude).
fn errors(method: ContactModel, integrator: Integrator, dt: f64) -> (f64, f64, f64) {
    let scene = scene();
    let (t_c, peak) = analytic(0.5);
    let (t_c1, _) = analytic(1.0);
    let mut worst = (0.0f64, 0.0f64, 0.0f64);
    for phase in 0..8 {
        // The contact lasts a whole number of steps at N = t_c/dt exactly, which flatters
        // some methods: stretch the step so the contact ends j/8 of a step later, and
        // start it at another point of a step (higher by a fraction of a step's travel).
        let j = f64::from(phase) / 8.0;
        let dt = t_c / (t_c / dt + j);
        let lift = dt * ((0.37 * f64::from(phase)) % 1.0);
        let start = |count| {
            let mut ps = particles(count);
            ps[0].pos.z += lift;
            ps
        };
        let s = settings(method, integrator, 0.5, dt, 3.0 * t_c + lift);
        let mut deepest = 0.0f64;
        let out = run_observed(&scene, start(1), &s, &mut |_, _, snapshot| {
            deepest = deepest.max(RADIUS - snapshot.look().0[0].particle.pos.z);
        });
        let e = out.particles[0].particle.vel.z;
        let restitution = (e / 0.5 - 1.0).abs();
        let overlap = if method == ContactModel::Hsdem {
            f64::NAN
        } else {
            (deepest / peak - 1.0).abs()
        };
        let elastic = run(
            &scene,
            start(1),
            &settings(method, integrator, 1.0, dt * t_c1 / t_c, 3.0 * t_c1 + lift),
        );
        let v = elastic.particles[0].particle.vel.norm();
        let energy = (v * v - 1.0).abs();
        worst = (
            worst.0.max(restitution),
            if overlap.is_nan() {
                overlap
            } else {
                worst.1.max(overlap)
            },
            worst.2.max(energy),
        );
    }
    worst
}

/// The time per contact of one method at `dt`: 1,000 particles, median of 5 runs.
fn cost(method: ContactModel, integrator: Integrator, dt: f64) -> f64 {
    let scene = scene();
    let (t_c, _) = analytic(0.5);
    let s = settings(method, integrator, 0.5, dt, 1.5 * t_c);
    let mut times: Vec<f64> = (0..5)
        .map(|_| {
            let ps = particles(PARTICLES);
            let start = Instant::now();
            let out = run(&scene, ps, &s);
            let elapsed = start.elapsed().as_secs_f64();
            assert_eq!(out.events.len(), PARTICLES, "one contact each");
            elapsed
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[2] / PARTICLES as f64 * 1e9
}

fn main() -> std::io::Result<()> {
    let (t_c, _) = analytic(0.5);
    let mut points = Vec::new();
    for (name, integrator) in INTEGRATORS {
        for n in [1.4, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0] {
            let dt = t_c / n;
            let (restitution, overlap, energy) = errors(ContactModel::Ssdem, integrator, dt);
            points.push(Point {
                method: name,
                n,
                restitution,
                overlap,
                energy,
                ns_per_contact: cost(ContactModel::Ssdem, integrator, dt),
            });
        }
    }
    // Hard spheres: exact at any step; one step longer than the flight.
    let (restitution, _, energy) = errors(ContactModel::Hsdem, Integrator::Leapfrog, t_c);
    points.push(Point {
        method: "HSDEM (exact)",
        n: 1.0,
        restitution,
        overlap: f64::NAN,
        energy,
        ns_per_contact: cost(ContactModel::Hsdem, Integrator::Leapfrog, t_c),
    });
    let dir = out_dir();
    std::fs::create_dir_all(&dir)?;
    let mut table = csv::Writer::from_path(dir.join("accuracy.csv"))?;
    table.write_record([
        "method",
        "steps_per_contact",
        "ns_per_contact",
        "restitution_error",
        "peak_overlap_error",
        "energy_error",
    ])?;
    for p in &points {
        table.write_record([
            p.method.to_string(),
            p.n.to_string(),
            p.ns_per_contact.to_string(),
            p.restitution.to_string(),
            p.overlap.to_string(),
            p.energy.to_string(),
        ])?;
        println!(
            "{:18} N = {:5}: {:9.0} ns/contact, restitution {:.2e}, peak overlap {:.2e}, energy {:.2e}",
            p.method, p.n, p.ns_per_contact, p.restitution, p.overlap, p.energy
        );
    }
    table.flush()?;
    // Exact zeros cannot be drawn on a log axis: at least a double's rounding.
    let floor = |e: f64| e.max(1e-16);
    for (name, what, pick) in [
        (
            "accuracy_restitution",
            "restitution error |e/ε − 1| (ε = 0.5)",
            (|p: &Point| p.restitution) as fn(&Point) -> f64,
        ),
        (
            "accuracy_overlap",
            "peak overlap error (ε = 0.5)",
            |p: &Point| p.overlap,
        ),
        (
            "accuracy_energy",
            "energy error |ΔE/E| (ε = 1)",
            |p: &Point| p.energy,
        ),
    ] {
        let mut series: Vec<Series> = INTEGRATORS
            .iter()
            .map(|(name, _)| name)
            .chain(&["HSDEM (exact)"])
            .map(|m| {
                let pts = points
                    .iter()
                    .filter(|p| p.method == *m)
                    .map(|p| (p.ns_per_contact, floor(pick(p))))
                    .filter(|(_, e)| e.is_finite())
                    .collect();
                let mark = if *m == "HSDEM (exact)" {
                    Mark::Dots
                } else {
                    Mark::Line
                };
                Series::new(*m, pts, mark)
            })
            .filter(|s| !s.points.is_empty())
            .collect();
        // HSDEM is exact and cheapest for an isolated collision, so it dominates alone;
        // the front that helps choose a soft-sphere step is the SSDEM methods'.
        let soft: Vec<(f64, f64)> = series
            .iter()
            .filter(|s| s.name != "HSDEM (exact)")
            .flat_map(|s| s.points.clone())
            .collect();
        series.push(Series::new(
            "Pareto front of the SSDEM methods",
            pareto_front(&soft),
            Mark::Dashed,
        ));
        let chart = Chart {
            name: name.into(),
            title: format!("{what} against cost"),
            x_label: "ns per contact (1,000 contacts, one thread)".into(),
            y_label: "relative error".into(),
            log_x: true,
            log_y: true,
        };
        write(&dir, &chart, &series)?;
    }
    Ok(())
}
