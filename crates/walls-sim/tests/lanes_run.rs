//! Whole runs through the pair contacts four at a time (`contact::lanes`), against what
//! the runs gave before the lanes existed, when every contact went one at a time (the
//! expected files in `tests/data/` were written by the ninth round's build, 1b260ed):
//! spheres thrown about in a box, with friction, rolling and twisting resistance and
//! pkdgrav's step, on one thread (400 spheres) and on two (1,100, the parallel loop).
//! The numbers must be the same to the last bit, written as Rust writes a double (the
//! shortest text that reads back to it).

use nalgebra::Vector3;
use walls_sim::run::{Outcome, ParticleMaterial, Settings, defaults, run};
use walls_test_support::scenes::box_of_spheres;

/// `n` spheres thrown about in the box for `steps` steps on `threads` threads.
fn thrown(n: usize, steps: f64, threads: usize) -> Outcome {
    let (scene, particles) = box_of_spheres(n, 2.0);
    let material = ParticleMaterial {
        eps_n: 0.5,
        mu_s: 0.5,
        mu_r: 0.1,
        mu_t: 0.1,
        ..defaults::default_material(1000.0)
    };
    let dt = 5e-6;
    let settings = Settings {
        gravity: Vector3::new(0.0, 0.0, -9.81),
        ..Settings::new(dt, steps * dt, material)
    };
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
        .install(|| run(&scene, particles, &settings))
}

/// The contacts begun, and every 25th sphere's position, velocity and spin at the end.
fn written(out: &Outcome) -> String {
    let mut text = format!("pair contacts begun: {}\n", out.pair_contacts);
    for (k, s) in out.particles.iter().enumerate().step_by(25) {
        let p = &s.particle;
        let v = |v: &Vector3<f64>| format!("{:?} {:?} {:?}", v.x, v.y, v.z);
        text += &format!("{k}: {} | {} | {}\n", v(&p.pos), v(&p.vel), v(&p.spin));
    }
    text
}

/// `n` spheres over `steps` steps on `threads` threads end as `expected` says.
fn end_as_before(n: usize, steps: f64, threads: usize, expected: &str) {
    let out = thrown(n, steps, threads);
    assert!(
        out.pair_contacts > 100,
        "the pile has contacts to take four at a time"
    );
    assert_eq!(written(&out), expected);
}

#[test]
fn one_thread_gives_what_it_gave_one_contact_at_a_time() {
    end_as_before(400, 400.0, 1, include_str!("data/lanes_run_one_thread.txt"));
}

#[test]
fn two_threads_give_what_they_gave_one_contact_at_a_time() {
    end_as_before(
        1100,
        200.0,
        2,
        include_str!("data/lanes_run_two_threads.txt"),
    );
}
