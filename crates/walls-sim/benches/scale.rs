//! The evaluator at the size of issue 7's target: 10⁵ particles against the sample scene
//! (`examples/sample.walls`) for 1,000 steps, in particle-steps per second, on one
//! thread and on two (rayon), for SSDEM and HSDEM, with particle contacts on.
//!
//! The particles (radius 0.005) sit on a lattice with gaps of a fifth of their radius
//! and move at speed 1 in scattered directions under gravity, with k_n for a 1 % overlap
//! at that speed: in 1,000 steps of the default timestep each travels about a fifth of
//! its radius, so neighbours that head for each other meet, and those near walls hit
//! them.
//!
//! A single timed run per configuration, not criterion: one run takes seconds.
//! Run with `cargo bench -p walls-sim --bench scale [-- PARTICLES STEPS]`; figures in
//! docs/performance.md.

use nalgebra::Vector3;
use std::time::Instant;
use walls_sim::run::defaults;
use walls_sim::run::{ContactModel, Settings, default_dt, run};
use walls_test_support::scenes::packed;

fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let n = args.first().copied().unwrap_or(100_000);
    let steps = args.get(1).copied().unwrap_or(1_000);
    let scene = walls_test_support::scene(include_str!("../../../examples/sample.walls"));
    let r = 0.005;
    let mut particles = packed(&scene, n, r);
    assert_eq!(particles.len(), n, "room for the particles");
    let frac = |i: usize, a: f64| (i as f64 * a).fract() - 0.5;
    for (i, p) in particles.iter_mut().enumerate() {
        let d = Vector3::new(
            frac(i, 0.754_877_666),
            frac(i, 0.569_840_291),
            frac(i, 0.430_159_709),
        );
        p.vel = d.try_normalize(0.0).unwrap_or_else(Vector3::z);
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
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a thread pool");
            let start = Instant::now();
            let out = pool.install(|| run(&scene, particles.clone(), &settings));
            let seconds = start.elapsed().as_secs_f64();
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
