//! The panel's HTTP server: one thread, non-blocking sockets, bounded everywhere.
//!
//! - At most [`MAX_CONNECTIONS`] connections at once; one more is answered `503` and
//!   closed. A request must arrive whole within [`REQUEST_TIMEOUT`] (else `408`), its
//!   head within [`MAX_HEAD`] bytes (`431`), its body within [`MAX_BODY`] (`413`).
//! - Every request carries the token (`?token=` or the `X-MCCL-Token` header), else `403`
//!   and nothing else happens. Controls are `POST` only (`405` otherwise).
//! - One request per connection (`Connection: close`), except the event stream, which
//!   stays open and gets the state [`PUSH_EVERY`]. A client that does not take its
//!   bytes (more than [`MAX_PENDING`] waiting) is dropped: nobody waits for a client.
//!
//! Routes: `GET /` the page, `GET /api/state` the state as JSON, `GET /api/events` the
//! state as server-sent events, `POST /api/control` a control (JSON body, see
//! [`super::control::Control`]).

use super::control;
use super::state::Source;
use std::io::{ErrorKind, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Connections served at once.
pub const MAX_CONNECTIONS: usize = 16;
/// Largest request head (request line and headers), bytes.
pub const MAX_HEAD: usize = 8 * 1024;
/// Largest request body, bytes.
pub const MAX_BODY: usize = 16 * 1024;
/// Bytes an event-stream client may leave unread before it is dropped.
pub const MAX_PENDING: usize = 256 * 1024;
/// Time a client has to send its whole request.
pub const REQUEST_TIMEOUT: Duration = Duration::from_secs(5);
/// Time between two events of the stream: 40 ms, 25 updates a second.
pub const PUSH_EVERY: Duration = Duration::from_millis(40);
/// The engine keeps copying its view this long after the last request.
const WANT_FOR: Duration = Duration::from_secs(2);
/// The loop's sleep when nothing happened.
const IDLE_SLEEP: Duration = Duration::from_millis(5);

/// The page, built into the library.
const PAGE: &str = include_str!("page.html");

enum Phase {
    /// Reading the request.
    Reading(Vec<u8>),
    /// Writing a response, then closing.
    Writing,
    /// An event stream.
    Streaming,
}

struct Conn {
    stream: TcpStream,
    phase: Phase,
    out: Vec<u8>,
    sent: usize,
    since: Instant,
    dead: bool,
}

/// A parsed request.
#[derive(Debug, PartialEq)]
struct Request<'a> {
    method: &'a str,
    path: &'a str,
    query: &'a str,
    token: Option<&'a str>,
    body: &'a [u8],
}

/// What to do with a request buffer so far.
#[derive(Debug, PartialEq)]
enum Parsed<'a> {
    /// More bytes needed.
    Incomplete,
    /// A whole request.
    Done(Request<'a>),
    /// Refused with this status and reason.
    Bad(u16, &'static str),
}

fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
    hay.windows(needle.len()).position(|w| w == needle)
}

fn parse(buf: &[u8]) -> Parsed<'_> {
    let Some(end) = find(buf, b"\r\n\r\n") else {
        return if buf.len() > MAX_HEAD {
            Parsed::Bad(431, "request head too large")
        } else {
            Parsed::Incomplete
        };
    };
    if end > MAX_HEAD {
        return Parsed::Bad(431, "request head too large");
    }
    let Ok(head) = std::str::from_utf8(&buf[..end]) else {
        return Parsed::Bad(400, "request head is not UTF-8");
    };
    let mut lines = head.split("\r\n");
    let line = lines.next().unwrap_or("");
    let mut parts = line.split(' ');
    let (Some(method), Some(target), Some(version), None) =
        (parts.next(), parts.next(), parts.next(), parts.next())
    else {
        return Parsed::Bad(400, "bad request line");
    };
    if !version.starts_with("HTTP/1.") {
        return Parsed::Bad(505, "HTTP/1.x only");
    }
    let (path, query) = target.split_once('?').unwrap_or((target, ""));
    let mut length = 0usize;
    let mut token = None;
    for h in lines {
        let Some((name, value)) = h.split_once(':') else {
            return Parsed::Bad(400, "bad header");
        };
        let value = value.trim();
        if name.eq_ignore_ascii_case("content-length") {
            match value.parse::<usize>() {
                Ok(n) if n <= MAX_BODY => length = n,
                Ok(_) => return Parsed::Bad(413, "body too large"),
                Err(_) => return Parsed::Bad(400, "bad Content-Length"),
            }
        } else if name.eq_ignore_ascii_case("transfer-encoding") {
            return Parsed::Bad(411, "send a Content-Length");
        } else if name.eq_ignore_ascii_case("x-mccl-token") {
            token = Some(value);
        }
    }
    let token = token.or_else(|| query.split('&').find_map(|kv| kv.strip_prefix("token=")));
    let start = end + 4;
    if buf.len() < start + length {
        return Parsed::Incomplete;
    }
    Parsed::Done(Request {
        method,
        path,
        query,
        token,
        body: &buf[start..start + length],
    })
}

/// Compares without stopping at the first difference (no timing hint of a prefix).
fn same(a: &[u8], b: &[u8]) -> bool {
    a.len() == b.len() && a.iter().zip(b).fold(0u8, |d, (x, y)| d | (x ^ y)) == 0
}

fn reason(status: u16) -> &'static str {
    match status {
        200 => "OK",
        400 => "Bad Request",
        403 => "Forbidden",
        404 => "Not Found",
        405 => "Method Not Allowed",
        408 => "Request Timeout",
        409 => "Conflict",
        411 => "Length Required",
        413 => "Content Too Large",
        431 => "Request Header Fields Too Large",
        503 => "Service Unavailable",
        505 => "HTTP Version Not Supported",
        _ => "Error",
    }
}

/// Headers on every answer: nothing cached, no page may frame it, the token in the URL
/// is never sent on as a referrer, the page may load nothing from elsewhere.
const COMMON: &str = "Cache-Control: no-store\r\nX-Frame-Options: DENY\r\n\
    X-Content-Type-Options: nosniff\r\nReferrer-Policy: no-referrer\r\n\
    Content-Security-Policy: default-src 'none'; script-src 'unsafe-inline'; \
    style-src 'unsafe-inline'; connect-src 'self'; img-src 'self' data:\r\n";

fn response(status: u16, content_type: &str, body: &[u8]) -> Vec<u8> {
    let mut out = format!(
        "HTTP/1.1 {status} {}\r\nContent-Type: {content_type}\r\nContent-Length: {}\r\n\
         {COMMON}Connection: close\r\n\r\n",
        reason(status),
        body.len()
    )
    .into_bytes();
    out.extend_from_slice(body);
    out
}

fn error(status: u16, msg: &str) -> Vec<u8> {
    let body = serde_json::json!({ "error": msg }).to_string();
    response(status, "application/json", body.as_bytes())
}

/// The server loop's state.
pub struct Server {
    listener: TcpListener,
    token: String,
    source: Source,
    stop: Arc<AtomicBool>,
    conns: Vec<Conn>,
    last_request: Option<Instant>,
    next_push: Instant,
}

impl Server {
    /// A server on a bound, non-blocking listener.
    pub fn new(
        listener: TcpListener,
        token: String,
        source: Source,
        stop: Arc<AtomicBool>,
    ) -> Server {
        Server {
            listener,
            token,
            source,
            stop,
            conns: Vec::new(),
            last_request: None,
            next_push: Instant::now(),
        }
    }

    /// Serves until stopped; then every socket closes with the server.
    pub fn run(mut self) {
        while !self.stop.load(Ordering::Acquire) {
            let busy = self.accept() | self.serve() | self.push();
            self.conns.retain(|c| !c.dead);
            let wanted = self
                .conns
                .iter()
                .any(|c| matches!(c.phase, Phase::Streaming))
                || self.last_request.is_some_and(|t| t.elapsed() < WANT_FOR);
            self.source.want(wanted);
            if !busy {
                std::thread::sleep(IDLE_SLEEP);
            }
        }
        self.source.want(false);
    }

    /// Takes waiting connections; beyond the limit answers 503 and closes.
    fn accept(&mut self) -> bool {
        let mut any = false;
        loop {
            match self.listener.accept() {
                Ok((stream, _)) => {
                    any = true;
                    if stream.set_nonblocking(true).is_err() {
                        continue;
                    }
                    let _ = stream.set_nodelay(true);
                    if self.conns.len() >= MAX_CONNECTIONS {
                        refuse(&stream);
                        continue;
                    }
                    self.conns.push(Conn {
                        stream,
                        phase: Phase::Reading(Vec::new()),
                        out: Vec::new(),
                        sent: 0,
                        since: Instant::now(),
                        dead: false,
                    });
                }
                Err(e) if e.kind() == ErrorKind::WouldBlock => return any,
                Err(e) if e.kind() == ErrorKind::Interrupted => {}
                // Out of descriptors and the like: try again on the next round.
                Err(_) => return any,
            }
        }
    }

    /// Reads requests, answers them, writes what is pending.
    fn serve(&mut self) -> bool {
        let mut any = false;
        for i in 0..self.conns.len() {
            any |= self.read(i);
            any |= write_pending(&mut self.conns[i]);
        }
        any
    }

    fn read(&mut self, i: usize) -> bool {
        let c = &mut self.conns[i];
        let Phase::Reading(buf) = &mut c.phase else {
            return false;
        };
        let mut any = false;
        let mut chunk = [0u8; 4096];
        loop {
            match c.stream.read(&mut chunk) {
                Ok(0) => {
                    c.dead = true;
                    return true;
                }
                Ok(n) => {
                    any = true;
                    buf.extend_from_slice(&chunk[..n]);
                    if buf.len() > MAX_HEAD + MAX_BODY + 4 {
                        break;
                    }
                }
                Err(e) if e.kind() == ErrorKind::WouldBlock => break,
                Err(e) if e.kind() == ErrorKind::Interrupted => {}
                Err(_) => {
                    c.dead = true;
                    return true;
                }
            }
        }
        let buf = std::mem::take(buf);
        let answer = match parse(&buf) {
            Parsed::Incomplete if c.since.elapsed() > REQUEST_TIMEOUT => {
                Some(error(408, "request too slow"))
            }
            Parsed::Incomplete if buf.len() > MAX_HEAD + MAX_BODY + 4 => {
                Some(error(413, "request too large"))
            }
            Parsed::Incomplete => {
                c.phase = Phase::Reading(buf);
                return any;
            }
            Parsed::Bad(status, why) => Some(error(status, why)),
            Parsed::Done(req) => self.handle(i, &req),
        };
        let c = &mut self.conns[i];
        if let Some(out) = answer {
            c.out = out;
            c.sent = 0;
            c.phase = Phase::Writing;
        }
        true
    }

    /// The answer to a whole request (`None`: the connection became an event stream).
    fn handle(&mut self, i: usize, req: &Request<'_>) -> Option<Vec<u8>> {
        if !req
            .token
            .is_some_and(|t| same(t.as_bytes(), self.token.as_bytes()))
        {
            return Some(error(403, "missing or wrong token"));
        }
        // Before the answer goes out: the ticks the client causes next copy the view.
        self.last_request = Some(Instant::now());
        self.source.want(true);
        let _ = req.query;
        match (req.method, req.path) {
            ("GET", "/") | ("GET", "/index.html") => {
                Some(response(200, "text/html; charset=utf-8", PAGE.as_bytes()))
            }
            ("GET", "/api/state") => {
                let body = self.source.json().to_string();
                Some(response(200, "application/json", body.as_bytes()))
            }
            ("GET", "/api/events") => {
                let c = &mut self.conns[i];
                c.out =
                    format!("HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\n{COMMON}\r\n")
                        .into_bytes();
                c.sent = 0;
                c.phase = Phase::Streaming;
                // The first event goes out with the next push, at once.
                self.next_push = Instant::now();
                None
            }
            ("POST", "/api/control") => Some(
                match control::parse(req.body).and_then(|c| control::apply(&self.source.shared, &c))
                {
                    Ok(()) => {
                        let body = serde_json::json!({
                            "ok": true,
                            "time_ms": self.source.shared.clock().now_ns() as f64 / 1e6,
                        })
                        .to_string();
                        response(200, "application/json", body.as_bytes())
                    }
                    Err(r) => error(r.status, &r.message),
                },
            ),
            (_, "/" | "/index.html" | "/api/state" | "/api/events" | "/api/control") => {
                Some(error(405, "method not allowed"))
            }
            _ => Some(error(404, "not found")),
        }
    }

    /// Sends the state to every event-stream client when due.
    fn push(&mut self) -> bool {
        if Instant::now() < self.next_push
            || !self
                .conns
                .iter()
                .any(|c| matches!(c.phase, Phase::Streaming))
        {
            return false;
        }
        self.next_push = Instant::now() + PUSH_EVERY;
        let event = format!("data: {}\n\n", self.source.json());
        for c in &mut self.conns {
            if matches!(c.phase, Phase::Streaming) && !c.dead {
                if c.out.len() - c.sent + event.len() > MAX_PENDING {
                    // A client that does not read is dropped, never waited for.
                    c.dead = true;
                    continue;
                }
                c.out.drain(..c.sent);
                c.sent = 0;
                c.out.extend_from_slice(event.as_bytes());
                write_pending(c);
            }
        }
        true
    }
}

/// Answers 503 to a connection beyond the limit and closes it; what the client sent so
/// far is read first (closing over unread bytes would reset the connection before the
/// client reads the answer).
fn refuse(stream: &TcpStream) {
    let mut sink = [0u8; 1024];
    let mut s = stream;
    for _ in 0..16 {
        match s.read(&mut sink) {
            Ok(n) if n > 0 => {}
            _ => break,
        }
    }
    let _ = s.write(&error(503, "too many connections"));
    let _ = stream.shutdown(std::net::Shutdown::Write);
}

/// Writes what a connection has pending without blocking; a finished response closes it.
fn write_pending(c: &mut Conn) -> bool {
    let mut any = false;
    while c.sent < c.out.len() && !c.dead {
        match c.stream.write(&c.out[c.sent..]) {
            Ok(0) => c.dead = true,
            Ok(n) => {
                c.sent += n;
                any = true;
            }
            Err(e) if e.kind() == ErrorKind::WouldBlock => break,
            Err(e) if e.kind() == ErrorKind::Interrupted => {}
            Err(_) => c.dead = true,
        }
    }
    if matches!(c.phase, Phase::Writing) {
        if c.sent >= c.out.len() {
            let _ = c.stream.shutdown(std::net::Shutdown::Write);
            c.dead = true;
        } else if c.since.elapsed() > REQUEST_TIMEOUT * 2 {
            // A client that does not take its answer is dropped.
            c.dead = true;
        }
    }
    if matches!(c.phase, Phase::Streaming) && c.sent == c.out.len() {
        c.out.clear();
        c.sent = 0;
    }
    any
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_requests_and_refuses_bad_ones() {
        let r = b"GET /api/state?token=abc HTTP/1.1\r\nHost: x\r\n\r\n";
        assert_eq!(
            parse(r),
            Parsed::Done(Request {
                method: "GET",
                path: "/api/state",
                query: "token=abc",
                token: Some("abc"),
                body: b"",
            })
        );
        let r = b"POST /api/control HTTP/1.1\r\nX-MCCL-Token: t\r\nContent-Length: 4\r\n\r\n{}";
        assert_eq!(parse(r), Parsed::Incomplete, "body not complete");
        let r = b"POST /api/control HTTP/1.1\r\nX-MCCL-Token: t\r\nContent-Length: 2\r\n\r\n{}";
        assert!(matches!(
            parse(r),
            Parsed::Done(Request {
                token: Some("t"),
                body: b"{}",
                ..
            })
        ));
        assert_eq!(parse(b"GET / HTTP/1.1\r\n"), Parsed::Incomplete);
        assert_eq!(
            parse(b"POST / HTTP/1.1\r\nContent-Length: 999999\r\n\r\n"),
            Parsed::Bad(413, "body too large")
        );
        assert_eq!(
            parse(b"POST / HTTP/1.1\r\nContent-Length: -1\r\n\r\n"),
            Parsed::Bad(400, "bad Content-Length")
        );
        assert_eq!(
            parse(b"GARBAGE\r\n\r\n"),
            Parsed::Bad(400, "bad request line")
        );
        assert_eq!(
            parse(b"GET / SPDY/3\r\n\r\n"),
            Parsed::Bad(505, "HTTP/1.x only")
        );
        let long = [b'a'; MAX_HEAD + 1];
        assert_eq!(parse(&long), Parsed::Bad(431, "request head too large"));
    }

    #[test]
    fn token_comparison() {
        assert!(same(b"abc", b"abc"));
        assert!(!same(b"abc", b"abd"));
        assert!(!same(b"abc", b"ab"));
        assert!(!same(b"", b"a"));
    }
}
