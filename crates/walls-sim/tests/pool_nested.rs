//! Parallel runs on pools shared with other work. Each parallel run keeps the pool's
//! other threads at hand with helpers, jobs that block the stacks they run on: runs in a
//! parallel loop over runs must all end, each with the outcome it has alone on one
//! thread, and a run must end while another thread of its pool is blocked outside
//! rayon. A test binary of its own: it builds its own pools.

use rayon::prelude::*;
use std::sync::mpsc;
use std::time::Duration;
use walls_sim::run::{Outcome, Settings, defaults, run};
use walls_test_support::scenes::box_of_spheres;

/// `n` spheres dropped into the box at `speed` for `steps` steps, on the current pool.
fn drop_run(n: usize, speed: f64, steps: u32) -> Outcome {
    let (scene, particles) = box_of_spheres(n, speed);
    let dt = 5e-6;
    let settings = Settings::new(
        dt,
        f64::from(steps) * dt,
        defaults::default_material(1000.0),
    );
    run(&scene, particles, &settings)
}

/// What is compared: the particles' positions and velocities, bit for bit.
fn state(out: &Outcome) -> Vec<[u64; 6]> {
    let bits = |p: &walls_sim::run::State| {
        let (x, v) = (p.particle.pos, p.particle.vel);
        [x.x, x.y, x.z, v.x, v.y, v.z].map(f64::to_bits)
    };
    out.particles.iter().map(bits).collect()
}

#[test]
fn runs_in_a_parallel_loop_over_runs_all_end_with_their_own_outcomes() {
    let speeds: Vec<f64> = (1..=8).map(|k| 0.25 * f64::from(k)).collect();
    let alone: Vec<_> = {
        let one = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .expect("a pool");
        one.install(|| {
            speeds
                .iter()
                .map(|&s| state(&drop_run(2000, s, 200)))
                .collect()
        })
    };
    let (sent, got) = mpsc::channel();
    std::thread::spawn(move || {
        let two = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .expect("a pool");
        let nested: Vec<_> = two.install(|| {
            speeds
                .par_iter()
                .map(|&s| state(&drop_run(2000, s, 200)))
                .collect()
        });
        sent.send(nested).expect("the test waits");
    });
    let nested = got
        .recv_timeout(Duration::from_secs(120))
        .expect("the runs in a parallel loop ended within two minutes");
    assert!(nested == alone, "the same outcomes as alone on one thread");
}

#[test]
fn a_run_ends_while_another_thread_of_its_pool_is_blocked_outside_rayon() {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(3)
        .build()
        .expect("a pool");
    let (started, blocked) = mpsc::channel();
    let (release, held) = mpsc::channel::<()>();
    pool.spawn(move || {
        started.send(()).expect("the test waits");
        // Blocked until the run has ended (or the test gives up).
        held.recv_timeout(Duration::from_secs(150)).ok();
    });
    blocked.recv().expect("one thread blocked");
    let alone = {
        let one = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .expect("a pool");
        one.install(|| state(&drop_run(2000, 1.0, 200)))
    };
    let (sent, got) = mpsc::channel();
    std::thread::spawn(move || {
        sent.send(pool.install(|| state(&drop_run(2000, 1.0, 200))))
            .expect("the test waits");
    });
    let out = got
        .recv_timeout(Duration::from_secs(120))
        .expect("the run ended with a thread of its pool blocked");
    release.send(()).expect("the blocked thread waits");
    assert!(out == alone, "the same outcome as alone on one thread");
}
