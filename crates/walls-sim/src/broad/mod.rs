//! The broad phase: which pairs could touch, without testing them all. [`grid`] finds
//! particle pairs on a cell grid; [`wall_index`] finds a particle's walls in a
//! bounding-volume hierarchy.

pub mod grid;
pub mod wall_index;
