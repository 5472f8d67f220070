//! Particles against walls and each other with the HSDEM model, against analytic
//! answers: exact to 1e−12 relative where the answer is exact.

use nalgebra::Vector3;
use walls_geometry::Wall;

use walls_sim::run::{ContactModel, EventKind, Outcome, ParticleMaterial, Settings, Warning, run};

use walls_test_support::ball as particle;

type Vec3 = Vector3<f64>;

fn scene(text: &str) -> Vec<Wall> {
    walls_test_support::scene_in(text, ContactModel::Hsdem)
}

fn settings(eps_n: f64, dt: f64, t_end: f64, gravity: [f64; 3]) -> Settings {
    Settings {
        build: walls_sim::build::Build::default_for(ContactModel::Hsdem),
        gravity: Vec3::from(gravity),
        ..Settings::new(
            dt,
            t_end,
            ParticleMaterial {
                eps_n,
                ..walls_sim::run::defaults::default_material(1.0)
            },
        )
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * b.abs().max(1.0)
}

fn bounces(out: &Outcome) -> Vec<&walls_sim::run::Event> {
    out.events
        .iter()
        .filter(|e| e.kind == EventKind::Bounce)
        .collect()
}

/// Every wall HSDEM supports, met head-on by a particle 0.5 away at speed 1, with the
/// wall's own εn (HSDEM takes a wall's coefficients as written).
const HEAD_ON: [(&str, [f64; 3], [f64; 3]); 6] = [
    ("wall type plane\n", [0.0, 0.0, 0.5], [0.0, 0.0, -1.0]),
    (
        "wall type rectangle\n  origin -1 -1 0\n  vertex1 2 0 0\n  vertex2 0 2 0\n",
        [0.0, 0.0, 0.5],
        [0.0, 0.0, -1.0],
    ),
    (
        "wall type disk\n  radius 1\n",
        [0.0, 0.0, -0.5],
        [0.0, 0.0, 1.0],
    ),
    (
        "wall type cylinder-infinite\n  radius 1\n",
        [1.5, 0.0, 0.0],
        [-1.0, 0.0, 0.0],
    ),
    (
        "wall type cylinder-finite\n  radius 1\n  length 2\n",
        [0.0, 1.5, 0.0],
        [0.0, -1.0, 0.0],
    ),
    (
        "wall type disk\n  radius 0\n",
        [0.0, 0.0, 0.5],
        [0.0, 0.0, -1.0],
    ),
];

#[test]
fn rebound_at_eps_n_exactly_from_every_hsdem_wall_type() {
    for eps in [1.0, 0.9, 0.5, 0.1] {
        for (walls, pos, vel) in HEAD_ON {
            let text = format!("{walls}  epsn {eps}\n  epst 1\n");
            // A step much longer than the flight: the collision falls inside it.
            let out = run(
                &scene(&text),
                vec![particle(pos, vel)],
                &settings(0.8, 0.7, 1.4, [0.0; 3]),
            );
            let b = bounces(&out);
            assert_eq!(b.len(), 1, "{text}: {:?}", out.events);
            assert!(close(b[0].vn_in, 1.0), "{text}: in {}", b[0].vn_in);
            assert!(
                close(b[0].vn_out, eps),
                "{text} ε = {eps}: out {}",
                b[0].vn_out
            );
            // It met the wall when its surface reached it: 0.4 after the start.
            assert!(close(b[0].t, 0.4), "{text}: at {}", b[0].t);
            let v = out.particles[0].particle.vel.norm();
            assert!(close(v, eps), "{text}: speed {v}");
        }
    }
}

#[test]
fn elastic_kick_off_a_moving_wall_exactly() {
    // The wall rises at 0.5; the particle falls at 1: it leaves at 2u − v = 2.
    let out = run(
        &scene("wall type plane\n  velocity 0 0 0.5\n  epsn 1\n  epst 1\n"),
        vec![particle([0.0, 0.0, 0.5], [0.0, 0.0, -1.0])],
        &settings(0.8, 0.05, 0.5, [0.0; 3]),
    );
    let v = out.particles[0].particle.vel.z;
    assert!(close(v, 2.0), "{v}");
    // Met at (0.5 − 0.1)/1.5.
    assert!(close(out.events[0].t, 0.4 / 1.5), "{}", out.events[0].t);
}

#[test]
fn elastic_bouncing_under_gravity_keeps_its_energy_to_first_order_in_dt() {
    // Gravity kicks velocities only between drifts, so a path within a step is straight:
    // a bounce at τ into a step of dt changes the energy by g·v·(2τ − dt), at most g·v·dt,
    // and the bounces' errors do not pile up beyond that.
    for dt in [1e-2, 1e-3, 1e-4] {
        let out = run(
            &scene("wall type plane\n  epsn 1\n  epst 1\n"),
            vec![particle([0.0, 0.0, 1.0], [0.0, 0.0, 0.0])],
            &settings(0.8, dt, 6.0, [0.0, 0.0, -1.0]),
        );
        let n = bounces(&out).len() as f64;
        assert!(n >= 2.0, "{:?}", out.events);
        let (before, after) = out.energy;
        let v_max = (2.0f64 * 0.9).sqrt();
        assert!(
            (after - before).abs() <= n * v_max * dt,
            "dt {dt}: {before} → {after} after {n} bounces"
        );
    }
}

#[test]
fn death_and_sticky_walls() {
    let ps = vec![particle([0.0, 0.0, 0.5], [0.0, 0.0, -1.0])];
    let gone = run(
        &scene("wall type plane\n  epsn -1\n  epst 1\n"),
        ps.clone(),
        &settings(0.8, 0.1, 1.0, [0.0; 3]),
    );
    assert!(!gone.particles[0].alive);
    assert_eq!(gone.events[0].kind, EventKind::Remove);
    assert!(close(gone.events[0].t, 0.4));
    let stuck = run(
        &scene("wall type plane\n  epsn 0\n  epst 1\n  velocity 1 0 0\n"),
        ps,
        &settings(0.8, 0.1, 1.0, [0.0; 3]),
    );
    assert_eq!(stuck.events[0].kind, EventKind::Stick);
    let p = &stuck.particles[0].particle;
    assert!(close(p.vel.x, 1.0) && close(p.vel.z, 0.0), "{p:?}");
    // Stuck at height r, carried along x with the wall.
    assert!(close(p.pos.z, 0.1) && close(p.pos.x, 0.6), "{p:?}");
}

#[test]
fn stuck_to_a_spinning_drum_it_moves_at_omega_times_r() {
    let out = run(
        &scene("wall type cylinder-infinite\n  radius 1\n  epsn 0\n  epst 1\n  ang-speed 2\n"),
        vec![particle([0.5, 0.0, 0.0], [1.0, 0.0, 0.0])],
        &settings(0.8, 0.01, 3.0, [0.0; 3]),
    );
    let p = &out.particles[0].particle;
    let r = (p.pos.x.powi(2) + p.pos.y.powi(2)).sqrt();
    assert!(close(r, 0.9), "it stays at the wall: r = {r}");
    assert!(
        close(p.vel.norm(), 2.0 * r),
        "{} vs {}",
        p.vel.norm(),
        2.0 * r
    );
}

#[test]
fn through_a_disks_hole_and_onto_its_rim() {
    let disk = "wall type disk\n  radius 2\n  hole-radius 0.5\n  epsn 1\n  epst 1\n";
    // Down the axis through a hole wider than the particle: nothing.
    let out = run(
        &scene(disk),
        vec![particle([0.0, 0.0, 1.0], [0.0, 0.0, -1.0])],
        &settings(0.8, 0.1, 3.0, [0.0; 3]),
    );
    assert!(out.events.is_empty() && out.particles[0].particle.pos.z < -1.0);
    // Down at radius 0.45: the hole's rim 0.05 away sideways, met at height √(r² − 0.05²),
    // and sent back up and outwards along the line from the rim to the centre.
    let out = run(
        &scene(disk),
        vec![particle([0.45, 0.0, 1.0], [0.0, 0.0, -1.0])],
        &settings(0.8, 0.1, 1.0, [0.0; 3]),
    );
    let b = bounces(&out);
    assert_eq!(b.len(), 1, "{:?}", out.events);
    let h = (0.01f64 - 0.0025).sqrt();
    assert!(close(b[0].t, 1.0 - h), "{} vs {}", b[0].t, 1.0 - h);
    let n = Vec3::new(-0.05, 0.0, h) / 0.1;
    let v = out.particles[0].particle.vel;
    let expected = Vec3::new(0.0, 0.0, -1.0) - n * (2.0 * n.dot(&Vec3::new(0.0, 0.0, -1.0)));
    assert!((v - expected).norm() < 1e-12, "{v:?} vs {expected:?}");
}

#[test]
fn inside_and_outside_cylinders_and_off_a_corner() {
    // Inside a finite cylinder, thrown along x: bounces back and forth between the sides,
    // every 1.8 of travel.
    let can = "wall type cylinder-finite\n  radius 1\n  length 2\n  epsn 1\n  epst 1\n";
    let out = run(
        &scene(can),
        vec![particle([0.0, 0.0, 0.0], [1.0, 0.0, 0.0])],
        &settings(0.8, 0.25, 4.0, [0.0; 3]),
    );
    let times: Vec<f64> = out.events.iter().map(|e| e.t).collect();
    assert_eq!(times.len(), 2, "{times:?}");
    assert!(close(times[0], 0.9) && close(times[1], 2.7), "{times:?}");
    // Off a rectangle's corner along the line from the corner to the centre.
    let dir = Vec3::new(-1.0, -1.0, 1.0).normalize();
    let start = dir * 0.5;
    let out = run(
        &scene("wall type rectangle\n  vertex1 1 0 0\n  vertex2 0 1 0\n  epsn 1\n  epst 1\n"),
        vec![particle(start.into(), (-dir).into())],
        &settings(0.8, 0.1, 1.0, [0.0; 3]),
    );
    let v = out.particles[0].particle.vel;
    assert!((v - dir).norm() < 1e-12, "leaves along {v:?}");
}

#[test]
fn particles_collide_with_each_other_keeping_momentum() {
    // Head-on, equal masses, elastic: they swap velocities, exactly.
    let mut a = particle([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
    let mut b = particle([1.0, 0.0, 0.0], [-0.5, 0.0, 0.0]);
    b.index = 1;
    let s = Settings {
        material: ParticleMaterial {
            eps_n: 1.0,
            ..walls_sim::run::defaults::default_material(1.0)
        },
        ..settings(1.0, 0.1, 1.0, [0.0; 3])
    };
    let out = run(
        &scene("wall type plane\n  origin 0 0 -5\n  epsn 1\n  epst 1\n"),
        vec![a.clone(), b.clone()],
        &s,
    );
    assert_eq!(out.pair_contacts, 1);
    assert!(close(out.particles[0].particle.vel.x, -0.5));
    assert!(close(out.particles[1].particle.vel.x, 1.0));
    // Unequal masses, inelastic, oblique: momentum is kept to 1e−12, and the normal
    // relative speed comes out at εn times what went in.
    a.mass = 3.0;
    a.vel = Vec3::new(1.0, 0.3, 0.0);
    b.pos = Vec3::new(1.0, 0.05, 0.0);
    let s = Settings {
        material: ParticleMaterial {
            eps_n: 0.7,
            eps_t: 0.5,
            ..walls_sim::run::defaults::default_material(1.0)
        },
        ..s
    };
    let before = a.vel * a.mass + b.vel * b.mass;
    let out = run(
        &scene("wall type plane\n  origin 0 0 -5\n  epsn 1\n  epst 1\n"),
        vec![a, b],
        &s,
    );
    assert_eq!(out.pair_contacts, 1);
    let after: Vec3 = out
        .particles
        .iter()
        .map(|s| s.particle.vel * s.particle.mass)
        .sum();
    assert!(
        (after - before).norm() <= 1e-12 * before.norm(),
        "{before:?} → {after:?}"
    );
    // Switched off, they pass through each other.
    let off = Settings {
        particle_contacts: false,
        ..s
    };
    let out = run(
        &scene("wall type plane\n  origin 0 0 -5\n  epsn 1\n  epst 1\n"),
        vec![
            particle([0.0; 3], [1.0, 0.0, 0.0]),
            particle([1.0, 0.0, 0.0], [-1.0, 0.0, 0.0]),
        ],
        &off,
    );
    assert_eq!(out.pair_contacts, 0);
    assert!(out.particles[0].particle.pos.x > 0.9);
}

#[test]
fn unsupported_walls_and_literal_99_are_reported() {
    let out = run(
        &scene("wall type triangle\nwall type plane\n"),
        vec![particle([0.0, 0.0, 0.5], [0.0, 0.0, -1.0])],
        &settings(0.8, 0.1, 1.0, [0.0; 3]),
    );
    assert!(
        out.warnings
            .iter()
            .any(|w| matches!(w, Warning::UnsupportedWall { wall: 0, .. })
                && w.to_string()
                    .starts_with("wall 0 (triangle) is not supported")),
        "{:?}",
        out.warnings
    );
    assert!(
        out.warnings.iter().any(
            |w| matches!(w, Warning::RestitutionAt99 { walls } if walls == &[0, 1])
                && w.to_string()
                    .contains("epsn or epst left at 99 on walls 0, 1:")
        ),
        "{:?}",
        out.warnings
    );
    // The plane still uses the particles' εn = 0.8.
    let b = bounces(&out);
    assert!(close(b[0].vn_out, 0.8), "{:?}", b);
}

#[test]
fn a_particle_jammed_between_walls_is_capped_and_reported() {
    // Between two plates 1e−6 wider than the particle, at speed 1: a million collisions a
    // step. The run stops at the cap, says so, and the particle stays between the plates.
    let walls = "wall type plane\n  epsn 1\n  epst 1\nwall type plane\n  origin 0 0 0.200001\n  epsn 1\n  epst 1\n";
    let out = run(
        &scene(walls),
        vec![particle([0.0, 0.0, 0.1000005], [0.0, 0.0, 1.0])],
        &settings(0.8, 1.0, 2.0, [0.0; 3]),
    );
    let z = out.particles[0].particle.pos.z;
    assert!((0.1 - 1e-12..=0.100001 + 1e-12).contains(&z), "{z}");
    assert!(
        out.warnings
            .iter()
            .any(|w| matches!(w, Warning::CollisionCap { particle: 0, .. })),
        "{:?}",
        out.warnings
    );
    assert!(out.events.len() >= walls_sim::run::COLLISION_CAP as usize);
}

#[test]
fn off_an_oscillating_plate_at_the_velocity_of_its_step() {
    // A plate z = A·sin(ωt) and a particle falling at 1 onto it, with steps of 0.1: the
    // plate moves in a straight line over each step, so the elastic kick is 2u − v with u
    // the plate's velocity over the step of the hit: the chord of the sinusoid, or with
    // pkdgrav's stepping the oscillation velocity at the step's start.
    let (a, omega, dt) = (0.01, 3.0, 0.1);
    let walls =
        format!("wall type plane\n  osc-ampl {a}\n  osc-freq {omega}\n  epsn 1\n  epst 1\n");
    for stepping in [
        walls_sim::OscillationStepping::Exact,
        walls_sim::OscillationStepping::Pkdgrav,
    ] {
        let s = Settings {
            stepping,
            ..settings(0.8, dt, 0.6, [0.0; 3])
        };
        let out = run(
            &scene(&walls),
            vec![particle([0.0, 0.0, 0.45], [0.0, 0.0, -1.0])],
            &s,
        );
        assert_eq!(out.events.len(), 1, "{:?}", out.events);
        let hit = out.events[0].t;
        let n = (hit / dt).floor();
        let t0 = n * dt;
        let u = match stepping {
            walls_sim::OscillationStepping::Exact => {
                a * ((omega * (t0 + dt)).sin() - (omega * t0).sin()) / dt
            }
            walls_sim::OscillationStepping::Pkdgrav => a * omega * (omega * t0).cos(),
        };
        let v = out.particles[0].particle.vel.z;
        assert!(
            close(v, 2.0 * u + 1.0),
            "{stepping:?}: {v} vs {}",
            2.0 * u + 1.0
        );
    }
}

#[test]
fn a_vibrated_plate_throws_a_resting_particle_only_above_one_g() {
    // A hard sphere cannot rest: on the plate it bounces in every step, by about g·dt.
    // It has left the plate when it goes a whole 1 % of a period without a collision; the
    // last collision before that is the lift-off, at ωt = arcsin(g/(Aω²)) when
    // Aω²/g > 1, and never otherwise.
    let (a, g): (f64, f64) = (0.01, 1.0);
    for gamma in [0.5f64, 2.0, 4.0] {
        let omega = (gamma * g / a).sqrt();
        let period = std::f64::consts::TAU / omega;
        let walls =
            format!("wall type plane\n  osc-ampl {a}\n  osc-freq {omega}\n  epsn 0.5\n  epst 1\n");
        let dt = period / 20_000.0;
        let out = run(
            &scene(&walls),
            vec![particle([0.0, 0.0, 0.1], [0.0, 0.0, a * omega])],
            &settings(0.8, dt, period, [0.0, 0.0, -g]),
        );
        let times: Vec<f64> = out.events.iter().map(|e| e.t).collect();
        let lift = times
            .windows(2)
            .find(|w| w[1] - w[0] > 0.01 * period)
            .map(|w| w[0]);
        let lift = lift.or_else(|| {
            times
                .last()
                .filter(|t| period - **t > 0.01 * period)
                .copied()
        });
        if gamma < 1.0 {
            assert_eq!(lift, None, "Γ = {gamma}: it stays on the plate");
            continue;
        }
        let phase = lift.expect("it lifts off") * omega;
        let expected = (1.0 / gamma).asin();
        assert!(
            (phase - expected).abs() < 0.01,
            "Γ = {gamma}: lift-off at phase {phase}, expected {expected}"
        );
    }
}

#[test]
fn off_a_spinning_disk_the_contact_feels_its_surface_velocity() {
    // Falling at 1 onto a disk spinning at 2 about z, at x = 0.5: the disk's surface there
    // moves at (0, 1, 0). With εt = −1 the contact point's tangential velocity relative to
    // the disk reverses: v′ = (0, 4/7, 1) and ω′ = (10/(7R), 0, 0) (docs/spec.md §3).
    let out = run(
        &scene("wall type disk\n  radius 1\n  ang-speed 2\n  epsn 1\n  epst -1\n"),
        vec![particle([0.5, 0.0, 0.5], [0.0, 0.0, -1.0])],
        &settings(0.8, 0.1, 0.5, [0.0; 3]),
    );
    let p = &out.particles[0].particle;
    assert!(
        (p.vel - Vec3::new(0.0, 4.0 / 7.0, 1.0)).norm() < 1e-12,
        "{p:?}"
    );
    assert!(
        (p.spin - Vec3::new(10.0 / 0.7, 0.0, 0.0)).norm() < 1e-12,
        "{p:?}"
    );
}

fn elastic(dt: f64, t_end: f64) -> Settings {
    Settings {
        material: ParticleMaterial {
            eps_n: 1.0,
            eps_t: 1.0,
            ..walls_sim::run::defaults::default_material(1.0)
        },
        ..settings(1.0, dt, t_end, [0.0; 3])
    }
}

#[test]
fn a_newtons_cradle_passes_the_speed_on_within_one_step() {
    // B hits A, which then hits C 0.4 further on, all within one step of 1: A was at rest
    // when the candidates were found, so C is found again when A speeds up.
    let far = scene("wall type plane\n  origin 0 0 -5\n  epsn 1\n  epst 1\n");
    let ps = vec![
        particle([-0.3, 0.0, 0.0], [1.0, 0.0, 0.0]),
        particle([0.0; 3], [0.0; 3]),
        particle([0.6, 0.0, 0.0], [0.0; 3]),
    ];
    let out = run(&far, ps, &elastic(1.0, 1.0));
    assert_eq!(out.pair_contacts, 2);
    let v: Vec<f64> = out.particles.iter().map(|s| s.particle.vel.x).collect();
    assert!(
        close(v[0], 0.0) && close(v[1], 0.0) && close(v[2], 1.0),
        "{v:?}"
    );
}

#[test]
fn particles_held_by_walls_are_obstacles() {
    // A lands on a sticky floor and stays; B, falling onto it, bounces off it as off a
    // wall (pkdgrav treats a stuck particle as infinitely massive), leaving A in place.
    let ps = vec![
        particle([0.0, 0.0, 0.15], [0.0, 0.0, -1.0]),
        particle([0.0, 0.0, 0.6], [0.0, 0.0, -1.0]),
    ];
    let out = run(
        &scene("wall type plane\n  epsn 0\n  epst 1\n"),
        ps,
        &elastic(0.01, 1.0),
    );
    assert_eq!(out.pair_contacts, 1);
    let (a, b) = (&out.particles[0], &out.particles[1]);
    assert_eq!(a.stuck_to.as_deref().map(|s| s.0), Some(0));
    assert!(close(a.particle.pos.z, 0.1), "{a:?}");
    assert!(close(b.particle.vel.z, 1.0), "{b:?}");
    // It met A at z = 0.3 at t = 0.3, and rose for 0.7 after.
    assert!(close(b.particle.pos.z, 1.0), "{b:?}");
    // A particle held at the collision cap is an obstacle too: one jammed between plates
    // stops another crossing its path.
    let walls = "wall type plane\n  epsn 1\n  epst 1\nwall type plane\n  origin 0 0 0.200001\n  epsn 1\n  epst 1\n";
    let mut k = particle([0.5, 0.0, 0.1000005], [-1.0, 0.0, 0.0]);
    k.radius = 0.05;
    let ps = vec![particle([0.0, 0.0, 0.1000005], [0.0, 0.0, 1.0]), k];
    let out = run(&scene(walls), ps, &elastic(1.0, 1.0));
    assert!(out.pair_contacts >= 1, "{:?}", out.warnings);
    assert!(
        out.particles[1].particle.vel.x > 0.0,
        "{:?}",
        out.particles[1]
    );
}

#[test]
fn a_stuck_particle_turns_and_spins_with_its_wall_from_when_it_sticks() {
    // Spinning at 30, it sticks to a still floor and stops spinning (it keeps no energy).
    let mut p = particle([0.0, 0.0, 0.5], [0.0, 0.0, -1.0]);
    p.spin = Vec3::new(0.0, 0.0, 30.0);
    let out = run(
        &scene("wall type plane\n  epsn 0\n  epst 1\n"),
        vec![p],
        &settings(0.8, 0.1, 1.0, [0.0; 3]),
    );
    assert_eq!(out.particles[0].particle.spin, Vec3::zeros());
    assert!(close(out.energy.1, 0.0), "{:?}", out.energy);
    // In a drum spinning at 2, stuck 0.09 into a step of 0.1: with the leapfrog it has
    // turned 2·0.01 rad by the step's end, not 2·0.1, and spins with the drum (pkdgrav's
    // step carries it for the whole step, below).
    let out = run(
        &scene("wall type cylinder-infinite\n  radius 1\n  epsn 0\n  epst 1\n  ang-speed 2\n"),
        vec![particle([0.81, 0.0, 0.0], [1.0, 0.0, 0.0])],
        &Settings {
            integrator: walls_sim::run::Integrator::Leapfrog,
            ..settings(0.8, 0.1, 0.1, [0.0; 3])
        },
    );
    let s = &out.particles[0];
    assert!(close(out.events[0].t, 0.09), "{:?}", out.events);
    let angle = s.particle.pos.y.atan2(s.particle.pos.x);
    assert!((angle - 0.02).abs() < 1e-12, "{angle}");
    assert_eq!(s.particle.spin, Vec3::new(0.0, 0.0, 2.0));
}

#[test]
fn dropped_down_the_axis_onto_a_small_hole_it_bounces_straight_back() {
    // The whole rim touches at once; the bounce is along the axis.
    let out = run(
        &scene("wall type disk\n  radius 1\n  hole-radius 0.05\n  epsn 1\n  epst 1\n"),
        vec![particle([0.0, 0.0, 0.5], [0.0, 0.0, -1.0])],
        &settings(0.8, 0.1, 0.5, [0.0; 3]),
    );
    let v = out.particles[0].particle.vel;
    assert!((v - Vec3::new(0.0, 0.0, 1.0)).norm() < 1e-12, "{v:?}");
}

#[test]
fn pkdgrav_carries_a_particle_that_sticks_within_a_step_by_the_walls_whole_step() {
    // A sticky plate moving along x at 2; the particle falls onto it and touches at
    // t = 0.35, τ = 0.05 into the step from 0.3 to 0.4. pkdgrav leaves it where it touched
    // and adds the wall's travel over the whole step at the step's end
    // (docs/pkdgrav-physics.md §6): at t = 1 it is 2·(1 − 0.3) along, v_wall·τ = 0.1
    // further than the wall carried it after the impact, 2·(1 − 0.35), which the other
    // integrators give.
    let walls = scene(
        "wall type rectangle\n  origin -5 -5 0\n  vertex1 10 0 0\n  vertex2 0 10 0\n  epsn 0\n  epst 1\n  velocity 2 0 0\n",
    );
    let ps = vec![particle([0.0, 0.0, 0.45], [0.0, 0.0, -1.0])];
    let leapfrog = Settings {
        integrator: walls_sim::run::Integrator::Leapfrog,
        ..settings(0.8, 0.1, 1.0, [0.0; 3])
    };
    let pkdgrav = Settings {
        integrator: walls_sim::run::Integrator::Pkdgrav,
        ..leapfrog.clone()
    };
    let after = run(&walls, ps.clone(), &leapfrog);
    let whole = run(&walls, ps, &pkdgrav);
    for out in [&after, &whole] {
        assert_eq!(out.events[0].kind, EventKind::Stick);
        assert!(close(out.events[0].t, 0.35), "{:?}", out.events);
        let p = &out.particles[0].particle;
        assert!(close(p.pos.z, 0.1) && close(p.vel.x, 2.0), "{p:?}");
    }
    let (xa, xw) = (
        after.particles[0].particle.pos.x,
        whole.particles[0].particle.pos.x,
    );
    assert!(close(xa, 2.0 * 0.65), "{xa}");
    assert!(close(xw, 2.0 * 0.7), "{xw}");
    assert!(close(xw - xa, 2.0 * 0.05));
}
