//! Rigid bodies beyond the particles: pkdgrav's aggregates of particles ([`aggregate`]),
//! reactive walls' assemblies ([`reactive`]) and the
//! rotation of a rigid body by Euler's equations ([`rigid`]). Wall kinematics (where a
//! wall is and how fast its surface moves) is walls-geometry's `Motion`.

pub mod aggregate;
pub mod euler_rigid;
pub mod reactive;
pub mod rigid;

/// The moment of inertia of a solid sphere of mass `m` and radius `r`, 0.4·m·r², worked
/// out in that order (a run's numbers depend on it, bit for bit).
#[inline]
pub(crate) fn sphere_inertia(m: f64, r: f64) -> f64 {
    0.4 * m * r * r
}
