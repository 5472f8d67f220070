//! How the cost of finding the walls a particle touches grows with the number of walls:
//! every wall asked for its nearest point, against the wall index
//! ([`walls_sim::WallIndex`]: candidates from a hierarchy of boxes, then the nearest
//! point of each candidate).
//!
//! The walls are a closed sphere hull of radius 1 in N triangles (N = 100 to 100,000:
//! m rings of 2m quads, 4m² triangles), the particles 1,000 of radius 0.01 just inside
//! it, each 0.005 to 0.015 under a random point of a random triangle (about half of
//! them touching). A query finds every wall within the radius. Writes
//! `docs/charts/wall_scaling.{csv,svg,png}` (nanoseconds per particle query, log–log,
//! with a dashed line ∝ N through the scan's points) and prints the table with the
//! index's build time.

use nalgebra::Vector3;
use std::hint::black_box;
use std::time::{Duration, Instant};
use walls_charts::{Chart, Mark, Series};
use walls_geometry::Shape;
use walls_geometry::shape::Triangle;
use walls_sim::WallIndex;
use walls_test_support::scene_uncapped as scene;
use walls_test_support::scenes::sphere_hull;

type Vec3 = Vector3<f64>;

/// The particles' radius, which is the reach of every query.
const RADIUS: f64 = 0.01;

/// How many particles query.
const PARTICLES: usize = 1000;

fn main() -> std::io::Result<()> {
    let mut scan = Vec::new();
    let mut indexed = Vec::new();
    println!(
        "{:>7} {:>14} {:>14} {:>8} {:>11} {:>11} {:>12}",
        "walls",
        "scan ns/query",
        "index ns/query",
        "speedup",
        "candidates",
        "build ms",
        "build/1000 ns"
    );
    for target in [100, 300, 1_000, 3_000, 10_000, 30_000, 100_000] {
        let m = (target as f64 / 4.0).sqrt().round() as usize;
        let scene = scene(&sphere_hull(m));
        let n = scene.len();
        let origins: Vec<Vec3> = scene
            .iter()
            .map(|w| w.motion.position(0.0).expect("a finite origin"))
            .collect();
        let shapes: Vec<Shape> = scene
            .iter()
            .zip(&origins)
            .map(|(w, o)| w.shape.at(*o))
            .collect();
        let particles = particles(&shapes);

        let (build, index) = {
            let mut best = Duration::MAX;
            let mut index = None;
            let start = Instant::now();
            while index.is_none() || start.elapsed() < Duration::from_millis(300) {
                let t = Instant::now();
                index = Some(black_box(WallIndex::new(&scene)));
                best = best.min(t.elapsed());
            }
            (best, index.expect("built at least once"))
        };

        let touching_scan = |p: &Vec3| {
            shapes
                .iter()
                .filter(|s| s.nearest(p).distance <= RADIUS)
                .count()
        };
        let touching_index = |p: &Vec3| {
            let mut k = 0;
            index.for_each_candidate(p, RADIUS, &origins, |w| {
                k += usize::from(shapes[w].nearest(p).distance <= RADIUS);
            });
            k
        };
        // Both find the same walls.
        let found: Vec<usize> = particles.iter().map(touching_scan).collect();
        assert_eq!(
            found,
            particles.iter().map(touching_index).collect::<Vec<_>>()
        );
        let candidates: usize = particles
            .iter()
            .map(|p| {
                let mut k = 0;
                index.for_each_candidate(p, RADIUS, &origins, |_| k += 1);
                k
            })
            .sum();

        let scan_ns = ns_per_query(&particles, touching_scan);
        let index_ns = ns_per_query(&particles, touching_index);
        let build_ms = build.as_secs_f64() * 1e3;
        println!(
            "{n:>7} {scan_ns:>14.0} {index_ns:>14.0} {:>8.0} {:>11.1} {build_ms:>11.3} {:>12.0}",
            scan_ns / index_ns,
            candidates as f64 / PARTICLES as f64,
            build.as_secs_f64() * 1e9 / PARTICLES as f64,
        );
        let touching = found.iter().filter(|k| **k > 0).count();
        assert!(touching > PARTICLES / 4, "{touching} particles touch");
        scan.push((n as f64, scan_ns));
        indexed.push((n as f64, index_ns));
    }
    // A line ∝ N through the scan's points (their geometric mean of ns per wall).
    let per_wall = (scan.iter().map(|(n, y)| (y / n).ln()).sum::<f64>() / scan.len() as f64).exp();
    let reference = vec![
        (scan[0].0, per_wall * scan[0].0),
        (scan[scan.len() - 1].0, per_wall * scan[scan.len() - 1].0),
    ];
    walls_charts::write(
        &walls_charts::out_dir(),
        &Chart {
            name: "wall_scaling".into(),
            title: "Finding the walls a particle touches, sphere hull of N triangles".into(),
            x_label: "walls N".into(),
            y_label: "ns per particle".into(),
            log_x: true,
            log_y: true,
        },
        &[
            Series::new("every wall", scan, Mark::Line),
            Series::new("wall index", indexed, Mark::Line),
            Series::new(
                format!("∝ N ({per_wall:.1} ns a wall)"),
                reference,
                Mark::Dashed,
            ),
        ],
    )
}

/// Nanoseconds per particle of `query` over every particle: the fastest of seven
/// measurements, each of rounds over every particle repeated for at least 0.1 s, after
/// one round to warm up (the fastest, as other work on the machine only slows it).
fn ns_per_query(particles: &[Vec3], query: impl Fn(&Vec3) -> usize) -> f64 {
    let round = || particles.iter().map(|p| query(black_box(p))).sum::<usize>();
    black_box(round());
    (0..7)
        .map(|_| {
            let start = Instant::now();
            let mut rounds = 0u32;
            while rounds == 0 || start.elapsed() < Duration::from_millis(100) {
                black_box(round());
                rounds += 1;
            }
            start.elapsed().as_secs_f64() * 1e9 / (f64::from(rounds) * particles.len() as f64)
        })
        .fold(f64::INFINITY, f64::min)
}

/// The particles: each under a random point of a random triangle, 0.5 to 1.5 radii
/// inwards along its normal (a fixed seed: the same every run).
fn particles(shapes: &[Shape]) -> Vec<Vec3> {
    let mut state = 0x5eed_u64;
    let mut uniform = move || {
        // splitmix64
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..PARTICLES)
        .map(|_| {
            let k = ((uniform() * shapes.len() as f64) as usize).min(shapes.len() - 1);
            let Shape::Triangle(Triangle { origin, e1, e2 }) = &shapes[k] else {
                unreachable!("the hull is triangles")
            };
            let (mut a, mut b) = (uniform(), uniform());
            if a + b > 1.0 {
                (a, b) = (1.0 - a, 1.0 - b);
            }
            let q = origin + e1 * a + e2 * b;
            let mut n = e1.cross(e2).normalize();
            if n.dot(&q) > 0.0 {
                n = -n;
            }
            q + n * (RADIUS * (0.5 + uniform()))
        })
        .collect()
}
