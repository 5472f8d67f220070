//! Each method pushed past its limit: the evaluator notices and says so instead of
//! returning a wrong answer quietly (docs/stability.md lists them all).

use nalgebra::Vector3;
use walls_sim::contact::ssdem::damping;
use walls_sim::run::{ContactModel, EventKind, ParticleMaterial, Settings, Warning, run};

use walls_test_support::{ball as particle, scene};

type Vec3 = Vector3<f64>;

const K_N: f64 = 1e4;

/// The contact time π/ω_d against a wall at restitution `eps`.
fn contact_time(eps: f64) -> f64 {
    let c = damping(eps, K_N, 1.0);
    std::f64::consts::PI / (K_N - c * c / 4.0).sqrt()
}

fn soft(eps: f64, dt: f64, t_end: f64) -> Settings {
    Settings::new(
        dt,
        t_end,
        ParticleMaterial {
            eps_n: eps,
            ..walls_sim::run::defaults::default_material(K_N)
        },
    )
}

fn says(warnings: &[Warning], what: &str) -> bool {
    warnings.iter().any(|w| w.to_string().contains(what))
}

#[test]
fn a_timestep_above_the_stability_limit_gains_energy_and_is_reported() {
    // 1.4 steps per contact: dt > 2/ω₀, the spring pumps energy in.
    let dt = contact_time(1.0) / 1.4;
    let out = run(
        &scene("wall type plane\n"),
        vec![particle([0.0, 0.0, 0.1], [0.0, 0.0, -1.0])],
        &soft(1.0, dt, 10.0 * dt),
    );
    let e = &out.events[0];
    assert!(e.vn_out > 1.2 * e.vn_in, "{e:?}");
    assert!(
        says(&out.warnings, "above the stability limit"),
        "{:?}",
        out.warnings
    );
    assert!(
        says(&out.warnings, "faster than it came"),
        "{:?}",
        out.warnings
    );
}

#[test]
fn too_few_steps_per_contact_are_reported_with_the_error_to_expect() {
    let dt = contact_time(0.5) / 5.0;
    let out = run(
        &scene("wall type plane\n"),
        vec![particle([0.0, 0.0, 0.1], [0.0, 0.0, -1.0])],
        &soft(0.5, dt, 10.0 * dt),
    );
    // 1.2/N of the rebound at N = 4.9 undamped steps per contact.
    assert!(
        says(
            &out.warnings,
            "only 4.9 steps per contact for the stiffest contact (wall 0, k_n = 10000): rebound speeds may be off by up to 25%"
        ),
        "{:?}",
        out.warnings
    );
    // And not at the default of about 141 steps per wall contact.
    let dt = contact_time(0.5) / 141.0;
    let out = run(
        &scene("wall type plane\n"),
        vec![particle([0.0, 0.0, 0.1], [0.0, 0.0, -1.0])],
        &soft(0.5, dt, 300.0 * dt),
    );
    assert!(
        !says(&out.warnings, "steps per contact"),
        "{:?}",
        out.warnings
    );
}

#[test]
fn a_fast_particle_tunnels_through_a_thin_wall_in_ssdem_is_reported_and_hsdem_stops_it() {
    // 3.5 radii per step: from 0.2 above the plane to 0.15 below it in one step, never
    // overlapping it.
    let dt = 1e-3;
    let v = 0.35 / dt;
    let start = particle([0.0, 0.0, 0.2], [0.0, 0.0, -v]);
    let out = run(
        &scene("wall type plane\n"),
        vec![start.clone()],
        &soft(0.5, dt, 3.0 * dt),
    );
    assert!(out.events.is_empty(), "{:?}", out.events);
    assert!(out.particles[0].particle.pos.z < 0.0, "through");
    assert!(
        says(&out.warnings, "can pass through a thin wall"),
        "{:?}",
        out.warnings
    );
    let hard = Settings {
        build: walls_sim::build::Build::default_for(ContactModel::Hsdem),
        ..soft(0.5, dt, 3.0 * dt)
    };
    let out = run(
        &scene("wall type plane\n  epsn 0.5\n  epst 1\n"),
        vec![start],
        &hard,
    );
    assert_eq!(out.events.len(), 1);
    assert!(out.particles[0].particle.pos.z > 0.1);
}

#[test]
fn a_wall_moving_too_far_in_a_step_is_reported() {
    let dt = contact_time(0.5) / 100.0;
    let out = run(
        &scene("wall type plane\n  velocity 0 0 100\n"),
        vec![particle([0.0, 0.0, 5.0], [0.0; 3])],
        &soft(0.5, dt, dt),
    );
    assert!(
        says(&out.warnings, "wall 0 moves up to"),
        "{:?}",
        out.warnings
    );
    // A `step` that makes the wall jump far counts as well.
    let out = run(
        &scene("wall type plane\n  velocity 0 0 0.5\n  step 0.1\n"),
        vec![particle([0.0, 0.0, 5.0], [0.0; 3])],
        &soft(0.5, dt, dt),
    );
    assert!(
        says(&out.warnings, "wall 0 moves up to"),
        "{:?}",
        out.warnings
    );
}

#[test]
fn degenerate_shapes_still_bounce_particles_correctly() {
    // Head-on at a point (zero-radius disk, a cone of taper 1 at its apex, a shell
    // opened 180°) and across a line (zero-radius cylinder): back along the line of
    // centres at εn·v, in both models where the model has the shape, never NaN.
    let cases = [
        ("wall type disk\n  radius 0\n", [0.0, 0.0, 0.5], true),
        (
            "wall type cylinder-infinite\n  radius 0\n  orient 1 0 0\n",
            [0.0, 0.0, 0.5],
            true,
        ),
        (
            "wall type cylinder-finite\n  radius 1\n  length 2\n  taper 1\n",
            [0.0, 0.0, 1.5],
            false,
        ),
        (
            "wall type shell\n  radius 1\n  open-angle 180\n",
            [0.0, 0.0, -1.5],
            false,
        ),
    ];
    for (walls, pos, hard_too) in cases {
        let from = Vec3::from(pos);
        let target = if walls.contains("taper") {
            Vec3::new(0.0, 0.0, 1.0)
        } else if walls.contains("shell") {
            Vec3::new(0.0, 0.0, -1.0)
        } else {
            Vec3::zeros()
        };
        let dir = (target - from).normalize();
        let start = particle(pos, dir.into());
        let dt = contact_time(0.5) / 141.0;
        let out = run(&scene(walls), vec![start.clone()], &soft(0.5, dt, 1.5));
        let v = out.particles[0].particle.vel;
        assert!(v.iter().all(|x| x.is_finite()), "{walls}: {v:?}");
        assert!((v + dir * 0.5).norm() < 0.01, "{walls}: {v:?}");
        if hard_too {
            let text = format!("{walls}  epsn 0.5\n  epst 1\n");
            let hard = Settings {
                build: walls_sim::build::Build::default_for(ContactModel::Hsdem),
                ..soft(0.5, 0.1, 1.5)
            };
            let out = run(&scene(&text), vec![start], &hard);
            assert_eq!(out.events[0].kind, EventKind::Bounce);
            let v = out.particles[0].particle.vel;
            assert!((v + dir * 0.5).norm() < 1e-12, "{walls}: {v:?}");
        }
    }
}
