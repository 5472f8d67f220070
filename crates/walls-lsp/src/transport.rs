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
//! Memory has a bound: a body longer than [`MAX_MESSAGE`] bytes is answered (-32600,
//! and a message to the user naming its size) and skipped as it arrives, never kept,
//! and one holding more than [`MAX_VALUES`] JSON values (counted first, allocating
//! nothing) is answered the same way, before anything turns it into a
//! `serde_json::Value` (which costs up to some 600 bytes a value: `{"a":0}` is 7 bytes).
//! A message read costs at most a few copies of itself, and [`MAX_VALUES`] values.
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
/// The longest message the server reads: 256 MiB (a walls document that large would
/// take some 3 GB to check; VS Code gives extensions no file over 50 MB).
pub const MAX_MESSAGE: usize = 256 << 20;
/// The most JSON values (each object, array, string, number, `true`, `false` and `null`)
/// a message may hold: an editor's largest, `initialize`, has a few thousand.
pub const MAX_VALUES: usize = 100_000;

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
    /// A body longer than the limit, of this length; skipped.
    TooLarge(usize),
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
    /// The longest body kept; a longer one is skipped.
    max: usize,
    /// The bytes of a body too long still to skip.
    discard: usize,
}

impl<R: AsyncRead + Unpin> Frames<R> {
    /// The frames of `input`, each body at most `max` bytes.
    fn new(input: R, max: usize) -> Self {
        Frames {
            input,
            buf: Vec::new(),
            start: 0,
            skipping: false,
            max,
            discard: 0,
        }
    }

    /// The next frame, or `None` at the end of the input (an unfinished frame there is
    /// dropped).
    async fn next(&mut self) -> Option<Frame> {
        loop {
            let skipped = self.discard.min(self.buf.len() - self.start);
            self.start += skipped;
            self.discard -= skipped;
            if self.discard == 0
                && let Some(frame) = self.parse()
            {
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
        if length > self.max {
            // Its bytes are dropped as they come.
            self.start = body_start;
            self.discard = length;
            return Some(Frame::TooLarge(length));
        }
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

/// Why a frame is not passed on.
enum Refused {
    /// Not a message: answered with this error.
    Malformed(Error),
    /// Past a limit, which this says: answered with an invalid request (-32600) that says
    /// so, and told to the user.
    TooLarge(String),
}

/// The frame to pass on (a body tower-lsp reads as a request, a notification or a
/// response), or why not.
fn check(frame: Frame) -> Result<Vec<u8>, Refused> {
    let body = match frame {
        Frame::Body(body) => body,
        Frame::BadHeader => return Err(Refused::Malformed(Error::parse_error())),
        Frame::TooLarge(length) => {
            return Err(Refused::TooLarge(format!(
                "a message of {length} bytes, more than the {MAX_MESSAGE} the server reads"
            )));
        }
    };
    let mut values = Count::default();
    let counted = serde::de::DeserializeSeed::deserialize(
        &mut values,
        &mut serde_json::Deserializer::from_slice(&body),
    );
    if values.too_many {
        return Err(Refused::TooLarge(format!(
            "a message of more than {MAX_VALUES} JSON values, the most the server reads"
        )));
    }
    if counted.is_ok()
        && (serde_json::from_slice::<Request>(&body).is_ok()
            || serde_json::from_slice::<Response>(&body).is_ok())
    {
        return Ok(body);
    }
    // Only on the way to an error: is it JSON at all?
    Err(Refused::Malformed(
        match serde_json::from_slice::<serde::de::IgnoredAny>(&body) {
            Ok(_) => Error::invalid_request(),
            Err(_) => Error::parse_error(),
        },
    ))
}

/// The frames that answer a refused frame: the error (id `null`), and for one past a
/// limit, a message to the user (`window/showMessage`), since a notification's error
/// reaches no one.
fn answers(refused: Refused) -> Vec<Vec<u8>> {
    let (error, tell) = match refused {
        Refused::Malformed(error) => (error, None),
        Refused::TooLarge(what) => {
            let error = Error {
                message: format!("{what}: not read").into(),
                ..Error::invalid_request()
            };
            let message = serde_json::json!({
                "jsonrpc": "2.0",
                "method": "window/showMessage",
                "params": {"type": 1, "message": format!("walls: {what}; it was not read")},
            });
            (error, Some(message))
        }
    };
    let reply =
        serde_json::to_vec(&Response::from_error(Id::Null, error)).expect("a response serialises");
    std::iter::once(reply)
        .chain(tell.map(|m| m.to_string().into_bytes()))
        .map(|body| framed(&body))
        .collect()
}

/// The JSON values of a body, counted as it is read; allocating nothing (but the text of
/// an escaped string, one at a time), and stopping past [`MAX_VALUES`].
#[derive(Default)]
struct Count {
    values: usize,
    too_many: bool,
}

impl Count {
    /// One more value; an error past the limit.
    fn one<E: serde::de::Error>(&mut self) -> Result<(), E> {
        self.values += 1;
        if self.values > MAX_VALUES {
            self.too_many = true;
            return Err(E::custom("too many values"));
        }
        Ok(())
    }
}

impl<'de> serde::de::DeserializeSeed<'de> for &mut Count {
    type Value = ();
    fn deserialize<D: serde::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> serde::de::Visitor<'de> for &mut Count {
    type Value = ();
    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("JSON")
    }
    fn visit_bool<E: serde::de::Error>(self, _: bool) -> Result<(), E> {
        self.one()
    }
    fn visit_i64<E: serde::de::Error>(self, _: i64) -> Result<(), E> {
        self.one()
    }
    fn visit_u64<E: serde::de::Error>(self, _: u64) -> Result<(), E> {
        self.one()
    }
    fn visit_f64<E: serde::de::Error>(self, _: f64) -> Result<(), E> {
        self.one()
    }
    fn visit_str<E: serde::de::Error>(self, _: &str) -> Result<(), E> {
        self.one()
    }
    fn visit_unit<E: serde::de::Error>(self) -> Result<(), E> {
        self.one()
    }
    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        self.one()?;
        while seq.next_element_seed(&mut *self)?.is_some() {}
        Ok(())
    }
    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        self.one()?;
        while map.next_key_seed(&mut *self)?.is_some() {
            map.next_value_seed(&mut *self)?;
        }
        Ok(())
    }
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
    let mut frames = Frames::new(input, MAX_MESSAGE);
    while let Some(frame) = frames.next().await {
        match check(frame) {
            Ok(body) => {
                let header = format!("Content-Length: {}\r\n\r\n", body.len());
                if to_server.write_all(header.as_bytes()).await.is_err()
                    || to_server.write_all(&body).await.is_err()
                {
                    return;
                }
            }
            Err(refused) => {
                for answer in answers(refused) {
                    // The writer is gone only when the server is: nothing to answer.
                    let _ = replies.send(answer);
                }
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
    // The server's own answers are bounded by what it sends (docs/editors.md, "Limits").
    let mut frames = Frames::new(from_server, usize::MAX);
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

    /// The frames of `input` with bodies of at most `max` bytes: a body, or the length
    /// of one too long (as a negative number), or -32700 for a bad header.
    async fn frames_within(input: &[u8], max: usize) -> Vec<Result<String, i64>> {
        let mut frames = Frames::new(input, max);
        let mut out = Vec::new();
        while let Some(frame) = frames.next().await {
            out.push(match frame {
                Frame::Body(body) => Ok(String::from_utf8(body).unwrap()),
                Frame::BadHeader => Err(-32700),
                Frame::TooLarge(length) => Err(-(length as i64)),
            });
        }
        out
    }

    async fn frames(input: &[u8]) -> Vec<Result<String, i64>> {
        frames_within(input, MAX_MESSAGE).await
    }

    #[tokio::test]
    async fn a_body_too_long_is_skipped_never_kept() {
        let long = format!("Content-Length: 30\r\n\r\n{:<30}", "[1, 2, 3]");
        let input = format!("{long}Content-Length: 2\r\n\r\n{{}}{long}");
        assert_eq!(
            frames_within(input.as_bytes(), 10).await,
            [Err(-30), Ok("{}".into()), Err(-30)]
        );
        // Read a byte at a time, the buffer never holds the long body.
        let (mut client, server) = tokio::io::duplex(1);
        let writer = tokio::spawn(async move {
            client.write_all(input.as_bytes()).await.unwrap();
        });
        let mut frames = Frames::new(server, 10);
        let mut longest = 0;
        let mut got = Vec::new();
        while got.len() < 3 {
            let frame = frames.next().await.unwrap();
            longest = longest.max(frames.buf.len());
            got.push(matches!(frame, Frame::Body(_)));
        }
        // The rest of the last body, skipped to the end.
        assert!(frames.next().await.is_none());
        writer.await.unwrap();
        assert_eq!(got, [false, true, false]);
        assert!(longest <= PIPE + 30, "{longest}");
    }

    #[test]
    fn a_body_of_too_many_values_is_refused_before_it_is_a_value() {
        let values = |n: usize| format!("[{}0]", "0,".repeat(n - 2));
        let refused = |body: String| match check(Frame::Body(body.into_bytes())) {
            Err(Refused::TooLarge(what)) => Some(what),
            _ => None,
        };
        // The array and its numbers: MAX_VALUES values are read.
        assert_eq!(refused(values(MAX_VALUES)), None);
        assert_eq!(
            refused(values(MAX_VALUES + 1)).as_deref(),
            Some("a message of more than 100000 JSON values, the most the server reads")
        );
        // Keys count too.
        let object = format!("{{{}\"z\":0}}", r#""a":0,"#.repeat(MAX_VALUES / 2));
        assert!(refused(object).is_some());
        // The answer says so, and so does a message to the user.
        let answers = answers(Refused::TooLarge("a message of 9 bytes".into()));
        let text: Vec<String> = answers
            .iter()
            .map(|a| String::from_utf8(a.clone()).unwrap())
            .collect();
        assert!(
            text[0].ends_with(r#""message":"a message of 9 bytes: not read"},"id":null}"#),
            "{}",
            text[0]
        );
        assert!(
            text[1].contains(r#""method":"window/showMessage""#),
            "{}",
            text[1]
        );
        assert!(
            text[1].contains("walls: a message of 9 bytes; it was not read"),
            "{}",
            text[1]
        );
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
        let code = |body: &str| {
            check(Frame::Body(body.into())).map_err(|e| match e {
                Refused::Malformed(e) => e.code.code(),
                Refused::TooLarge(_) => 0,
            })
        };
        assert_eq!(code("{"), Err(-32700));
        assert_eq!(code("{}x"), Err(-32700));
        assert_eq!(code(""), Err(-32700));
        assert_eq!(code("{}"), Err(-32600));
        assert_eq!(code("[]"), Err(-32600));
        assert_eq!(code(r#"{"jsonrpc": "1.0", "method": "x"}"#), Err(-32600));
        assert!(code(r#"{"jsonrpc": "2.0", "method": "x"}"#).is_ok());
        assert!(matches!(
            check(Frame::BadHeader),
            Err(Refused::Malformed(e)) if e.code.code() == -32700
        ));
    }
}
