//! Particles against walls with the SSDEM model, against analytic answers (and a free
//! fall with HSDEM too).

use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_sim::run::{
    ContactModel, EventKind, Integrator, ParticleMaterial, Settings, default_dt, run,
};

use walls_test_support::{ball as particle, scene};

type Vec3 = Vector3<f64>;

fn settings(particles: &[Particle], eps_n: f64, t_end: f64, gravity: [f64; 3]) -> Settings {
    // Stiff enough that a particle at speed 1 overlaps by 1 % of its radius.
    let k_n = 1e6;
    Settings {
        gravity: Vec3::from(gravity),
        ..Settings::new(
            default_dt(particles, k_n),
            t_end,
            ParticleMaterial {
                eps_n,
                ..walls_sim::run::defaults::default_material(k_n)
            },
        )
    }
}

#[test]
fn rebound_at_eps_n_from_every_wall_type() {
    // Each wall is met head-on by a particle 0.5 away moving at 1 towards it.
    let cases = [
        ("wall type plane\n", [0.0, 0.0, 0.5], [0.0, 0.0, -1.0]),
        (
            "wall type rectangle\n  origin -1 -1 0\n  vertex1 2 0 0\n  vertex2 0 2 0\n",
            [0.0, 0.0, 0.5],
            [0.0, 0.0, -1.0],
        ),
        (
            "wall type triangle\n  origin -1 -1 0\n  vertex1 3 0 0\n  vertex2 0 3 0\n",
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
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
        ),
        (
            "wall type cylinder-finite\n  radius 1\n  length 2\n",
            [3.0, 0.0, 0.0],
            [-1.0, 0.0, 0.0],
        ),
        (
            "wall type shell\n  radius 1\n",
            [0.0, 0.3, 0.0],
            [0.0, 1.0, 0.0],
        ),
    ];
    for eps in [0.9, 0.5] {
        for (walls, pos, vel) in cases {
            let ps = vec![particle(pos, vel)];
            let out = run(
                &scene(walls),
                ps.clone(),
                &settings(&ps, eps, 2.0, [0.0; 3]),
            );
            let bounces: Vec<_> = out
                .events
                .iter()
                .filter(|e| e.kind == EventKind::Bounce)
                .collect();
            assert_eq!(bounces.len(), 1, "{walls}: {:?}", out.events);
            let ratio = bounces[0].vn_out / bounces[0].vn_in;
            assert!(
                (ratio / eps - 1.0).abs() < 0.01,
                "{walls} ε = {eps}: {ratio}"
            );
            assert!(out.warnings.is_empty(), "{:?}", out.warnings);
        }
    }
}

#[test]
fn a_walls_own_restitution_wins_over_the_particles() {
    let ps = vec![particle([0.0, 0.0, 0.5], [0.0, 0.0, -1.0])];
    let out = run(
        &scene("wall type plane\n  epsn 0.3\n"),
        ps.clone(),
        &settings(&ps, 0.9, 1.0, [0.0; 3]),
    );
    let e = &out.events[0];
    assert!((e.vn_out / e.vn_in / 0.3 - 1.0).abs() < 0.01);
}

#[test]
fn elastic_kick_off_a_moving_wall() {
    // The wall moves up at 0.5; the particle comes down at 1: it leaves at 2u − v = 2.
    let ps = vec![particle([0.0, 0.0, 0.5], [0.0, 0.0, -1.0])];
    let out = run(
        &scene("wall type plane\n  velocity 0 0 0.5\n"),
        ps.clone(),
        &settings(&ps, 1.0, 0.5, [0.0; 3]),
    );
    let v = out.particles[0].particle.vel.z;
    assert!((v / 2.0 - 1.0).abs() < 0.01, "{v}");
}

#[test]
fn death_and_sticky_walls() {
    let ps = vec![particle([0.0, 0.0, 0.5], [0.0, 0.0, -1.0])];
    let gone = run(
        &scene("wall type plane\n  epsn -1\n"),
        ps.clone(),
        &settings(&ps, 0.9, 1.0, [0.0; 3]),
    );
    assert!(!gone.particles[0].alive);
    assert_eq!(gone.events[0].kind, EventKind::Remove);
    // Stuck to a wall moving sideways, it moves with it.
    let stuck = run(
        &scene("wall type plane\n  epsn 0\n  velocity 1 0 0\n"),
        ps.clone(),
        &settings(&ps, 0.9, 1.0, [0.0; 3]),
    );
    assert_eq!(stuck.events[0].kind, EventKind::Stick);
    assert!((stuck.particles[0].particle.vel - Vec3::new(1.0, 0.0, 0.0)).norm() < 1e-12);
}

#[test]
fn stuck_to_a_spinning_drum_it_moves_at_omega_times_r() {
    // Inside a drum of radius 1 spinning at 2 about z, a particle thrown at the wall sticks
    // and then goes round at Ω·r, r being its centre's distance from the axis.
    let ps = vec![particle([0.5, 0.0, 0.0], [1.0, 0.0, 0.0])];
    let out = run(
        &scene("wall type cylinder-infinite\n  radius 1\n  epsn 0\n  ang-speed 2\n"),
        ps.clone(),
        &settings(&ps, 0.9, 3.0, [0.0; 3]),
    );
    let p = &out.particles[0].particle;
    let r = (p.pos.x.powi(2) + p.pos.y.powi(2)).sqrt();
    assert!(
        (p.vel.norm() - 2.0 * r).abs() < 1e-9,
        "{} vs {}",
        p.vel.norm(),
        2.0 * r
    );
    assert!((r - 0.9).abs() < 0.01, "it stays at the wall: r = {r}");
}

#[test]
fn elastic_bouncing_under_gravity_keeps_its_energy() {
    let ps = vec![particle([0.0, 0.0, 1.0], [0.0, 0.0, 0.0])];
    let out = run(
        &scene("wall type plane\n"),
        ps.clone(),
        &settings(&ps, 1.0, 6.0, [0.0, 0.0, -1.0]),
    );
    let (before, after) = out.energy;
    assert!(
        out.events.len() >= 2,
        "{:?} {:?}",
        out.events,
        out.particles[0].particle.pos
    );
    assert!((after / before - 1.0).abs() < 1e-3, "{before} → {after}");
}

#[test]
fn holes_and_openings_let_particles_through() {
    // Along the axis of a disk with a hole wider than the particle: no contact.
    let ps = vec![particle([0.0, 0.0, 1.0], [0.0, 0.0, -1.0])];
    let out = run(
        &scene("wall type disk\n  radius 2\n  hole-radius 0.5\n"),
        ps.clone(),
        &settings(&ps, 0.9, 3.0, [0.0; 3]),
    );
    assert!(out.events.is_empty() && out.particles[0].particle.pos.z < -1.0);
    // Up through a shell's opening from inside: out; down from inside: a bounce.
    let up = vec![particle([0.0, 0.0, 0.0], [0.0, 0.0, 1.0])];
    let shell = scene("wall type shell\n  radius 1\n  open-angle 45\n");
    let out = run(&shell, up.clone(), &settings(&up, 0.9, 3.0, [0.0; 3]));
    assert!(out.events.is_empty() && out.particles[0].particle.pos.z > 2.0);
    let down = vec![particle([0.0, 0.0, 0.0], [0.0, 0.0, -1.0])];
    let out = run(&shell, down.clone(), &settings(&down, 0.9, 3.0, [0.0; 3]));
    assert_eq!(out.events[0].kind, EventKind::Bounce);
}

#[test]
fn off_a_triangles_vertex_along_the_line_to_the_centre() {
    // Aimed so that it meets the vertex at the origin along (−1, −1, 1)/√3.
    let dir = Vec3::new(-1.0, -1.0, 1.0).normalize();
    let start = dir * 0.5;
    let ps = vec![particle(start.into(), (-dir).into())];
    let out = run(
        &scene("wall type triangle\n  vertex1 1 0 0\n  vertex2 0 1 0\n"),
        ps.clone(),
        &settings(&ps, 1.0, 1.0, [0.0; 3]),
    );
    let v = out.particles[0].particle.vel;
    assert!((v.normalize() - dir).norm() < 1e-6, "leaves along {v:?}");
}

#[test]
fn a_vibrated_plate_throws_a_resting_particle_only_above_one_g() {
    // A plate z = A·sin(ωt) carries a particle resting on it. The particle leaves when the
    // plate decelerates faster than gravity: at ωt = arcsin(g/(Aω²)), and only if Aω²/g > 1.
    let (a, g): (f64, f64) = (0.01, 1.0);
    for gamma in [0.5f64, 2.0, 4.0] {
        let omega = (gamma * g / a).sqrt();
        let walls = format!("wall type plane\n  osc-ampl {a}\n  osc-freq {omega}\n");
        // At rest on the plate: at the spring's equilibrium, moving with it.
        let k_n = 1e6;
        let ps = vec![particle([0.0, 0.0, 0.1 - g / k_n], [0.0, 0.0, a * omega])];
        let period = std::f64::consts::TAU / omega;
        let out = run(
            &scene(&walls),
            ps.clone(),
            &settings(&ps, 0.5, 2.0 * period, [0.0, 0.0, -g]),
        );
        let first = out.events.first();
        if gamma < 1.0 {
            assert!(
                first.is_none(),
                "Γ = {gamma}: it stays on the plate: {first:?}"
            );
            continue;
        }
        let phase = first.expect("it lifts off").t * omega;
        let expected = (1.0 / gamma).asin();
        assert!(
            (phase - expected).abs() < 0.02,
            "Γ = {gamma}: lift-off at phase {phase}, expected {expected}"
        );
    }
}

#[test]
fn particles_bounce_off_each_other_at_eps_n_keeping_momentum() {
    // Head-on at a closing speed of 1.5: the pair's contact time is π√(μ/k) with μ = m/2,
    // which the default timestep resolves in 100 steps.
    for eps in [0.9, 0.5] {
        let a = particle([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        let mut b = particle([0.5, 0.0, 0.0], [-0.5, 0.0, 0.0]);
        b.mass = 2.0;
        let ps = vec![a, b];
        let out = run(
            &scene("wall type plane\n  origin 0 0 -5\n"),
            ps.clone(),
            &settings(&ps, eps, 1.0, [0.0; 3]),
        );
        assert_eq!(out.pair_contacts, 1);
        let (va, vb) = (out.particles[0].particle.vel, out.particles[1].particle.vel);
        let ratio = (vb.x - va.x) / 1.5;
        assert!((ratio / eps - 1.0).abs() < 0.01, "ε = {eps}: {ratio}");
        let momentum = va + vb * 2.0;
        assert!(
            (momentum - Vec3::new(0.0, 0.0, 0.0)).norm() < 1e-12,
            "{momentum:?}"
        );
    }
    // Switched off, they pass through each other.
    let ps = vec![
        particle([0.0; 3], [1.0, 0.0, 0.0]),
        particle([0.5, 0.0, 0.0], [-1.0, 0.0, 0.0]),
    ];
    let mut s = settings(&ps, 0.9, 1.0, [0.0; 3]);
    s.particle_contacts = false;
    let out = run(&scene("wall type plane\n  origin 0 0 -5\n"), ps, &s);
    assert_eq!(out.pair_contacts, 0);
    assert!((out.particles[0].particle.vel.x - 1.0).abs() < 1e-12);
}

/// A particle resting on the plane z = 0 (radius 0.1, mass 1, k_n 10³, g = 1), at its
/// equilibrium overlap of 1 % of the radius, with velocity `vel` and spin `spin`, in a
/// pkdgrav build without `DEM_ROTATION_DASHPOT`: rolling and twisting resistance are
/// directional constant torques (docs/pkdgrav-physics.md §1.6), twisting only with
/// `bUseContactRadius` (`contact_radius`), which also makes the contact radius the
/// rolling lever.
fn resting(
    vel: [f64; 3],
    spin: [f64; 3],
    mu_r: f64,
    mu_t: f64,
    t_end: f64,
    contact_radius: bool,
) -> walls_sim::run::Outcome {
    let k_n = 1e3;
    let mut p = particle([0.0, 0.0, 0.1 - 1.0 / k_n], vel);
    p.spin = Vec3::from(spin);
    let ps = vec![p];
    let s = Settings {
        gravity: Vec3::new(0.0, 0.0, -1.0),
        build: walls_sim::build::Build::parse("DEM").expect("a build"),
        contact_radius,
        ..Settings::new(
            default_dt(&ps, k_n),
            t_end,
            ParticleMaterial {
                eps_n: 0.5,
                mu_s: 0.5,
                mu_r,
                mu_t,
                ..walls_sim::run::defaults::default_material(k_n)
            },
        )
    };
    run(&scene("wall type plane\n"), ps, &s)
}

#[test]
fn rolling_resistance_slows_a_rolling_ball_at_five_sevenths_mu_r_g() {
    // Rolling at v0 = 1 with ω = v0/R about y. pkdgrav's contact point is at the lever
    // d = R − x (docs/pkdgrav-physics.md §1.1), so the ball first slips to rolling at v1 = ω d with its
    // angular momentum about the contact point kept: (I ω0 + m d v0) = (I/d + m d) v1.
    // Then the torque μ_r·R·mg against the spin, shared with the friction that keeps it
    // rolling, decelerates it at a = μ_r·g·R·d/(0.4R² + d²): (5/7)·μ_r·g when x = 0.
    let (mu_r, g, r, x) = (0.2, 1.0, 0.1, 1e-3);
    let d = r - x;
    let inertia = 0.4 * r * r;
    let v1 = (inertia * 10.0 + d) / (inertia / d + d);
    let a = mu_r * g * r * d / (0.4 * r * r + d * d);
    let half = resting([1.0, 0.0, 0.0], [0.0, 10.0, 0.0], mu_r, 0.0, 3.5, false);
    let v = half.particles[0].particle.vel.x;
    let expected = v1 - a * 3.5;
    assert!((v / expected - 1.0).abs() < 0.005, "{v} vs {expected}");
    // Stopped after v1²/(2a), where the tangential spring (undamped with ε_t = 1) rocks it
    // by a few thousandths.
    let stopped = resting([1.0, 0.0, 0.0], [0.0, 10.0, 0.0], mu_r, 0.0, 9.0, false);
    let p = &stopped.particles[0].particle;
    assert!(
        (p.pos.x / (v1 * v1 / (2.0 * a)) - 1.0).abs() < 0.01,
        "{p:?}"
    );
    assert!(p.vel.norm() < 1e-2 && p.spin.norm() < 0.1, "{p:?}");
    // Without it the ball rolls on.
    let free = resting([1.0, 0.0, 0.0], [0.0, 10.0, 0.0], 0.0, 0.0, 3.5, false);
    let v = free.particles[0].particle.vel.x;
    assert!((v - v1).abs() < 5e-3, "{v} vs {v1}");
}

#[test]
fn twisting_resistance_stops_a_spin_about_the_normal() {
    // Spinning at 10 about z on the plane: torque μ_t·a·mg with a = √(2Rx − x²) the
    // contact circle's radius at overlap x = mg/k_n, so ω falls at μ_t·a·mg/(0.4·mR²)
    // (pkdgrav's twisting needs bUseContactRadius in a build without the dashpot).
    // The torque has no cap (docs/pkdgrav-physics.md §1.6): once stopped, the spin flips
    // about zero by at most one step's change.
    let (mu_t, x, r): (f64, f64, f64) = (1.0, 1e-3, 0.1);
    let a = (2.0 * r * x - x * x).sqrt();
    let rate = mu_t * a / (0.4 * r * r);
    let out = resting([0.0; 3], [0.0, 0.0, 10.0], 0.0, mu_t, 1.0, true);
    let w = out.particles[0].particle.spin.z;
    assert!(
        (w / (10.0 - rate) - 1.0).abs() < 0.01,
        "{w} vs {}",
        10.0 - rate
    );
    let out = resting(
        [0.0; 3],
        [0.0, 0.0, 10.0],
        0.0,
        mu_t,
        10.0 / rate + 1.0,
        true,
    );
    let w = out.particles[0].particle.spin.z;
    let dt = walls_sim::run::default_dt(&[particle([0.0; 3], [0.0; 3])], 1e3);
    assert!(w.abs() <= 1.01 * rate * dt, "stopped, within a step: {w}");
}

#[test]
fn a_particle_stuck_to_a_wall_is_an_obstacle_to_the_others() {
    // A lands on a sticky floor; B falls onto it and bounces off, A staying put.
    let ps = vec![
        particle([0.0, 0.0, 0.15], [0.0, 0.0, -1.0]),
        particle([0.0, 0.0, 0.6], [0.0, 0.0, -1.0]),
    ];
    let out = run(
        &scene("wall type plane\n  epsn 0\n"),
        ps.clone(),
        &settings(&ps, 0.9, 1.0, [0.0; 3]),
    );
    assert_eq!(out.pair_contacts, 1);
    let (a, b) = (&out.particles[0], &out.particles[1]);
    assert_eq!(a.stuck_to.as_deref().map(|s| s.0), Some(0));
    assert!((a.particle.pos.z - 0.1).abs() < 1e-3, "{a:?}");
    // Against an infinite mass the pair rebounds at the pair's εn.
    assert!((b.particle.vel.z / 0.9 - 1.0).abs() < 0.01, "{b:?}");
}

#[test]
fn a_particle_removed_by_a_death_wall_is_no_obstacle() {
    // A and B fall together, a ten-thousandth apart, onto a death floor: A is removed
    // where it touches it, and B goes on through where A was (before the candidate
    // pairs are found again) to be removed in its turn, meeting nothing.
    let ps = vec![
        particle([0.0, 0.0, 0.15], [0.0, 0.0, -1.0]),
        particle([0.0, 0.0, 0.3501], [0.0, 0.0, -1.0]),
    ];
    let out = run(
        &scene("wall type plane\n  epsn -1\n"),
        ps.clone(),
        &settings(&ps, 0.9, 0.5, [0.0; 3]),
    );
    assert_eq!(out.pair_contacts, 0);
    let removed: Vec<usize> = (out.events.iter())
        .filter(|e| e.kind == EventKind::Remove)
        .map(|e| e.particle)
        .collect();
    assert_eq!(removed, [0, 1]);
}

#[test]
fn rolling_resistance_between_particles_does_not_reverse_their_relative_spin() {
    // Two particles pressed together, one spinning across the normal: the resistance
    // acts on the relative spin through the reduced inertia, so it stops it, and the
    // total spin (equal particles) is kept.
    let mut a = particle([0.0, 0.0, 0.0], [-0.01, 0.0, 0.0]);
    a.spin = Vec3::new(0.0, 0.01, 0.0);
    let b = particle([0.199, 0.0, 0.0], [0.01, 0.0, 0.0]);
    let ps = vec![a, b];
    let mut s = settings(&ps, 0.5, 0.5, [0.0; 3]);
    s.material.mu_r = 1.0;
    let out = run(&scene("wall type plane\n  origin 0 0 -5\n"), ps, &s);
    let (wa, wb) = (
        out.particles[0].particle.spin.y,
        out.particles[1].particle.spin.y,
    );
    assert!((wa + wb - 0.01).abs() < 1e-12, "{wa} + {wb}");
    assert!(wa - wb >= -1e-12, "relative spin reversed: {wa} − {wb}");
}

#[test]
fn free_fall_gains_g_dt_a_step_from_the_first_step_with_every_integrator() {
    // Gravity alone (the floor far below): every step adds g·dt to the velocity, the
    // first ones too, whether or not the integrator has pkdgrav's force evaluation before
    // the first step; the kick-drift-kick ones place the particle at z₀ + v₀t − g t²/2,
    // explicit Euler (drift, then kick) g·dt²·n(n−1)/2 higher. Hard spheres (HSDEM) kick,
    // drift and kick under every integrator.
    let (z0, v0, g, dt) = (1.0, 0.25, 9.81, 1e-3);
    for model in [ContactModel::Ssdem, ContactModel::Hsdem] {
        let walls = walls_test_support::scene_in("wall type plane\n  origin 0 0 -100\n", model);
        for integrator in [
            Integrator::Pkdgrav,
            Integrator::Leapfrog,
            Integrator::LeapfrogPredicted,
            Integrator::ExplicitEuler,
        ] {
            for steps in [1u32, 2, 3, 10] {
                let ps = vec![particle([0.0, 0.0, z0], [0.0, 0.0, v0])];
                let mut s = settings(&ps, 0.5, f64::from(steps) * dt, [0.0, 0.0, -g]);
                s.dt = dt;
                s.integrator = integrator;
                s.build = walls_sim::build::Build::default_for(model);
                let out = run(&walls, ps, &s);
                assert_eq!(out.steps, u64::from(steps), "{model:?}, {integrator:?}");
                let n = f64::from(steps);
                let p = &out.particles[0].particle;
                let t = n * dt;
                assert!(
                    (p.vel.z - (v0 - g * t)).abs() < 1e-13,
                    "{model:?}, {integrator:?}, {steps} steps: v = {}, not {}",
                    p.vel.z,
                    v0 - g * t
                );
                let z = if integrator == Integrator::ExplicitEuler && model == ContactModel::Ssdem {
                    z0 + v0 * t - g * dt * dt * n * (n - 1.0) / 2.0
                } else {
                    z0 + v0 * t - g * t * t / 2.0
                };
                assert!(
                    (p.pos.z - z).abs() < 1e-13,
                    "{model:?}, {integrator:?}, {steps} steps: z = {}, not {z}",
                    p.pos.z
                );
            }
        }
    }
}
