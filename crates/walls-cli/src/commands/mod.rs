//! The commands of the walls tools, one module each: its arguments (clap derive) and a
//! function from them to an exit status. The binaries only parse and dispatch.
//!
//! * [`lint`]: `walls-lint`;
//! * [`fmt`]: `walls-fmt`;
//! * [`sim`]: `walls-sim scene`, `run`, `plan`, `advise` and `preview`.

pub mod fmt;
pub mod lint;
pub mod sim;
