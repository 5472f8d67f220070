//! Every renderer takes time linear in the text and the number of diagnostics.
//!
//! Two inputs, each at a quarter size and at full size: 100,000 diagnostics on as
//! many lines, each with a secondary label on the first line (a mistake repeated over
//! every wall), and 100,000 diagnostics on one 10 MB line. Wall-clock bounds flake on a
//! loaded machine, so the test compares the two sizes instead: four times the input
//! must take less than eight times as long (linear time gives four, quadratic sixteen),
//! with the best of three runs each. The human renderer's output on the long line is
//! also bounded: a window per diagnostic, never the line.

use std::time::{Duration, Instant};
use walls_diagnostics::render::{self, FileReport, ToolInfo};
use walls_diagnostics::{Code, Diagnostic};

static CODE: Code = Code {
    id: "C206",
    name: "sticky-wall-order",
    summary: "A sticky wall after a non-sticky one.",
    explanation: "Bad:\n```walls\nwall\n```\n\nGood:\n```walls\nwall\n```\n",
};

/// `n` lines, each with a diagnostic and a label on the first line.
fn many_lines(n: usize) -> (String, Vec<Diagnostic>) {
    let mut source = String::new();
    let mut diagnostics = Vec::with_capacity(n);
    for i in 0..n {
        let at = source.len();
        source.push_str(&format!("wall type disk epsn 0 # μ {i}\n"));
        diagnostics.push(
            Diagnostic::warning(
                &CODE,
                at + 15..at + 21,
                "sticky wall after a non-sticky one",
            )
            .with_label(0..4, "the first non-sticky wall")
            .with_help("list sticky walls first"),
        );
    }
    (source, diagnostics)
}

/// One line of `n` × 100 bytes with a diagnostic every 100 bytes.
fn long_line(n: usize) -> (String, Vec<Diagnostic>) {
    let chunk = format!("{:μ<93}epsn 0 ", "");
    let source: String = chunk.repeat(n) + "\n";
    let diagnostics = (0..n)
        .map(|i| {
            let at = i * chunk.len() + chunk.len() - 7;
            Diagnostic::warning(&CODE, at..at + 6, "sticky").with_label(0..2, "line start")
        })
        .collect();
    (source, diagnostics)
}

type Renderer = fn(&mut Vec<u8>, &[FileReport]);

fn renderers() -> [(&'static str, Renderer); 5] {
    [
        ("human", |out, files| {
            for f in files {
                render::human(out, f, true).unwrap();
            }
        }),
        ("json", |out, files| render::json(out, files, &[]).unwrap()),
        ("sarif", |out, files| {
            let tool = ToolInfo {
                name: "walls-lint",
                version: "0",
                information_uri: None,
            };
            render::sarif(out, files, &[], &tool, &[&CODE]).unwrap()
        }),
        ("github", |out, files| {
            render::github(out, files, &[]).unwrap()
        }),
        ("gitlab", |out, files| {
            render::gitlab(out, files, &[]).unwrap()
        }),
    ]
}

/// The best of three runs of `renderer` over the input, and the bytes it wrote.
fn time(renderer: Renderer, input: &(String, Vec<Diagnostic>)) -> (Duration, usize) {
    let file = FileReport {
        path: "scene.walls",
        source: &input.0,
        diagnostics: &input.1,
    };
    let mut best = Duration::MAX;
    let mut bytes = 0;
    for _ in 0..3 {
        let mut out = Vec::new();
        let start = Instant::now();
        renderer(&mut out, &[file]);
        best = best.min(start.elapsed());
        bytes = out.len();
    }
    (best, bytes)
}

#[test]
fn every_renderer_is_linear() {
    const FULL: usize = 100_000;
    for (input_name, make) in [
        ("100k lines", many_lines as fn(usize) -> _),
        ("10 MB line", long_line),
    ] {
        let quarter = make(FULL / 4);
        let full = make(FULL);
        for (name, renderer) in renderers() {
            let (small, _) = time(renderer, &quarter);
            let (large, bytes) = time(renderer, &full);
            eprintln!(
                "{input_name:>10} {name:>6}: {:>5} diagnostics {small:>10.1?}, {FULL} {large:>10.1?} ({bytes} bytes out)",
                FULL / 4
            );
            assert!(
                large < small * 8 + Duration::from_millis(50),
                "{name} on {input_name}: {small:?} for a quarter, {large:?} for all"
            );
            if input_name == "10 MB line" && name == "human" {
                assert!(bytes < FULL * 1000, "{bytes} bytes of snippets");
            }
        }
    }
}
