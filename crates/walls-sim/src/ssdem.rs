//! The soft-sphere (SSDEM) contact of a particle with a wall (SPEC §3): a linear
//! spring–dashpot along the normal, and a tangential spring that follows the contact,
//! capped by Coulomb friction. The wall counts as infinitely massive and flat: the
//! reduced mass and radius are the particle's.
//!
//! Damping from restitution: C = −2·ln ε·√(m·k/(π² + ln²ε)), 0 when ε is 0 or 1. The
//! contact lasts π/ω_d with ω_d² = k/m − (C/2m)².

use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// Material values of one contact, with the walls' 99 and −1 already replaced by the
/// particles' values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Normal coefficient of restitution.
    pub eps_n: f64,
    /// Tangential coefficient of restitution.
    pub eps_t: f64,
    /// Normal spring constant.
    pub k_n: f64,
    /// Tangential spring constant.
    pub k_t: f64,
    /// Static friction coefficient (0: frictionless).
    pub mu_s: f64,
}

/// The damping coefficient for restitution `eps` of a spring `k` on mass `m`.
pub fn damping(eps: f64, k: f64, m: f64) -> f64 {
    if eps <= 0.0 || eps >= 1.0 {
        return 0.0;
    }
    let l = eps.ln();
    -2.0 * l * (m * k / (std::f64::consts::PI.powi(2) + l * l)).sqrt()
}

/// The force and torque on a particle from one wall contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactForce {
    /// Force on the particle.
    pub force: Vec3,
    /// Torque on the particle about its centre.
    pub torque: Vec3,
}

/// Where and how a particle touches a wall.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Touch {
    /// How far the particle's surface overlaps the wall.
    pub overlap: f64,
    /// Unit normal from the wall to the particle.
    pub normal: Vec3,
    /// Velocity of the particle's contact point relative to the wall's material there.
    pub velocity: Vec3,
}

/// The contact force on a particle of mass `m` and radius `r` touching a wall. `spring`
/// is the contact's tangential spring: it is turned into the tangent plane, stretched by
/// the tangential motion over `dt`, and cut back when the contact slides.
pub fn contact(
    m: f64,
    r: f64,
    touch: &Touch,
    spring: &mut Vec3,
    dt: f64,
    mat: &Material,
) -> ContactForce {
    let (overlap, normal, u) = (touch.overlap, &touch.normal, &touch.velocity);
    let un = normal * normal.dot(u);
    let ut = u - un;
    let c_n = damping(mat.eps_n, mat.k_n, m);
    let c_t = damping(mat.eps_t, mat.k_t, m);
    let f_n = normal * (mat.k_n * overlap) - un * c_n;
    // Keep the spring in the tangent plane (the contact turns), then stretch it.
    let along = normal * normal.dot(spring);
    let length = spring.norm();
    *spring -= along;
    if let Some(d) = spring.try_normalize(0.0) {
        *spring = d * length;
    }
    *spring += ut * dt;
    let mut f_t = -(*spring * mat.k_t) - ut * c_t;
    let cap = mat.mu_s * f_n.norm();
    if f_t.norm() > cap {
        // Sliding: the friction is the cap, the spring what would give it.
        f_t = match f_t.try_normalize(0.0) {
            Some(d) => d * cap,
            None => Vec3::zeros(),
        };
        *spring = if mat.k_t > 0.0 {
            -(f_t + ut * c_t) / mat.k_t
        } else {
            Vec3::zeros()
        };
    }
    // The tangential force acts at the contact point, −r·n̂ from the centre.
    let torque = (-normal * r).cross(&f_t);
    ContactForce {
        force: f_n + f_t,
        torque,
    }
}
