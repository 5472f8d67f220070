//! Two `.par` switches of pkdgrav's force evaluation, followed as pkdgrav follows them:
//! `bDoGravity = 0` (no forces at all: no uniform gravity, no contacts;
//! docs/pkdgrav-physics.md §2) and `dAccCrit` (small motions zeroed after the forces,
//! before the closing kick; §1.7).

use nalgebra::Vector3;
use walls_sim::config::{Flags, resolve};
use walls_sim::io::par::read_par;
use walls_sim::run::run;
use walls_test_support::{ball, scene};

type Vec3 = Vector3<f64>;

const FLOOR: &str = "wall type plane origin 0 0 0\n";

#[test]
fn without_do_gravity_particles_coast_through_walls_and_each_other() {
    let par =
        read_par("dDelta = 1e-4\nnSteps = 2000\ndKn = 1e5\ndzUnifGrav = -9.8\nbDoGravity = 0\n")
            .unwrap();
    let ps = vec![
        ball([0.0, 0.0, 0.05], [0.0, 0.0, -1.0]),
        ball([0.0, 0.0, 0.5], [0.0, 0.0, -1.0]),
    ];
    let walls = scene(FLOOR);
    let r = resolve(&Flags::default(), Some(&par), &walls, Some(ps)).unwrap();
    assert_eq!(r.settings.gravity, Vec3::zeros());
    assert!(!r.settings.forces);
    let out = run(&walls, r.particles, &r.settings);
    // 2000 steps of 1e-4 at −1: 0.2 down, through the floor, untouched.
    for (s, z0) in out.particles.iter().zip([0.05, 0.5]) {
        assert!((s.particle.pos.z - (z0 - 0.2)).abs() < 1e-12, "{s:?}");
        assert_eq!(s.particle.vel, Vec3::new(0.0, 0.0, -1.0));
    }
    assert!(out.events.is_empty());
    // With it (the default), the floor holds the first.
    let par = read_par("dDelta = 1e-4\nnSteps = 2000\ndKn = 1e5\ndzUnifGrav = -9.8\n").unwrap();
    let ps = vec![ball([0.0, 0.0, 0.05], [0.0, 0.0, -1.0])];
    let r = resolve(&Flags::default(), Some(&par), &walls, Some(ps)).unwrap();
    let out = run(&walls, r.particles, &r.settings);
    assert!(out.particles[0].particle.pos.z > 0.0);
}

#[test]
fn acc_crit_stops_a_particle_slowing_down_below_the_thresholds() {
    // Free space, gravity 1e-3 down, rising at 1e-6: slowing down (a·v < 0), |a| < 1 and
    // |v| < 1·dt, so pkdgrav's first force evaluation (at t₀) stops it; the first step
    // then starts from rest.
    let dt = 1e-3;
    let g = -1e-3;
    let text = |acc_crit: &str| {
        format!("dDelta = {dt}\nnSteps = 1\ndKn = 1e5\ndzUnifGrav = {g}\n{acc_crit}")
    };
    let walls = scene("wall type plane origin 0 0 -100\n");
    let after_one_step = |acc_crit: &str| {
        let par = read_par(&text(acc_crit)).unwrap();
        let ps = vec![ball([0.0, 0.0, 1.0], [0.0, 0.0, 1e-6])];
        let r = resolve(&Flags::default(), Some(&par), &walls, Some(ps)).unwrap();
        run(&walls, r.particles, &r.settings).particles[0]
            .particle
            .clone()
    };
    let stopped = after_one_step("dAccCrit = 1\n");
    assert_eq!(stopped.pos.z, 1.0);
    assert_eq!(stopped.vel.z, 0.5 * dt * g);
    let free = after_one_step("");
    assert_eq!(free.pos.z, 1.0 + dt * (1e-6 + 0.5 * dt * g));
    assert_eq!(free.vel.z, 1e-6 + dt * g);
    // Above the threshold it is left alone.
    let fast = after_one_step("dAccCrit = 1e-4\n");
    assert_eq!(fast, free);
}
