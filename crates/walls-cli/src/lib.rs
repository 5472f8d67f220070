//! The walls command-line tools: each as a function from argv to exit status
//! ([`entry`]), their commands ([`commands`]), and what they share: printing that never
//! panics ([`console`]), reading inputs (files or standard input), a run's outputs as a movie's frames ([`movie`]), the memory
//! pages a run asks for ([`pages`]) and the contact model that `--mode` takes. The whole
//! check of one file and the registry of diagnostic codes are `walls-ide`'s, re-exported
//! here for the tools, with the run directory's `R…` codes ([`all_codes`]) that `--explain`
//! and SARIF read; every file the tools write goes
//! through `walls-output`, the one writer, which also removes what a signal leaves.

#![deny(clippy::print_stdout, clippy::print_stderr)]

pub mod commands;
pub mod console;
pub mod entry;
pub mod input;
pub mod movie;
pub mod pages;

pub use walls_ide::{Checked, check_bytes};

/// Every diagnostic code the tools can emit, in code order: `walls-ide`'s registry (the
/// codes of walls files and `.par` files, and the `R…` codes of a run directory checked
/// before the job, [`walls_sim::precheck`], which only `walls-lint` emits).
pub use walls_ide::all_codes;

/// Finds a code by its id (`R001`, any case) or its name (`initial-pair-overlap`).
pub fn find_code(query: &str) -> Option<&'static walls_diagnostics::Code> {
    all_codes().find(|c| c.id.eq_ignore_ascii_case(query) || c.name.eq_ignore_ascii_case(query))
}

/// `--mode` and `--method`: the contact model a file is for (one type from the keyword
/// table down to the run).
pub use walls_keywords::ContactModel;
