//! Rigid bodies beyond the particles: pkdgrav's aggregates of particles ([`aggregate`]),
//! reactive walls' assemblies ([`reactive`]) and the
//! rotation of a rigid body by Euler's equations ([`rigid`]). Wall kinematics (where a
//! wall is and how fast its surface moves) is walls-geometry's `Motion`.

pub mod aggregate;
pub mod euler_rigid;
pub mod reactive;
pub mod rigid;
