//! The reference evaluator of walls files (docs/spec.md §3), on the typed walls of
//! walls-geometry (shapes, motion, material). Its layout is the pipeline:
//!
//! * [`build`]: pkdgrav's compile options, which decide its physics;
//! * [`bodies`]: the particles as a run carries them, one [`bodies::State`] each;
//! * [`io`]: the particles and parameters of a pkdgrav run (CSV, `.ss`, `.par`), the
//!   trajectory and pkdgrav's WALLSREACT files, each reader beside its writer; and
//!   [`config`], the run's settings from flags, then the `.par` file, then defaults;
//! * [`contact`]: the contact laws, soft-sphere ([`contact::ssdem`]) and hard-sphere
//!   ([`contact::hsdem`]);
//! * [`dynamics`]: reactive walls' assemblies and rigid rotation;
//! * [`broad`]: which particles and walls could touch (cell grid, wall index);
//! * [`run`]: the plan, the defaults, the soft- and hard-sphere steppers, stability
//!   checks, and the outcome; [`warning`]: what a run (and reading its inputs) warns
//!   about, as coded data;
//! * [`precheck`]: a run directory checked before the job (`R…` codes): initial
//!   overlaps, particles outside their container, steps per contact, fast walls, tokens
//!   the build lacks, outputs;
//! * [`report`]: the outcome as pkdgrav users read it; [`advise`]: k_n and the timestep
//!   for the real pkdgrav run; [`export`]: the run as a pkdgrav run directory's `.par`
//!   file and README;
//! * with the `clap` feature, the settings' types are command-line values, and `cli`
//!   holds the value parsers their options share.

pub mod advise;
pub mod bodies;
pub mod broad;
pub mod build;
#[cfg(feature = "clap")]
pub mod cli;
pub mod config;
pub mod contact;
pub mod dynamics;
pub mod export;
pub mod io;
mod permute;
pub mod precheck;
pub mod report;
pub mod run;
pub mod warning;

pub use broad::wall_index::WallIndex;
pub use walls_geometry::OscillationStepping;
