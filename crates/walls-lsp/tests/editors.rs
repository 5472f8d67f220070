//! The real binary with real clients: raw JSON-RPC over standard input and output,
//! Neovim (headless, `tests/nvim/lsp.lua`) as a user's editor, and the Neovim plugin of
//! `editors/neovim` (`tests/nvim/plugin.lua`).

use serde_json::{Value, json};
use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};

fn frame(message: &Value) -> Vec<u8> {
    let body = message.to_string();
    format!("Content-Length: {}\r\n\r\n{body}", body.len()).into_bytes()
}

fn read_message(out: &mut impl BufRead) -> Value {
    let mut length = 0;
    loop {
        let mut line = String::new();
        out.read_line(&mut line).unwrap();
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        if let Some(n) = line.strip_prefix("Content-Length: ") {
            length = n.parse().unwrap();
        }
    }
    let mut body = vec![0; length];
    out.read_exact(&mut body).unwrap();
    serde_json::from_slice(&body).unwrap()
}

#[test]
fn speaks_lsp_over_stdio() {
    let mut server = Command::new(env!("CARGO_BIN_EXE_walls-lsp"))
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let mut input = server.stdin.take().unwrap();
    let mut output = BufReader::new(server.stdout.take().unwrap());
    let uri = "file:///tmp/stdio.walls";
    input.write_all(&frame(&json!({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}}))).unwrap();
    let init = read_message(&mut output);
    assert_eq!(init["result"]["capabilities"]["hoverProvider"], true);
    input
        .write_all(&frame(
            &json!({"jsonrpc": "2.0", "method": "initialized", "params": {}}),
        ))
        .unwrap();
    input
        .write_all(&frame(&json!({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {
            "textDocument": {"uri": uri, "languageId": "walls", "version": 7, "text": "wall type dsk\n"}}})))
        .unwrap();
    let published = loop {
        let m = read_message(&mut output);
        if m["method"] == "textDocument/publishDiagnostics" {
            break m;
        }
    };
    assert_eq!(published["params"]["version"], 7);
    assert_eq!(published["params"]["diagnostics"][0]["code"], "S106");
    input
        .write_all(&frame(
            &json!({"jsonrpc": "2.0", "id": 2, "method": "shutdown"}),
        ))
        .unwrap();
    assert_eq!(read_message(&mut output)["id"], 2);
    input
        .write_all(&frame(&json!({"jsonrpc": "2.0", "method": "exit"})))
        .unwrap();
    drop(input);
    assert!(server.wait().unwrap().success());
}

#[test]
fn neovim_shows_diagnostics_hovers_completes_formats() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("scene.walls");
    std::fs::write(&file, "wall type disk\n  radius,0.5\n  vertex1 1 0 0\n").unwrap();
    let out = dir.path().join("result.json");
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/nvim/lsp.lua");
    let run = Command::new("nvim")
        .args(["--headless", "-u", "NONE", "-i", "NONE", "-n", "-c"])
        .arg(format!("luafile {script}"))
        .env("WALLS_LSP", env!("CARGO_BIN_EXE_walls-lsp"))
        .env("WALLS_FILE", &file)
        .env("WALLS_OUT", &out)
        .output()
        .expect("Neovim is installed (scripts/install-test-tools installs it)");
    assert!(
        run.status.success(),
        "nvim failed: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    let result: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(
        result["diagnostics"],
        json!([{"code": "C201", "line": 2, "col": 2, "severity": 2}])
    );
    let hover = result["hover"].as_str().unwrap();
    assert!(
        hover.starts_with("**radius**") && hover.contains("In wall 0: **0.5**"),
        "{hover}"
    );
    let completion: Vec<&str> = result["completion"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_str().unwrap())
        .collect();
    assert!(
        completion.contains(&"disk") && completion.contains(&"shell"),
        "{completion:?}"
    );
    assert_eq!(result["symbols"], json!(["wall 0: disk"]));
    assert_eq!(
        result["actions"],
        json!([
            "remove `vertex1`, which has no effect (C201)",
            "Fix all safe problems (1)"
        ])
    );
    assert_eq!(
        result["formatted"],
        json!(["wall type disk", "  radius 0.5", "  vertex1 1 0 0"])
    );
}

#[test]
fn the_neovim_plugin_detects_and_attaches() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("walls-box.dat");
    std::fs::write(&file, "wall type plane\n  radius 2\n").unwrap();
    let out = dir.path().join("result.json");
    let repo = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
    let run = Command::new("nvim")
        .args(["--headless", "-u", "NONE", "-i", "NONE", "-n"])
        .args(["--cmd", &format!("set runtimepath^={repo}/editors/neovim")])
        .args(["--cmd", "filetype plugin on"])
        .args(["-c", &format!("luafile {repo}/tests/nvim/plugin.lua")])
        .env("WALLS_LSP", env!("CARGO_BIN_EXE_walls-lsp"))
        .env("WALLS_FILE", &file)
        .env("WALLS_OUT", &out)
        .output()
        .expect("Neovim is installed (scripts/install-test-tools installs it)");
    assert!(
        run.status.success(),
        "nvim failed: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    let result: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(
        result,
        json!({"filetype": "walls", "commentstring": "# %s", "codes": ["C201"]})
    );
}
