//! The soft-sphere (SSDEM) contact of a particle with a wall (SPEC §3): a linear
//! spring–dashpot along the normal, and a tangential spring that follows the contact,
//! capped by Coulomb friction. The wall counts as infinitely massive and flat: the
//! reduced mass and radius are the particle's.
//!
//! Rolling and twisting resistance (SPEC §3) oppose the relative spin: rolling with
//! torque μ_r·|F_n|·l against the spin across the normal (l the lever: the particle's
//! radius against a wall, the reduced radius between particles), twisting with
//! μ_t·|F_n|·a against the spin about the normal, a = √(2Rx − x²) being the radius of the
//! contact circle of a sphere of radius R overlapping by x. Each is capped so that it
//! cannot reverse the spin within a step.
//!
//! Damping from restitution: C = −2·ln ε·√(m·k/(π² + ln²ε)), 0 when ε is 0 or 1. The
//! contact lasts π/ω_d with ω_d² = k/m − (C/2m)².

use nalgebra::Vector3;

type Vec3 = Vector3<f64>;

/// Material values of one contact, with the walls' 99 and −1 already replaced by the
/// particles' values ([`Material::against`]).
pub use walls_geometry::Material;

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

/// The damping coefficient divided by √m: C = √m · this, for restitution `eps` of a
/// spring `k` (so that it can be worked out once per material, not per contact).
pub fn damping_per_root_mass(eps: f64, k: f64) -> f64 {
    damping(eps, k, 1.0)
}

/// The normal force alone, for scenes without sliding friction: what [`contact`] gives
/// when μ_s = 0, without keeping a tangential spring, with the damping coefficient `c_n`
/// worked out beforehand.
pub fn normal_contact(touch: &Touch, k_n: f64, c_n: f64) -> ContactForce {
    let un = touch.normal * touch.normal.dot(&touch.velocity);
    ContactForce {
        force: touch.normal * (k_n * touch.overlap) - un * c_n,
        torque: Vec3::zeros(),
    }
}

/// The contact force on a particle of mass `m` and radius `r` touching a wall. `spring`
/// is the contact's tangential spring: it is turned into the tangent plane, stretched by
/// the tangential motion over `dt`, and reset when the contact slides.
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
        // Sliding: the friction is the cap, and the spring starts again (SPEC §3).
        f_t = match f_t.try_normalize(0.0) {
            Some(d) => d * cap,
            None => Vec3::zeros(),
        };
        *spring = Vec3::zeros();
    }
    // The tangential force acts at the contact point, −r·n̂ from the centre.
    let torque = (-normal * r).cross(&f_t);
    ContactForce {
        force: f_n + f_t,
        torque,
    }
}

/// Where a rolling and twisting resistance acts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rolling {
    /// Spin of the particle relative to what it touches.
    pub spin: Vec3,
    /// Unit normal from what it touches to the particle.
    pub normal: Vec3,
    /// The size of the normal force.
    pub normal_force: f64,
    /// The rolling lever.
    pub lever: f64,
    /// The radius of the contact circle.
    pub contact_radius: f64,
    /// The moment of inertia that the torque turns (for the cap).
    pub inertia: f64,
}

/// The rolling and twisting resistance torque on a particle over a step of `dt`.
pub fn resistance(c: &Rolling, mu_r: f64, mu_t: f64, dt: f64) -> Vec3 {
    let n = &c.normal;
    let about = n * n.dot(&c.spin);
    let across = c.spin - about;
    // The largest torque that stops, without reversing, a spin w within the step.
    let stop = |w: f64| c.inertia * w / dt;
    let mut torque = Vec3::zeros();
    if mu_r > 0.0
        && let Some((axis, w)) = nalgebra::Unit::try_new_and_get(across, 0.0)
    {
        torque -= axis.into_inner() * (mu_r * c.normal_force * c.lever).min(stop(w));
    }
    if mu_t > 0.0
        && let Some((axis, w)) = nalgebra::Unit::try_new_and_get(about, 0.0)
    {
        torque -= axis.into_inner() * (mu_t * c.normal_force * c.contact_radius).min(stop(w));
    }
    torque
}

/// The radius of the circle where a sphere of radius `r` overlaps a flat wall by `x`.
pub fn contact_radius(r: f64, x: f64) -> f64 {
    (2.0 * r * x - x * x).max(0.0).sqrt()
}
