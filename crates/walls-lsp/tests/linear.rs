//! The server's time grows linearly with its input: each feature (diagnostics published
//! after opening, semantic tokens, hover, formatting, code actions over the whole
//! document, the outline, folding, inlay hints over the whole document) is timed on a
//! document and on one twice as large, and the larger may take less than three times as
//! long (a quadratic feature takes four). Three documents: 100k diagnostics on as many
//! lines, one line of 10 MB with 100k tokens and diagnostics, and 100k safe fixes (the
//! "fix all" action compared each fix with every fix taken before: 20k took 10 s). The shortest of a few runs is taken,
//! and times under 20 ms count as 20 ms, so that noise on a busy machine is no failure;
//! a comparison that fails is measured again, up to three times.
//! These are the sizes of `cargo test --release -p walls-lsp --test linear`; a debug
//! build runs a tenth of them (`WALLS_LINEAR_SCALE` sets the factor). The times are
//! printed (`--nocapture`).

use futures::StreamExt;
use serde_json::{Value, json};
use std::time::{Duration, Instant};
use tower::{Service, ServiceExt};
use tower_lsp_server::jsonrpc::Request;
use tower_lsp_server::{ClientSocket, LspService};

const URI: &str = "file:///linear/scene.walls";
/// Times below this are noise: they count as this.
const FLOOR: Duration = Duration::from_millis(20);

async fn call(service: &mut LspService<walls_lsp::Backend>, req: Request) -> Option<Value> {
    let response = service.ready().await.unwrap().call(req).await.unwrap()?;
    response.into_parts().1.ok()
}

async fn request(
    service: &mut LspService<walls_lsp::Backend>,
    method: &'static str,
    params: Value,
) -> Value {
    call(
        service,
        Request::build(method).params(params).id(1).finish(),
    )
    .await
    .unwrap_or(Value::Null)
}

/// The features timed, in the order [`times`] gives them.
const FEATURES: [&str; 8] = [
    "open → diagnostics",
    "semantic tokens",
    "hover",
    "formatting",
    "code actions",
    "outline",
    "folding",
    "inlay hints",
];

/// Seconds per feature on `text` (see [`FEATURES`]). Returns the number of diagnostics
/// and tokens too.
async fn times(text: &str) -> ([Duration; 8], usize, usize) {
    let (mut service, mut socket): (_, ClientSocket) = walls_lsp::service();
    request(&mut service, "initialize", json!({"capabilities": {}})).await;
    let open = Request::build("textDocument/didOpen")
        .params(json!({"textDocument": {"uri": URI, "languageId": "walls", "version": 1, "text": text}}))
        .finish();
    let start = Instant::now();
    call(&mut service, open).await;
    let published = loop {
        let message = socket.next().await.unwrap();
        if message.method() == "textDocument/publishDiagnostics" {
            break message.params().cloned().unwrap();
        }
    };
    let open = start.elapsed();
    // All of them: those published, or the number the last one gives when they are
    // more than the server publishes.
    let published = published["diagnostics"].as_array().unwrap();
    let diagnostics = published
        .last()
        .and_then(|d| d["message"].as_str()?.split("of this file's ").nth(1))
        .and_then(|rest| rest.split(',').next()?.parse().ok())
        .unwrap_or(published.len());
    let doc = json!({"uri": URI});
    let start = Instant::now();
    let tokens = request(
        &mut service,
        "textDocument/semanticTokens/full",
        json!({"textDocument": doc}),
    )
    .await;
    let tokens_time = start.elapsed();
    let tokens = tokens["data"].as_array().unwrap().len() / 5;
    let last_line = text.lines().count() - 1;
    let last_column = text.lines().last().unwrap().encode_utf16().count() - 1;
    let start = Instant::now();
    request(
        &mut service,
        "textDocument/hover",
        json!({"textDocument": doc, "position": {"line": last_line, "character": last_column}}),
    )
    .await;
    let hover = start.elapsed();
    let start = Instant::now();
    request(
        &mut service,
        "textDocument/formatting",
        json!({"textDocument": doc, "options": {"tabSize": 2, "insertSpaces": true}}),
    )
    .await;
    let format = start.elapsed();
    let all = json!({"start": {"line": 0, "character": 0}, "end": {"line": last_line + 1, "character": 0}});
    let mut time = async |method: &'static str, params: Value| {
        let start = Instant::now();
        request(&mut service, method, params).await;
        start.elapsed()
    };
    let actions = time(
        "textDocument/codeAction",
        json!({"textDocument": doc, "range": all, "context": {"diagnostics": []}}),
    )
    .await;
    let outline = time("textDocument/documentSymbol", json!({"textDocument": doc})).await;
    let folding = time("textDocument/foldingRange", json!({"textDocument": doc})).await;
    let hints = time(
        "textDocument/inlayHint",
        json!({"textDocument": doc, "range": all}),
    )
    .await;
    (
        [
            open,
            tokens_time,
            hover,
            format,
            actions,
            outline,
            folding,
            hints,
        ],
        diagnostics,
        tokens,
    )
}

/// The sizes' factor: `WALLS_LINEAR_SCALE`, else 1 in an optimised build and 0.1 in a
/// debug build (whose checker takes some 20 s for 100k diagnostics).
fn scale() -> f64 {
    std::env::var("WALLS_LINEAR_SCALE")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(if cfg!(debug_assertions) { 0.1 } else { 1.0 })
}

/// How many times a comparison that fails is measured again before it counts: a busy
/// machine can slow one measure several times over, a quadratic feature fails every one.
const ATTEMPTS: usize = 3;

/// Runs `document(n)` and `document(2n)` a few times and checks every feature, measuring
/// again (up to [`ATTEMPTS`] times) while a feature looks more than linear.
async fn grows_linearly(name: &str, n: usize, document: impl Fn(usize) -> String) {
    let n = ((n as f64 * scale()) as usize).max(100);
    let (small, large) = (document(n), document(2 * n));
    for attempt in 1..=ATTEMPTS {
        let mut best = [[Duration::MAX; 8]; 2];
        let mut counts = [(0, 0); 2];
        for _ in 0..3 {
            for (k, text) in [&small, &large].into_iter().enumerate() {
                let (t, diagnostics, tokens) = times(text).await;
                counts[k] = (diagnostics, tokens);
                for (b, t) in best[k].iter_mut().zip(t) {
                    *b = (*b).min(t);
                }
            }
        }
        for k in 0..2 {
            println!(
                "{name} ({} bytes, {} diagnostics, {} tokens): {}",
                [&small, &large][k].len(),
                counts[k].0,
                counts[k].1,
                FEATURES
                    .iter()
                    .zip(best[k])
                    .map(|(f, t)| format!("{f} {t:.2?}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            );
        }
        assert!(counts[1].0 >= 2 * counts[0].0 - 2, "{counts:?}");
        let slow: Vec<String> = FEATURES
            .iter()
            .enumerate()
            .map(|(i, feature)| (feature, best[0][i].max(FLOOR), best[1][i].max(FLOOR)))
            .filter(|&(_, a, b)| b >= a * 3)
            .map(|(feature, a, b)| format!("{feature} takes {b:?} on twice the input of {a:?}"))
            .collect();
        if slow.is_empty() {
            return;
        }
        assert!(
            attempt < ATTEMPTS,
            "{name}: not linear in {ATTEMPTS} measures: {}",
            slow.join("; ")
        );
        println!("{name}: measuring again ({})", slow.join("; "));
    }
}

/// `n` lines, each an unknown word: `n` diagnostics.
fn many_lines(n: usize) -> String {
    let mut text = String::from("wall type plane\n");
    for i in 0..n {
        text.push_str(&format!("  raduis{i} 1\n"));
    }
    text
}

/// One line of `n` unknown words and `n` numbers (`n` diagnostics, `2n` tokens), with a
/// non-ASCII character every so often, as long as `n` makes it (about 100 bytes each: 10 MB for 100k).
fn one_long_line(n: usize) -> String {
    let mut text = String::from("wall type plane ");
    for i in 0..n {
        let word = if i % 64 == 0 { "µ" } else { "x" };
        text.push_str(&format!("{word}{i} 1.{i:0>90} "));
    }
    text.push('\n');
    text
}

/// A plane with `n` radii: `n` warnings with a safe fix each (C202 on all but the last,
/// C201 on the last).
fn many_fixes(n: usize) -> String {
    format!("wall type plane\n{}", "  radius 1\n".repeat(n))
}

#[tokio::test]
async fn a_hundred_thousand_fixes() {
    grows_linearly("many fixes", 50_000, many_fixes).await;
}

#[tokio::test]
async fn a_hundred_thousand_diagnostics() {
    grows_linearly("many lines", 50_000, many_lines).await;
}

#[tokio::test]
async fn a_ten_megabyte_line() {
    grows_linearly("one long line", 50_000, one_long_line).await;
}
