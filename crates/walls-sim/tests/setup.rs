//! The defaults of a run without particles or parameters: the embedded particles fall
//! onto the scene, and the derived spring keeps overlaps near 1 % of the radius, well
//! under pkdgrav's 3 % warning.

use nalgebra::Vector3;
use walls_geometry::scene_bounds;
use walls_sim::run::defaults;
use walls_sim::run::{Settings, default_dt, run};
use walls_test_support::scene;

#[test]
fn embedded_particles_fall_onto_the_scene_without_overlap_warnings() {
    let scene = scene("wall type plane\nwall type disk origin 0 0 0.5 radius 2\n");
    let (lo, hi) = scene_bounds(&scene, &[]);
    let particles = defaults::default_particles(&scene);
    assert_eq!(particles.len(), 9);
    assert_eq!(
        particles,
        defaults::default_particles(&scene),
        "deterministic"
    );
    for p in &particles {
        assert!(p.pos.z - p.radius > hi.z, "{p:?} starts above the scene");
        assert!(p.pos.x > lo.x && p.pos.x < hi.x && p.pos.y > lo.y && p.pos.y < hi.y);
    }
    let gravity = Vector3::new(0.0, 0.0, -1.0);
    let k_n = defaults::default_k_n(&scene, &particles, &gravity);
    let settings = Settings {
        gravity,
        ..Settings::new(
            default_dt(&particles, k_n),
            // Half the default duration: one and a half free falls, enough to land.
            defaults::default_duration(&scene, &particles, &gravity) / 2.0,
            defaults::default_material(k_n),
        )
    };
    let out = run(&scene, particles.clone(), &settings);
    assert!(out.warnings.is_empty(), "{:?}", out.warnings);
    // Every particle lands on the disk (at z = 0.5) and bounces at least once.
    for (i, s) in out.particles.iter().enumerate() {
        assert!(out.events.iter().any(|e| e.particle == i && e.wall == 1));
        assert!(s.alive && s.particle.pos.z > 0.5, "{s:?}");
    }
    assert!(out.energy.1 < out.energy.0, "restitution 0.8 loses energy");
}
