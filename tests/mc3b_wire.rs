//! The serial client against the `mc3b-emu` binary over a real pty, at the
//! level of §6 frames (including errors the C library never provokes).

mod common;
use common::emu::Emu;
use std::process::Command as Proc;
use std::time::Duration;

use mc3b::client::{Client, ClientError, Transport};
use mc3b::codec::{Command, CommandCode, ErrorCode, Response};
use mc3b::serial::open_port;
use serialport::TTYPort;

fn connect(emu: &Emu) -> Client<TTYPort> {
    let port = open_port(&emu.path, Duration::from_millis(300)).expect("open pty");
    Client::new(port, Duration::from_millis(300))
}

#[test]
fn every_command_is_acknowledged_over_the_pty() {
    let emu = Emu::spawn();
    let mut c = connect(&emu);
    let id = 0;
    let acked = [
        Command::Initialize { id },
        Command::SetAcceleration {
            id,
            motor: 0,
            value: 100_000,
        },
        Command::SetDeceleration {
            id,
            motor: 0,
            value: 100_000,
        },
        Command::SetMaxVelocity {
            id,
            motor: 0,
            value: 5000,
            direction_modifier: None,
        },
        Command::SetLimits {
            id,
            motor: 2,
            h0_and: 8,
            h0_xor: 0,
            h1_and: 32,
            h1_xor: 32,
        },
        Command::SetHalfStep {
            id,
            motor: 1,
            half: 0,
        },
        Command::SetHoldingCurrent {
            id,
            motor: 1,
            enable: 1,
        },
        Command::SetCurrentLimits {
            id,
            motor: 1,
            holding: 500,
            running: 2000,
        },
        Command::SetDebounce { id, count: 1 },
        Command::Run {
            id,
            motor: 0,
            direction: 0,
        },
        Command::Stop { id, motor: 0 },
        Command::Move {
            id,
            motor: 0,
            steps: 10,
            direction: 1,
        },
        Command::RateMove {
            id,
            motor: 1,
            steps: 100,
            direction: 0,
            rate: 75,
        },
        Command::Home {
            id,
            motor: 2,
            direction: 0,
        },
        Command::Stop { id, motor: 2 },
        Command::SyncMove {
            id,
            steps: [0, 0, 0],
            directions: [0, 0, 0],
            execute: Some(0),
        },
    ];
    for cmd in &acked {
        c.command(cmd).unwrap_or_else(|e| panic!("{cmd:?}: {e}"));
    }
    assert_eq!(c.product_id(0).expect("P"), (1, 100));
    assert_eq!(c.query_limits(0).expect("B"), 0);
    // Motor 2 with the guide's masks: bit 5 low means home 1.
    let st = c.query_status(0, 2).expect("Q");
    assert!(!st.running && !st.home0 && st.home1);
    // The rate move (100 steps at 750 us) is running, then done at 75 ms.
    assert!(c.query_status(0, 1).expect("Q").running);
    std::thread::sleep(Duration::from_millis(150));
    assert!(!c.query_status(0, 1).expect("Q").running);
    let mut emu = emu;
    let pos = emu.ctl("pos");
    let p: Vec<&str> = pos.split_whitespace().collect();
    assert_eq!(p.get(2), Some(&"100"), "{pos}");
}

#[test]
fn device_errors_over_the_pty() {
    let emu = Emu::spawn();
    let mut c = connect(&emu);
    c.initialize(0).expect("0I");
    let err = |c: &mut Client<TTYPort>, raw: &[u8]| -> Response {
        c.transport().send(raw).expect("send");
        let mut buf = [0u8; 64];
        let mut parser = mc3b::codec::ResponseParser::new();
        for _ in 0..50 {
            let n = c
                .transport()
                .recv(&mut buf, Duration::from_millis(20))
                .expect("recv");
            parser.feed(&buf[..n]);
            if let Some(r) = parser.next_response() {
                return r.expect("well-formed reply");
            }
        }
        panic!("no reply to {raw:?}");
    };
    let e = |code| Response::Error { id: 0, code };
    assert_eq!(err(&mut c, b"0X1\r"), e(ErrorCode::InvalidCommand));
    assert_eq!(err(&mut c, b"0M0,5\r"), e(ErrorCode::WrongParameterCount));
    assert_eq!(err(&mut c, b"0N0\r"), e(ErrorCode::OutOfRange));
    assert_eq!(err(&mut c, b"0A0,abc\r"), e(ErrorCode::OutOfRange));
    // A command split in pieces with line feeds is still one command.
    c.transport().send(b"\n0").expect("send");
    std::thread::sleep(Duration::from_millis(20));
    assert_eq!(
        err(&mut c, b"R1,\n0\r\n"),
        Response::Ack {
            id: 0,
            code: CommandCode::Run
        }
    );
    let r = c.command(&Command::Move {
        id: 0,
        motor: 1,
        steps: 5,
        direction: 0,
    });
    assert!(matches!(
        r,
        Err(ClientError::Device(ErrorCode::MotorRunning))
    ));
    // Garbage on the line does not upset the device.
    let mut junk: Vec<u8> = (0..2000u32).map(|i| (i * 37 % 251) as u8).collect();
    junk.push(b'\r');
    c.transport().send(&junk).expect("send junk");
    std::thread::sleep(Duration::from_millis(50));
    c.command(&Command::Stop { id: 0, motor: 1 }).expect("stop");
    assert_eq!(c.product_id(0).expect("P"), (1, 100));
    // Another controller ID gets no answer.
    assert!(matches!(c.query_limits(3), Err(ClientError::Timeout)));
}

/// The control commands that show what the device holds: `settings`, `velocity`,
/// `received`. Values set over the line come back as sent.
#[test]
fn control_channel_shows_settings_speeds_and_frames() {
    let mut emu = Emu::spawn();
    let mut c = connect(&emu);
    let id = 0;
    assert_eq!(
        emu.ctl("settings 1"),
        "settings v=1000 a=5000 d=5000 half=1 hold=0 ih=500 ir=2000 masks=0,0,0,0 \
         modifier=0 debounce=1 chain=0",
        "the defaults of §6.1"
    );
    for cmd in [
        Command::SetMaxVelocity {
            id,
            motor: 1,
            value: 400,
            direction_modifier: Some(1),
        },
        Command::SetAcceleration {
            id,
            motor: 1,
            value: 100_000,
        },
        Command::SetDeceleration {
            id,
            motor: 1,
            value: 700,
        },
        Command::SetHalfStep {
            id,
            motor: 1,
            half: 0,
        },
        Command::SetHoldingCurrent {
            id,
            motor: 1,
            enable: 1,
        },
        Command::SetCurrentLimits {
            id,
            motor: 1,
            holding: 300,
            running: 1200,
        },
        Command::SetLimits {
            id,
            motor: 1,
            h0_and: 4,
            h0_xor: 0,
            h1_and: 16,
            h1_xor: 16,
        },
        Command::SetDebounce { id, count: 9 },
        Command::SyncMove {
            id,
            steps: [1, 0, 0],
            directions: [0, 0, 0],
            execute: Some(0),
        },
    ] {
        c.command(&cmd).unwrap_or_else(|e| panic!("{cmd:?}: {e}"));
    }
    assert_eq!(
        emu.ctl("settings 1"),
        "settings v=400 a=100000 d=700 half=0 hold=1 ih=300 ir=1200 masks=4,0,16,16 \
         modifier=1 debounce=9 chain=1"
    );
    assert!(emu.ctl("settings 3").starts_with("err"));
    // Free run of motor 1 in direction 1 with modifier 1: travel in direction 0
    // (§6.4). At 100000 steps/s² it is at 400 steps/s after 4 ms; 100 ms is plenty.
    c.command(&Command::Run {
        id,
        motor: 1,
        direction: 1,
    })
    .expect("R");
    std::thread::sleep(Duration::from_millis(100));
    assert_eq!(emu.ctl("velocity"), "velocity 0.0 400.0 0.0");
    c.command(&Command::Stop { id, motor: 1 }).expect("S");
    assert_eq!(emu.ctl("velocity"), "velocity 0.0 0.0 0.0");
    let r = emu.ctl("received");
    assert!(
        r.starts_with("received I=0 A=1 D=1 V=1 L=1 F=1 R=1 M=0 H=0 G=0 S=1 Y=1 Q=0 B=0 "),
        "{r}"
    );
    assert!(r.ends_with(" C=1 K=1 N=1 P=0"), "{r}");
}

#[test]
fn help_and_control_channel() {
    let out = Proc::new(env!("CARGO_BIN_EXE_mc3b-emu"))
        .arg("--help")
        .output()
        .expect("run --help");
    let help = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    for word in [
        "input <bit",
        "inputs <byte>",
        "home <motor",
        "pos",
        "state",
        "velocity",
        "settings <motor",
        "received",
        "quit",
    ] {
        assert!(help.contains(word), "--help lacks {word}");
    }
    let bad = Proc::new(env!("CARGO_BIN_EXE_mc3b-emu"))
        .arg("--bogus")
        .output()
        .expect("run");
    assert_eq!(bad.status.code(), Some(2));

    let mut emu = Emu::spawn();
    assert!(emu.ctl("frobnicate").starts_with("err"));
    assert!(emu.ctl("input 9 1").starts_with("err"));
    assert!(
        emu.ctl("home 0 0 1").starts_with("err"),
        "no home configured"
    );
    assert_eq!(emu.ctl("inputs 63"), "ok");
    std::thread::sleep(Duration::from_millis(10));
    let st = emu.ctl("state");
    assert!(st.contains("raw=63 debounced=63"), "{st}");
    assert_eq!(emu.ctl("quit"), "ok");
    let status = emu.child.wait().expect("wait");
    assert!(status.success());
}
