//! The grammar in a real editor: Debian's Neovim 0.7 (headless; installed by
//! `scripts/install-test-tools`) loads `parser.c` compiled as nvim-treesitter compiles it,
//! and highlights `tests/data/highlight.walls` with the queries of `editors/neovim`
//! (`tests/nvim/highlight.lua`); the captures are `tests/data/highlight.captures`.
//! `require('walls').register_parser` registers the grammar with stand-ins of both
//! nvim-treesitter branches (`tests/nvim/register.lua`).

use serde_json::{Value, json};
use std::path::{Path, PathBuf};
use std::process::Command;

const GRAMMAR: &str = env!("CARGO_MANIFEST_DIR");

fn repo() -> PathBuf {
    Path::new(GRAMMAR).join("../..")
}

/// Runs `nvim` headless with no user configuration, `editors/neovim` first on the runtime
/// path, then `script`; fails the test with Neovim's standard error if it fails.
fn nvim(runtime: &[&Path], script: &str, env: &[(&str, &Path)]) {
    let mut command = Command::new("nvim");
    command.args(["--headless", "-u", "NONE", "-i", "NONE", "-n"]);
    for dir in runtime
        .iter()
        .copied()
        .chain([repo().join("editors/neovim").as_path()])
    {
        command
            .arg("--cmd")
            .arg(format!("set runtimepath^={}", dir.display()));
    }
    command
        .arg("-c")
        .arg(format!("luafile {GRAMMAR}/tests/nvim/{script}"));
    command.envs(env.iter().copied());
    let run = command
        .output()
        .expect("Neovim is installed (scripts/install-test-tools installs it)");
    assert!(
        run.status.success(),
        "nvim failed: {}",
        String::from_utf8_lossy(&run.stderr)
    );
}

#[test]
fn debians_neovim_loads_the_parser_and_highlights_every_token_kind() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("parser")).unwrap();
    let library = dir.path().join("parser/walls.so");
    let compiler = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let cc = Command::new(&compiler)
        .args(["-shared", "-fPIC", "-O1", "-I", "src", "src/parser.c", "-o"])
        .arg(&library)
        .current_dir(GRAMMAR)
        .output()
        .unwrap_or_else(|e| panic!("{compiler}: {e}"));
    assert!(
        cc.status.success(),
        "{compiler} failed: {}",
        String::from_utf8_lossy(&cc.stderr)
    );
    let out = dir.path().join("captures");
    let sample = Path::new(GRAMMAR).join("tests/data/highlight.walls");
    nvim(
        &[dir.path()],
        "highlight.lua",
        &[("WALLS_FILE", &sample), ("WALLS_OUT", &out)],
    );
    let expected = std::fs::read_to_string(sample.with_extension("captures")).unwrap();
    assert_eq!(std::fs::read_to_string(&out).unwrap(), expected);
}

#[test]
fn register_parser_works_with_both_nvim_treesitter_branches() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("result.json");
    let grammar = Path::new("/src/walls/grammar/tree-sitter-walls");
    let stubs = Path::new(GRAMMAR).join("tests/nvim");
    nvim(
        &[],
        "register.lua",
        &[
            ("WALLS_GRAMMAR", grammar),
            ("WALLS_STUBS", &stubs),
            ("WALLS_OUT", &out),
        ],
    );
    let result: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let main = json!({"install_info": {"path": grammar, "queries": "queries"}});
    assert_eq!(
        result,
        json!({
            "without": false,
            "master": "master",
            "master_walls": {
                "install_info": {"url": grammar, "files": ["src/parser.c"]},
                "filetype": "walls",
            },
            "master_keeps_lua": true,
            "main": "main",
            "main_walls": main,
            "reloaded_without_event": null,
            "after_tsupdate": main,
            "main_keeps_lua": true,
            "autocommands": 1,
        })
    );
}
