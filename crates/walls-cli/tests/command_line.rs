//! The tools' command lines as shells and `man` see them: `--completions SHELL` prints a
//! script for every shell, which bash loads and completes with, and `docs/man/` holds the
//! pages the clap definitions make (`UPDATE_DOCS=1 cargo test -p walls-cli --test
//! command_line` rewrites them).

use clap::CommandFactory;
use std::path::Path;
use walls_cli::commands::{fmt::FmtArgs, lint::LintArgs, mesh::MeshArgs, sim::SimArgs};
use walls_test_support::cli::{bash_completes, completion_scripts, man_pages_in_step};

const TOOLS: [(&str, &str); 4] = [
    ("walls-lint", env!("CARGO_BIN_EXE_walls-lint")),
    ("walls-fmt", env!("CARGO_BIN_EXE_walls-fmt")),
    ("walls-sim", env!("CARGO_BIN_EXE_walls-sim")),
    ("walls-mesh", env!("CARGO_BIN_EXE_walls-mesh")),
];

#[test]
fn every_tool_prints_a_completion_script_for_every_shell() {
    for (name, bin) in TOOLS {
        completion_scripts(Path::new(bin), name);
    }
}

#[test]
fn bash_loads_the_scripts_and_completes_options_values_and_commands() {
    let complete = |name: &str, words: &[&str]| {
        let bin = TOOLS.iter().find(|(n, _)| *n == name).unwrap().1;
        bash_completes(Path::new(bin), name, words)
    };
    assert_eq!(
        complete("walls-lint", &["--form"]),
        [
            "complete -o bashdefault -o default -o nosort -F _walls__lint walls-lint",
            "--format"
        ]
    );
    assert_eq!(
        complete("walls-lint", &["--format", ""])[1..],
        ["human", "json", "sarif", "github", "gitlab"]
    );
    assert_eq!(complete("walls-fmt", &["--che"])[1..], ["--check"]);
    assert_eq!(complete("walls-sim", &["sc"])[1..], ["scene"]);
    assert_eq!(
        complete("walls-mesh", &["--orientation", ""])[1..],
        ["keep", "outward", "inward"]
    );
    assert_eq!(
        complete("walls-sim", &["--completions", "f"])[1..],
        ["fish"]
    );
}

#[test]
fn man_pages_are_those_of_the_command_lines() {
    man_pages_in_step(LintArgs::command());
    man_pages_in_step(FmtArgs::command());
    man_pages_in_step(SimArgs::command());
    man_pages_in_step(MeshArgs::command());
}

#[test]
fn entry_points_return_the_exit_status_without_ending_the_process() {
    let argv = |words: &[&str]| words.iter().map(Into::into).collect::<Vec<_>>();
    assert_eq!(
        walls_cli::entry::lint(argv(&["walls-lint", "--no-such"])),
        2
    );
    assert_eq!(walls_cli::entry::fmt(argv(&["walls-fmt", "--version"])), 0);
    assert_eq!(walls_cli::entry::sim(argv(&["walls-sim"])), 2);
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("scene.walls");
    // No final newline: an error (S002) whose fix the formatter agrees with.
    std::fs::write(&file, "wall type plane").unwrap();
    let file = file.to_str().unwrap();
    assert_eq!(walls_cli::entry::lint(argv(&["walls-lint", file])), 1);
    assert_eq!(
        walls_cli::entry::fmt(argv(&["walls-fmt", "--check", file])),
        1
    );
    assert_eq!(
        walls_cli::entry::lint(argv(&["walls-lint", "--unsafe-fixes", file])),
        0
    );
    assert_eq!(
        walls_cli::entry::fmt(argv(&["walls-fmt", "--check", file])),
        0
    );
}
