//! The evaluator at the size of issue 7's target: 10⁵ particles against the sample scene
//! (`examples/sample.walls`) for 1,000 steps, in particle-steps per second, on one
//! thread and on two (rayon), for SSDEM and HSDEM, with particle contacts on.
//!
//! A single timed run per configuration, not criterion: one run takes seconds.
//! Run with `cargo bench -p walls-sim --bench scale [-- PARTICLES STEPS]`; figures in
//! docs/performance.md.

use nalgebra::Vector3;
use std::time::Instant;
use walls_model::{Options, analyze};
use walls_sim::run::{Method, Settings, default_dt, run};
use walls_sim::setup;

fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let n = args.first().copied().unwrap_or(100_000);
    let steps = args.get(1).copied().unwrap_or(1_000);
    let text = include_str!("../../../examples/sample.walls");
    let scene = analyze(&walls_syntax::parse(text).tree, &Options::default()).scene;
    let particles = setup::scattered(&scene, n, 0.005);
    assert_eq!(particles.len(), n, "room for the particles");
    let k_n = 1e3;
    let dt = default_dt(&particles, k_n);
    for method in [Method::Soft, Method::Hard] {
        for threads in [1, 2] {
            let settings = Settings {
                method,
                gravity: Vector3::new(0.0, 0.0, -1.0),
                ..Settings::new(dt, dt * steps as f64, setup::default_material(k_n))
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
