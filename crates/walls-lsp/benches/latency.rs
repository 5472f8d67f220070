//! Server-side latency on a 1,000-wall file, through the real service (JSON-RPC
//! requests in, responses and notifications out): diagnostics after a one-character
//! edit, hover, completion. Targets: under 5 ms, 1 ms and 1 ms. Run with
//! `cargo bench -p walls-lsp --bench latency`; figures in docs/performance.md.

use criterion::{Criterion, criterion_group, criterion_main};
use futures::StreamExt;
use serde_json::{Value, json};
use tower::{Service, ServiceExt};
use tower_lsp_server::jsonrpc::Request;

#[path = "../../walls-cli/benches/hull.rs"]
mod hull;

const URI: &str = "file:///bench/hull.walls";

async fn call(
    service: &mut tower_lsp_server::LspService<walls_lsp::Backend>,
    req: Request,
) -> Option<Value> {
    let response = service.ready().await.unwrap().call(req).await.unwrap()?;
    response.into_parts().1.ok()
}

fn latency(c: &mut Criterion) {
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .unwrap();
    let text = hull::triangles(1000);
    let (mut service, mut socket) = walls_lsp::service();
    runtime.block_on(async {
        call(&mut service, Request::build("initialize").params(json!({"capabilities": {}})).id(1).finish()).await;
        call(&mut service, Request::build("initialized").params(json!({})).finish()).await;
        call(
            &mut service,
            Request::build("textDocument/didOpen")
                .params(json!({"textDocument": {"uri": URI, "languageId": "walls", "version": 1, "text": text}}))
                .finish(),
        )
        .await;
        socket.next().await;
    });
    let mut group = c.benchmark_group("lsp-1k-walls");
    let mut version = 1;
    // The edit turns the first digit of the file's last number into another digit.
    let last_digit = text.trim_end().len() - 1;
    group.bench_function("edit-to-diagnostics", |b| {
        b.iter(|| {
            version += 1;
            let mut edited = text.clone();
            let digit = char::from(b'0' + (version % 10) as u8);
            edited.replace_range(last_digit..last_digit + 1, &digit.to_string());
            runtime.block_on(async {
                call(
                    &mut service,
                    Request::build("textDocument/didChange")
                        .params(json!({"textDocument": {"uri": URI, "version": version}, "contentChanges": [{"text": edited}]}))
                        .finish(),
                )
                .await;
                loop {
                    let m = socket.next().await.unwrap();
                    if m.method() == "textDocument/publishDiagnostics" {
                        break;
                    }
                }
            })
        })
    });
    let position = json!({"textDocument": {"uri": URI}, "position": {"line": 600, "character": 4}});
    let mut id = 10;
    group.bench_function("hover", |b| {
        b.iter(|| {
            id += 1;
            runtime.block_on(call(
                &mut service,
                Request::build("textDocument/hover")
                    .params(position.clone())
                    .id(id)
                    .finish(),
            ))
        })
    });
    group.bench_function("completion", |b| {
        b.iter(|| {
            id += 1;
            runtime.block_on(call(
                &mut service,
                Request::build("textDocument/completion")
                    .params(position.clone())
                    .id(id)
                    .finish(),
            ))
        })
    });
    group.finish();
}

criterion_group!(benches, latency);
criterion_main!(benches);
