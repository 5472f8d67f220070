//! The evaluator at scale, in particle-steps per second, one timed run per
//! configuration (not criterion: one run takes seconds).
//!
//! * `cargo bench -p walls-sim --bench scale [-- PARTICLES STEPS]`: issue 7's target,
//!   10⁵ particles against the sample scene (`examples/sample.walls`) for 1,000 steps,
//!   on one thread and on two (rayon), for SSDEM and HSDEM, with particle contacts on.
//!   The particles (radius 0.005) sit on a lattice with gaps of a fifth of their radius
//!   and move at speed 1 in scattered directions under gravity, with k_n for a 1 %
//!   overlap at that speed: in 1,000 steps of the default timestep each travels about a
//!   fifth of its radius, so neighbours that head for each other meet, and those near
//!   walls hit them.
//! * `cargo bench -p walls-sim --bench scale -- box PARTICLES STEPS [THREADS]`: the peer
//!   benchmark's box (docs/performance.md, "Against LAMMPS and LIGGGHTS"): spheres of
//!   1 mm and 2500 kg/m³ on a lattice with gaps of a tenth of their diameter, with small
//!   scattered speeds, dropped into a box of five planes under gravity (k_n = 1000 N/m,
//!   k_t = 2/7 k_n, ε_n = 0.5, μ_s = 0.5, dt = 5e-6 s), pkdgrav's contact model; one
//!   and two threads unless THREADS is given. It prints the cost per particle-step, so
//!   that sizes and thread counts compare directly.
//!
//! Figures in docs/performance.md.

use nalgebra::Vector3;
use std::time::Instant;
use walls_sim::run::defaults;
use walls_sim::run::{ContactModel, ParticleMaterial, Settings, default_dt, run};
use walls_test_support::scenes::{box_of_spheres, packed};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let numbers: Vec<usize> = args.iter().filter_map(|a| a.parse().ok()).collect();
    if args.iter().any(|a| a == "box") {
        let n = numbers.first().copied().unwrap_or(10_000);
        let steps = numbers.get(1).copied().unwrap_or(5_000);
        let threads = match numbers.get(2) {
            Some(&t) => vec![t],
            None => vec![1, 2],
        };
        drop_into_a_box(n, steps, &threads);
        return;
    }
    let n = numbers.first().copied().unwrap_or(100_000);
    let steps = numbers.get(1).copied().unwrap_or(1_000);
    let scene = walls_test_support::scene(include_str!("../../../examples/sample.walls"));
    let r = 0.005;
    let mut particles = packed(&scene, n, r);
    assert_eq!(particles.len(), n, "room for the particles");
    for (i, p) in particles.iter_mut().enumerate() {
        p.vel = scattered(i).try_normalize(0.0).unwrap_or_else(Vector3::z);
    }
    let k_n = particles[0].mass * (1.0 / (0.01 * r)).powi(2);
    let dt = default_dt(&particles, k_n);
    for method in [ContactModel::Ssdem, ContactModel::Hsdem] {
        for threads in [1, 2] {
            let settings = Settings {
                build: walls_sim::build::Build::default_for(method),
                gravity: Vector3::new(0.0, 0.0, -1.0),
                ..Settings::new(dt, dt * steps as f64, defaults::default_material(k_n))
            };
            let (seconds, out) = timed(threads, || run(&scene, particles.clone(), &settings));
            assert_eq!(out.steps, steps as u64, "{:?}", out.warnings);
            println!(
                "{method:?}, {threads} thread(s): {n} particles × {steps} steps in {seconds:.2} s = {:.2} M particle-steps/s ({} wall events, {} particle contacts)",
                (n * steps) as f64 / seconds / 1e6,
                out.events.len(),
                out.pair_contacts
            );
        }
    }
}

/// A direction that differs from particle to particle (each component in ±½).
fn scattered(i: usize) -> Vector3<f64> {
    let frac = |a: f64| (i as f64 * a).fract() - 0.5;
    Vector3::new(
        frac(0.754_877_666),
        frac(0.569_840_291),
        frac(0.430_159_709),
    )
}

/// `run` on a pool of `threads` threads, and how long it took.
fn timed<T: Send>(threads: usize, run: impl FnOnce() -> T + Send) -> (f64, T) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool");
    let start = Instant::now();
    let out = pool.install(run);
    (start.elapsed().as_secs_f64(), out)
}

/// The peer benchmark's box with `n` spheres, for `steps` steps on each thread count.
fn drop_into_a_box(n: usize, steps: usize, threads: &[usize]) {
    let (scene, particles) = box_of_spheres(n, 0.1);
    let k_n = 1000.0;
    let material = ParticleMaterial {
        eps_n: 0.5,
        eps_t: 1.0,
        k_n,
        k_t: 2.0 / 7.0 * k_n,
        mu_s: 0.5,
        mu_r: 0.0,
        mu_t: 0.0,
        ..defaults::default_material(k_n)
    };
    let dt = 5e-6;
    let settings = Settings {
        gravity: Vector3::new(0.0, 0.0, -9.81),
        ..Settings::new(dt, dt * steps as f64, material)
    };
    for &t in threads {
        let (seconds, out) = timed(t, || run(&scene, particles.clone(), &settings));
        assert_eq!(out.steps, steps as u64, "{:?}", out.warnings);
        let per = seconds / (n * steps) as f64;
        println!(
            "box, {t} thread(s): {n} particles × {steps} steps in {seconds:.2} s = {:.2} M particle-steps/s, {:.1} ns a particle-step ({} particle contacts)",
            1e-6 / per,
            per * 1e9,
            out.pair_contacts
        );
    }
}
