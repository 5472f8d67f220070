//! The plan: which parts of the model a scene needs, why, and that leaving the others
//! out does not change the answer.

use nalgebra::Vector3;
use walls_model::{Options, Scene, analyze};
use walls_sim::input::Particle;
use walls_sim::plan::{Plan, parts};
use walls_sim::run::{Method, Planning, Settings, run};
use walls_sim::setup;

type Vec3 = Vector3<f64>;

fn scene(text: &str) -> Scene {
    let parsed = walls_syntax::parse(text);
    assert!(parsed.diagnostics.is_empty(), "{:?}", parsed.diagnostics);
    analyze(&parsed.tree, &Options::default()).scene
}

fn settings(k_n: f64, t_end: f64) -> Settings {
    Settings {
        gravity: Vec3::new(0.0, 0.0, -1.0),
        ..Settings::new(1e-4, t_end, setup::default_material(k_n))
    }
}

fn used(scene: &Scene, ps: &[Particle], s: &Settings) -> Vec<&'static str> {
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
    let ps = setup::default_particles(&floor);
    let s = settings(1e4, 1.0);
    assert_eq!(used(&floor, &ps, &s), ["uniform gravity"]);
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
    let ps = setup::default_particles(&busy);
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
        }
    );
    let reason = |name: &str| list.iter().find(|p| p.name == name).unwrap().reason.clone();
    assert_eq!(reason("moving walls"), "walls 0 move");
    assert_eq!(reason("sticky walls"), "walls 1 have epsn 0");
    assert_eq!(reason("death walls"), "walls 2 have a negative epsn");
    // In HSDEM the disk's rim calls for edge detection.
    let hard = Settings {
        method: Method::Hard,
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
            setup::default_particles(&scene("wall type plane\n")),
        ),
        (
            scene("wall type plane\nwall type plane\n  origin 0 0 -0.2\n"),
            setup::packed(&scene("wall type plane\n"), 200, 0.02),
        ),
    ] {
        let k_n = setup::default_k_n(&floor, &ps, &Vec3::new(0.0, 0.0, -1.0));
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
