//! `Integrator::Pkdgrav`, pkdgrav's order of operations in a soft-sphere step
//! (docs/pkdgrav-physics.md §2), step by step against the same arithmetic written out by
//! hand: the force evaluation before the first step, the velocities and spins predicted
//! to the step's end for wall and pair contacts, the lever r − x against a wall, and the
//! walls moved as pkdgrav's soft-sphere build moves them (§5). The golden scenes pin the
//! rest.

use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_sim::contact::ssdem::damping;
use walls_sim::run::{EventKind, Integrator, ParticleMaterial, Settings, run, run_observed};
use walls_test_support::{ball, scene};

type Vec3 = Vector3<f64>;

const K_N: f64 = 1e6;
const DT: f64 = 1e-4;

fn material(eps_n: f64, eps_t: f64, mu_s: f64) -> ParticleMaterial {
    ParticleMaterial {
        eps_n,
        eps_t,
        k_n: K_N,
        k_t: 2.0 / 7.0 * K_N,
        mu_s,
        mu_r: 0.0,
        mu_t: 0.0,
        beta_s: walls_geometry::BETA_S_DEFAULT,
    }
}

/// pkdgrav's step for `steps` steps, without gravity.
fn settings(mat: ParticleMaterial, steps: f64) -> Settings {
    Settings {
        integrator: Integrator::Pkdgrav,
        ..Settings::new(DT, steps * DT, mat)
    }
}

fn close(what: &str, got: Vec3, want: Vec3, scale: f64) {
    assert!(
        (got - want).norm() <= 1e-12 * scale,
        "{what}: {got:?}, expected {want:?}"
    );
}

#[test]
fn the_forces_at_the_start_and_the_predicted_velocity_against_a_wall() {
    // At rest on a floor, overlapping it by x0 at t0: pkdgrav's first kick already
    // carries the spring's push, and the dashpot of step 1 sees v0 + a0·dt.
    let x0 = 0.002;
    let p = ball([0.0, 0.0, 0.1 - x0], [0.0; 3]);
    let (m, r) = (p.mass, p.radius);
    let eps = 0.5;
    let out = run(
        &scene("wall type plane\n"),
        vec![p.clone()],
        &settings(material(eps, 1.0, 0.0), 1.0),
    );
    assert_eq!(out.steps, 1);
    let a0 = K_N * x0 / m;
    let v_half = 0.5 * DT * a0;
    let z1 = p.pos.z + DT * v_half;
    let v_pred = DT * a0;
    let a1 = (K_N * (r - z1) - damping(eps, K_N, m) * v_pred) / m;
    let v1 = v_half + 0.5 * DT * a1;
    let got = &out.particles[0].particle;
    close("position", got.pos, Vec3::new(0.0, 0.0, z1), r);
    close("velocity", got.vel, Vec3::new(0.0, 0.0, v1), v1.abs());
}

#[test]
fn pair_contacts_see_predicted_velocities_from_the_start() {
    // Two equal spheres at rest overlapping by x0 along x: pushed apart at t0, and the
    // pair's dashpot (reduced mass m/2) sees the predicted velocities ±a0·dt.
    let x0 = 0.002;
    let c = 0.1 - x0 / 2.0;
    let ps = vec![
        ball([-c, 0.0, 0.0], [0.0; 3]),
        ball([c, 0.0, 0.0], [0.0; 3]),
    ];
    let (m, r) = (ps[0].mass, ps[0].radius);
    let eps = 0.5;
    let out = run(&[], ps, &settings(material(eps, 1.0, 0.0), 1.0));
    let a0 = K_N * x0 / m;
    let v_half = 0.5 * DT * a0;
    let x1 = c + DT * v_half;
    let approach = -2.0 * DT * a0;
    let a1 = (K_N * (2.0 * r - 2.0 * x1) + damping(eps, K_N, m / 2.0) * approach) / m;
    let v1 = v_half + 0.5 * DT * a1;
    let got = &out.particles[1].particle;
    close("position", got.pos, Vec3::new(x1, 0.0, 0.0), r);
    close("velocity", got.vel, Vec3::new(v1, 0.0, 0.0), v1.abs());
    close(
        "the other's velocity",
        out.particles[0].particle.vel,
        Vec3::new(-v1, 0.0, 0.0),
        v1.abs(),
    );
}

#[test]
fn spins_are_predicted_and_the_wall_lever_is_r_minus_x() {
    // A sphere spinning about x on a floor it overlaps at t0, held by its tangential
    // spring (μ_s large, no damping): the spring steps once at t0 with the lever
    // d = r − x, and again in step 1 with the predicted velocity and spin.
    let x0 = 0.002;
    let w0 = 3.0;
    let p = Particle {
        spin: Vec3::new(w0, 0.0, 0.0),
        ..ball([0.0, 0.0, 0.1 - x0], [0.0; 3])
    };
    let (m, r) = (p.mass, p.radius);
    let inertia = 0.4 * m * r * r;
    let k_t = 2.0 / 7.0 * K_N;
    let out = run(
        &scene("wall type plane\n"),
        vec![p.clone()],
        &settings(material(1.0, 1.0, 1e3), 1.0),
    );
    let n = Vec3::z();
    // t0: the contact velocity at the lever r − x0, the spring, the force and torque.
    let d0 = r - x0;
    let u0 = p.spin.cross(&(-n * d0));
    let spring0 = u0 * DT;
    let f0 = n * (K_N * x0) - spring0 * k_t;
    let tau0 = (-n * d0).cross(&(-spring0 * k_t));
    let (a0, alpha0) = (f0 / m, tau0 / inertia);
    // Step 1: kick, drift, predict, forces, kick.
    let v_half = a0 * (0.5 * DT);
    let w_half = p.spin + alpha0 * (0.5 * DT);
    let pos1 = p.pos + v_half * DT;
    let (v_pred, w_pred) = (a0 * DT, p.spin + alpha0 * DT);
    let x1 = r - pos1.z;
    let d1 = r - x1;
    let u1 = v_pred + w_pred.cross(&(-n * d1));
    let ut1 = u1 - n * n.dot(&u1);
    let spring1 = spring0 + ut1 * DT;
    let f1 = n * (K_N * x1) - spring1 * k_t;
    let tau1 = (-n * d1).cross(&(-spring1 * k_t));
    let v1 = v_half + f1 / m * (0.5 * DT);
    let w1 = w_half + tau1 / inertia * (0.5 * DT);
    let got = &out.particles[0].particle;
    close("position", got.pos, pos1, r);
    close("velocity", got.vel, v1, v1.norm());
    close("spin", got.spin, w1, w1.norm());
}

#[test]
fn walls_move_in_steps_to_the_sinusoid_with_the_velocity_half_a_step_later() {
    // A particle that sticks at t0 to an oscillating sticky floor is carried with it,
    // so it shows where the floor is and how fast it moves after each step: at
    // A·sin(ω·q + 2πφ), q the whole `step` (dt when 0) that holds t_n + ½dt, moving at
    // A·ω·cos(ω·(t_n + ½dt) + 2πφ), not quantised.
    let (a, omega, phase) = (0.01, 300.0, 0.1);
    for every in [0.0, 5.0 * DT] {
        let walls = scene(&format!(
            "wall type plane\n  epsn 0\n  osc-ampl {a}\n  osc-freq {omega}\n  \
             osc-phase {phase}\n  osc-vec 0 0 1\n  step {every}\n"
        ));
        let phi = std::f64::consts::TAU * phase;
        let z0 = a * phi.sin() + 0.099;
        let p = ball([0.0, 0.0, z0], [0.0; 3]);
        let mut seen = Vec::new();
        let out = run_observed(
            &walls,
            vec![p],
            &settings(material(0.8, 1.0, 0.0), 40.0),
            &mut |step, t, snapshot| seen.push((step, t, snapshot.look().0[0].particle.clone())),
        );
        assert_eq!(out.events[0].kind, EventKind::Stick);
        assert_eq!(out.events[0].t, 0.0);
        assert_eq!(seen.len(), 40);
        let step = if every > 0.0 { every } else { DT };
        for (n, t, p) in seen {
            let q = ((t + 0.5 * DT) / step).floor() * step;
            let z = z0 + a * ((omega * q + phi).sin() - phi.sin());
            let v = a * omega * (omega * (t + 0.5 * DT) + phi).cos();
            close(
                &format!("step {n}: position"),
                p.pos,
                Vec3::new(0.0, 0.0, z),
                a,
            );
            close(
                &format!("step {n}: velocity"),
                p.vel,
                Vec3::new(0.0, 0.0, v),
                a * omega,
            );
        }
    }
}

#[test]
fn pair_torques_act_at_the_plane_of_intersection() {
    // Unequal spheres overlapping at t0, the larger spinning across the line of
    // centres: the tangential force turns each about its distance to the plane where
    // the spheres intersect (l1, l2 of docs/pkdgrav-physics.md §1.1), not about its
    // radius. The levers' ratio is 0.446 at t0 and changes by about 1e-3 within the step;
    // the radii's is 0.5.
    let (r1, r2, x0) = (0.1, 0.05, 0.01);
    let d = r1 + r2 - x0;
    let ps = vec![
        Particle {
            spin: Vec3::new(0.0, 0.0, 5.0),
            ..ball([0.0; 3], [0.0; 3])
        },
        Particle {
            mass: 0.5,
            radius: r2,
            ..ball([d, 0.0, 0.0], [0.0; 3])
        },
    ];
    let out = run(&[], ps.clone(), &settings(material(1.0, 1.0, 1e3), 1.0));
    let l1 = (r1 * r1 - r2 * r2 + d * d) / (2.0 * d);
    let l2 = d - l1;
    let angular = |k: usize| {
        let (p, q) = (&ps[k], &out.particles[k].particle);
        (q.spin - p.spin).z * 0.4 * p.mass * p.radius * p.radius
    };
    let ratio = angular(1) / angular(0);
    assert!(
        (ratio / (l2 / l1) - 1.0).abs() < 5e-3,
        "{ratio}, levers {}, radii {}",
        l2 / l1,
        r2 / r1
    );
}
