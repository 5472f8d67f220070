//! Walls files from programs (docs/meshes.md).
//!
//! [`Wall`] is a wall type and its tokens, each checked against the keyword table as it
//! is set: an unknown keyword (with "did you mean"), a value of the wrong shape, a
//! fraction for an integer, a bool for a number and a value that is not finite are
//! [`BuildError`]s. [`dumps`] writes walls as a whole file (a comment, [`Units`], a
//! defaults block) in walls-fmt's canonical layout, with each number the shortest
//! decimal that pkdgrav reads back exactly, and checks it as `walls-lint` does: errors
//! fail the dump, warnings come back with the text.
//!
//! [`mesh`] reads STL and OBJ meshes and turns their faces into triangle walls,
//! optionally oriented and with rectangles merged.

mod dump;
pub mod mesh;
mod value;
mod wall;

pub use dump::{DumpError, DumpOptions, Dumped, describe, dumps};
pub use value::{BuildError, Given, Value, number, wall_type_named};
pub use wall::{LengthUnit, Units, Wall};
pub use walls_model::{ContactModel, Options as CheckOptions};
