//! The hard-sphere (HSDEM) collision of a particle with a wall (SPEC §3): when, within a
//! step, a particle moving in a straight line meets a flat face moving in a straight
//! line, and how it bounces.
//!
//! Bounce, with u the velocity of the particle's contact point relative to the wall and
//! n̂ the normal: v′ = v − (1 + εn)·u_n − (2/7)(1 − εt)·u_t and
//! ω′ = ω − (5/(7R²))(1 − εt)·((−R·n̂) × u).

use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// A particle's velocity and spin after bouncing off a wall.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounce {
    /// Velocity after.
    pub velocity: Vec3,
    /// Spin after.
    pub spin: Vec3,
}

/// The bounce of a particle of radius `r` with velocity `v` and spin `w` off a wall whose
/// material at the contact moves at `wall_velocity`, along unit normal `n` (from the wall
/// to the particle), with restitution `eps_n`, `eps_t`.
pub fn bounce(
    r: f64,
    v: &Vec3,
    w: &Vec3,
    wall_velocity: &Vec3,
    n: &Vec3,
    eps_n: f64,
    eps_t: f64,
) -> Bounce {
    let arm = -n * r;
    let u = v + w.cross(&arm) - wall_velocity;
    let un = n * n.dot(&u);
    let ut = u - un;
    Bounce {
        velocity: v - un * (1.0 + eps_n) - ut * (2.0 / 7.0 * (1.0 - eps_t)),
        spin: w - arm.cross(&u) * (5.0 / (7.0 * r * r) * (1.0 - eps_t)),
    }
}

/// When, in `[0, dt]`, a sphere of radius `r` at `p` moving at `v` first touches the
/// plane through `q` with unit normal `n` moving at `wall_velocity`, from the side it
/// starts on; `None` if it does not within the step (or moves away).
pub fn plane_hit(
    p: &Vec3,
    v: &Vec3,
    r: f64,
    q: &Vec3,
    n: &Vec3,
    wall_velocity: &Vec3,
    dt: f64,
) -> Option<f64> {
    let h = n.dot(&(p - q));
    let side = if h >= 0.0 { 1.0 } else { -1.0 };
    let gap = side * h - r;
    let closing = -side * n.dot(&(v - wall_velocity));
    if closing <= 0.0 {
        return None;
    }
    let t = gap / closing;
    (0.0..=dt).contains(&t).then_some(t)
}
