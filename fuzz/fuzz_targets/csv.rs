//! Fuzz target: arbitrary text through the CSV readers: particles (`--particles`), a
//! run's `particles.csv` and `walls.csv` outputs read back for movies, and the cohesion
//! table. Checks that nothing panics or hangs and that every particle read is usable.
#![no_main]

use libfuzzer_sys::fuzz_target;
use walls_sim::io::{cohesion, particles, trajectory};

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Ok(read) = particles::read_csv(&text) {
        for p in &read.particles {
            assert!(p.mass > 0.0 && p.mass.is_finite(), "mass {}", p.mass);
            assert!(p.radius > 0.0 && p.radius.is_finite(), "radius {}", p.radius);
            assert!(p.pos.iter().chain(&p.vel).chain(&p.spin).all(|x| x.is_finite()));
        }
    }
    let _ = trajectory::read_particles(&text);
    let _ = trajectory::read_walls(&text);
    let _ = cohesion::read_cohesion(&text);
});
