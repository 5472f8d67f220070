//! `walls-lsp`: the walls language server over standard input and output.

#[tokio::main]
async fn main() {
    walls_lsp::serve_stdio().await;
}
