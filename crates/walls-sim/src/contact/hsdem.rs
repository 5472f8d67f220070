//! The hard-sphere (HSDEM) collision of a particle with a wall or another particle
//! (docs/spec.md §3): how it bounces. When it happens, within a step, is the shapes' time
//! of impact ([`walls_geometry::Shape::first_hit`]).
//!
//! Bounce, with u the velocity of the particle's contact point relative to the wall and
//! n̂ the normal: v′ = v − (1 + εn)·u_n − (2/7)(1 − εt)·u_t and
//! ω′ = ω − (5/(7R²))(1 − εt)·((−R·n̂) × u).

use nalgebra::Vector3;

/// Collisions one particle may have in one step before it counts as inelastic collapse.
pub const COLLISION_CAP: u32 = 1000;

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

/// A sphere's mass, radius, velocity and spin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// Mass.
    pub mass: f64,
    /// Radius.
    pub radius: f64,
    /// Velocity.
    pub velocity: Vec3,
    /// Spin.
    pub spin: Vec3,
}

/// The collision of two solid spheres touching along unit `n` (from `b` to `a`): the
/// same rule with the reduced mass (Richardson 1994). The factor 2/7 holds for any pair
/// of solid spheres, since each one's tangential response is 1/m + R²/I = 7/(2m).
pub fn pair_bounce(a: &Body, b: &Body, n: &Vec3, eps_n: f64, eps_t: f64) -> (Bounce, Bounce) {
    let (arm_a, arm_b) = (-n * a.radius, n * b.radius);
    let u = a.velocity + a.spin.cross(&arm_a) - b.velocity - b.spin.cross(&arm_b);
    let un = n * n.dot(&u);
    let ut = u - un;
    // An infinite mass (a particle stuck to a wall) is a wall to the other.
    let reduced = if b.mass.is_infinite() {
        a.mass
    } else {
        a.mass * b.mass / (a.mass + b.mass)
    };
    // The impulse on a; b gets the opposite.
    let normal = -un * (reduced * (1.0 + eps_n));
    let tangential = -ut * (reduced * 2.0 / 7.0 * (1.0 - eps_t));
    let impulse = normal + tangential;
    let turn = |arm: &Vec3, j: &Vec3, body: &Body| {
        body.spin + arm.cross(j) / crate::dynamics::sphere_inertia(body.mass, body.radius)
    };
    (
        Bounce {
            velocity: a.velocity + impulse / a.mass,
            spin: turn(&arm_a, &tangential, a),
        },
        Bounce {
            velocity: b.velocity - impulse / b.mass,
            spin: turn(&arm_b, &-tangential, b),
        },
    )
}
