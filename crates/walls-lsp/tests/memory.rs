//! The memory of the server's answers, measured on its process (Linux: `VmHWM` in
//! `/proc/PID/status`, reset between requests through `/proc/PID/clear_refs`).
//!
//! * A mesh as `walls-mesh` writes it, of 10 MB (105,000 triangles) and of 20 MB: the
//!   process's peak, through opening it and every request, is at most 20 times the
//!   document (before, the outline alone peaked at 2.9 GB for 10 MB and 9 GB for 20 MB).
//! * Documents that make each answer as large as it can be (a diagnostic every 11
//!   bytes, a token every 2, a block every 15, a fix every 11, every line to re-indent,
//!   every wall inheriting), 10 MB each in an optimised build and 2 MB in a debug one
//!   (`WALLS_LINEAR_SCALE` sets the factor): what each request adds to the process's
//!   memory is at most 48 MB, or 48 MB and 16 times the document for formatting (the
//!   layout's own memory, some 15 times a document of one-line statements) and 5 times
//!   for "fix all" (the fixed text, in an edit).
//!
//! The figures are printed (`--nocapture`); docs/editors.md ("Limits") has them.
#![cfg(target_os = "linux")]

mod wire;

use serde_json::{Value, json};
use std::io::{BufReader, Write};
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};

const URI: &str = "file:///memory/scene.walls";
const MB: usize = 1 << 20;

/// A server process and its pipes.
struct Server {
    child: Child,
    input: ChildStdin,
    output: BufReader<ChildStdout>,
    next_id: i64,
}

impl Server {
    fn start() -> Server {
        let mut child = Command::new(env!("CARGO_BIN_EXE_walls-lsp"))
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .unwrap();
        let input = child.stdin.take().unwrap();
        let output = BufReader::new(child.stdout.take().unwrap());
        let mut s = Server {
            child,
            input,
            output,
            next_id: 1,
        };
        s.request("initialize", json!({"capabilities": {}}));
        s.send(json!({"jsonrpc": "2.0", "method": "initialized", "params": {}}));
        s
    }

    fn send(&mut self, message: Value) {
        self.input.write_all(&wire::frame(&message)).unwrap();
        self.input.flush().unwrap();
    }

    /// The next message's body.
    fn receive(&mut self) -> Vec<u8> {
        wire::read_body(&mut self.output)
    }

    /// Sends a request; the size of its answer.
    fn request(&mut self, method: &str, params: Value) -> usize {
        let id = self.next_id;
        self.next_id += 1;
        self.send(json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        loop {
            let body = self.receive();
            let message: Value = serde_json::from_slice(&body).unwrap();
            if message["id"] == id {
                assert!(message.get("error").is_none(), "{method}: {message}");
                return body.len();
            }
        }
    }

    /// Opens `text`; the size of the diagnostics published.
    fn open(&mut self, text: &str) -> usize {
        self.send(
            json!({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {
            "textDocument": {"uri": URI, "languageId": "walls", "version": 1, "text": text}}}),
        );
        loop {
            let body = self.receive();
            if serde_json::from_slice::<Value>(&body).unwrap()["method"]
                == "textDocument/publishDiagnostics"
            {
                return body.len();
            }
        }
    }

    /// A line of `/proc/PID/status`, in bytes.
    fn status(&self, key: &str) -> usize {
        let status = std::fs::read_to_string(format!("/proc/{}/status", self.child.id())).unwrap();
        let line = status.lines().find(|l| l.starts_with(key)).unwrap();
        let kb: usize = line.split_whitespace().nth(1).unwrap().parse().unwrap();
        kb * 1024
    }

    /// The peak since the last reset.
    fn peak(&self) -> usize {
        self.status("VmHWM:")
    }

    /// Starts a new peak from the memory in use now; what is in use now.
    fn reset(&self) -> usize {
        std::fs::write(format!("/proc/{}/clear_refs", self.child.id()), "5").unwrap();
        self.status("VmRSS:")
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A number as `walls-mesh` writes one: the shortest decimal of a double.
fn number(x: f64) -> String {
    format!("{x}")
}

/// Triangles as `walls-mesh` writes them (a relief of 0.25 squares, each as two), up to
/// `bytes` bytes.
fn mesh(bytes: usize) -> String {
    let mut text = String::from("# Made by walls-mesh from relief.stl.\n");
    let side = 500;
    let mut i = 0;
    while text.len() < bytes {
        let (x, y) = ((i % side) as f64 * 0.25, (i / side) as f64 * 0.25);
        let z = 0.001 * ((i * 7) % 17) as f64;
        for (o, v1, v2) in [
            ((x, y, z), (0.25, 0.0, 0.0), (0.0, 0.25, 0.01)),
            (
                (x + 0.25, y, z),
                (0.0, 0.25, 0.0),
                (-0.25, 0.25, 0.01 - z / 3.0),
            ),
        ] {
            text.push_str(&format!(
                "\nwall type triangle\n  origin {} {} {}\n  vertex1 {} {} {}\n  vertex2 {} {} {}\n",
                number(o.0),
                number(o.1),
                number(o.2),
                number(v1.0),
                number(v1.1),
                number(v1.2),
                number(v2.0),
                number(v2.1),
                number(v2.2)
            ));
        }
        i += 1;
    }
    text
}

/// `unit` repeated after `head` up to `bytes` bytes.
fn repeated(head: &str, unit: &str, bytes: usize) -> String {
    let mut text = String::from(head);
    text.push_str(&unit.repeat(bytes.saturating_sub(head.len()) / unit.len() + 1));
    text
}

/// Every request an editor makes, with its parameters for a document of `lines` lines.
fn requests(lines: usize) -> Vec<(&'static str, Value)> {
    let doc = json!({"uri": URI});
    let all = json!({"start": {"line": 0, "character": 0}, "end": {"line": lines, "character": 0}});
    let middle = json!({"line": lines / 2, "character": 3});
    vec![
        ("textDocument/documentSymbol", json!({"textDocument": doc})),
        (
            "textDocument/semanticTokens/full",
            json!({"textDocument": doc}),
        ),
        (
            "textDocument/semanticTokens/range",
            json!({"textDocument": doc, "range": all}),
        ),
        ("textDocument/foldingRange", json!({"textDocument": doc})),
        (
            "textDocument/inlayHint",
            json!({"textDocument": doc, "range": all}),
        ),
        (
            "textDocument/codeAction",
            json!({"textDocument": doc, "range": all, "context": {"diagnostics": []}}),
        ),
        (
            "textDocument/formatting",
            json!({"textDocument": doc, "options": {"tabSize": 2, "insertSpaces": true}}),
        ),
        (
            "textDocument/rangeFormatting",
            json!({"textDocument": doc, "range": all, "options": {"tabSize": 2, "insertSpaces": true}}),
        ),
        (
            "textDocument/hover",
            json!({"textDocument": doc, "position": middle}),
        ),
        (
            "textDocument/completion",
            json!({"textDocument": doc, "position": middle}),
        ),
        (
            "textDocument/definition",
            json!({"textDocument": doc, "position": middle}),
        ),
    ]
}

/// Opens `text` in a new server, then makes every request; for each, what it added to
/// the memory in use before it, and the size of its answer. The first is the opening,
/// with the process's peak, and the published diagnostics.
fn measure(text: &str) -> Vec<(&'static str, usize, usize)> {
    let mut s = Server::start();
    let before = s.reset();
    let published = s.open(text);
    let mut out = vec![("open", s.peak().saturating_sub(before), published)];
    for (method, params) in requests(text.lines().count()) {
        let before = s.reset();
        let answer = s.request(method, params);
        out.push((method, s.peak().saturating_sub(before), answer));
    }
    out
}

fn show(name: &str, size: usize, figures: &[(&str, usize, usize)]) {
    for (what, memory, answer) in figures {
        println!(
            "{name} ({:.1} MB): {what}: +{:.1} MB, answer {answer} bytes",
            size as f64 / MB as f64,
            *memory as f64 / MB as f64
        );
    }
}

#[test]
fn a_mesh_of_10_and_20_mb_peaks_under_20_times_its_size() {
    for bytes in [10_000_000, 20_000_000] {
        let text = mesh(bytes);
        let mut s = Server::start();
        s.open(&text);
        let mut worst = ("open", s.peak());
        for (method, params) in requests(text.lines().count()) {
            s.request(method, params);
            worst = worst.max((method, s.peak()));
        }
        let peak = s.peak();
        println!(
            "mesh of {:.1} MB: peak {:.1} MB ({:.1} times)",
            text.len() as f64 / MB as f64,
            peak as f64 / MB as f64,
            peak as f64 / text.len() as f64
        );
        assert!(
            peak <= 20 * text.len(),
            "a {} byte mesh peaked at {peak} bytes",
            text.len()
        );
        show("mesh", text.len(), &measure(&text));
    }
}

#[test]
fn every_answer_adds_a_bounded_amount_of_memory() {
    let scale = std::env::var("WALLS_LINEAR_SCALE")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(if cfg!(debug_assertions) { 0.2 } else { 1.0 });
    let bytes = (10_000_000.0 * scale) as usize;
    let documents = [
        (
            "a diagnostic every 11 bytes",
            repeated("wall type plane\n", "  raduis 1\n", bytes),
        ),
        (
            "a token every 2 bytes",
            repeated("wall type plane\n  origin", " 1", bytes) + "\n",
        ),
        (
            "a block every 15 bytes",
            repeated("", "wall type disk\n", bytes),
        ),
        (
            "every wall inherits",
            repeated("defaults\n  color 3\n", "wall type disk\n", bytes),
        ),
        (
            "a safe fix every 11 bytes",
            repeated("wall type plane\n", "  radius 1\n", bytes),
        ),
        (
            "every line to indent",
            repeated("", "wall type disk\nradius 1\n", bytes),
        ),
    ];
    let mut over = Vec::new();
    for (name, text) in &documents {
        let figures = measure(text);
        show(name, text.len(), &figures);
        for &(what, memory, _) in &figures[1..] {
            let times = match what {
                "textDocument/formatting" | "textDocument/rangeFormatting" => 16,
                "textDocument/codeAction" => 5,
                _ => 0,
            };
            let bound = 48 * MB + times * text.len();
            if memory > bound {
                over.push(format!(
                    "{name}: {what} added {memory} bytes, more than {bound}"
                ));
            }
        }
    }
    assert!(over.is_empty(), "{over:#?}");
}
