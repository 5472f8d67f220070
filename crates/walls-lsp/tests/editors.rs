//! The real binary with real clients: raw JSON-RPC over standard input and output,
//! Neovim (headless, `tests/nvim/lsp.lua`) as a user's editor, and the Neovim plugin of
//! `editors/neovim` (`tests/nvim/plugin.lua`).

mod wire;

use serde_json::{Value, json};
use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};
use wire::frame;

fn read_message(out: &mut impl BufRead) -> Value {
    serde_json::from_slice(&wire::read_body(out)).unwrap()
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

fn start() -> (
    std::process::Child,
    std::process::ChildStdin,
    BufReader<std::process::ChildStdout>,
) {
    let mut server = Command::new(env!("CARGO_BIN_EXE_walls-lsp"))
        .arg("--stdio")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let input = server.stdin.take().unwrap();
    let output = BufReader::new(server.stdout.take().unwrap());
    // A server that hangs is killed, so that the test reading its output fails.
    let pid = server.id().to_string();
    std::thread::spawn(move || {
        std::thread::sleep(std::time::Duration::from_secs(30));
        let _ = Command::new("kill").arg(pid).status();
    });
    (server, input, output)
}

/// Waits for the process to end, for at most ten seconds.
fn wait(server: &mut std::process::Child) -> std::process::ExitStatus {
    for _ in 0..1000 {
        if let Some(status) = server.try_wait().unwrap() {
            return status;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    server.kill().unwrap();
    panic!("the server did not end");
}

#[test]
fn bad_frames_are_answered_and_the_server_keeps_serving() {
    let (mut server, mut input, mut output) = start();
    let error = |code: i64| json!({"jsonrpc": "2.0", "error": {"code": code, "message": if code == -32700 { "Parse error" } else { "Invalid request" }}, "id": null});
    // Not JSON, JSON but no request, a missing length, a length that is no number (each
    // bad header skipped to the next `Content-Length`).
    for (bad, code) in [
        (&b"Content-Length: 10\r\n\r\n{\"jsonrpc\""[..], -32700),
        (b"Content-Length: 2\r\n\r\n{}", -32600),
        (b"Content-Type: text/plain\r\n\r\n", -32700),
        (b"Content-Length: 9x\r\n\r\n{\"jsonrpc\"", -32700),
    ] {
        input.write_all(bad).unwrap();
        assert_eq!(
            read_message(&mut output),
            error(code),
            "{}",
            String::from_utf8_lossy(bad)
        );
    }
    input.write_all(&frame(&json!({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}}))).unwrap();
    assert_eq!(
        read_message(&mut output)["result"]["serverInfo"]["name"],
        "walls-lsp"
    );
    // The next frame read as part of a body too long: an error, then the frame.
    let shutdown = frame(&json!({"jsonrpc": "2.0", "id": 2, "method": "shutdown"}));
    input.write_all(b"Content-Length: 30\r\n\r\n{").unwrap();
    input.write_all(&shutdown).unwrap();
    input.write_all(&shutdown).unwrap();
    assert_eq!(read_message(&mut output), error(-32700));
    assert_eq!(read_message(&mut output)["id"], 2);
    // `exit` ends the server even if the client keeps its input open.
    input
        .write_all(&frame(&json!({"jsonrpc": "2.0", "method": "exit"})))
        .unwrap();
    assert!(wait(&mut server).success());
    drop(input);
}

#[test]
fn help_and_version_print_and_exit() {
    let run = |arg: &str| {
        Command::new(env!("CARGO_BIN_EXE_walls-lsp"))
            .arg(arg)
            .stdin(Stdio::null())
            .output()
            .unwrap()
    };
    let help = run("--help");
    assert_eq!(help.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&help.stdout).contains("Usage: walls-lsp"));
    let version = run("--version");
    assert_eq!(version.status.code(), Some(0));
    assert_eq!(
        String::from_utf8_lossy(&version.stdout),
        format!("walls-lsp {}\n", env!("CARGO_PKG_VERSION"))
    );
    let unknown = run("--port=9");
    assert_eq!(unknown.status.code(), Some(2));
    assert!(unknown.stdout.is_empty());
    assert!(String::from_utf8_lossy(&unknown.stderr).contains("Usage: walls-lsp"));
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
