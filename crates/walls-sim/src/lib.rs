//! The reference evaluator of walls files (SPEC §3): where each wall is and how fast its
//! surface moves, and which point of it a particle is nearest, with the feature it
//! touches (face, edge, vertex, rim, hole rim). Particle contacts and integration build
//! on these.

pub mod geometry;
pub mod kinematics;

pub use geometry::{Feature, Nearest, Shape};
pub use kinematics::{Motion, OscillationStepping};
