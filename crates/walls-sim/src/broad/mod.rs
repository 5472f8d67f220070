//! The broad phase: which pairs could touch, without testing them all. [`grid`] finds
//! particle pairs on a cell grid; `pairs` keeps the soft-sphere run's candidate pairs
//! from step to step; [`wall_index`] finds a particle's walls in a bounding-volume
//! hierarchy.

pub mod grid;
pub(crate) mod pairs;
pub mod wall_index;
