//! Fuzz target: arbitrary bytes as the language server's input stream. Checks that the
//! server neither panics nor hangs (libFuzzer's `-timeout`) and ends when its input does.
//!
//! Input starting with `F` is a list of bodies, one a line, each framed with its right
//! `Content-Length` after an `initialize` and an `initialized`, so that random JSON
//! reaches the handlers; any other input is the raw stream (random framing).
#![no_main]

use libfuzzer_sys::fuzz_target;

/// `body` with its header.
fn frame(out: &mut Vec<u8>, body: &[u8]) {
    out.extend_from_slice(format!("Content-Length: {}\r\n\r\n", body.len()).as_bytes());
    out.extend_from_slice(body);
}

fuzz_target!(|data: &[u8]| {
    let input = match data.strip_prefix(b"F") {
        Some(bodies) => {
            let mut input = Vec::new();
            frame(
                &mut input,
                br#"{"jsonrpc":"2.0","id":0,"method":"initialize","params":{"capabilities":{}}}"#,
            );
            frame(
                &mut input,
                br#"{"jsonrpc":"2.0","method":"initialized","params":{}}"#,
            );
            for body in bodies.split(|&b| b == b'\n') {
                frame(&mut input, body);
            }
            input
        }
        None => data.to_vec(),
    };
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .expect("a runtime");
    runtime.block_on(walls_lsp::serve(&input[..], tokio::io::sink()));
});
