//! The browser panel's HTTP API over a real socket (`MCCL_PANEL=127.0.0.1:0`, stepped
//! clock): the state it shows is what the C calls read at the same virtual time, its
//! controls work the simulated machine, and bad or unauthorised requests change nothing.
#![cfg(feature = "panel")]

mod common;

use common::{fresh, init_ms};
use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::{Duration, Instant};
use MCCLPCI_IMP::ffi::coordinate::*;
use MCCLPCI_IMP::ffi::limits::*;
use MCCLPCI_IMP::ffi::motion::*;
use MCCLPCI_IMP::ffi::sim::*;
use MCCLPCI_IMP::ffi::status::*;
use MCCLPCI_IMP::ffi::system::*;
use MCCLPCI_IMP::ffi::trajectory::*;
use MCCLPCI_IMP::vendor::consts::*;

/// Every socket operation of these tests gives up after this (a hang is a failure).
const IO_TIMEOUT: Duration = Duration::from_secs(10);

/// The panel's address and token, from its URL.
fn panel() -> (String, String) {
    let url = MCCLPCI_IMP::panel::url().expect("MCCL_PANEL set: a panel runs");
    let rest = url.strip_prefix("http://").expect("http URL");
    let (addr, q) = rest.split_once("/?token=").expect("token in the URL");
    (addr.to_string(), q.to_string())
}

fn connect(addr: &str) -> TcpStream {
    let s = TcpStream::connect(addr).expect("connect to the panel");
    s.set_read_timeout(Some(IO_TIMEOUT)).unwrap();
    s.set_write_timeout(Some(IO_TIMEOUT)).unwrap();
    s
}

/// Sends raw bytes, reads the whole answer: (status, body); status 0 when the panel
/// refused the connection by closing it.
fn raw(addr: &str, req: &[u8]) -> (u16, String) {
    let mut s = connect(addr);
    let mut out = Vec::new();
    let sent = s.write_all(req);
    match s.read_to_end(&mut out) {
        Ok(_) => {}
        Err(e) if e.kind() == std::io::ErrorKind::ConnectionReset => return (0, String::new()),
        Err(e) => panic!("the panel answers and closes: {e}"),
    }
    if sent.is_err() && out.is_empty() {
        return (0, String::new());
    }
    let text = String::from_utf8_lossy(&out).into_owned();
    let status = text
        .split(' ')
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("no status line in {text:?}"));
    let body = text
        .split_once("\r\n\r\n")
        .map(|(_, b)| b.to_string())
        .unwrap_or_default();
    (status, body)
}

fn get(addr: &str, path: &str) -> (u16, String) {
    raw(
        addr,
        format!("GET {path} HTTP/1.1\r\nHost: {addr}\r\n\r\n").as_bytes(),
    )
}

fn post(addr: &str, token: &str, body: &str) -> (u16, String) {
    raw(
        addr,
        format!(
            "POST /api/control HTTP/1.1\r\nHost: {addr}\r\nX-MCCL-Token: {token}\r\n\
             Content-Type: application/json\r\nContent-Length: {}\r\n\r\n{body}",
            body.len()
        )
        .as_bytes(),
    )
}

fn state(addr: &str, token: &str) -> serde_json::Value {
    let (st, body) = get(addr, &format!("/api/state?token={token}"));
    assert_eq!(st, 200, "{body}");
    serde_json::from_str(&body).expect("state is JSON")
}

fn cur_pos() -> [f64; 8] {
    let mut p = [0.0; 8];
    let [a, b, c, d, e, f, g, h] = &mut p;
    // SAFETY: eight valid pointers.
    assert_eq!(unsafe { MCC_GetCurPos(a, b, c, d, e, f, g, h, 0) }, NO_ERR);
    p
}

fn sim_time() -> f64 {
    let mut t = 0.0;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCCL_SimGetTime(&mut t) }, NO_ERR);
    t
}

/// Channel 0's limit switches read normally open, a 1 ms card with the panel on an
/// ephemeral loopback port, feed 10 UU/s without ramps: X moves 0.01 UU per tick.
fn setup() -> parking_lot::MutexGuard<'static, ()> {
    let g = fresh();
    std::env::set_var("MCCL_PANEL", "127.0.0.1:0");
    let mut m = MCCLPCI_IMP::config::default_mac_param();
    m.wOverTravelUpSensorMode = SL_NORMAL_OPEN;
    m.wOverTravelDownSensorMode = SL_NORMAL_OPEN;
    // SAFETY: valid pointer.
    assert_eq!(unsafe { MCC_SetMacParam(&mut m, 0, 0) }, NO_ERR);
    assert_eq!(init_ms(1, 1), NO_ERR);
    std::env::remove_var("MCCL_PANEL");
    assert_eq!(MCC_SetFeedSpeed(10.0, 0), 10.0);
    assert_eq!(MCC_SetAccTime(0.0, 0), NO_ERR);
    assert_eq!(MCC_SetDecTime(0.0, 0), NO_ERR);
    g
}

fn line_x(x: f64) -> i32 {
    MCC_Line(x, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0, IMP_AXIS_ALL)
}

#[test]
fn state_is_what_the_program_reads_at_the_same_virtual_time() {
    let _g = setup();
    let (addr, token) = panel();
    assert_eq!(line_x(10.0), 0, "command index 0");
    MCC_TimeDelay(300);
    let s = state(&addr, &token);
    // 300 ticks of 1 ms at 10 UU/s: 3.0 UU, the line still running (it ends at 1 s).
    let p = cur_pos();
    assert!((p[0] - 3.0).abs() < 1e-9, "x = {}", p[0]);
    assert_eq!(s["clock"], "stepped");
    assert_eq!(s["virtual_time"], true);
    assert_eq!(s["time_ms"].as_f64(), Some(sim_time()));
    assert_eq!(s["time_ms"].as_f64(), Some(300.0));
    let g = &s["groups"][0];
    assert_eq!(g["index"], 0);
    assert_eq!(
        g["status"].as_i64(),
        Some(i64::from(MCC_GetMotionStatus(0)))
    );
    assert_eq!(g["status_name"], "RUNNING");
    assert_eq!(g["command_index"], 0);
    assert_eq!(g["error"], 0);
    for (k, want) in p.iter().enumerate() {
        let got = g["pos"][k].as_f64().unwrap();
        assert!((got - want).abs() < 1e-6, "axis {k}: {got} vs {want}");
    }
    assert!((g["path_speed"].as_f64().unwrap() - 10.0).abs() < 1e-9);
    // The engine copies the I/O view while a client looks (the request above asked), so
    // after 200 more ticks it shows 500 ms: X at 5.0 UU, and the encoder of channel 0
    // counts one per pulse at x4 (default parameters: 500 PPR, pitch 1, gear 1, so
    // 500 pulses/UU): 5.0 x 500 = 2500.
    MCC_TimeDelay(200);
    let s = state(&addr, &token);
    assert_eq!(s["io_time_ms"].as_f64(), Some(500.0));
    let ch0 = &s["cards"][0]["channels"][0];
    assert_eq!(ch0["encoder"], 2500, "5.0 UU x 500 pulses/UU at x4");
    assert_eq!(s["groups"][0]["override"].as_f64(), Some(100.0));
    assert_eq!(s["missed_ticks"], 0);
    MCC_TimeDelay(1000);
    let s = state(&addr, &token);
    assert_eq!(s["groups"][0]["status_name"], "STOP");
    assert_eq!(s["groups"][0]["pos"][0].as_f64(), Some(10.0));
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    assert!(MCCLPCI_IMP::panel::url().is_none(), "the panel stopped");
}

#[test]
fn a_pressed_limit_switch_stops_the_group_with_its_record() {
    let _g = setup();
    let (addr, token) = panel();
    // HLP_BIDIR_GEN_ERR: a switch of a moving axis turning active stops its group and
    // records 0xF701 + axis (docs/simulated-machine.md, "The checks that stop a group").
    assert_eq!(MCC_EnableLimitSwitchCheck(HLP_BIDIR_GEN_ERR), NO_ERR);
    assert_eq!(line_x(10.0), 0);
    MCC_TimeDelay(100);
    let (st, body) = post(
        &addr,
        &token,
        r#"{"action":"sensor","card":0,"channel":0,"sensor":"limit_plus","level":1}"#,
    );
    assert_eq!(st, 200, "{body}");
    // 100 ticks: 1.0 UU; the next tick sees the switch and stops the group there.
    MCC_TimeDelay(10);
    assert_eq!(MCC_GetErrorCode(0), 0xF701);
    assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    let x = cur_pos()[0];
    assert!((1.0..=1.0101).contains(&x), "stopped at {x}");
    let s = state(&addr, &token);
    let g = &s["groups"][0];
    assert_eq!(g["error"], 0xF701);
    assert_eq!(g["error_hex"], "0xF701");
    assert_eq!(g["error_meaning"], "limit switch, axis X");
    MCC_TimeDelay(10);
    let s = state(&addr, &token);
    assert_eq!(s["cards"][0]["channels"][0]["limit_plus"], true);
    assert_eq!(s["cards"][0]["channels"][0]["limit_minus"], false);
    // Released: the input follows the position again (no switch placed: inactive).
    let (st, _) = post(
        &addr,
        &token,
        r#"{"action":"sensor","card":0,"channel":0,"sensor":"limit_plus","level":-1}"#,
    );
    assert_eq!(st, 200);
    // The emergency stop through the panel: pressed while the group has work, 0xF102.
    assert_eq!(MCC_ClearError(0), NO_ERR);
    assert!(line_x(5.0) >= 0);
    MCC_TimeDelay(10);
    let (st, _) = post(
        &addr,
        &token,
        r#"{"action":"emergency_stop","card":0,"on":true}"#,
    );
    assert_eq!(st, 200);
    MCC_TimeDelay(10);
    assert_eq!(MCC_GetErrorCode(0), 0xF102);
    assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn feed_hold_continue_and_abort_act_as_the_vendor_calls() {
    let _g = setup();
    let (addr, token) = panel();
    assert_eq!(line_x(10.0), 0);
    MCC_TimeDelay(100);
    let hold = r#"{"action":"hold","group":0}"#;
    assert_eq!(post(&addr, &token, hold).0, 200);
    // Without dec time the hold stops in one period (n = floor(0) + 1, covering
    // nothing), the next shows the hold (phase 22) and the status reads HOLD two
    // periods after that, in the fourth, as MCC_HoldMotion does.
    let x0 = cur_pos()[0];
    MCC_TimeDelay(3);
    assert_eq!(MCC_GetMotionStatus(0), GMS_RUNNING);
    MCC_TimeDelay(1);
    assert_eq!(MCC_GetMotionStatus(0), GMS_HOLD);
    let held = cur_pos()[0];
    assert_eq!(held, x0, "stopped where the hold came");
    MCC_TimeDelay(100);
    assert_eq!(cur_pos()[0], held);
    let (st, _) = post(&addr, &token, r#"{"action":"continue","group":0}"#);
    assert_eq!(st, 200);
    MCC_TimeDelay(100);
    assert!(cur_pos()[0] > held);
    assert_eq!(
        post(&addr, &token, r#"{"action":"abort","group":0}"#).0,
        200
    );
    MCC_TimeDelay(10);
    assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    let here = cur_pos()[0];
    // Nothing held: the group changes nothing and answers NO_ERR, as MCC_ContiMotion
    // does (the vendor's library answers 0): 200.
    let (st, _) = post(&addr, &token, r#"{"action":"continue","group":0}"#);
    assert_eq!(st, 200);
    MCC_TimeDelay(10);
    assert_eq!(MCC_GetMotionStatus(0), GMS_STOP);
    assert_eq!(cur_pos()[0], here);
    assert_eq!(post(&addr, &token, r#"{"action":"hold","group":7}"#).0, 400);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn without_the_token_nothing_is_shown_and_nothing_changes() {
    let _g = setup();
    let (addr, token) = panel();
    assert_eq!(line_x(10.0), 0);
    MCC_TimeDelay(100);
    let press = r#"{"action":"emergency_stop","card":0,"on":true}"#;
    assert_eq!(get(&addr, "/").0, 403);
    assert_eq!(get(&addr, "/api/state").0, 403);
    assert_eq!(get(&addr, "/api/state?token=").0, 403);
    assert_eq!(
        get(&addr, "/api/state?token=0123456789abcdef0123456789abcdef").0,
        403
    );
    let wrong: String = token.chars().rev().collect();
    assert_eq!(get(&addr, &format!("/api/state?token={wrong}")).0, 403);
    assert_eq!(get(&addr, "/api/events").0, 403);
    assert_eq!(post(&addr, "", press).0, 403);
    assert_eq!(post(&addr, &wrong, press).0, 403);
    assert_eq!(post(&addr, &token[..31], press).0, 403);
    // Nothing changed: the line runs on to its end.
    MCC_TimeDelay(1000);
    assert_eq!(MCC_GetErrorCode(0), 0);
    assert_eq!(cur_pos()[0], 10.0);
    // With the token the page and the state are there; controls are POST only.
    let (st, page) = get(&addr, &format!("/?token={token}"));
    assert_eq!(st, 200);
    assert!(page.contains("MCCL machine panel"));
    assert_eq!(get(&addr, &format!("/api/control?token={token}")).0, 405);
    assert_eq!(get(&addr, &format!("/nothing?token={token}")).0, 404);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn bad_requests_get_4xx_and_change_nothing() {
    let _g = setup();
    let (addr, token) = panel();
    assert_eq!(line_x(10.0), 0);
    for body in [
        "{",
        "null",
        r#"{"action":"emergency_stop"}"#,
        r#"{"action":"emergency_stop","card":12,"on":true}"#,
        r#"{"action":"emergency_stop","card":1,"on":true}"#,
        r#"{"action":"sensor","card":0,"channel":8,"sensor":"home","level":1}"#,
        r#"{"action":"sensor","card":0,"channel":0,"sensor":"door","level":1}"#,
        r#"{"action":"sensor","card":0,"channel":0,"sensor":"limit_plus","level":2}"#,
        r#"{"action":"adc","card":0,"channel":0,"volts":10.5}"#,
        r#"{"action":"adc","card":0,"channel":0,"volts":"nan"}"#,
        r#"{"action":"rio_input","card":0,"set":2,"port":0,"value":1}"#,
        r#"{"action":"rio_input","card":0,"set":0,"port":4,"value":1}"#,
    ] {
        let (st, msg) = post(&addr, &token, body);
        assert_eq!(st, 400, "{body}: {msg}");
    }
    // A body over 16 KiB is refused before it is read.
    let huge = format!(
        "POST /api/control HTTP/1.1\r\nX-MCCL-Token: {token}\r\nContent-Length: 100000000\r\n\r\n"
    );
    assert_eq!(raw(&addr, huge.as_bytes()).0, 413);
    // A head over 8 KiB.
    let mut long = format!("GET /api/state?token={token} HTTP/1.1\r\nX-Pad: ");
    long.push_str(&"a".repeat(20_000));
    long.push_str("\r\n\r\n");
    assert_eq!(raw(&addr, long.as_bytes()).0, 431);
    assert_eq!(raw(&addr, b"\x00\x01\x02\r\n\r\n").0, 400);
    assert_eq!(
        raw(
            &addr,
            b"GET / HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n"
        )
        .0,
        411
    );
    // Nothing changed.
    MCC_TimeDelay(1000);
    assert_eq!(MCC_GetErrorCode(0), 0);
    assert_eq!(cur_pos()[0], 10.0);
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn many_idle_connections_are_refused_and_never_stall_the_engine() {
    let _g = setup();
    let (addr, token) = panel();
    // 40 connections that never send a byte: 16 are held, the rest answered 503.
    let held: Vec<TcpStream> = (0..40).map(|_| connect(&addr)).collect();
    // The engine runs on meanwhile: 1000 ticks at 10 UU/s are 10 UU.
    assert_eq!(line_x(10.0), 0);
    let t0 = Instant::now();
    MCC_TimeDelay(1000);
    assert!(t0.elapsed() < IO_TIMEOUT, "the engine was not stalled");
    assert_eq!(cur_pos()[0], 10.0);
    let (st, _) = get(&addr, &format!("/api/state?token={token}"));
    assert!([0, 200, 503].contains(&st), "refused or served, got {st}");
    let refused = held
        .into_iter()
        .filter_map(|mut s| {
            let mut b = [0u8; 64];
            // The refused ones got a 503 at once; the held ones time out after 5 s (408).
            let n = s.read(&mut b).unwrap_or(0);
            Some(String::from_utf8_lossy(&b[..n]).contains(" 503 ")).filter(|&r| r)
        })
        .count();
    assert!(refused >= 24, "{refused} of 40 refused");
    // Once the idle ones are gone the panel serves again.
    let deadline = Instant::now() + IO_TIMEOUT;
    loop {
        if get(&addr, &format!("/api/state?token={token}")).0 == 200 {
            break;
        }
        assert!(Instant::now() < deadline, "the panel serves again");
        std::thread::sleep(Duration::from_millis(50));
    }
    assert_eq!(MCC_CloseSystem(), NO_ERR);
}

#[test]
fn the_event_stream_sends_the_state() {
    let _g = setup();
    let (addr, token) = panel();
    let mut s = connect(&addr);
    write!(
        s,
        "GET /api/events?token={token} HTTP/1.1\r\nHost: {addr}\r\n\r\n"
    )
    .unwrap();
    let mut got = Vec::new();
    let mut b = [0u8; 4096];
    let deadline = Instant::now() + IO_TIMEOUT;
    let event = loop {
        let n = s.read(&mut b).expect("events arrive");
        assert!(n > 0, "the stream stays open");
        got.extend_from_slice(&b[..n]);
        let text = String::from_utf8_lossy(&got).into_owned();
        if let Some(i) = text.find("data: ") {
            if let Some(j) = text[i..].find("\n\n") {
                break text[i + 6..i + j].to_string();
            }
        }
        assert!(Instant::now() < deadline);
    };
    let head = String::from_utf8_lossy(&got).into_owned();
    assert!(head.starts_with("HTTP/1.1 200"));
    assert!(head.contains("text/event-stream"));
    let v: serde_json::Value = serde_json::from_str(&event).unwrap();
    assert_eq!(v["groups"][0]["status_name"], "STOP");
    // Closing with a client connected closes its stream and the port.
    assert_eq!(MCC_CloseSystem(), NO_ERR);
    let mut rest = Vec::new();
    let _ = s.read_to_end(&mut rest);
    assert!(TcpStream::connect(&addr).is_err(), "port closed");
}
