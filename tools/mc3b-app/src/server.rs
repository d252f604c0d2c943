//! The HTTP side, on `tiny_http`: the page, its state (JSON and server-sent events), the
//! serial ports, the parameter record, and the page's requests.
//!
//! Security, as for the project's machine panel: loopback unless told otherwise; a
//! random token on every request (`?token=` or the `X-MC3B-Token` header), compared
//! without an early exit, else `403` and nothing happens; requests that act are `POST`
//! (`405` otherwise); bodies of at most [`MAX_BODY`] bytes (`413`); no CORS headers, so a
//! page of another origin cannot read an answer; the page loads nothing from elsewhere
//! (a Content-Security-Policy that allows no other source), is never framed and never
//! passes the token on as a referrer.
//!
//! Routes: `GET /` the page; `GET /api/state` the state; `GET /api/events` the state as
//! server-sent events, each new state and at least every [`PUSH_EVERY`]; `GET /api/ports` the serial ports;
//! `GET /api/params?motor=M` a motor's parameter record; `POST /api/heartbeat`;
//! `POST /api/bye` (the page closes); `POST /api/action` a request of the page
//! (JSON, see [`crate::checks::Action`]).
//!
//! Every request with the right token counts as a heartbeat. The event stream is how a
//! page's going is seen at once: when writing to it fails, the page has gone (closed,
//! browser ended, connection dropped) and every motor that may run is stopped.

use std::io::{Read, Write};
use std::net::SocketAddr;
use std::sync::Arc;
use std::time::Duration;

use serde_json::json;
use tiny_http::{Header, Method, Request, Response, Server};

use crate::checks::{self, Action, Checked, FieldError};
use crate::ports;
use crate::shared::{Refusal, Shared};

/// Largest request body, bytes.
pub const MAX_BODY: usize = 16 * 1024;
/// Event streams open at once (pages); one more is answered `503`.
pub const MAX_STREAMS: usize = 8;
/// Longest time between two events of a stream (each carries the whole state).
pub const PUSH_EVERY: Duration = Duration::from_millis(100);
/// Threads that answer requests (an event stream gets a thread of its own).
pub const WORKERS: usize = 4;

/// The page, built into the program.
const PAGE: &str = include_str!("page.html");

/// Headers on every answer: nothing cached, no framing, no sniffing, the token in the
/// URL never sent on as a referrer, nothing loaded from elsewhere.
const COMMON: [(&str, &str); 5] = [
    ("Cache-Control", "no-store"),
    ("X-Frame-Options", "DENY"),
    ("X-Content-Type-Options", "nosniff"),
    ("Referrer-Policy", "no-referrer"),
    (
        "Content-Security-Policy",
        "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; \
         connect-src 'self'; img-src 'self' data:",
    ),
];

/// A serving application.
pub struct Http {
    server: Arc<Server>,
    token: Arc<str>,
    shared: Arc<Shared>,
    addr: SocketAddr,
}

/// 16 random bytes from the operating system as 32 hex digits.
fn new_token() -> Result<String, String> {
    let mut b = [0u8; 16];
    getrandom::fill(&mut b).map_err(|e| format!("no random bytes for the token: {e}"))?;
    Ok(b.iter().map(|x| format!("{x:02x}")).collect())
}

/// Compares without stopping at the first difference.
fn same(a: &[u8], b: &[u8]) -> bool {
    a.len() == b.len() && a.iter().zip(b).fold(0u8, |d, (x, y)| d | (x ^ y)) == 0
}

fn header(name: &str, value: &str) -> Option<Header> {
    Header::from_bytes(name.as_bytes(), value.as_bytes()).ok()
}

fn with_common<R: Read>(mut r: Response<R>) -> Response<R> {
    for (n, v) in COMMON {
        if let Some(h) = header(n, v) {
            r.add_header(h);
        }
    }
    r
}

fn json_response(status: u16, body: &serde_json::Value) -> Response<std::io::Cursor<Vec<u8>>> {
    let mut r = Response::from_string(body.to_string()).with_status_code(status);
    if let Some(h) = header("Content-Type", "application/json") {
        r.add_header(h);
    }
    with_common(r)
}

fn refusal_response(r: &Refusal) -> Response<std::io::Cursor<Vec<u8>>> {
    json_response(r.status, &json!({ "error": r.message, "fields": r.fields }))
}

fn fields_response(fields: &[FieldError]) -> Response<std::io::Cursor<Vec<u8>>> {
    let first = fields.first().map_or("bad input", |f| f.message.as_str());
    json_response(400, &json!({ "error": first, "fields": fields }))
}

/// The value of `key` in a query string.
fn query_value<'a>(query: &'a str, key: &str) -> Option<&'a str> {
    query.split('&').find_map(|kv| {
        kv.split_once('=')
            .and_then(|(k, v)| (k == key).then_some(v))
    })
}

impl Http {
    /// Serves on `addr` (port 0: a free one).
    pub fn bind(addr: SocketAddr, shared: Arc<Shared>) -> Result<Http, String> {
        let server = Server::http(addr).map_err(|e| format!("cannot serve on {addr}: {e}"))?;
        let addr = server
            .server_addr()
            .to_ip()
            .ok_or_else(|| "the server has no IP address".to_string())?;
        Ok(Http {
            server: Arc::new(server),
            token: Arc::from(new_token()?),
            shared,
            addr,
        })
    }

    /// The page's address, token included.
    pub fn url(&self) -> String {
        format!("http://{}/?token={}", self.addr, self.token)
    }

    /// Starts the worker threads; they end when the application ends.
    pub fn start(&self) -> Vec<std::thread::JoinHandle<()>> {
        (0..WORKERS)
            .filter_map(|i| {
                let server = self.server.clone();
                let token = self.token.clone();
                let shared = self.shared.clone();
                std::thread::Builder::new()
                    .name(format!("mc3b-app-http-{i}"))
                    .spawn(move || {
                        while !shared.shutting_down() {
                            match server.recv_timeout(Duration::from_millis(200)) {
                                Ok(Some(rq)) => handle(rq, &token, &shared),
                                Ok(None) => {}
                                Err(_) => std::thread::sleep(Duration::from_millis(50)),
                            }
                        }
                    })
                    .ok()
            })
            .collect()
    }
}

/// Answers one request.
fn handle(mut rq: Request, token: &str, shared: &Arc<Shared>) {
    let url = rq.url().to_string();
    let (path, query) = url.split_once('?').unwrap_or((url.as_str(), ""));
    let given = rq
        .headers()
        .iter()
        .find(|h| h.field.equiv("X-MC3B-Token"))
        .map(|h| h.value.as_str().to_string())
        .or_else(|| query_value(query, "token").map(str::to_string));
    if !given.is_some_and(|g| same(g.as_bytes(), token.as_bytes())) {
        let _ = rq.respond(json_response(
            403,
            &json!({ "error": "open the address mc3b-app printed, token included" }),
        ));
        return;
    }
    shared.heartbeat();
    let post = *rq.method() == Method::Post;
    let get = *rq.method() == Method::Get;
    let response = match (path, get, post) {
        ("/", true, _) => {
            let mut r = Response::from_string(PAGE);
            if let Some(h) = header("Content-Type", "text/html; charset=utf-8") {
                r.add_header(h);
            }
            with_common(r)
        }
        ("/api/state", true, _) => {
            let (_, snap) = shared.snapshot();
            let mut r = Response::from_string(snap.as_deref().unwrap_or("{}").to_string());
            if let Some(h) = header("Content-Type", "application/json") {
                r.add_header(h);
            }
            with_common(r)
        }
        ("/api/events", true, _) => {
            stream(rq, shared);
            return;
        }
        ("/api/ports", true, _) => json_response(200, &json!({ "ports": ports::list() })),
        ("/api/params", true, _) => {
            match query_value(query, "motor").and_then(|m| m.parse::<u32>().ok()) {
                Some(m) => match shared.motor_params(m) {
                    (Some(p), connected) => json_response(
                        200,
                        &json!({ "motor": m, "params": p, "connected": connected }),
                    ),
                    (None, _) => json_response(400, &json!({ "error": "motor 0, 1 or 2" })),
                },
                None => json_response(400, &json!({ "error": "motor=0, 1 or 2" })),
            }
        }
        ("/api/heartbeat", _, true) => json_response(200, &json!({ "ok": true })),
        ("/api/bye", _, true) => {
            shared.page_leaving();
            json_response(200, &json!({ "ok": true }))
        }
        ("/api/action", _, true) => match read_body(&mut rq) {
            Ok(body) => action(&body, shared),
            Err(r) => r,
        },
        ("/" | "/api/state" | "/api/events" | "/api/ports" | "/api/params", false, _) => {
            json_response(405, &json!({ "error": "GET only" }))
        }
        ("/api/heartbeat" | "/api/bye" | "/api/action", _, false) => {
            json_response(405, &json!({ "error": "POST only" }))
        }
        _ => json_response(404, &json!({ "error": "no such page" })),
    };
    let _ = rq.respond(response);
}

fn read_body(rq: &mut Request) -> Result<Vec<u8>, Response<std::io::Cursor<Vec<u8>>>> {
    if rq.body_length().is_some_and(|n| n > MAX_BODY) {
        return Err(json_response(413, &json!({ "error": "body too large" })));
    }
    let mut body = Vec::new();
    let limit = (MAX_BODY + 1) as u64;
    if rq.as_reader().take(limit).read_to_end(&mut body).is_err() {
        return Err(json_response(400, &json!({ "error": "unreadable body" })));
    }
    if body.len() > MAX_BODY {
        return Err(json_response(413, &json!({ "error": "body too large" })));
    }
    Ok(body)
}

/// A request of the page: checked, then carried out (or stops and slider speeds
/// handed over at once).
fn action(body: &[u8], shared: &Arc<Shared>) -> Response<std::io::Cursor<Vec<u8>>> {
    let a: Action = match serde_json::from_slice(body) {
        Ok(a) => a,
        Err(e) => {
            return json_response(400, &json!({ "error": format!("malformed request: {e}") }))
        }
    };
    let checked = match checks::check(&a) {
        Ok(c) => c,
        Err(fields) => return fields_response(&fields),
    };
    match checked {
        Checked::Op(op) => match shared.submit(op) {
            Ok(message) => json_response(200, &json!({ "ok": true, "message": message })),
            Err(r) => refusal_response(&r),
        },
        Checked::Stop(motor) => {
            let reason = match motor {
                Some(m) => format!("the stop button of motor {m}"),
                None => "STOP ALL".to_string(),
            };
            let gen = shared.request_stop(motor, &reason);
            match shared.wait_stop(gen) {
                Some(message) => json_response(200, &json!({ "ok": true, "message": message })),
                None => json_response(
                    504,
                    &json!({ "error": "the stop was asked for but not yet confirmed" }),
                ),
            }
        }
        Checked::Manual { motor, speed } => {
            let (params, connected) = shared.motor_params(motor);
            if !connected {
                return json_response(503, &json!({ "error": "no MC3B connected" }));
            }
            let max = params.map_or(0, |p| p.max_velocity);
            match checks::manual_speed(motor, speed, max) {
                Ok(s) => {
                    shared.set_manual(motor, s);
                    let message = if s == 0 {
                        format!("motor {motor}: stop")
                    } else {
                        format!(
                            "motor {motor}: {} steps/s in direction {}",
                            s.unsigned_abs(),
                            u8::from(s < 0)
                        )
                    };
                    json_response(200, &json!({ "ok": true, "message": message }))
                }
                Err(f) => fields_response(&[f]),
            }
        }
        Checked::ManualEnd => {
            for m in 0..checks::MOTORS as u32 {
                shared.set_manual(m, 0);
            }
            json_response(200, &json!({ "ok": true }))
        }
    }
}

/// A page's event stream: each new state, and the last one again after [`PUSH_EVERY`],
/// until writing fails; then the page counts as gone.
fn stream(rq: Request, shared: &Arc<Shared>) {
    if shared.stream_opened(MAX_STREAMS).is_none() {
        let _ = rq.respond(json_response(
            503,
            &json!({ "error": "too many pages open" }),
        ));
        return;
    }
    let stream_shared = shared.clone();
    let spawned = std::thread::Builder::new()
        .name("mc3b-app-events".into())
        .spawn(move || {
            let shared = stream_shared;
            let mut w = rq.into_writer();
            let mut head = String::from(
                "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nConnection: close\r\n",
            );
            for (n, v) in COMMON {
                head.push_str(&format!("{n}: {v}\r\n"));
            }
            head.push_str("\r\nretry: 1000\n\n");
            let mut ok = w.write_all(head.as_bytes()).and_then(|_| w.flush()).is_ok();
            let mut seq = 0;
            while ok && !shared.shutting_down() {
                // A new state as soon as there is one, the last one again after
                // PUSH_EVERY: a broken connection is found within that time.
                let (s, snap) = shared.wait_snapshot(seq, PUSH_EVERY);
                seq = s;
                let data = format!("data: {}\n\n", snap.as_deref().unwrap_or("{}"));
                ok = w.write_all(data.as_bytes()).and_then(|_| w.flush()).is_ok();
            }
            drop(w);
            shared.stream_closed();
        });
    if spawned.is_err() {
        shared.stream_closed();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_are_32_hex_digits_and_differ() {
        let a = new_token().expect("token");
        let b = new_token().expect("token");
        assert_eq!(a.len(), 32);
        assert!(a.bytes().all(|c| c.is_ascii_hexdigit()));
        assert_ne!(a, b);
        assert!(same(a.as_bytes(), a.as_bytes()));
        assert!(!same(a.as_bytes(), b.as_bytes()));
        assert!(!same(b"ab", b"abc"));
    }

    #[test]
    fn query_values() {
        assert_eq!(query_value("token=abc&motor=2", "motor"), Some("2"));
        assert_eq!(query_value("token=abc", "motor"), None);
        assert_eq!(query_value("", "token"), None);
    }
}
