//! Reactive walls: assemblies that move in response to particles, against what
//! mechanics says: a torque-free body spins on, momentum is kept exactly, and an
//! impulse off the centre of gravity turns a lid about it.

use nalgebra::{Rotation3, Vector3};
use walls_sim::run::{Settings, Warning, run};

use walls_test_support::{ball as particle, scene};

type Vec3 = Vector3<f64>;

fn settings(t_end: f64) -> Settings {
    let k_n: f64 = 1e5;
    Settings::new(
        std::f64::consts::PI * (0.5 / k_n).sqrt() / 100.0,
        t_end,
        walls_sim::run::ParticleMaterial {
            eps_n: 0.5,
            ..walls_sim::run::defaults::default_material(k_n)
        },
    )
}

#[test]
fn the_documents_tetrahedron_spins_torque_free_at_its_rot_vec() {
    // Section 7.3's regular tetrahedron (in pkdgrav units), spinning at 1 about z, with a
    // particle far away: after t = 1 it has turned by 1 rad about z, still at 1.
    let tetra = "defaults cog 0 0 0\ndefaults ixj-vec 0.2 0 0\ndefaults iyj-vec 0 0.2 0\ndefaults izj-vec 0 0 0.2\n\
        defaults rot-vec 0 0 1\ndefaults mass 1\ndefaults assembly 0\n\
        wall type triangle\n origin 1 1 1\n vertex1 0 -2 -2\n vertex2 -2 0 -2\n\
        wall type triangle\n origin 1 1 1\n vertex1 0 -2 -2\n vertex2 -2 -2 0\n\
        wall type triangle\n origin 1 1 1\n vertex1 -2 0 -2\n vertex2 -2 -2 0\n\
        wall type triangle\n origin 1 -1 -1\n vertex1 -2 2 0\n vertex2 -2 0 2\n";
    let s = scene(tetra);
    let out = run(
        &s,
        vec![particle([50.0, 0.0, 0.0], [0.0; 3])],
        &settings(1.0),
    );
    let a = &out.assemblies[0];
    assert_eq!(a.walls, vec![0, 1, 2, 3]);
    assert!((a.mass - 4.0).abs() < 1e-12);
    assert!(
        (a.rotation.omega - Vec3::z()).norm() < 1e-9,
        "{:?}",
        a.rotation.omega
    );
    let turned = Rotation3::from_axis_angle(&Vector3::z_axis(), out.t);
    let origin = a.origin(0);
    assert!(
        (origin - turned * Vec3::new(1.0, 1.0, 1.0)).norm() < 1e-6,
        "{origin:?}"
    );
    assert!(a.cog.norm() < 1e-12 && a.velocity.norm() < 1e-12);
}

#[test]
fn a_particle_hitting_a_free_plate_keeps_the_total_momentum() {
    // A plate of mass 10 hit from above at speed 1: the particle rebounds, the plate moves
    // down, and the total momentum stays what it was to 1e−12.
    let plate = "wall type rectangle\n origin -1 -1 0\n vertex1 2 0 0\n vertex2 0 2 0\n mass 10\n assembly 0\n cog 0 0 0\n";
    let out = run(
        &scene(plate),
        vec![particle([0.0, 0.0, 0.15], [0.0, 0.0, -1.0])],
        &settings(0.2),
    );
    let a = &out.assemblies[0];
    let total = out.particles[0].particle.vel + a.velocity * a.mass;
    assert!(
        (total - Vec3::new(0.0, 0.0, -1.0)).norm() < 1e-12,
        "{total:?}"
    );
    assert!(out.particles[0].particle.vel.z > 0.0 && a.velocity.z < 0.0);
    // Walls follow their assembly: the plate is where its centre of gravity went.
    assert!((a.origin(0) - (a.cog + Vec3::new(-1.0, -1.0, 0.0))).norm() < 1e-12);
}

#[test]
fn a_lid_hit_off_its_centre_of_gravity_turns_about_it_like_a_hinge() {
    // A lid along x from 0 to 1, its centre of gravity at the hinge edge (x = 0), mass 1,
    // I about y = 1/3. A particle strikes it at x = 0.9: the lid's centre of gravity takes
    // J/M and it turns about y at 0.9·J/I, J being the impulse the particle gave.
    let lid = "wall type rectangle\n origin 0 -0.5 0\n vertex1 1 0 0\n vertex2 0 1 0\n mass 1\n assembly 0\n cog 0 0 0\n\
        ixj-vec 0.0833333333333 0 0\n iyj-vec 0 0.333333333333 0\n izj-vec 0 0 0.416666666667\n";
    let out = run(
        &scene(lid),
        vec![particle([0.9, 0.0, 0.15], [0.0, 0.0, -1.0])],
        &settings(0.1),
    );
    let p = &out.particles[0].particle;
    // The impulse the particle took (upwards); the lid took as much downwards.
    let j = 1.0 * (p.vel.z + 1.0);
    let a = &out.assemblies[0];
    assert!(
        (a.velocity.z + j).abs() < 1e-9 * j,
        "{} vs {}",
        a.velocity.z,
        -j
    );
    let omega = a.spin();
    let expected = 0.9 * j / 0.333333333333;
    assert!(
        (omega.y / expected - 1.0).abs() < 0.02,
        "ω_y {} vs {expected}",
        omega.y
    );
    assert!(omega.x.abs() < 1e-9 * expected && omega.z.abs() < 1e-9 * expected);
}

#[test]
fn an_elastic_strike_keeps_the_energy_of_particle_and_plate() {
    // Off-centre, elastic: the particle's energy goes into the plate's translation and
    // rotation, and the total is kept to the spring's integration error.
    let plate = "wall type rectangle\n origin -1 -1 0\n vertex1 2 0 0\n vertex2 0 2 0\n mass 10\n assembly 0\n cog 0 0 0\n epsn 1\n";
    let mut s = settings(0.2);
    s.material.eps_n = 1.0;
    let out = run(
        &scene(plate),
        vec![particle([0.5, 0.0, 0.15], [0.0, 0.0, -1.0])],
        &s,
    );
    let (before, after) = out.energy;
    assert!((after / before - 1.0).abs() < 1e-3, "{before} → {after}");
    assert!(out.assemblies[0].spin().y.abs() > 0.01, "it turns");
}

#[test]
fn an_assembly_without_a_positive_moment_of_inertia_stays_and_is_reported() {
    // izj-vec 0 (a rod's moment about its own axis): Euler's equations cannot turn it. It
    // stays where it is, the run says so, and the run ends.
    let plate = "wall type rectangle\n origin -1 -1 0\n vertex1 2 0 0\n vertex2 0 2 0\n mass 10\n assembly 0\n cog 0 0 0\n izj-vec 0 0 0\n";
    let out = run(
        &scene(plate),
        vec![particle([0.5, 0.0, 0.15], [0.3, 0.0, -1.0])],
        &settings(0.3),
    );
    assert!(out.assemblies.is_empty());
    assert!(
        out.warnings
            .iter()
            .any(|w| matches!(w, Warning::ImmovableAssemblies { .. })
                && w.to_string().contains("principal moment of inertia")),
        "{:?}",
        out.warnings
    );
    assert!(
        out.particles[0].particle.vel.z > 0.0,
        "it bounced off the plate"
    );
}
