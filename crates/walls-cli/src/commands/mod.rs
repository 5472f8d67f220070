//! The commands of the walls tools, one module each: its arguments (clap derive) and a
//! function from them to an exit status. The binaries only parse and dispatch.
//!
//! * `walls-lint` is [`lint`];
//! * `walls-fmt` is [`fmt`];
//! * `walls-sim scene`, `run`, `plan`, `advise` and `preview` are [`sim`]'s modules;
//! * [`settings`] is where `walls-lint` and `walls-fmt` find each file's settings.
//! * `walls-mesh` is [`mesh`].

pub mod fmt;
pub mod lint;
pub mod mesh;
pub mod settings;
pub mod sim;
