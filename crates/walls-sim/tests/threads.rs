//! A run's outcome does not depend on the number of threads: the passes over the
//! particles, the search for touching pairs and their forces run in parallel from 1,024
//! particles up, and everything is merged in particle and pair order. Two thousand
//! spheres dropped into a box of five planes, with friction, run on one thread and on
//! three, must end bit for bit the same (positions, velocities, events, contacts,
//! warnings).

use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_sim::run::{Outcome, ParticleMaterial, Settings, defaults, run};

fn dropped(threads: usize) -> Outcome {
    let scene = walls_test_support::scene(
        "wall type plane\n  origin 0 0 0\n  orient 0 0 1\n\
         wall type plane\n  origin 0 0 0\n  orient 1 0 0\n\
         wall type plane\n  origin 0.0264 0 0\n  orient -1 0 0\n\
         wall type plane\n  origin 0 0 0\n  orient 0 1 0\n\
         wall type plane\n  origin 0 0.0264 0\n  orient 0 -1 0\n",
    );
    let (r, spacing, side) = (1e-3, 2.2e-3, 12);
    let particles: Vec<Particle> = (0..2000)
        .map(|k| {
            let (i, j, l) = (k % side, (k / side) % side, k / (side * side));
            let at = Vector3::new(
                (i as f64 + 0.5) * spacing,
                (j as f64 + 0.5) * spacing,
                1.1 * r + l as f64 * spacing,
            );
            let wobble = |a: f64| ((k as f64 * a).fract() - 0.5) * 2.0;
            Particle {
                mass: 1.047e-5,
                vel: Vector3::new(wobble(0.7549), wobble(0.5698), wobble(0.4302)),
                ..Particle::at_rest(r, at, k)
            }
        })
        .collect();
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
