//! Reactive walls: assemblies that move in response to particles, against what
//! mechanics says: a torque-free body spins on, momentum is kept exactly, and an
//! impulse off the centre of gravity turns a lid about it.

use nalgebra::{Rotation3, Vector3};
use walls_sim::build::Build;
use walls_sim::dynamics::euler_rigid;
use walls_sim::dynamics::reactive::assemblies;
use walls_sim::dynamics::rigid::Rotation;
use walls_sim::run::{Integrator, Settings, Stop, Warning, run};

use walls_test_support::{ball as particle, scene};

type Vec3 = Vector3<f64>;

/// A build with reactive walls (pkdgrav's default build lacks them).
fn react_build() -> Build {
    Build::parse("DEM DEM_ROTATION_DASHPOT DEM_WALLS_REACT").unwrap()
}

fn settings(t_end: f64) -> Settings {
    let k_n: f64 = 1e5;
    Settings {
        build: react_build(),
        ..Settings::new(
            std::f64::consts::PI * (0.5 / k_n).sqrt() / 100.0,
            t_end,
            walls_sim::run::ParticleMaterial {
                eps_n: 0.5,
                ..walls_sim::run::defaults::default_material(k_n)
            },
        )
    }
}

/// [`settings`] with pkdgrav's step order and reactive-wall motion.
fn pkdgrav_settings(t_end: f64) -> Settings {
    Settings {
        integrator: Integrator::Pkdgrav,
        ..settings(t_end)
    }
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
fn an_assembly_whose_numbers_overflow_stops_the_run_before_it_is_shown() {
    // A plate of mass 1e-305 pressed by a particle: its acceleration is beyond a double.
    // The run went on with an infinite plate, and its WALLSREACT rows said `inf` and
    // `nan`.
    let plate = "wall type rectangle\n origin -1 -1 0\n vertex1 2 0 0\n vertex2 0 2 0\n mass 1e-305\n assembly 0\n cog 0 0 0\n";
    let mut shown = Vec::new();
    let out = walls_sim::run::run_watched(
        &scene(plate),
        vec![particle([0.0, 0.0, 0.07], [0.0, 0.0, 0.0])],
        &settings(0.2),
        &mut |step, _, snapshot| {
            let (_, assemblies) = snapshot.look();
            shown.push((step, assemblies.iter().all(|a| a.finite())));
        },
        &|| false,
    );
    assert_eq!(out.stopped, Some(Stop::AssemblyNotFinite(0)));
    assert!(!out.assemblies[0].finite());
    assert!(shown.iter().all(|&(_, finite)| finite), "{shown:?}");
    assert_eq!(shown.len() as u64 + 1, out.steps);
    assert_eq!(Stop::AssemblyNotFinite(0).code(), "not-finite");
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
    let plate = "wall type rectangle\n origin -1 -1 0\n vertex1 2 0 0\n vertex2 0 2 0\n mass 10\n assembly 0\n cog 0 0 0.5\n izj-vec 0 0 0\n";
    let ball = particle([0.5, 0.0, 0.15], [0.3, 0.0, -1.0]);
    let s = settings(0.3);
    let out = run(&scene(plate), vec![ball.clone()], &s);
    assert!(out.assemblies.is_empty());
    // The energy at the start is the particle's alone, as at the end: the plate that
    // stays is not counted in one and left out of the other.
    let p = &ball;
    let start = p.mass * (0.5 * p.vel.norm_squared() - s.gravity.dot(&p.pos));
    assert!(
        (out.energy.0 / start - 1.0).abs() < 1e-12,
        "{} vs {start}",
        out.energy.0
    );
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

#[test]
fn pkdgravs_rotation_keeps_a_torque_free_asymmetric_bodys_angular_momentum() {
    // Distinct moments, ω off every axis, axes off the coordinate axes: over 2000 steps
    // of 0.05 rad each, the space angular momentum and the energy stay what they were to
    // far better than the integrator's tolerance (its error per step is ~(ω·dt)⁶).
    let inertia = Vec3::new(1.0, 2.0, 3.5);
    let turn = Rotation3::from_euler_angles(0.3, -0.2, 0.7);
    let mut rot = Rotation {
        omega: Vec3::new(0.4, 1.0, -0.3),
        axes: [turn * Vec3::x(), turn * Vec3::y(), turn * Vec3::z()],
    };
    let (l0, e0) = (rot.momentum_world(&inertia), rot.twice_energy(&inertia));
    let dt = 0.05;
    let mut accepted = 0;
    for _ in 0..2000 {
        accepted += euler_rigid::integrate(&mut rot, &inertia, &Vec3::zeros(), dt).accepted;
    }
    // The body-frame ω really moved (it tumbles), and one Cash–Karp step did each step.
    assert!((rot.omega - Vec3::new(0.4, 1.0, -0.3)).norm() > 0.1);
    assert_eq!(accepted, 2000);
    let l = rot.momentum_world(&inertia);
    assert!((l - l0).norm() < 1e-6 * l0.norm(), "{l0:?} → {l:?}");
    let e = rot.twice_energy(&inertia);
    assert!((e / e0 - 1.0).abs() < 1e-6, "{e0} → {e}");
    assert!(rot.orthonormality_error() < 1e-6);
    // Over one step of 10, where the tolerance decides the substeps (above the minimum,
    // 0.01): a tolerance 10⁴ times tighter keeps L far better.
    let l_error = |tolerance: f64| {
        let mut r = Rotation {
            omega: Vec3::new(0.4, 1.0, -0.3),
            axes: [turn * Vec3::x(), turn * Vec3::y(), turn * Vec3::z()],
        };
        let cost = euler_rigid::integrate_with(&mut r, &inertia, &Vec3::zeros(), 10.0, tolerance);
        assert!(cost.accepted > 10, "{cost:?}");
        (r.momentum_world(&inertia) - l0).norm() / l0.norm()
    };
    let (coarse, fine) = (l_error(1e-6), l_error(1e-10));
    assert!(coarse < 1e-4 && fine < coarse / 100.0, "{coarse} {fine}");
}

#[test]
fn pkdgravs_wall_move_turns_the_walls_about_the_new_axes_one_after_another() {
    // A sphere-like assembly (equal moments: ω stays, the axes turn at ω), spinning about
    // all three axes: one move turns the walls about the centre of gravity by ω₁dt about
    // the new p̂₁, then ω₂dt about the new p̂₂, then ω₃dt about the new p̂₃; the rotations
    // do not commute, so another order lands elsewhere.
    let text = "wall type rectangle\n origin 1 0 0\n vertex1 1 0 0\n vertex2 0 1 0\n mass 2\n assembly 0\n cog 0.5 0.25 0\n\
        ixj-vec 1 0 0\n iyj-vec 0 1 0\n izj-vec 0 0 1\n rot-vec 3 -2 5\n velocity 0.5 0 -1\n";
    let walls = scene(text);
    let mut a = assemblies(&walls).remove(0);
    a.follow_pkdgrav(&walls);
    let dt = 0.1;
    a.move_pkdgrav(dt);
    let cog = Vec3::new(0.5, 0.25, 0.0) + Vec3::new(0.5, 0.0, -1.0) * dt;
    assert!((a.cog - cog).norm() < 1e-15);
    assert!((a.rotation.omega - Vec3::new(3.0, -2.0, 5.0)).norm() < 1e-12);
    let about = |k: usize| {
        let w = [3.0, -2.0, 5.0][k];
        Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(a.rotation.axes[k]), w * dt)
    };
    let turn = about(2) * about(1) * about(0);
    let origin = Vec3::new(1.0, 0.0, 0.0) + Vec3::new(0.5, 0.0, -1.0) * dt;
    let expected = cog + turn * (origin - cog);
    assert!(
        (a.origin(0) - expected).norm() < 1e-14,
        "{:?} vs {expected:?}",
        a.origin(0)
    );
    let shape = a.shape(&walls[0].shape, 0);
    let (e1, e2) = shape.edges().unwrap();
    assert!((e1 - turn * Vec3::x()).norm() < 1e-14 && (e2 - turn * Vec3::y()).norm() < 1e-14);
    let other = about(0) * about(1) * about(2);
    assert!((a.origin(0) - (cog + other * (origin - cog))).norm() > 1e-3);
    // The contacts see the body-frame rot-vec as it is (pkdgrav's use of it).
    assert_eq!(a.spin(), a.rotation.omega);
}

#[test]
fn gravity_pulls_a_reactive_wall_too() {
    // No particle reaches the plate: it falls freely, exactly as the particles' leapfrog
    // would take it, v = g·t and Δz = −½gt².
    let plate = "wall type rectangle\n origin -1 -1 0\n vertex1 2 0 0\n vertex2 0 2 0\n mass 10\n assembly 0\n cog 0 0 0\n\
        ixj-vec 1 0 0\n iyj-vec 0 1 0\n izj-vec 0 0 2\n";
    let mut s = pkdgrav_settings(0.0);
    s.gravity = Vec3::new(0.0, 0.0, -2.0);
    let steps = 200;
    s.t_end = s.dt * steps as f64;
    s.last_step = Some(steps);
    let out = run(
        &scene(plate),
        vec![particle([50.0, 0.0, 0.0], [0.0; 3])],
        &s,
    );
    assert_eq!(out.steps, steps);
    let a = &out.assemblies[0];
    let t = out.t;
    assert!(
        (a.velocity.z + 2.0 * t).abs() < 1e-12 * 2.0 * t,
        "{:?}",
        a.velocity
    );
    assert!((a.cog.z + t * t).abs() < 1e-9 * t * t, "{:?} at {t}", a.cog);
    assert!((a.origin(0).z - a.cog.z).abs() < 1e-15);
    assert_eq!(a.rotation.omega, Vec3::zeros());
}

#[test]
fn pkdgravs_reactive_plate_keeps_momentum_and_turns() {
    // pkdgrav's motion keeps the total momentum exactly as the other integrators do, and
    // an off-centre strike turns the plate about y (rot-vec, body frame).
    let plate = "wall type rectangle\n origin -1 -1 0\n vertex1 2 0 0\n vertex2 0 2 0\n mass 10\n assembly 0\n cog 0 0 0\n\
        ixj-vec 3 0 0\n iyj-vec 0 3 0\n izj-vec 0 0 6\n";
    let out = run(
        &scene(plate),
        vec![particle([0.5, 0.0, 0.15], [0.0, 0.0, -1.0])],
        &pkdgrav_settings(0.2),
    );
    let a = &out.assemblies[0];
    let total = out.particles[0].particle.vel + a.velocity * a.mass;
    assert!(
        (total - Vec3::new(0.0, 0.0, -1.0)).norm() < 1e-12,
        "{total:?}"
    );
    assert!(a.rotation.omega.y > 0.01, "{:?}", a.rotation.omega);
    // The plate's normal is the turned z axis, as its pzj-vec is, nearly: pkdgrav turns
    // the geometry by the step's final ω·dt and integrates the axes over the step, and
    // the two part while the contact changes ω.
    let (e1, e2) = a.shape(&scene(plate)[0].shape, 0).edges().unwrap();
    let normal = e1.cross(&e2).normalize();
    assert!(normal.x > 0.01, "{normal:?}");
    assert!(
        (normal - a.rotation.axes[2]).norm() < 1e-3 * normal.x,
        "{normal:?} vs {:?}",
        a.rotation.axes[2]
    );
}

#[test]
fn wall_masses_are_ignored_without_dem_walls_react_and_the_run_says_so() {
    // pkdgrav's default build: the plate's mass is read and ignored; the plate moves as
    // its velocity token says (W402), and the particle bounces off it as off any wall.
    let plate = "wall type rectangle\n origin -1 -1 0\n vertex1 2 0 0\n vertex2 0 2 0\n mass 10\n assembly 0\n cog 0 0 0\n\
        velocity 0 0 0.5\n";
    let s = Settings {
        build: Build::default(),
        ..settings(0.2)
    };
    let out = run(
        &scene(plate),
        vec![particle([0.5, 0.0, 0.3], [0.0, 0.0, -1.0])],
        &s,
    );
    assert!(out.assemblies.is_empty());
    let w = out
        .warnings
        .iter()
        .find(|w| matches!(w, Warning::MassesIgnored { .. }))
        .unwrap_or_else(|| panic!("{:?}", out.warnings));
    assert_eq!(w.code(), "W402");
    assert!(w.to_string().contains("DEM_WALLS_REACT"));
    // The bounce off a wall moving up at 0.5 (not off a plate it could push down).
    assert!(
        out.particles[0].particle.vel.z > 0.5,
        "{:?}",
        out.particles[0]
    );
    // With the build, it is reactive and says nothing.
    let out = run(
        &scene(plate),
        vec![particle([0.5, 0.0, 0.3], [0.0, 0.0, -1.0])],
        &settings(0.2),
    );
    assert_eq!(out.assemblies.len(), 1);
    assert!(!out.warnings.iter().any(|w| w.code() == "W402"));
}

#[test]
fn a_reactive_walls_spin_seen_by_the_rolling_springs_depends_on_its_type() {
    // docs/pkdgrav-physics.md §10: the face normal's component for triangles and
    // rectangles, orient's for disks and cylinders, all of it for shells.
    use walls_sim::dynamics::reactive::relative_spin;
    let w = Vec3::new(1.0, 2.0, 3.0);
    let shape = |text: &str| scene(text).remove(0).shape;
    let rect = shape("wall type rectangle\n origin 0 0 0\n vertex1 2 0 0\n vertex2 0 3 0\n");
    assert_eq!(relative_spin(&rect, &w), Vec3::new(0.0, 0.0, 3.0));
    let tri = shape("wall type triangle\n origin 0 0 0\n vertex1 0 1 0\n vertex2 0 0 1\n");
    assert_eq!(relative_spin(&tri, &w), Vec3::new(1.0, 0.0, 0.0));
    let disk = shape("wall type disk\n orient 0 1 0\n radius 1\n");
    assert_eq!(relative_spin(&disk, &w), Vec3::new(0.0, 2.0, 0.0));
    let cyl = shape("wall type cylinder-finite\n orient 1 0 0\n radius 1\n length 2\n");
    assert_eq!(relative_spin(&cyl, &w), Vec3::new(1.0, 0.0, 0.0));
    let shell = shape("wall type shell\n radius 1\n");
    assert_eq!(relative_spin(&shell, &w), w);
}
