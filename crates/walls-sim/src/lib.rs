//! The reference evaluator of walls files (SPEC §3), on the typed walls of
//! walls-geometry (shapes, motion, material): the particles and parameters of a pkdgrav
//! run ([`io`]: CSV, `.ss`, `.par`) and the settings they give ([`config`]); contacts in
//! the soft-sphere ([`ssdem`]) and hard-sphere ([`hsdem`]) models; and runs of particles
//! against walls and each other ([`run`]), with their trajectories ([`io::trajectory`])
//! and reports ([`report`]); reactive walls ([`reactive`]), the rotation of their
//! assemblies ([`rigid`]) and pkdgrav's output files for them ([`io::wallsreact`]); and
//! advice on k_n and the timestep for the real pkdgrav run ([`advise`]).

pub mod advise;
pub mod config;
pub mod grid;
pub mod hsdem;
pub mod io;
pub mod plan;
pub mod reactive;
pub mod report;
pub mod rigid;
pub mod run;
pub mod setup;
pub mod ssdem;
pub mod wall_index;

pub use wall_index::WallIndex;
pub use walls_geometry::OscillationStepping;
