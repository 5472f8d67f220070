//! A run's outcome does not depend on the number of threads: the passes over the
//! particles, the search for touching pairs and their forces run in parallel from 1,024
//! particles up, and everything is merged in particle and pair order. Two thousand
//! spheres dropped into a box of five planes, with friction, run on one thread and on
//! three, must end bit for bit the same (positions, velocities, events, contacts,
//! warnings).

use nalgebra::Vector3;
use walls_sim::run::{Outcome, ParticleMaterial, Settings, defaults, run};
use walls_test_support::scenes::box_of_spheres;

fn dropped(threads: usize) -> Outcome {
    let (scene, particles) = box_of_spheres(2000, 2.0);
    let material = ParticleMaterial {
        eps_n: 0.5,
        mu_s: 0.5,
        ..defaults::default_material(1000.0)
    };
    let dt = 5e-6;
    let settings = Settings {
        gravity: Vector3::new(0.0, 0.0, -9.81),
        ..Settings::new(dt, 600.0 * dt, material)
    };
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
        .install(|| run(&scene, particles, &settings))
}

#[test]
fn one_thread_and_three_end_the_same() {
    let one = dropped(1);
    assert!(
        one.pair_contacts > 1000,
        "{} particle contacts",
        one.pair_contacts
    );
    assert!(!one.events.is_empty());
    assert_eq!(one, dropped(3));
}
