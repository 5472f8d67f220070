//! The walls of a resolved scene as typed parts, decoded from their keywords once
//! ([`Wall::decode`]): the back end's one view of a wall. Contacts, bounds, meshes,
//! previews and the run's plan read these parts and never a keyword.
//!
//! * [`Shape`]: one variant per wall type, in pkdgrav units, with every query by kind
//!   beside it: the nearest point (SSDEM), the time of impact (HSDEM, [`impact`] and the
//!   quartic of [`poly`]), bounds, and tessellation ([`mesh`]). Each wall type's code is
//!   in one module under [`shape`].
//! * [`Motion`]: velocity, oscillation, step and spin; the origin and the material's
//!   velocity at a time.
//! * [`Material`]: the contact values, with pkdgrav's −1/99 fall-backs resolved against
//!   the particles' values by [`Material::against`]; [`OptionalMaterial`], a wall's
//!   cohesion and two-layer values (pkdgrav's optional builds), resolved by the run.
//! * [`Appearance`] (colour, transparency) and [`Reactive`] (mass, assembly, centre of
//!   gravity, inertia, axes).
//!
//! [`Particle`] is the sphere that meets the walls, as pkdgrav's files hold it.
//!
//! [`json`] writes the resolved scene as `walls-sim scene` prints it, with each wall's
//! position at a time.

mod bounds;
pub mod impact;
pub mod json;
pub mod material;
pub mod mesh;
pub mod motion;
mod particle;
pub mod poly;
pub mod shape;
pub mod units;
mod wall;

pub use bounds::{scene_bounds, scene_bounds_at};
pub use material::{BETA_S_DEFAULT, Material, OptionalMaterial};
pub use mesh::Mesh;
pub use motion::{Motion, Oscillation, OscillationStepping};
pub use particle::Particle;
pub use shape::{Feature, Hit, Nearest, Shape};
pub use wall::{Appearance, Reactive, Wall, decode, token_spans};
