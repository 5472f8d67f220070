//! Contact laws: what one contact does to a particle. [`ssdem`] is pkdgrav's
//! soft-sphere spring–dashpot with friction, rolling and twisting resistance; [`hsdem`]
//! its hard-sphere bounce; [`cohesion`] the cohesive force of its `DEM_COHESION` build. When contacts happen is the shapes' business
//! (walls-geometry: nearest points and times of impact) and the run's ([`crate::run`]).

pub mod cohesion;
pub mod hsdem;
pub mod lanes;
pub mod ssdem;
