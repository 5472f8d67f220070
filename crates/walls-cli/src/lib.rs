//! The walls command-line tools: each as a function from argv to exit status
//! ([`entry`]), their commands ([`commands`]), and what they share: printing that never
//! panics ([`console`]), reading inputs (files or standard input), a run's outputs as a movie's frames ([`movie`]), the memory
//! pages a run asks for ([`pages`]) and the contact model that `--mode` takes. The whole
//! check of one file and the registry of diagnostic codes that `--explain` and SARIF read
//! are `walls-ide`'s, re-exported here for the tools; every file the tools write goes
//! through `walls-output`, the one writer, which also removes what a signal leaves.

#![deny(clippy::print_stdout, clippy::print_stderr)]

pub mod commands;
pub mod console;
pub mod entry;
pub mod input;
pub mod movie;
pub mod pages;

pub use walls_ide::{Checked, all_codes, check_bytes, find_code};

/// `--mode` and `--method`: the contact model a file is for (one type from the keyword
/// table down to the run).
pub use walls_keywords::ContactModel;
