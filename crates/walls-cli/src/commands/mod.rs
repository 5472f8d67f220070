//! The commands of the walls tools, one module each: its arguments (clap derive) and a
//! function from them to an exit status. The binaries only parse and dispatch.
//!
//! * `walls-lint` is [`lint`];
//! * `walls-fmt` is [`fmt`];
//! * `walls-sim scene`, `run`, `plan`, `advise` and `preview` are [`sim`]'s modules;
//! * `walls-mesh` is [`mesh`].

pub mod fmt;
pub mod lint;
pub mod mesh;
pub mod sim;
