//! The evaluator's speed on the sample scene that ships with the project
//! (`examples/sample.walls`: a plane, a disk, a finite cylinder, a shell and a
//! rectangle):
//! - particle–wall contact checks per second (the nearest point of every wall to every
//!   particle), against the target of 10⁷ per core;
//! - particle-steps per second of a whole SSDEM run;
//! - the plan's saving: a static plane run with the parts it needs and with every part
//!   forced on (group "plan");
//! - and, apart from the scene, the particle–particle broad phase: building the cell grid
//!   and visiting every overlapping pair, per particle, for 10⁴ and 10⁵ spheres of radius
//!   0.01 at random in a box at volume fraction 0.3 (group "grid").
//!
//! Run with `cargo bench -p walls-sim --bench contacts`; figures in docs/performance.md.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use nalgebra::Vector3;
use std::hint::black_box;
use walls_geometry::{Shape, Wall};
use walls_sim::broad::grid::CellGrid;
use walls_sim::run::defaults;
use walls_sim::run::{Planning, Settings, default_dt, run};
use walls_test_support::scenes::packed;

type Vec3 = Vector3<f64>;

fn scene() -> Vec<Wall> {
    walls_test_support::scene(include_str!("../../../examples/sample.walls"))
}

fn contacts(c: &mut Criterion) {
    let scene = scene();
    let shapes: Vec<Shape> = scene.iter().map(|w| w.shape.clone()).collect();
    let points: Vec<Vec3> = packed(&scene, 10_000, 0.01).iter().map(|p| p.pos).collect();
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
    let ps = packed(&scene, 10_000, 0.01);
    assert_eq!(ps.len(), 10_000);
    let steps = 20;
    let k_n = 1e3;
    let dt = default_dt(&ps, k_n);
    let settings = Settings {
        gravity: Vec3::new(0.0, 0.0, -1.0),
        ..Settings::new(dt, dt * steps as f64, defaults::default_material(k_n))
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

/// `n` spheres of radius `r` uniformly at random (a fixed SplitMix64 sequence, overlaps
/// allowed) in a cube sized for volume fraction `phi`.
fn random_box(n: usize, r: f64, phi: f64) -> Vec<Vec3> {
    let side = (n as f64 * 4.0 / 3.0 * std::f64::consts::PI * r.powi(3) / phi).cbrt();
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut uniform = move || {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        (z ^ (z >> 31)) as f64 / u64::MAX as f64
    };
    (0..n)
        .map(|_| Vec3::new(uniform(), uniform(), uniform()) * side)
        .collect()
}

fn grid(c: &mut Criterion) {
    let mut group = c.benchmark_group("grid");
    for n in [10_000, 100_000] {
        let positions = random_box(n, 0.01, 0.3);
        let radii = vec![0.01; n];
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function(format!("build and visit pairs, {n} particles"), |b| {
            b.iter(|| {
                let grid = CellGrid::new(black_box(&positions), black_box(&radii));
                let mut pairs = 0usize;
                grid.for_each_pair(|_, _| pairs += 1);
                pairs
            })
        });
    }
    group.finish();
}

/// A layer of `n` particles of radius `r` and unit density resting on the plane z = 0
/// (at the overlap where the spring `k_n` carries their weight under gravity 1), 3r apart.
fn resting_layer(n: usize, r: f64, k_n: f64) -> Vec<walls_geometry::Particle> {
    let side = (n as f64).sqrt().ceil() as usize;
    let mass = 4.0 / 3.0 * std::f64::consts::PI * r.powi(3);
    (0..n)
        .map(|i| walls_geometry::Particle {
            mass,
            radius: r,
            pos: Vec3::new(
                (i % side) as f64 * 3.0 * r,
                (i / side) as f64 * 3.0 * r,
                r - mass / k_n,
            ),
            vel: Vec3::zeros(),
            spin: Vec3::zeros(),
            color: 3,
            index: i as i32,
        })
        .collect()
}

/// The plan's saving: 2,000 particles resting on a static plane, run with the parts the
/// scene needs and with every part forced on (issue 8: at least 2×).
fn plan(c: &mut Criterion) {
    let scene = walls_test_support::scene("wall type plane\n");
    let k_n = 1e3;
    let ps = resting_layer(2_000, 0.01, k_n);
    let dt = default_dt(&ps, k_n);
    let steps = 200;
    let needed = Settings {
        gravity: Vec3::new(0.0, 0.0, -1.0),
        ..Settings::new(dt, dt * steps as f64, defaults::default_material(k_n))
    };
    let everything = Settings {
        planning: Planning::Everything,
        ..needed.clone()
    };
    let mut group = c.benchmark_group("plan");
    group.sample_size(10);
    group.throughput(Throughput::Elements((ps.len() * steps) as u64));
    for (how, settings) in [("planned", &needed), ("every part", &everything)] {
        group.bench_function(
            format!("2,000 particles resting on a static plane, {how}"),
            |b| b.iter(|| run(&scene, black_box(ps.clone()), settings).steps),
        );
    }
    group.finish();
}

criterion_group!(benches, contacts, grid, plan);
criterion_main!(benches);
