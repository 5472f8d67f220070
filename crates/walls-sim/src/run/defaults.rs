//! What a run needs when the user does not say: the embedded particles, and material
//! values, timestep and duration derived from the scene (docs/evaluator.md).
//!
//! * Particles: nine, on a 3 × 3 grid over the middle of the scene, one scene-size above
//!   its top, with radius 2 % of the scene's size and unit density: deterministic, so
//!   that the same file gives the same run.
//! * Gravity: 1 along −z (pkdgrav units) for the embedded particles, none otherwise.
//! * Material: ε_n 0.8, ε_t 1, μ_s = μ_r = μ_t = 0, and k_n stiff enough that the fastest expected
//!   impact (the larger of the fastest particle and free fall over the scene) overlaps
//!   by 1 % of the smallest radius; k_t = 2/7 k_n.
//! * HSDEM timestep: collisions are exact within a step, but a particle's path in a step
//!   is straight, so under gravity it strays from its parabola by up to g·dt²/8: the
//!   default keeps that below 0.1 % of the smallest radius (without gravity, 100 steps
//!   over the run).
//! * Duration: three free-fall times over the scene (or three crossings at the fastest
//!   speed without gravity).

use crate::run::ParticleMaterial;
use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_geometry::{Wall, scene_bounds as bounds};

type Vec3 = Vector3<f64>;

/// The embedded particles for the scene of `walls`.
pub fn default_particles(walls: &[Wall]) -> Vec<Particle> {
    let (lo, hi) = bounds(walls);
    let size = (hi - lo).max();
    let r = 0.02 * size;
    let centre = (lo + hi) / 2.0;
    let mut out = Vec::new();
    for i in -1..=1 {
        for j in -1..=1 {
            let pos = Vec3::new(
                centre.x + i as f64 * 6.0 * r,
                centre.y + j as f64 * 6.0 * r,
                hi.z + size,
            );
            out.push(at_rest(r, pos, out.len()));
        }
    }
    out
}

/// The particles' material when the user gives only (or not even) `k_n`: ε_n 0.8,
/// ε_t 1, no friction of any kind, k_t = 2/7 k_n.
pub fn default_material(k_n: f64) -> ParticleMaterial {
    ParticleMaterial {
        eps_n: 0.8,
        eps_t: 1.0,
        k_n,
        k_t: 2.0 / 7.0 * k_n,
        mu_s: 0.0,
        mu_r: 0.0,
        mu_t: 0.0,
    }
}

/// A normal spring constant for which the fastest expected impact overlaps by 1 % of the
/// smallest radius: k_n = m·(v/(0.01·r))².
pub fn default_k_n(walls: &[Wall], particles: &[Particle], gravity: &Vec3) -> f64 {
    let (lo, hi) = bounds(walls);
    let span = particles
        .iter()
        .fold(hi - lo, |s, p| s.sup(&(p.pos - lo).abs()));
    let fall = (2.0 * gravity.norm() * span.max()).sqrt();
    let fastest = particles.iter().map(|p| p.vel.norm()).fold(0.0, f64::max);
    let v = fall.max(fastest).max(1e-12);
    let m = particles.iter().map(|p| p.mass).fold(0.0, f64::max);
    let r = particles
        .iter()
        .map(|p| p.radius)
        .fold(f64::INFINITY, f64::min);
    m * (v / (0.01 * r)).powi(2)
}

/// How long to run when not told: three free falls (or crossings) over the scene.
pub fn default_duration(walls: &[Wall], particles: &[Particle], gravity: &Vec3) -> f64 {
    let (lo, hi) = bounds(walls);
    let span = particles
        .iter()
        .fold(hi - lo, |s, p| s.sup(&(p.pos - lo).abs()))
        .max();
    let g = gravity.norm();
    if g > 0.0 {
        3.0 * (2.0 * span / g).sqrt()
    } else {
        let fastest = particles.iter().map(|p| p.vel.norm()).fold(0.0, f64::max);
        if fastest > 0.0 {
            3.0 * span / fastest
        } else {
            1.0
        }
    }
}

/// The HSDEM timestep when not told: the straight path of a step strays from the
/// parabola by at most g·dt²/8; keep that below 0.1 % of the smallest radius. Without
/// gravity paths are straight and any step is exact: a hundredth of the run.
pub fn default_hard_dt(particles: &[Particle], gravity: &Vec3, t_end: f64) -> f64 {
    let r = particles
        .iter()
        .map(|p| p.radius)
        .fold(f64::INFINITY, f64::min);
    let g = gravity.norm();
    if g > 0.0 {
        (8.0 * 1e-3 * r / g).sqrt().min(t_end)
    } else {
        t_end / 100.0
    }
}

/// `n` particles of radius `r` and unit density at rest, packed into the bottom of the
/// scene's box: the lowest sites of a cubic lattice of spacing 2.2r (gaps of 0.2r), each
/// clear of every wall by its diameter, layer by layer. None overlaps another, and the
/// same scene gives the same pack: a deterministic crowd for benchmarks and stress runs.
/// Fewer than `n` when the box has no room.
pub fn packed(walls: &[Wall], n: usize, r: f64) -> Vec<Particle> {
    let (lo, hi) = bounds(walls);
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
        .map(|(i, pos)| at_rest(r, pos, i))
        .collect()
}

/// A particle of radius `r` and unit density at rest at `pos`, drawn in ssdraw's blue.
fn at_rest(r: f64, pos: Vec3, index: usize) -> Particle {
    Particle {
        mass: 4.0 / 3.0 * std::f64::consts::PI * r.powi(3),
        radius: r,
        pos,
        vel: Vec3::zeros(),
        spin: Vec3::zeros(),
        color: 3,
        index: index as i32,
    }
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
