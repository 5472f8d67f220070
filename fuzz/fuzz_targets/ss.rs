//! Fuzz target: arbitrary bytes through the `.ss` reader. Checks that nothing panics,
//! that every particle read is usable (positive, finite mass and radius, finite state),
//! and that a standard `.ss` file read and written again gives the same bytes.
#![no_main]

use libfuzzer_sys::fuzz_target;
use walls_sim::io::particles::{read_ss, write_ss};

fuzz_target!(|data: &[u8]| {
    let Ok((time, read)) = read_ss(data) else {
        return;
    };
    let particles = read.particles;
    for p in &particles {
        assert!(p.mass > 0.0 && p.mass.is_finite(), "mass {}", p.mass);
        assert!(p.radius > 0.0 && p.radius.is_finite(), "radius {}", p.radius);
        assert!(p.pos.iter().chain(&p.vel).chain(&p.spin).all(|x| x.is_finite()));
    }
    // A standard file (magic −1) is written back byte for byte.
    if data.get(12..16) == Some(&(-1i32).to_be_bytes()[..]) {
        assert_eq!(write_ss(time, &particles), data, "read then written differs");
    }
});
