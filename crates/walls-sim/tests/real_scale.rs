//! Runs at pkdgrav's real scale: a 5.5 cm tube in AU, the defaults sized for it; a
//! default timestep that cannot miss a moving wall; runs that end on `--t-end`; and
//! the walls run alone.

use nalgebra::Vector3;
use walls_geometry::{Particle, Wall};
use walls_sim::config::{Flags, Inputs, resolve};
use walls_sim::run::{ContactModel, EventKind, Warning, defaults, run};
use walls_test_support::scene;

type Vec3 = Vector3<f64>;

/// pkdgrav's `tests/orientation/cylinder`: a floor and a tube of radius 1 and length
/// 5.5 standing on it, in centimetres (`lengthunit`) or at a scale of 1e3.
fn tube(units: &str) -> Vec<Wall> {
    scene(&format!(
        "{units}\nwall type plane origin 0 0 0 orient 0 0 1\n\
         wall type cylinder-finite origin 0 0 2.75 orient 0 0 1 radius 1 length 5.5\n"
    ))
}

/// Checks that the embedded particles of `walls` (a tube of radius `radius` from
/// z = 0 to `length`) are inside it, and that the default run has no overlap
/// warning and does not stop.
fn embedded_inside_the_tube(walls: &[Wall], radius: f64, length: f64) {
    let particles = defaults::default_particles(walls);
    assert_eq!(particles.len(), 9);
    for p in &particles {
        let axial = Vec3::new(p.pos.x, p.pos.y, 0.0).norm();
        assert!(axial + p.radius < radius, "{p:?} inside the tube");
        assert!(
            p.pos.z - p.radius > 0.0 && p.pos.z + p.radius < length,
            "{p:?}"
        );
        // 2 % of the tube's length.
        assert!((p.radius / (0.02 * length) - 1.0).abs() < 1e-12, "{p:?}");
    }
    let run_ = resolve(&Flags::default(), None, walls, None).unwrap();
    assert_eq!(run_.particles, particles);
    let out = run(walls, run_.particles, &run_.settings);
    assert!(out.warnings.is_empty(), "{:?}", out.warnings);
    assert_eq!(out.t, run_.settings.t_end, "ran to the end");
    // Each lands on the floor inside the tube, and stays inside.
    for (i, s) in out.particles.iter().enumerate() {
        assert!(out.events.iter().any(|e| e.particle == i && e.wall == 0));
        let p = &s.particle;
        assert!(Vec3::new(p.pos.x, p.pos.y, 0.0).norm() + p.radius < radius);
        assert!(p.pos.z > 0.0);
    }
}

#[test]
fn embedded_particles_fall_inside_a_tube_in_centimetres() {
    let au_per_cm = 6.68445e-14;
    let walls = tube(&format!("lengthunit {au_per_cm}\ntimeunit 1.99102e-7"));
    embedded_inside_the_tube(&walls, au_per_cm, 5.5 * au_per_cm);
}

#[test]
fn embedded_particles_fall_inside_a_tube_a_thousand_times_larger() {
    let walls = tube("lengthunit 1e3");
    embedded_inside_the_tube(&walls, 1e3, 5.5e3);
}

#[test]
fn without_a_container_the_particles_start_above_the_scene() {
    let walls = scene("wall type disk origin 0 0 0.5 radius 2\n");
    // The disk's box: 4 wide, and a hundredth of that thick (0.48 to 0.52).
    let (_, hi) = walls_geometry::scene_bounds(&walls, &[]);
    assert_eq!(hi.z, 0.52);
    let particles = defaults::default_particles(&walls);
    for p in &particles {
        assert!((p.radius - 0.08).abs() < 1e-12, "2 % of the disk's width");
        assert!((p.pos.z - 4.52).abs() < 1e-12, "one size above: {p:?}");
    }
}

/// A particle of radius 0.1 at rest at x = 1, 0.9 from a plane moving towards it at
/// speed 1.
fn struck() -> (Vec<Wall>, Vec<Particle>) {
    let walls = scene("wall type plane origin 0 0 0 orient 1 0 0 velocity 1 0 0\n");
    let p = Particle::at_rest(0.1, Vec3::new(1.0, 0.0, 0.0), 0);
    (walls, vec![p])
}

#[test]
fn a_moving_plane_meets_a_particle_at_rest_soft() {
    let (walls, particles) = struck();
    let flags = Flags {
        inputs: Inputs {
            t_end: Some(1.0),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let r = resolve(&flags, None, &walls, Some(particles.clone())).unwrap();
    let s = &r.settings;
    // k_n from the wall's speed: 1 % of the radius at speed 1.
    let m = particles[0].mass;
    assert!((s.material.k_n / (m * (1.0 / 0.001_f64).powi(2)) - 1.0).abs() < 1e-12);
    let out = run(&walls, r.particles, s);
    assert_eq!(out.steps, s.end_step());
    assert!(out.steps > 100, "{} steps", out.steps);
    assert_eq!(out.t, 1.0);
    assert_eq!(out.events.len(), 1, "{:?}", out.events);
    let e = &out.events[0];
    assert_eq!(e.kind, EventKind::Bounce);
    // The contact begins at 0.9 and lasts half a damped period, π/ω with
    // ω = ω₀·√(1 − ζ²) and ζ from ε_n = 0.8.
    let q = -(0.8_f64).ln() / std::f64::consts::PI;
    let zeta = q / (1.0 + q * q).sqrt();
    let contact = std::f64::consts::PI * (m / s.material.k_n).sqrt() / (1.0 - zeta * zeta).sqrt();
    assert!(
        (e.t - (0.9 + contact)).abs() < 2.0 * s.dt,
        "ends at {} for {}",
        e.t,
        0.9 + contact
    );
    assert!(out.warnings.is_empty(), "{:?}", out.warnings);
}

#[test]
fn a_moving_plane_meets_a_particle_at_rest_hard() {
    let (walls, particles) = struck();
    let flags = Flags {
        inputs: Inputs {
            t_end: Some(1.0),
            method: ContactModel::Hsdem,
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let r = resolve(&flags, None, &walls, Some(particles)).unwrap();
    // No more than 2 % of the radius a step at speed 1.
    assert!(r.settings.dt <= 0.002);
    let out = run(&walls, r.particles, &r.settings);
    assert_eq!(out.steps, 500);
    assert_eq!(out.events.len(), 1, "{:?}", out.events);
    assert_eq!(out.events[0].kind, EventKind::Bounce);
    assert!((out.events[0].t - 0.9).abs() < 1e-12, "{:?}", out.events[0]);
}

#[test]
fn a_default_timestep_ends_on_t_end() {
    let walls = scene("wall type plane\n");
    let ball = Particle::at_rest(0.1, Vec3::new(0.0, 0.0, 0.5), 0);
    let flags = Flags {
        inputs: Inputs {
            t_end: Some(3.0),
            gravity: Some(vec![0.0, 0.0, -1.0]),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let r = resolve(&flags, None, &walls, Some(vec![ball])).unwrap();
    let out = run(&walls, r.particles, &r.settings);
    assert_eq!(out.t, 3.0);
    assert_eq!(out.steps as f64 * r.settings.dt, 3.0);
    assert!(out.warnings.is_empty(), "{:?}", out.warnings);
}

#[test]
fn a_given_timestep_that_does_not_divide_t_end_runs_past_it_and_says_so() {
    let walls = scene("wall type plane\n");
    let ball = Particle::at_rest(0.1, Vec3::new(0.0, 0.0, 5.0), 0);
    let flags = Flags {
        inputs: Inputs {
            t_end: Some(1.0),
            dt: Some(0.3),
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let r = resolve(&flags, None, &walls, Some(vec![ball])).unwrap();
    let out = run(&walls, r.particles, &r.settings);
    assert_eq!(out.steps, 4);
    assert_eq!(out.t, 4.0 * 0.3);
    assert_eq!(out.warnings.len(), 1);
    assert_eq!(out.warnings[0].code(), "W108");
    assert_eq!(
        out.warnings[0].to_string(),
        "the end time 1 is not a whole number of timesteps: the run ends at step 4, t = 1.2, not at --t-end (give a timestep that divides it, or leave --dt out)"
    );
    assert!(matches!(
        out.warnings[0],
        Warning::EndsAfterTEnd { step: 4, .. }
    ));
    // A timestep that divides it, up to round-off, does not warn and ends on it.
    let flags = Flags {
        inputs: Inputs {
            dt: Some(0.1),
            ..flags.inputs
        },
        ..flags
    };
    let ball = Particle::at_rest(0.1, Vec3::new(0.0, 0.0, 5.0), 0);
    let r = resolve(&flags, None, &walls, Some(vec![ball])).unwrap();
    let out = run(&walls, r.particles, &r.settings);
    assert_eq!((out.steps, out.t), (10, 1.0));
    assert!(out.warnings.is_empty(), "{:?}", out.warnings);
}

#[test]
fn the_walls_run_alone_for_two_oscillation_periods() {
    let walls =
        scene("wall type disk radius 1 osc-ampl 0.1 osc-freq 6.283185307179586 osc-vec 0 0 1\n");
    let flags = Flags {
        inputs: Inputs {
            no_particles: true,
            ..Inputs::default()
        },
        ..Flags::default()
    };
    let r = resolve(&flags, None, &walls, None).unwrap();
    assert!(r.particles.is_empty());
    assert_eq!((r.settings.dt, r.settings.t_end), (0.01, 2.0));
    let out = run(&walls, r.particles, &r.settings);
    assert_eq!((out.steps, out.t), (200, 2.0));
    assert!(out.events.is_empty() && out.warnings.is_empty());
}
