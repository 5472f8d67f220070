//! The reference evaluator of walls files (SPEC §3): where each wall is and how fast its
//! surface moves, and which point of it a particle is nearest, with the feature it
//! touches (face, edge, vertex, rim, hole rim); and the particles and parameters of a
//! pkdgrav run (CSV, `.ss`, `.par`). Particle contacts and integration build on these.

pub mod geometry;
pub mod grid;
pub mod hsdem;
pub mod input;
pub mod kinematics;
pub mod poly;
pub mod run;
pub mod setup;
pub mod ssdem;

pub use geometry::{Feature, Nearest, Shape};
pub use kinematics::{Motion, OscillationStepping};
