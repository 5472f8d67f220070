//! The particles and parameters of a pkdgrav run at the path the evaluator's modules and
//! tests use: their readers are in [`crate::io::particles`] and [`crate::io::par`].

pub use crate::io::InputError;
pub use crate::io::par::{Params, Rule, read_par};
pub use crate::io::particles::{Particle, read_csv, read_ss};
