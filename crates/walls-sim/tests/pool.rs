//! Where a run steps. A run of many particles with more than one thread steps on one of
//! rayon's threads, observer and interrupt check included, so that each pass of a step
//! is split between the threads where it is rather than handed to the pool from outside
//! (docs/performance-history.md, "Eighth round"); a run of few particles, or on one thread,
//! steps on the caller's. A test binary of its own: it sets rayon's global pool.

use std::sync::atomic::{AtomicUsize, Ordering};
use walls_sim::run::{Settings, Snapshot, defaults, run_watched};
use walls_test_support::scenes::box_of_spheres;

/// Runs `n` spheres dropped into the box for ten steps and returns on how many steps
/// the observer, and the interrupt check, ran on one of the pool's threads.
fn steps_on_the_pool(n: usize) -> (usize, usize) {
    let (scene, particles) = box_of_spheres(n, 1.0);
    let dt = 5e-6;
    let settings = Settings::new(dt, 10.0 * dt, defaults::default_material(1000.0));
    let observed = AtomicUsize::new(0);
    let checked = AtomicUsize::new(0);
    let on_the_pool = |count: &AtomicUsize| {
        if rayon::current_thread_index().is_some() {
            count.fetch_add(1, Ordering::Relaxed);
        }
    };
    let out = run_watched(
        &scene,
        particles,
        &settings,
        &mut |_, _, _: &mut dyn Snapshot| on_the_pool(&observed),
        &|| {
            on_the_pool(&checked);
            false
        },
    );
    assert_eq!(out.steps, 10);
    (
        observed.load(Ordering::Relaxed),
        checked.load(Ordering::Relaxed),
    )
}

#[test]
fn a_parallel_run_steps_on_the_pool_and_a_small_one_on_the_callers_thread() {
    rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build_global()
        .expect("the global pool, set once");
    assert_eq!(rayon::current_thread_index(), None);
    // 2,000 particles: past the 1,024 from which the passes are split.
    assert_eq!(steps_on_the_pool(2000), (10, 10));
    // 100: every step on this thread.
    assert_eq!(steps_on_the_pool(100), (0, 0));
}
