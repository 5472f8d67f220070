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
//!
//! Only what a run uses lives here: the fixtures of tests and benchmarks (a packed crowd
//! of particles, a many-walled hull) are in walls-test-support's `scenes`.

use crate::run::ParticleMaterial;
use nalgebra::Vector3;
use walls_geometry::Particle;
use walls_geometry::{Wall, scene_bounds};

type Vec3 = Vector3<f64>;

/// The embedded particles for the scene of `walls`.
pub fn default_particles(walls: &[Wall]) -> Vec<Particle> {
    let (lo, hi) = scene_bounds(walls, &[]);
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
            out.push(Particle::at_rest(r, pos, out.len()));
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
        beta_s: walls_geometry::BETA_S_DEFAULT,
    }
}

/// A normal spring constant for which the fastest expected impact overlaps by 1 % of the
/// smallest radius: k_n = m·(v/(0.01·r))².
pub fn default_k_n(walls: &[Wall], particles: &[Particle], gravity: &Vec3) -> f64 {
    let (lo, hi) = scene_bounds(walls, &[]);
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
    let (lo, hi) = scene_bounds(walls, &[]);
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
