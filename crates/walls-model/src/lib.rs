//! The meaning of a walls file to pkdgrav, beyond its syntax.
//!
//! For now: the contact model a file is meant for ([`Mode`]) and the checks of the
//! features pkdgrav implements only in its soft-sphere code ([`check_mode`]).

pub mod codes;
mod mode;

pub use mode::{Mode, check_mode};
