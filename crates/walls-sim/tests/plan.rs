//! The plan: which parts of the model a scene needs, why, and that leaving the others
//! out does not change the answer.

use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_geometry::Wall;
use walls_sim::run::defaults;
use walls_sim::run::plan::{Plan, parts};
use walls_sim::run::{ContactModel, Planning, Settings, run};

use walls_test_support::scene;
use walls_test_support::scenes::packed;

type Vec3 = Vector3<f64>;

fn settings(k_n: f64, t_end: f64) -> Settings {
    Settings {
        gravity: Vec3::new(0.0, 0.0, -1.0),
        ..Settings::new(1e-4, t_end, defaults::default_material(k_n))
    }
}

fn used(scene: &[Wall], ps: &[Particle], s: &Settings) -> Vec<&'static str> {
    parts(scene, ps, s)
        .1
        .into_iter()
        .filter(|p| p.used)
        .map(|p| p.name)
        .collect()
}

#[test]
fn a_static_frictionless_floor_needs_only_gravity_and_springs() {
    let floor = scene("wall type plane\n");
    let ps = defaults::default_particles(&floor);
    let s = settings(1e4, 1.0);
    assert_eq!(used(&floor, &ps, &s), ["pkdgrav build", "uniform gravity"]);
    // The nine particles fall side by side onto a frictionless floor: proved never to
    // meet. With friction they could be pushed sideways, so they might.
    let mut rough = s.clone();
    rough.material.mu_s = 0.3;
    assert!(used(&floor, &ps, &rough).contains(&"particle-particle contacts (cell grid)"));
    // Nor when one moves sideways.
    let mut sideways = ps.clone();
    sideways[0].vel.x = 0.1;
    assert!(used(&floor, &sideways, &s).contains(&"particle-particle contacts (cell grid)"));
}

#[test]
fn each_part_is_needed_for_its_reason() {
    let busy = scene(
        "wall type plane\n  osc-ampl 0.01\n  osc-freq 30\n  mu_r 0.1\n\
         wall type cylinder-infinite\n  radius 1\n  ang-speed 2\n  epsn 0\n\
         wall type disk\n  origin 0 0 3\n  epsn -1\n",
    );
    let ps = defaults::default_particles(&busy);
    let mut s = settings(1e4, 1.0);
    s.material.mu_t = 0.2;
    let (plan, list) = parts(&busy, &ps, &s);
    assert_eq!(
        plan,
        Plan {
            moving_walls: true,
            spin: true,
            sliding_friction: false,
            rolling: true,
            twisting: true,
            edges: false,
            particle_contacts: true,
            wall_index: false,
            reactive: false,
        }
    );
    let reason = |name: &str| list.iter().find(|p| p.name == name).unwrap().reason.clone();
    assert_eq!(reason("moving walls"), "walls 0 move");
    assert_eq!(reason("sticky walls"), "walls 1 have epsn 0");
    assert_eq!(reason("death walls"), "walls 2 have a negative epsn");
    // In HSDEM the disk's rim calls for edge detection.
    let hard = Settings {
        build: walls_sim::build::Build::default_for(ContactModel::Hsdem),
        ..s
    };
    assert!(parts(&busy, &ps, &hard).0.edges);
}

#[test]
fn leaving_out_unneeded_parts_does_not_change_the_answer() {
    // A layer resting and a crowd falling on a static frictionless floor: the planned run
    // (no tangential springs, walls placed once, no particle contacts where they are
    // proved impossible) and the run with every part agree to rounding.
    for (floor, ps) in [
        (
            scene("wall type plane\n"),
            defaults::default_particles(&scene("wall type plane\n")),
        ),
        (
            scene("wall type plane\nwall type plane\n  origin 0 0 -0.2\n"),
            packed(&scene("wall type plane\n"), 200, 0.02),
        ),
    ] {
        let k_n = defaults::default_k_n(&floor, &ps, &Vec3::new(0.0, 0.0, -1.0));
        let s = Settings {
            dt: walls_sim::run::default_dt(&ps, k_n),
            ..settings(k_n, 0.5)
        };
        let planned = run(&floor, ps.clone(), &s);
        let all = run(
            &floor,
            ps.clone(),
            &Settings {
                planning: Planning::Everything,
                ..s.clone()
            },
        );
        assert_eq!(planned.events.len(), all.events.len());
        for (a, b) in planned.particles.iter().zip(&all.particles) {
            assert!(
                (a.particle.pos - b.particle.pos).norm() < 1e-9
                    && (a.particle.vel - b.particle.vel).norm() < 1e-9,
                "{a:?} vs {b:?}"
            );
        }
    }
}

/// A closed box of 6 × 5 × 5 = 150 square tiles around the origin, side 2.
fn tiled_box() -> Vec<Wall> {
    let mut text = String::new();
    let h = 0.4;
    for k in 0..5 {
        for l in 0..5 {
            let (a, b) = (-1.0 + h * k as f64, -1.0 + h * l as f64);
            for (o, e1, e2) in [
                ([a, b, -1.0], [h, 0.0, 0.0], [0.0, h, 0.0]),
                ([a, b, 1.0], [h, 0.0, 0.0], [0.0, h, 0.0]),
                ([a, -1.0, b], [h, 0.0, 0.0], [0.0, 0.0, h]),
                ([a, 1.0, b], [h, 0.0, 0.0], [0.0, 0.0, h]),
                ([-1.0, a, b], [0.0, h, 0.0], [0.0, 0.0, h]),
                ([1.0, a, b], [0.0, h, 0.0], [0.0, 0.0, h]),
            ] {
                text += &format!(
                    "wall type rectangle\n  origin {} {} {}\n  vertex1 {} {} {}\n  vertex2 {} {} {}\n  epsn 0.8\n  epst 1\n",
                    o[0], o[1], o[2], e1[0], e1[1], e1[2], e2[0], e2[1], e2[2]
                );
            }
        }
    }
    scene(&text)
}

#[test]
fn the_wall_index_finds_the_same_contacts_as_looking_at_every_wall() {
    // Particles rattling in a box of 150 tiles, in both models: with the index and
    // without it, the same events, positions and velocities to the last bit.
    let tiles = tiled_box();
    let ps: Vec<Particle> = (0..40)
        .map(|i| {
            let f = |a: f64| ((i as f64 * a).fract() - 0.5) * 1.6;
            Particle {
                mass: 1e-3,
                radius: 0.05,
                pos: Vec3::new(f(0.754_877_666), f(0.569_840_291), f(0.430_159_709)),
                vel: Vec3::new(f(0.31), f(0.57), f(0.77)) * 3.0,
                spin: Vec3::zeros(),
                color: 3,
                index: i,
            }
        })
        .filter(|p| p.pos.amax() < 0.9)
        .collect();
    for method in [ContactModel::Ssdem, ContactModel::Hsdem] {
        let base = Settings {
            build: walls_sim::build::Build::default_for(method),
            dt: if method == ContactModel::Ssdem {
                2e-5
            } else {
                1e-3
            },
            ..settings(1e4, 0.3)
        };
        let with = parts(&tiles, &ps, &base).0;
        assert!(with.wall_index, "150 tiles call for the index");
        let runs = with_and_without_index(&tiles, &ps, &base, with);
        assert!(
            runs[0].events.len() > 10,
            "{method:?}: {}",
            runs[0].events.len()
        );
        assert_eq!(runs[0].events, runs[1].events, "{method:?}");
        assert_eq!(runs[0].particles, runs[1].particles, "{method:?}");
    }
}

#[test]
fn the_walls_near_each_particle_found_through_the_index_follow_a_moving_mesh() {
    // A floor of 10 × 10 triangle pairs oscillating up and down under particles that
    // fall on it and bounce (SSDEM, pkdgrav's step): the walls near each particle, found
    // through the index at each rebuild, give the same run to the last bit as looking
    // at every wall; the floor's move rebuilds them.
    let mut text = String::new();
    let h = 0.2;
    for k in 0..10 {
        for l in 0..10 {
            let (a, b) = (-1.0 + h * k as f64, -1.0 + h * l as f64);
            for (o, v1, v2) in [
                ([a, b], [h, 0.0], [0.0, h]),
                ([a + h, b + h], [-h, 0.0], [0.0, -h]),
            ] {
                text += &format!(
                    "wall type triangle\n  origin {} {} 0\n  vertex1 {} {} 0\n  vertex2 {} {} 0\n  \
                     epsn 0.8\n  epst 1\n  osc-ampl 0.05\n  osc-freq 40\n  osc-vec 0 0 1\n",
                    o[0], o[1], v1[0], v1[1], v2[0], v2[1]
                );
            }
        }
    }
    let floor = scene(&text);
    let ps: Vec<Particle> = (0..60)
        .map(|i| {
            let f = |a: f64| ((i as f64 * a).fract() - 0.5) * 1.6;
            Particle {
                mass: 1e-3,
                radius: 0.05,
                pos: Vec3::new(
                    f(0.754_877_666),
                    f(0.569_840_291),
                    0.1 + 0.3 * f(0.43).abs(),
                ),
                vel: Vec3::new(f(0.31), f(0.57), -1.0),
                spin: Vec3::zeros(),
                color: 3,
                index: i,
            }
        })
        .collect();
    let base = Settings {
        dt: 2e-5,
        ..settings(1e4, 0.1)
    };
    let with = parts(&floor, &ps, &base).0;
    assert!(with.wall_index && with.moving_walls, "{with:?}");
    let runs = with_and_without_index(&floor, &ps, &base, with);
    assert!(runs[0].events.len() > 10, "{}", runs[0].events.len());
    assert_eq!(runs[0].events, runs[1].events);
    assert_eq!(runs[0].particles, runs[1].particles);
}

/// The runs of `ps` against `walls` with `settings` and `plan`, with the wall index and
/// without it.
fn with_and_without_index(
    walls: &[Wall],
    ps: &[Particle],
    settings: &Settings,
    plan: Plan,
) -> Vec<walls_sim::run::Outcome> {
    [true, false]
        .into_iter()
        .map(|on| {
            let s = Settings {
                planning: Planning::Exactly(Plan {
                    wall_index: on,
                    ..plan
                }),
                ..settings.clone()
            };
            run(walls, ps.to_vec(), &s)
        })
        .collect()
}
