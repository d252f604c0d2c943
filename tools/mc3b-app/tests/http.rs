//! The HTTP side over a real socket: the token, methods, sizes, malformed and refused
//! requests, and the state a client gets. The board thread runs with an opener that
//! finds no port, so nothing here can reach a device.

use std::io::{Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::sync::Arc;
use std::time::Duration;

use mc3b_app::board::{Board, Opener};
use mc3b_app::server::{Http, MAX_BODY};
use mc3b_app::shared::Shared;

struct App {
    addr: SocketAddr,
    token: String,
    shared: Arc<Shared>,
    threads: Vec<std::thread::JoinHandle<()>>,
}

impl App {
    fn start() -> App {
        let shared = Shared::new();
        let http = Http::bind("127.0.0.1:0".parse().expect("addr"), shared.clone()).expect("bind");
        let url = http.url();
        let rest = url.strip_prefix("http://").expect("http URL");
        let (addr, token) = rest.split_once("/?token=").expect("token in the URL");
        let opener: Opener = Box::new(|path, _| Err(format!("{path}: No such file or directory")));
        let board = Board::new(shared.clone(), opener, Duration::from_millis(100));
        let mut threads = http.start();
        threads.push(std::thread::spawn(move || board.run()));
        App {
            addr: addr.parse().expect("address"),
            token: token.to_string(),
            shared,
            threads,
        }
    }

    /// One request; `(status, body)`.
    fn request(&self, method: &str, path: &str, headers: &str, body: &[u8]) -> (u16, String) {
        let mut s = TcpStream::connect(self.addr).expect("connect");
        s.set_read_timeout(Some(Duration::from_secs(20)))
            .expect("timeout");
        let head = format!(
            "{method} {path} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n{headers}\
             Content-Length: {}\r\n\r\n",
            body.len()
        );
        s.write_all(head.as_bytes()).expect("write head");
        let _ = s.write_all(body);
        let mut out = Vec::new();
        let _ = s.read_to_end(&mut out);
        let text = String::from_utf8_lossy(&out).to_string();
        let status = text
            .split_whitespace()
            .nth(1)
            .and_then(|c| c.parse().ok())
            .unwrap_or(0);
        let body = text
            .split_once("\r\n\r\n")
            .map(|(_, b)| b.to_string())
            .unwrap_or_default();
        (status, body)
    }

    fn with_token(&self, path: &str) -> String {
        let sep = if path.contains('?') { '&' } else { '?' };
        format!("{path}{sep}token={}", self.token)
    }

    fn action(&self, json: &str) -> (u16, String) {
        let h = format!("X-MC3B-Token: {}\r\n", self.token);
        self.request("POST", "/api/action", &h, json.as_bytes())
    }
}

impl Drop for App {
    fn drop(&mut self) {
        self.shared.shutdown();
        for t in self.threads.drain(..) {
            let _ = t.join();
        }
    }
}

#[test]
fn every_request_needs_the_token() {
    let app = App::start();
    for path in [
        "/",
        "/api/state",
        "/api/events",
        "/api/ports",
        "/api/params?motor=0",
    ] {
        assert_eq!(app.request("GET", path, "", b"").0, 403, "{path}");
        let wrong = format!(
            "{path}{}token=00",
            if path.contains('?') { '&' } else { '?' }
        );
        assert_eq!(app.request("GET", &wrong, "", b"").0, 403, "{wrong}");
    }
    let (status, _) = app.request("POST", "/api/action", "", br#"{"action":"stop_all"}"#);
    assert_eq!(status, 403);
    let (status, page) = app.request("GET", &app.with_token("/"), "", b"");
    assert_eq!(status, 200);
    assert!(page.contains("<title>MC3B control</title>"));
    let h = format!("X-MC3B-Token: {}\r\n", app.token);
    assert_eq!(app.request("GET", "/api/ports", &h, b"").0, 200);
}

#[test]
fn methods_sizes_and_malformed_requests() {
    let app = App::start();
    assert_eq!(
        app.request("GET", &app.with_token("/api/action"), "", b"")
            .0,
        405
    );
    assert_eq!(app.request("POST", &app.with_token("/"), "", b"").0, 405);
    assert_eq!(
        app.request("GET", &app.with_token("/nothing"), "", b"").0,
        404
    );
    let big = vec![b' '; MAX_BODY + 1];
    let h = format!("X-MC3B-Token: {}\r\n", app.token);
    assert_eq!(app.request("POST", "/api/action", &h, &big).0, 413);
    let (status, body) = app.action("{not json");
    assert_eq!(status, 400);
    assert!(body.contains("malformed request"), "{body}");
    let (status, body) = app.action(r#"{"action":"fly"}"#);
    assert_eq!(status, 400, "{body}");
    let (status, body) = app.action(r#"{"action":"stop","motor":0,"extra":1}"#);
    assert_eq!(status, 400, "unknown fields are refused: {body}");
}

#[test]
fn bad_input_names_its_fields_and_no_board_is_said_so() {
    let app = App::start();
    let (status, body) = app.action(
        r#"{"action":"set_params","motor":0,"params":{"max_velocity":"6000",
            "acceleration":"5000","deceleration":"5000","half_steps":true,"holding_on":false,
            "holding_current":"500","running_current":"2000",
            "limit0":[{"bit":0,"high":true},{"bit":1,"high":false}],"limit1":[]}}"#,
    );
    assert_eq!(status, 400);
    let v: serde_json::Value = serde_json::from_str(&body).expect("JSON");
    let fields: Vec<&str> = v["fields"]
        .as_array()
        .expect("fields")
        .iter()
        .filter_map(|f| f["field"].as_str())
        .collect();
    assert_eq!(fields, ["max_velocity", "limit0"]);
    let (status, body) = app.action(r#"{"action":"connect","port":"/dev/none"}"#);
    assert_eq!(status, 400);
    assert!(body.contains("cannot open /dev/none"), "{body}");
    let (status, body) = app.action(r#"{"action":"move","motor":0,"direction":0,"steps":"5"}"#);
    assert_eq!(status, 503, "{body}");
    assert!(body.contains("no MC3B connected"), "{body}");
    let (status, _) = app.action(r#"{"action":"manual","motor":0,"speed":100}"#);
    assert_eq!(status, 503);
    // A stop with no board is answered (nothing to stop), never left waiting.
    let (status, body) = app.action(r#"{"action":"stop_all"}"#);
    assert_eq!(status, 200, "{body}");
    assert!(body.contains("nothing to stop"), "{body}");
    let (status, state) = app.request("GET", &app.with_token("/api/state"), "", b"");
    assert_eq!(status, 200);
    let v: serde_json::Value = serde_json::from_str(&state).expect("state JSON");
    assert_eq!(v["link"], "none");
    assert_eq!(v["port"], "/dev/none");
}
