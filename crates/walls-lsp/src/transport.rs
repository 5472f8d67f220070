//! The framing in front of tower-lsp's server, so that no message can stop it.
//!
//! tower-lsp's transport answers the first undecodable message and then stops reading
//! (its framed reader ends after a codec error), so the server exited 0 after one bad
//! frame. Here every frame is read and checked first:
//! - a header block that is not `Name: value` lines with one valid `Content-Length` is
//!   answered with a parse error (-32700, id `null`) and skipped up to the next
//!   `Content-Length`;
//! - a body that is not JSON is a parse error (-32700), JSON that is not a JSON-RPC
//!   request, notification or response (`{}`, an array, `"jsonrpc": "1.0"`, …) an
//!   invalid request (-32600), both with id `null` as JSON-RPC 2.0 requires when the id
//!   could not be read; a body that does not parse but holds a `Content-Length` (one
//!   whose length was too large swallowed the next frame) is read again from there;
//! - every other frame is passed on, re-framed with only its `Content-Length`.
//!
//! The answers go out through the same output as the server's messages: the server
//! writes into a pipe, and one writer copies its frames and these answers whole, one
//! after the other. The server ends at `exit` or at the end of the input, as before.

use memchr::memmem;
use tokio::io::{AsyncRead, AsyncReadExt, AsyncWrite, AsyncWriteExt, DuplexStream};
use tokio::sync::mpsc;
use tower_lsp_server::Server;
use tower_lsp_server::jsonrpc::{Error, Id, Request, Response};

/// The header that starts a frame.
const CONTENT_LENGTH: &[u8] = b"Content-Length";
/// A header block longer than this without its blank line is not one.
const MAX_HEADER: usize = 64 * 1024;
/// The capacity of the pipes to and from the server.
const PIPE: usize = 64 * 1024;

/// Serves LSP on `input` and `output` until `exit` or the end of the input; no bytes
/// make it panic or stop early.
pub async fn serve<I, O>(input: I, output: O)
where
    I: AsyncRead + Unpin,
    O: AsyncWrite + Unpin,
{
    let (service, socket) = crate::service();
    let (server_in, to_server) = tokio::io::duplex(PIPE);
    let (server_out, from_server) = tokio::io::duplex(PIPE);
    let (replies, replies_rx) = mpsc::unbounded_channel();
    let server = Server::new(server_in, server_out, socket).serve(service);
    let write = write_out(from_server, replies_rx, output);
    // The input may stay open after `exit`: the server's end ends everything.
    let feed = async {
        feed(input, to_server, replies).await;
        std::future::pending::<()>().await
    };
    tokio::select! {
        _ = async { tokio::join!(server, write) } => {}
        () = feed => {}
    }
}

/// What a frame held.
enum Frame {
    /// A message's body.
    Body(Vec<u8>),
    /// A header block that does not give the body's length; skipped.
    BadHeader,
}

/// Frames read from a byte stream. Cancel-safe: everything read is kept in `buf`
/// before any wait.
struct Frames<R> {
    input: R,
    buf: Vec<u8>,
    /// Where the unread bytes of `buf` start.
    start: usize,
    /// After a bad header: looking for the next `Content-Length`.
    skipping: bool,
}

impl<R: AsyncRead + Unpin> Frames<R> {
    fn new(input: R) -> Self {
        Frames {
            input,
            buf: Vec::new(),
            start: 0,
            skipping: false,
        }
    }

    /// The next frame, or `None` at the end of the input (an unfinished frame there is
    /// dropped).
    async fn next(&mut self) -> Option<Frame> {
        loop {
            if let Some(frame) = self.parse() {
                return Some(frame);
            }
            if self.start > 0 {
                self.buf.drain(..self.start);
                self.start = 0;
            }
            self.buf.reserve(PIPE);
            match self.input.read_buf(&mut self.buf).await {
                Ok(0) | Err(_) => return None,
                Ok(_) => {}
            }
        }
    }

    /// A frame from the bytes read so far, if they hold one.
    fn parse(&mut self) -> Option<Frame> {
        if self.skipping {
            let rest = &self.buf[self.start..];
            match memmem::find(rest, CONTENT_LENGTH) {
                Some(at) => {
                    self.start += at;
                    self.skipping = false;
                }
                None => {
                    // Keep what could be the start of a `Content-Length` cut in two.
                    self.start += rest.len().saturating_sub(CONTENT_LENGTH.len() - 1);
                    return None;
                }
            }
        }
        let rest = &self.buf[self.start..];
        let Some(end) = memmem::find(rest, b"\r\n\r\n") else {
            if rest.len() > MAX_HEADER {
                return Some(self.bad_header());
            }
            return None;
        };
        let Some(length) = content_length(&rest[..end]) else {
            return Some(self.bad_header());
        };
        let body_start = self.start + end + 4;
        let body = self.buf.get(body_start..body_start.checked_add(length)?)?;
        if let Some(at) = memmem::find(body, CONTENT_LENGTH)
            && serde_json::from_slice::<serde::de::IgnoredAny>(body).is_err()
        {
            // A length too large took in the next frame: answer, and read it.
            let body = body[..at].to_vec();
            self.start = body_start + at;
            return Some(Frame::Body(body));
        }
        let body = body.to_vec();
        self.start = body_start + length;
        Some(Frame::Body(body))
    }

    /// Skips a bad header block, to the next `Content-Length` after its start.
    fn bad_header(&mut self) -> Frame {
        self.start += 1;
        self.skipping = true;
        Frame::BadHeader
    }
}

/// The `Content-Length` of a header block: `Name: value` lines, names in any case, the
/// length given once (or the same twice), other headers ignored.
fn content_length(block: &[u8]) -> Option<usize> {
    let block = std::str::from_utf8(block).ok()?;
    let mut length = None;
    for line in block.split("\r\n") {
        let (name, value) = line.split_once(':')?;
        if name.trim().eq_ignore_ascii_case("content-length") {
            let value = value.trim();
            if value.is_empty() || !value.bytes().all(|b| b.is_ascii_digit()) {
                return None;
            }
            let n: usize = value.parse().ok()?;
            if length.is_some_and(|l| l != n) {
                return None;
            }
            length = Some(n);
        }
    }
    length
}

/// The frame to pass on (a body tower-lsp reads as a request, a notification or a
/// response), or the error to answer.
fn check(frame: Frame) -> Result<Vec<u8>, Error> {
    let Frame::Body(body) = frame else {
        return Err(Error::parse_error());
    };
    if serde_json::from_slice::<Request>(&body).is_ok()
        || serde_json::from_slice::<Response>(&body).is_ok()
    {
        return Ok(body);
    }
    // Only on the way to an error: is it JSON at all?
    Err(
        match serde_json::from_slice::<serde::de::IgnoredAny>(&body) {
            Ok(_) => Error::invalid_request(),
            Err(_) => Error::parse_error(),
        },
    )
}

/// `body` with its header.
fn framed(body: &[u8]) -> Vec<u8> {
    let mut out = format!("Content-Length: {}\r\n\r\n", body.len()).into_bytes();
    out.extend_from_slice(body);
    out
}

/// Reads the client's frames: good ones go to the server, bad ones are answered.
async fn feed<R: AsyncRead + Unpin>(
    input: R,
    mut to_server: DuplexStream,
    replies: mpsc::UnboundedSender<Vec<u8>>,
) {
    let mut frames = Frames::new(input);
    while let Some(frame) = frames.next().await {
        match check(frame) {
            Ok(body) => {
                if to_server.write_all(&framed(&body)).await.is_err() {
                    return;
                }
            }
            Err(error) => {
                let reply = serde_json::to_vec(&Response::from_error(Id::Null, error))
                    .expect("a response serialises");
                // The writer is gone only when the server is: nothing to answer.
                let _ = replies.send(framed(&reply));
            }
        }
    }
}

/// Writes the server's frames and the answers to bad frames, each whole, until the
/// server ends (then the answers already queued).
async fn write_out<W: AsyncWrite + Unpin>(
    from_server: DuplexStream,
    mut replies: mpsc::UnboundedReceiver<Vec<u8>>,
    mut output: W,
) {
    let mut frames = Frames::new(from_server);
    loop {
        // The answers first: an answer is queued before the frame after the bad one
        // reaches the server, so the client gets them in the order it sent them.
        let bytes = tokio::select! {
            biased;
            Some(reply) = replies.recv() => reply,
            frame = frames.next() => match frame {
                Some(Frame::Body(body)) => framed(&body),
                _ => break,
            },
        };
        if write(&mut output, &bytes).await.is_err() {
            return;
        }
    }
    while let Ok(reply) = replies.try_recv() {
        if write(&mut output, &reply).await.is_err() {
            return;
        }
    }
}

async fn write<W: AsyncWrite + Unpin>(output: &mut W, bytes: &[u8]) -> std::io::Result<()> {
    output.write_all(bytes).await?;
    output.flush().await
}

#[cfg(test)]
mod tests {
    use super::*;

    async fn frames(input: &[u8]) -> Vec<Result<String, i64>> {
        let mut frames = Frames::new(input);
        let mut out = Vec::new();
        while let Some(frame) = frames.next().await {
            out.push(match frame {
                Frame::Body(body) => Ok(String::from_utf8(body).unwrap()),
                Frame::BadHeader => Err(-32700),
            });
        }
        out
    }

    #[tokio::test]
    async fn bad_headers_are_skipped_to_the_next_frame() {
        let input = b"Content-Length: x\r\n\r\n{}garbage\r\n\r\nContent-Length: 2\r\n\r\n{}\
            content-length:3\r\nContent-Type: a\r\n\r\n[1]Content-Length: 25\r\n\r\n{}Content-Length: 2\r\n\r\n{}";
        assert_eq!(
            frames(input).await,
            [
                Err(-32700),
                Ok("{}".into()),
                Ok("[1]".into()),
                Ok("{}".into()),
                Ok("{}".into())
            ]
        );
    }

    #[test]
    fn content_lengths() {
        assert_eq!(content_length(b"Content-Length: 12"), Some(12));
        assert_eq!(content_length(b"CONTENT-LENGTH:12\r\nX: y"), Some(12));
        for bad in [
            &b"Content-Length: -1"[..],
            b"Content-Length: 1e3",
            b"Content-Length: 99999999999999999999999",
            b"Content-Length: 1\r\nContent-Length: 2",
            b"Content-Type: x",
            b"garbage",
            b"Content-Length: \xff",
        ] {
            assert_eq!(content_length(bad), None, "{bad:?}");
        }
    }

    #[test]
    fn answers_say_what_was_wrong() {
        let code = |body: &str| check(Frame::Body(body.into())).map_err(|e| e.code.code());
        assert_eq!(code("{"), Err(-32700));
        assert_eq!(code("{}x"), Err(-32700));
        assert_eq!(code(""), Err(-32700));
        assert_eq!(code("{}"), Err(-32600));
        assert_eq!(code("[]"), Err(-32600));
        assert_eq!(code(r#"{"jsonrpc": "1.0", "method": "x"}"#), Err(-32600));
        assert!(code(r#"{"jsonrpc": "2.0", "method": "x"}"#).is_ok());
        assert_eq!(check(Frame::BadHeader).unwrap_err().code.code(), -32700);
    }
}
