//! The reference evaluator of walls files (SPEC §3), on the typed walls of
//! walls-geometry (shapes, motion, material): the particles and parameters of a
//! pkdgrav run (CSV, `.ss`, `.par`); contacts in the soft-sphere ([`ssdem`]) and
//! hard-sphere ([`hsdem`]) models; and runs of particles against walls and each other
//! ([`run`]), with their trajectories ([`trajectory`]); reactive walls ([`reactive`]),
//! the rotation of their assemblies ([`rigid`]) and pkdgrav's output files for them
//! ([`reactive_output`]); and advice on k_n and the timestep for the real pkdgrav run
//! ([`advise`]).

pub mod advise;
pub mod grid;
pub mod hsdem;
pub mod input;
pub mod plan;
pub mod reactive;
pub mod reactive_output;
pub mod rigid;
pub mod run;
pub mod setup;
pub mod ssdem;
pub mod trajectory;
pub mod wall_index;

pub use wall_index::WallIndex;
pub use walls_geometry::OscillationStepping;
