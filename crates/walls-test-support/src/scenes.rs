//! Particles and walls for tests and benchmarks: the ball most run tests throw, a
//! deterministic crowd packed into a scene, and a deterministic many-walled hull.
//! Benchmarks and tests depend on their exact values: change them only on purpose.

use nalgebra::Vector3;
use walls_geometry::{Particle, Wall, scene_bounds};

type Vec3 = Vector3<f64>;

/// A ball of mass 1 and radius 0.1 at `pos` moving at `vel`, not spinning, drawn in
/// ssdraw's blue.
pub fn ball(pos: [f64; 3], vel: [f64; 3]) -> Particle {
    Particle {
        mass: 1.0,
        radius: 0.1,
        pos: Vec3::from(pos),
        vel: Vec3::from(vel),
        spin: Vec3::zeros(),
        color: 3,
        index: 0,
    }
}

/// `n` particles of radius `r` and unit density at rest, packed into the bottom of the
/// scene's box: the lowest sites of a cubic lattice of spacing 2.2r (gaps of 0.2r), each
/// clear of every wall by its diameter, layer by layer. None overlaps another, and the
/// same scene gives the same pack: a deterministic crowd for benchmarks and stress runs.
/// Fewer than `n` when the box has no room.
pub fn packed(walls: &[Wall], n: usize, r: f64) -> Vec<Particle> {
    let (lo, hi) = scene_bounds(walls, &[]);
    let spacing = 2.2 * r;
    let count = |axis: usize| ((hi[axis] - lo[axis]) / spacing).floor().max(0.0) as usize;
    let (nx, ny, nz) = (count(0), count(1), count(2));
    (0..nx * ny * nz)
        .map(|k| {
            let (i, j, l) = (k % nx, (k / nx) % ny, k / (nx * ny));
            lo + Vec3::new(i as f64 + 0.5, j as f64 + 0.5, l as f64 + 0.5) * spacing
        })
        .filter(|p| walls.iter().all(|w| w.shape.nearest(p).distance > 2.0 * r))
        .take(n)
        .enumerate()
        .map(|(i, pos)| Particle::at_rest(r, pos, i))
        .collect()
}

/// A closed sphere of radius 1 in 4m² triangles: m + 1 rings of 2m quads (the polar
/// ones triangles), as walls-file text: a deterministic many-walled scene, like a
/// spacecraft hull, for benchmarks and tests of the wall index.
pub fn sphere_hull(m: usize) -> String {
    let (rings, around) = (m + 1, 2 * m);
    let vertex = |i: usize, j: usize| {
        let theta = std::f64::consts::PI * i as f64 / rings as f64;
        let phi = std::f64::consts::TAU * j as f64 / around as f64;
        Vec3::new(
            theta.sin() * phi.cos(),
            theta.sin() * phi.sin(),
            theta.cos(),
        )
    };
    let v = |p: &Vec3| format!("{} {} {}", p.x, p.y, p.z);
    let mut text = String::new();
    let mut triangle = |a: Vec3, b: Vec3, c: Vec3| {
        text.push_str(&format!(
            "wall\n type triangle\n origin {}\n vertex1 {}\n vertex2 {}\n",
            v(&a),
            v(&(b - a)),
            v(&(c - a))
        ));
    };
    for i in 0..rings {
        for j in 0..around {
            let (a, b) = (vertex(i, j), vertex(i, j + 1));
            let (c, d) = (vertex(i + 1, j), vertex(i + 1, j + 1));
            if i > 0 {
                triangle(a, c, b);
            }
            if i + 1 < rings {
                triangle(b, c, d);
            }
        }
    }
    text
}

/// The peer benchmark's box (docs/performance.md, "Against LAMMPS and LIGGGHTS"): `n`
/// spheres of radius 1 mm and 2500 kg/m³ on a square lattice of spacing 2.2 mm about
/// 1.25 times as tall as it is wide, the lowest layer 1.1 mm above the floor, each with
/// a velocity of components within ±`speed`/2 that differs from sphere to sphere; and
/// the five planes around them (the floor z = 0 and four sides). Deterministic.
pub fn box_of_spheres(n: usize, speed: f64) -> (Vec<Wall>, Vec<Particle>) {
    let (r, spacing): (f64, f64) = (1e-3, 2.2e-3);
    let side = (1..).find(|s| s * s * (5 * s / 4) >= n).expect("a side");
    let width = side as f64 * spacing;
    let mut walls = String::from("wall type plane\n  origin 0 0 0\n  orient 0 0 1\n");
    for (x, y, nx, ny) in [
        (0.0, 0.0, 1, 0),
        (width, 0.0, -1, 0),
        (0.0, 0.0, 0, 1),
        (0.0, width, 0, -1),
    ] {
        walls += &format!("wall type plane\n  origin {x} {y} 0\n  orient {nx} {ny} 0\n");
    }
    let mass = 2500.0 * 4.0 / 3.0 * std::f64::consts::PI * r.powi(3);
    let particles = (0..n)
        .map(|k| {
            let (i, j, l) = (k % side, (k / side) % side, k / (side * side));
            let at = Vec3::new(
                (i as f64 + 0.5) * spacing,
                (j as f64 + 0.5) * spacing,
                1.1 * r + l as f64 * spacing,
            );
            let part = |a: f64| ((k as f64 * a).fract() - 0.5) * speed;
            Particle {
                mass,
                vel: Vec3::new(
                    part(0.754_877_666),
                    part(0.569_840_291),
                    part(0.430_159_709),
                ),
                ..Particle::at_rest(r, at, k)
            }
        })
        .collect();
    (crate::scene(&walls), particles)
}
