//! `walls-lsp`'s command line as shells and `man` see it: `--completions SHELL` prints
//! a script for every shell, which bash loads, and `docs/man/walls-lsp.1` is the page
//! the clap definition makes (`UPDATE_DOCS=1 cargo test -p walls-lsp --test
//! command_line` rewrites it).

use clap::CommandFactory;
use std::path::Path;
use walls_test_support::cli::{bash_completes, completion_scripts, man_pages_in_step};

const BIN: &str = env!("CARGO_BIN_EXE_walls-lsp");

#[test]
fn completion_scripts_are_printed_and_bash_completes_with_them() {
    completion_scripts(Path::new(BIN), "walls-lsp");
    assert_eq!(
        bash_completes(Path::new(BIN), "walls-lsp", &["--st"]),
        [
            "complete -o bashdefault -o default -o nosort -F _walls__lsp walls-lsp",
            "--stdio"
        ]
    );
}

#[test]
fn the_man_page_is_that_of_the_command_line() {
    man_pages_in_step(walls_lsp::Args::command());
}
