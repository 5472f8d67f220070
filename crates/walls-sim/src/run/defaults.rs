//! What a run needs when the user does not say: the embedded particles, and material
//! values, timestep and duration derived from the scene (docs/evaluator.md).
//!
//! * Particles: nine of unit density, sized and placed for the scene's finite walls
//!   (the box of [`scene_bounds`] without particles), deterministic so that the same
//!   file gives the same run. The radius starts at 2 % of the box's size and is halved
//!   (up to three times) until a layout fits: a 3 × 3 grid of spacing 3r around the
//!   box's centre in x and y, tried at heights from the box's top less 2r downwards in
//!   steps of r, is taken when every particle is clear of every wall (more than 1.5 r
//!   from it, walls at t = 0) and inside a container: a wall on each side (±x, ±y) and
//!   below. A scene with no container (a lone disk or rectangle, a floor) gets the grid
//!   at spacing 6r one box-size above the box's top, clear of the walls.
//! * Gravity: 1 along −z (pkdgrav units) for the embedded particles, none otherwise.
//! * Material: ε_n 0.8, ε_t 1, μ_s = μ_r = μ_t = 0, and k_n stiff enough that the fastest expected
//!   impact (the larger of the fastest particle and free fall over the scene, plus the
//!   fastest wall) overlaps by 1 % of the smallest radius; k_t = 2/7 k_n.
//! * The fastest wall: its origin's top speed (|velocity| + |A·ω|), plus its rim speed
//!   when it spins (|ang-speed| times its radius; a plane's, triangle's or rectangle's
//!   reach is half the scene's size), plus a reactive wall's |rot-vec| times half the
//!   scene's size.
//! * Timestep cap: nothing moves more than 2 % of the smallest radius in a step at the
//!   fastest relative speed, so a moving wall cannot step over a particle (pkdgrav's
//!   overlap warnings start at 3 %, which one step's travel then cannot reach alone).
//! * HSDEM timestep: collisions are exact within a step, but a particle's path in a step
//!   is straight, so under gravity it strays from its parabola by up to g·dt²/8: the
//!   default keeps that below 0.1 % of the smallest radius (without gravity, 100 steps
//!   over the run), and under the cap above (a moving wall's path is a chord per step).
//! * Without particles: a hundredth of the shortest oscillation period, else a
//!   hundredth of the run.
//! * Duration: three free-fall times over the scene (or three crossings at the fastest
//!   speed without gravity); without particles, two periods of the slowest oscillation.
//!
//! Only what a run uses lives here: the fixtures of tests and benchmarks (a packed crowd
//! of particles, a many-walled hull) are in walls-test-support's `scenes`.

use crate::run::ParticleMaterial;
use nalgebra::Vector3;
use walls_geometry::{Particle, Shape, Wall, scene_bounds};

type Vec3 = Vector3<f64>;

/// The most a default step lets anything move, as a fraction of the smallest radius.
pub const TRAVEL_PER_STEP: f64 = 0.02;

/// The embedded particles for the scene of `walls` (see the module documentation).
pub fn default_particles(walls: &[Wall]) -> Vec<Particle> {
    let (lo, hi) = scene_bounds(walls, &[]);
    let size = (hi - lo).max();
    let centre = (lo + hi) / 2.0;
    let placed: Vec<Shape> = walls
        .iter()
        .map(|w| w.shape.at(w.motion.position_or_origin(0.0)))
        .collect();
    let grid = |r: f64, spacing: f64, z: f64| -> Vec<Particle> {
        let mut out = Vec::new();
        for i in -1..=1 {
            for j in -1..=1 {
                let pos = Vec3::new(
                    centre.x + f64::from(i) * spacing,
                    centre.y + f64::from(j) * spacing,
                    z,
                );
                out.push(Particle::at_rest(r, pos, out.len()));
            }
        }
        out
    };
    let clear = |ps: &[Particle]| {
        ps.iter().all(|p| {
            placed
                .iter()
                .all(|s| s.nearest(&p.pos).distance > 1.5 * p.radius)
        })
    };
    let contained = |ps: &[Particle]| {
        let sides = [Vec3::x(), -Vec3::x(), Vec3::y(), -Vec3::y(), -Vec3::z()];
        ps.iter()
            .all(|p| sides.iter().all(|d| meets(&placed, &p.pos, d, 2.0 * size)))
    };
    let radii = (0..4).map(|k| 0.02 * size / f64::from(1 << k));
    for r in radii.clone() {
        let mut z = hi.z - 2.0 * r;
        while z - r > lo.z {
            let ps = grid(r, 3.0 * r, z);
            if clear(&ps) && contained(&ps) {
                return ps;
            }
            z -= r;
        }
    }
    let above = |r: f64| grid(r, 6.0 * r, hi.z + size);
    radii
        .map(above)
        .find(|ps| clear(ps))
        .unwrap_or_else(|| above(0.02 * size))
}

/// Whether the ray from `p` along the unit `d` meets one of `walls` within `reach`:
/// marched by the distance to the nearest wall, so that it cannot step over one.
fn meets(walls: &[Shape], p: &Vec3, d: &Vec3, reach: f64) -> bool {
    let mut s = 0.0;
    for _ in 0..256 {
        let q = p + d * s;
        let gap = walls
            .iter()
            .map(|w| w.nearest(&q).distance)
            .fold(f64::INFINITY, f64::min);
        if gap <= 1e-6 * reach {
            return true;
        }
        s += gap;
        if s > reach || !s.is_finite() {
            return false;
        }
    }
    false
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

/// The fastest any wall's material moves (see the module documentation).
pub fn fastest_wall(walls: &[Wall]) -> f64 {
    let (lo, hi) = scene_bounds(walls, &[]);
    let half = (hi - lo).max() / 2.0;
    walls
        .iter()
        .map(|w| {
            let reach = match &w.shape {
                Shape::Disk(s) => s.radius,
                Shape::FiniteCylinder(s) => s.radius,
                Shape::InfiniteCylinder(s) => s.radius,
                Shape::Shell(s) => s.radius,
                Shape::Plane(_) | Shape::Triangle(_) | Shape::Rectangle(_) => half,
            };
            let react = if w.reactive.is_heavy() {
                w.reactive.rot_vec.norm() * half
            } else {
                0.0
            };
            w.motion.top_speed() + w.motion.ang_speed.abs() * reach.abs() + react
        })
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max)
}

/// The fastest relative speed a run expects: the larger of the fastest particle and
/// free fall over the scene, plus the fastest wall.
pub fn fastest_speed(walls: &[Wall], particles: &[impl AsRef<Particle>], gravity: &Vec3) -> f64 {
    let (lo, hi) = scene_bounds(walls, &[]);
    let span =
        (particles.iter().map(AsRef::as_ref)).fold(hi - lo, |s, p| s.sup(&(p.pos - lo).abs()));
    let fall = (2.0 * gravity.norm() * span.max()).sqrt();
    let fastest = (particles.iter().map(|p| p.as_ref().vel.norm())).fold(0.0, f64::max);
    fall.max(fastest) + fastest_wall(walls)
}

/// The smallest radius of `particles` (infinite when there are none).
fn smallest_radius(particles: &[impl AsRef<Particle>]) -> f64 {
    particles
        .iter()
        .map(|p| p.as_ref().radius)
        .fold(f64::INFINITY, f64::min)
}

/// A normal spring constant for which the fastest expected impact overlaps by 1 % of the
/// smallest radius: k_n = m·(v/(0.01·r))²; 0 without particles.
pub fn default_k_n(walls: &[Wall], particles: &[impl AsRef<Particle>], gravity: &Vec3) -> f64 {
    if particles.is_empty() {
        return 0.0;
    }
    let v = fastest_speed(walls, particles, gravity).max(1e-12);
    let m = (particles.iter().map(|p| p.as_ref().mass)).fold(0.0, f64::max);
    m * (v / (0.01 * smallest_radius(particles))).powi(2)
}

/// The longest step for which nothing moves more than [`TRAVEL_PER_STEP`] of the
/// smallest radius at the fastest relative speed (infinite when nothing moves or there
/// are no particles).
pub fn travel_cap(walls: &[Wall], particles: &[impl AsRef<Particle>], gravity: &Vec3) -> f64 {
    let v = fastest_speed(walls, particles, gravity);
    TRAVEL_PER_STEP * smallest_radius(particles) / v
}

/// The shortest and the longest oscillation period among `walls`, if any oscillates.
fn periods(walls: &[Wall]) -> Option<(f64, f64)> {
    walls
        .iter()
        .map(|w| &w.motion.oscillation)
        .filter(|o| o.amplitude != 0.0 && o.frequency != 0.0)
        .map(|o| std::f64::consts::TAU / o.frequency.abs())
        .filter(|p| p.is_finite() && *p > 0.0)
        .fold(None, |m, p| match m {
            None => Some((p, p)),
            Some((a, b)) => Some((p.min(a), p.max(b))),
        })
}

/// The timestep of a run without particles: a hundredth of the shortest oscillation
/// period, else a hundredth of the run.
pub fn walls_only_dt(walls: &[Wall], t_end: f64) -> f64 {
    match periods(walls) {
        Some((shortest, _)) => (shortest / 100.0).min(t_end),
        None => t_end / 100.0,
    }
}

/// How long to run when not told: three free falls (or crossings) over the scene;
/// without particles, two periods of the slowest oscillation.
pub fn default_duration(walls: &[Wall], particles: &[impl AsRef<Particle>], gravity: &Vec3) -> f64 {
    if particles.is_empty()
        && let Some((_, longest)) = periods(walls)
    {
        return 2.0 * longest;
    }
    let (lo, hi) = scene_bounds(walls, &[]);
    let span = (particles.iter().map(AsRef::as_ref))
        .fold(hi - lo, |s, p| s.sup(&(p.pos - lo).abs()))
        .max();
    let g = gravity.norm();
    if g > 0.0 {
        3.0 * (2.0 * span / g).sqrt()
    } else {
        let fastest = (particles.iter().map(|p| p.as_ref().vel.norm())).fold(0.0, f64::max);
        if fastest > 0.0 {
            3.0 * span / fastest
        } else {
            1.0
        }
    }
}

/// The HSDEM timestep when not told: the straight path of a step strays from the
/// parabola by at most g·dt²/8; keep that below 0.1 % of the smallest radius. Without
/// gravity paths are straight and any step is exact: a hundredth of the run. Either way
/// no more than the [`travel_cap`]; without particles, [`walls_only_dt`].
pub fn default_hard_dt(
    walls: &[Wall],
    particles: &[impl AsRef<Particle>],
    gravity: &Vec3,
    t_end: f64,
) -> f64 {
    if particles.is_empty() {
        return walls_only_dt(walls, t_end);
    }
    let r = smallest_radius(particles);
    let g = gravity.norm();
    let dt = if g > 0.0 {
        (8.0 * 1e-3 * r / g).sqrt().min(t_end)
    } else {
        t_end / 100.0
    };
    dt.min(travel_cap(walls, particles, gravity))
}

/// The soft-sphere timestep when not told: pkdgrav's suggestion for the lightest
/// particle with `k_n` ([`crate::run::default_dt`]), no more than the [`travel_cap`];
/// without particles, [`walls_only_dt`].
pub fn default_soft_dt(
    walls: &[Wall],
    particles: &[impl AsRef<Particle>],
    gravity: &Vec3,
    k_n: f64,
    t_end: f64,
) -> f64 {
    if particles.is_empty() {
        return walls_only_dt(walls, t_end);
    }
    crate::run::default_dt(particles, k_n).min(travel_cap(walls, particles, gravity))
}

/// The default timestep `dt` shortened so that a whole number of steps ends on `t_end`:
/// t_end / ⌈t_end/dt⌉.
pub fn whole_steps(dt: f64, t_end: f64) -> f64 {
    let n = (t_end / dt).ceil().max(1.0);
    if n.is_finite() { t_end / n } else { dt }
}
