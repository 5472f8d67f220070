//! The evaluator's speed on the sample scene that ships with the project
//! (`examples/sample.walls`: a plane, a disk, a finite cylinder, a shell and a
//! rectangle):
//! - particle–wall contact checks per second (the nearest point of every wall to every
//!   particle), against the target of 10⁷ per core;
//! - particle-steps per second of a whole SSDEM run.
//!
//! Run with `cargo bench -p walls-sim --bench contacts`; figures in docs/performance.md.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use nalgebra::Vector3;
use std::hint::black_box;
use walls_model::{Options, Scene, analyze};
use walls_sim::geometry::Shape;
use walls_sim::input::Particle;
use walls_sim::run::{Settings, default_dt, run};
use walls_sim::setup;

type Vec3 = Vector3<f64>;

fn scene() -> Scene {
    let text = include_str!("../../../examples/sample.walls");
    analyze(&walls_syntax::parse(text).tree, &Options::default()).scene
}

/// `n` particles spread through the scene's box by a fixed low-discrepancy sequence.
fn particles(scene: &Scene, n: usize) -> Vec<Particle> {
    let (lo, hi) = setup::bounds(scene);
    let frac = |i: usize, a: f64| (i as f64 * a).fract();
    (0..n)
        .map(|i| {
            let u = Vec3::new(
                frac(i, 0.754_877_666),
                frac(i, 0.569_840_291),
                frac(i, 0.430_159_709),
            );
            Particle {
                mass: 1e-3,
                radius: 0.01,
                pos: lo + (hi - lo).component_mul(&u),
                vel: Vec3::zeros(),
                spin: Vec3::zeros(),
                color: 3,
                index: i as i32,
            }
        })
        .collect()
}

fn contacts(c: &mut Criterion) {
    let scene = scene();
    let shapes: Vec<Shape> = scene
        .walls
        .iter()
        .map(|w| Shape::of(w, w.vector(walls_keywords::Keyword::Origin)))
        .collect();
    let points: Vec<Vec3> = particles(&scene, 10_000).iter().map(|p| p.pos).collect();
    let mut group = c.benchmark_group("sample scene");
    group.throughput(Throughput::Elements((points.len() * shapes.len()) as u64));
    group.bench_function("contact checks", |b| {
        b.iter(|| {
            let mut touching = 0usize;
            for p in &points {
                for s in &shapes {
                    touching += usize::from(s.nearest(black_box(p)).distance < 0.01);
                }
            }
            touching
        })
    });
    // Particles clear of every wall, so that the run is not stopped by a deep overlap.
    let ps: Vec<Particle> = particles(&scene, 12_000)
        .into_iter()
        .filter(|p| {
            shapes
                .iter()
                .all(|s| s.nearest(&p.pos).distance > 2.0 * p.radius)
        })
        .take(10_000)
        .collect();
    assert_eq!(ps.len(), 10_000);
    let steps = 20;
    let k_n = 1e3;
    let dt = default_dt(&ps, k_n);
    let settings = Settings {
        dt,
        t_end: dt * steps as f64,
        gravity: Vec3::new(0.0, 0.0, -1.0),
        material: setup::default_material(k_n),
    };
    group.throughput(Throughput::Elements((ps.len() * steps) as u64));
    group.sample_size(10);
    group.bench_function("SSDEM particle-steps", |b| {
        b.iter(|| {
            let out = run(&scene, black_box(ps.clone()), &settings);
            assert_eq!(out.steps, steps as u64, "{:?}", out.warnings);
            out.steps
        })
    });
    group.finish();
}

criterion_group!(benches, contacts);
criterion_main!(benches);
