//! The HTTP/1.1 the explorer needs and no more, written so that no client can exhaust the
//! server: one request per connection (`Connection: close`), GET only, no request body kept.
//!
//! One thread reads the request heads of every connection at once (non-blocking sockets,
//! polled), so a client that sends its head slowly holds no thread: it holds one of at most
//! [`MAX_PENDING`] buffers of at most [`MAX_HEAD`] bytes, for at most [`HEAD_DEADLINE`]
//! (`408`), and the oldest is closed when a new connection needs its place. A head over
//! [`MAX_HEAD`] bytes is `431`; a declared body over [`MAX_BODY`] bytes is `413` and one
//! sent in chunks `411` (none is read, nothing is allocated for it); a `Host` other than
//! the bound address is `421` (a web page cannot drive the API through DNS rebinding); a
//! head that is not HTTP is `400`. Every error is the CLI's JSON error document.

use crate::cli::io::to_json;
use crate::render::json::ErrorJson;
use std::io::{ErrorKind, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::time::{Duration, Instant};

/// The longest request head (request line and headers), in bytes.
pub const MAX_HEAD: usize = 16 * 1024;
/// The largest request body accepted (and discarded: no endpoint reads one), in bytes.
pub const MAX_BODY: u64 = 64 * 1024;
/// Connections whose head is still arriving, at most (the oldest gives way to a new one).
pub const MAX_PENDING: usize = 256;
/// Time from the connection to the end of its head.
pub const HEAD_DEADLINE: Duration = Duration::from_secs(5);
/// Time a reply may take to be written (a client that does not read is dropped).
pub const WRITE_TIMEOUT: Duration = Duration::from_secs(5);

/// How long the reader waits after a failed `accept` (no file descriptor left, ...).
const ACCEPT_RETRY: Duration = Duration::from_millis(50);

/// How long the reader sleeps when no connection made progress.
const POLL: Duration = Duration::from_millis(2);

/// One HTTP answer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Reply {
    /// HTTP status code.
    pub status: u16,
    /// The Content-Type header.
    pub content_type: &'static str,
    /// The body.
    pub body: Vec<u8>,
}

const JSON: &str = "application/json";

impl Reply {
    /// The CLI's error document with `status`.
    pub fn error(status: u16, message: String) -> Reply {
        Reply {
            status,
            content_type: JSON,
            body: to_json(&ErrorJson::new(message)).into_bytes(),
        }
    }
    /// A page.
    pub fn text(content_type: &'static str, body: &str) -> Reply {
        Reply {
            status: 200,
            content_type,
            body: body.as_bytes().to_vec(),
        }
    }
    /// A command's JSON document.
    pub fn json(status: u16, body: Vec<u8>) -> Reply {
        Reply {
            status,
            content_type: JSON,
            body,
        }
    }
}

fn reason(status: u16) -> &'static str {
    match status {
        200 => "OK",
        400 => "Bad Request",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        411 => "Length Required",
        413 => "Content Too Large",
        414 => "URI Too Long",
        421 => "Misdirected Request",
        422 => "Unprocessable Content",
        431 => "Request Header Fields Too Large",
        499 => "Client Closed Request",
        503 => "Service Unavailable",
        _ => "Internal Server Error",
    }
}

/// The bytes of `reply` on the wire.
pub fn encode(reply: &Reply) -> Vec<u8> {
    let mut head = format!(
        "HTTP/1.1 {} {}\r\nContent-Type: {}\r\nContent-Length: {}\r\nCache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\nConnection: close\r\n",
        reply.status,
        reason(reply.status),
        reply.content_type,
        reply.body.len()
    );
    if reply.status == 405 {
        head.push_str("Allow: GET\r\n");
    }
    if reply.status == 503 {
        head.push_str("Retry-After: 1\r\n");
    }
    head.push_str("\r\n");
    let mut bytes = head.into_bytes();
    bytes.extend_from_slice(&reply.body);
    bytes
}

/// Writes `reply` and closes (a client that went away is not an error of ours).
pub fn send(mut stream: TcpStream, reply: &Reply) {
    let _ = stream.set_nonblocking(false);
    let _ = stream.set_write_timeout(Some(WRITE_TIMEOUT));
    let _ = stream.write_all(&encode(reply));
    let _ = stream.flush();
    let _ = stream.shutdown(std::net::Shutdown::Write);
}

/// A request head that passed every check.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Head {
    /// The method (`GET`, ...).
    pub method: String,
    /// The request target (path and query).
    pub target: String,
    /// Body bytes still to arrive after the head (declared, at most [`MAX_BODY`]).
    pub body_left: u64,
}

/// The checked head of `raw` (the bytes up to and without the blank line; `extra` body
/// bytes already read after it), for a server bound to `port`.
pub fn parse_head(raw: &[u8], extra: usize, port: u16) -> Result<Head, Reply> {
    let bad = |what: &str| Reply::error(400, format!("malformed request: {what}"));
    let text = std::str::from_utf8(raw).map_err(|_| bad("the head is not UTF-8"))?;
    let mut lines = text.split("\r\n");
    let line = lines.next().unwrap_or("");
    let mut parts = line.split(' ');
    let (Some(method), Some(target), Some(version), None) =
        (parts.next(), parts.next(), parts.next(), parts.next())
    else {
        return Err(bad("the request line is not 'METHOD TARGET HTTP/1.x'"));
    };
    let token = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_alphabetic());
    let printable = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_graphic());
    if !token(method) || !printable(target) || !matches!(version, "HTTP/1.1" | "HTTP/1.0") {
        return Err(bad("the request line is not 'METHOD TARGET HTTP/1.x'"));
    }
    let (mut host, mut length, mut chunked) = (None, None::<u64>, false);
    for l in lines {
        let (name, value) = l
            .split_once(':')
            .ok_or_else(|| bad("a header without ':'"))?;
        let value = value.trim();
        match name.to_ascii_lowercase().as_str() {
            "host" if host.is_some() => return Err(bad("two Host headers")),
            "host" => host = Some(value.to_string()),
            "content-length" => {
                let n: u64 = value
                    .parse()
                    .map_err(|_| bad("Content-Length is not a number"))?;
                if length.is_some_and(|m| m != n) {
                    return Err(bad("two different Content-Length headers"));
                }
                length = Some(n);
            }
            "transfer-encoding" => chunked = true,
            _ => {}
        }
    }
    check_host(host.as_deref(), version, port)?;
    if chunked {
        return Err(Reply::error(
            411,
            "request bodies are not served (no endpoint reads one): send none, or a Content-Length"
                .into(),
        ));
    }
    let length = length.unwrap_or(0);
    if length > MAX_BODY {
        return Err(Reply::error(
            413,
            format!("the request declares a body of {length} bytes; at most {MAX_BODY} are accepted (no endpoint reads one)"),
        ));
    }
    Ok(Head {
        method: method.to_string(),
        target: target.to_string(),
        body_left: length.saturating_sub(extra as u64),
    })
}

/// The `Host` must name this server: 127.0.0.1, localhost or [::1], with its port or
/// none. HTTP/1.1 requires the header; HTTP/1.0 may omit it.
fn check_host(host: Option<&str>, version: &str, port: u16) -> Result<(), Reply> {
    let Some(host) = host else {
        if version == "HTTP/1.0" {
            return Ok(());
        }
        return Err(Reply::error(
            400,
            "malformed request: no Host header".into(),
        ));
    };
    let (name, at) = match host.rsplit_once(':') {
        Some((n, p)) if !n.ends_with(':') && p.bytes().all(|b| b.is_ascii_digit()) => (n, Some(p)),
        _ => (host, None),
    };
    let ours = matches!(
        name.to_ascii_lowercase().as_str(),
        "127.0.0.1" | "localhost" | "[::1]"
    ) && at.is_none_or(|p| p.parse::<u16>() == Ok(port));
    if ours {
        Ok(())
    } else {
        Err(Reply::error(
            421,
            format!("Host '{host}' is not this server: it answers as 127.0.0.1:{port} or localhost:{port} only"),
        ))
    }
}

/// A connection whose head is complete: its stream, and the checked head or the reply
/// that refuses it.
pub struct Ready {
    /// The connection.
    pub stream: TcpStream,
    /// The head, or why it is refused.
    pub head: Result<Head, Reply>,
}

/// A connection whose head is still arriving.
struct Pending {
    stream: TcpStream,
    buf: Vec<u8>,
    since: Instant,
}

/// Reads request heads from `listener` forever, handing each complete one to `deliver`.
pub fn read_heads(listener: &TcpListener, port: u16, mut deliver: impl FnMut(Ready)) {
    let mut pending: Vec<Pending> = Vec::new();
    loop {
        if pending.is_empty() {
            // nothing to poll: wait for a connection
            let _ = listener.set_nonblocking(false);
            match listener.accept() {
                Ok((s, _)) => admit(&mut pending, s),
                // e.g. no file descriptor left: wait rather than spin
                Err(_) => std::thread::sleep(ACCEPT_RETRY),
            }
            let _ = listener.set_nonblocking(true);
        }
        while let Ok((s, _)) = listener.accept() {
            admit(&mut pending, s);
        }
        let mut progressed = false;
        let mut i = 0;
        while i < pending.len() {
            match step(&mut pending[i], port) {
                Step::Wait => i += 1,
                Step::Read => {
                    progressed = true;
                    i += 1;
                }
                Step::Done(head) => {
                    progressed = true;
                    let p = pending.swap_remove(i);
                    match head {
                        Some(head) => deliver(Ready {
                            stream: p.stream,
                            head,
                        }),
                        None => drop(p),
                    }
                }
            }
        }
        if !progressed {
            std::thread::sleep(POLL);
        }
    }
}

/// Takes a new connection, closing the oldest pending one when all places are taken.
fn admit(pending: &mut Vec<Pending>, stream: TcpStream) {
    if stream.set_nonblocking(true).is_err() {
        return;
    }
    if pending.len() >= MAX_PENDING {
        if let Some(oldest) = (0..pending.len()).min_by_key(|&i| pending[i].since) {
            pending.swap_remove(oldest);
        }
    }
    pending.push(Pending {
        stream,
        buf: Vec::new(),
        since: Instant::now(),
    });
}

enum Step {
    /// Nothing new.
    Wait,
    /// Bytes arrived; the head is not complete.
    Read,
    /// The head is complete (or refused), or the connection is gone (`None`).
    Done(Option<Result<Head, Reply>>),
}

/// Reads what has arrived on one pending connection.
fn step(p: &mut Pending, port: u16) -> Step {
    if p.since.elapsed() > HEAD_DEADLINE {
        let why = format!(
            "the request head did not arrive within {} s",
            HEAD_DEADLINE.as_secs()
        );
        return Step::Done(Some(Err(Reply::error(408, why))));
    }
    let mut chunk = [0u8; 4096];
    match p.stream.read(&mut chunk) {
        Ok(0) => Step::Done(None),
        Ok(n) => {
            let seen = p.buf.len().saturating_sub(3);
            p.buf.extend_from_slice(&chunk[..n]);
            if let Some(end) = p.buf[seen..].windows(4).position(|w| w == b"\r\n\r\n") {
                let end = seen + end;
                if end > MAX_HEAD {
                    return Step::Done(Some(Err(too_large())));
                }
                let extra = p.buf.len() - end - 4;
                return Step::Done(Some(parse_head(&p.buf[..end], extra, port)));
            }
            if p.buf.len() > MAX_HEAD {
                return Step::Done(Some(Err(too_large())));
            }
            Step::Read
        }
        Err(e) if e.kind() == ErrorKind::WouldBlock || e.kind() == ErrorKind::Interrupted => {
            Step::Wait
        }
        Err(_) => Step::Done(None),
    }
}

fn too_large() -> Reply {
    Reply::error(
        431,
        format!("the request head is longer than {MAX_HEAD} bytes"),
    )
}

/// Reads and drops the rest of a small body (so that closing does not reset the
/// connection before the client reads the reply), for at most a second.
pub fn drain(stream: &mut TcpStream, mut left: u64) {
    let _ = stream.set_nonblocking(false);
    let _ = stream.set_read_timeout(Some(Duration::from_secs(1)));
    let mut chunk = [0u8; 4096];
    while left > 0 {
        match stream.read(&mut chunk) {
            Ok(0) | Err(_) => return,
            Ok(n) => left = left.saturating_sub(n as u64),
        }
    }
}
