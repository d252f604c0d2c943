//! The board thread's operations over an in-process emulator: deterministic (the
//! emulator's clock moves only when a test or a reply wait moves it).

use super::*;
use std::io;
use std::sync::atomic::{AtomicU8, Ordering};

use mc3b::client::EmulatorLink;
use mc3b::codec::CommandCode;
use parking_lot::Mutex;

use crate::checks::Op;
use crate::circle;
use crate::params::Limit;

/// How the test's line behaves.
const FINE: u8 = 0;
/// Nothing comes back (a silent board).
const SILENT: u8 = 1;
/// The port fails (an unplugged adapter).
const GONE: u8 = 2;

/// The emulator behind a line the test can still look at and spoil.
#[derive(Clone)]
struct Line {
    link: Arc<Mutex<EmulatorLink>>,
    mode: Arc<AtomicU8>,
}

impl Transport for Line {
    fn send(&mut self, data: &[u8]) -> io::Result<()> {
        match self.mode.load(Ordering::Relaxed) {
            GONE => Err(io::Error::new(io::ErrorKind::BrokenPipe, "hung up")),
            SILENT => Ok(()),
            _ => self.link.lock().send(data),
        }
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        match self.mode.load(Ordering::Relaxed) {
            GONE => Err(io::Error::new(io::ErrorKind::BrokenPipe, "hung up")),
            SILENT => {
                self.link.lock().idle(timeout);
                Ok(0)
            }
            _ => self.link.lock().recv(buf, timeout),
        }
    }
    fn discard_input(&mut self) -> io::Result<()> {
        self.link.lock().discard_input()
    }
    fn now(&self) -> Duration {
        self.link.lock().now()
    }
    fn idle(&mut self, d: Duration) {
        self.link.lock().idle(d)
    }
    fn is_realtime(&self) -> bool {
        false
    }
}

struct Rig {
    board: Board,
    line: Line,
    shared: Arc<Shared>,
}

impl Rig {
    /// A board thread's state whose only port is `/dev/mc3b`, an emulator.
    fn new() -> Rig {
        let line = Line {
            link: Arc::new(Mutex::new(EmulatorLink::new())),
            mode: Arc::new(AtomicU8::new(FINE)),
        };
        let l = line.clone();
        let opener: Opener = Box::new(move |path, _| {
            if path == "/dev/mc3b" {
                Ok(Box::new(l.clone()))
            } else {
                Err("No such file or directory".into())
            }
        });
        let shared = Shared::new();
        shared.heartbeat();
        let board = Board::new(shared.clone(), opener, Duration::from_millis(100));
        Rig {
            board,
            line,
            shared,
        }
    }

    fn connected() -> Rig {
        let mut r = Rig::new();
        r.board
            .execute(Op::Connect("/dev/mc3b".into()))
            .expect("connect");
        r
    }

    fn emu<T>(&self, f: impl FnOnce(&mut Emulator) -> T) -> T {
        f(&mut self.line.link.lock().emulator)
    }

    fn received(&self, c: CommandCode) -> u64 {
        self.emu(|e| e.received(c))
    }

    /// Lets `ms` pass on the device, then polls.
    fn wait(&mut self, ms: u64) {
        self.emu(|e| e.advance(Duration::from_millis(ms)));
        self.board.poll();
    }

    fn state(&mut self) -> serde_json::Value {
        self.board.publish();
        let (_, json) = self.shared.snapshot();
        serde_json::from_str(json.as_deref().unwrap_or("{}")).expect("state JSON")
    }
}

/// Every command letter that changes something on the board (not the three queries).
const ACTING: [CommandCode; 15] = [
    CommandCode::Initialize,
    CommandCode::Acceleration,
    CommandCode::Deceleration,
    CommandCode::Velocity,
    CommandCode::Limits,
    CommandCode::HalfStep,
    CommandCode::Run,
    CommandCode::Move,
    CommandCode::Home,
    CommandCode::RateMove,
    CommandCode::Stop,
    CommandCode::SyncMove,
    CommandCode::HoldingCurrent,
    CommandCode::CurrentLimits,
    CommandCode::Debounce,
];

fn acting(r: &Rig) -> Vec<u64> {
    ACTING.iter().map(|&c| r.received(c)).collect()
}

#[test]
fn port_selection_finds_and_initializes_the_mc3b() {
    let mut r = Rig::new();
    let e = r
        .board
        .execute(Op::Connect("/dev/missing".into()))
        .expect_err("no such port");
    assert_eq!(e.status, 400);
    assert!(
        e.message.contains("cannot open /dev/missing"),
        "{}",
        e.message
    );
    assert_eq!(e.fields[0].field, "port");
    assert_eq!(r.received(CommandCode::ProductId), 0, "nothing sent");
    // Found: 0P (product 1), then 0I; then the first poll (Q0..Q2, B).
    let msg = r
        .board
        .execute(Op::Connect("/dev/mc3b".into()))
        .expect("found");
    assert!(msg.contains("firmware 1.00"), "{msg}");
    assert_eq!(r.received(CommandCode::ProductId), 1);
    assert_eq!(r.received(CommandCode::Initialize), 1);
    assert_eq!(r.received(CommandCode::QueryStatus), 3);
    assert_eq!(r.received(CommandCode::QueryLimits), 1);
    let s = r.state();
    assert_eq!(s["link"], "ok");
    assert_eq!(s["port"], "/dev/mc3b");
    assert_eq!(s["motors"][2]["params"]["max_velocity"], 1000);
}

#[test]
fn a_controller_with_another_id_is_found_through_initialize() {
    // An earlier program made the controller's ID 3 (§6.1): 0P gets no answer, 0I is
    // obeyed at any ID and makes it 0 again.
    let mut r = Rig::new();
    r.emu(|e| e.receive(b"3I\r"));
    r.board
        .execute(Op::Connect("/dev/mc3b".into()))
        .expect("found after 0I");
    assert_eq!(r.emu(|e| e.id()), 0);
}

#[test]
fn nothing_answering_is_said_so() {
    let mut r = Rig::new();
    r.line.mode.store(SILENT, Ordering::Relaxed);
    let e = r
        .board
        .execute(Op::Connect("/dev/mc3b".into()))
        .expect_err("silent");
    assert_eq!(e.status, 502);
    assert!(
        e.message.starts_with("nothing answers on /dev/mc3b"),
        "{}",
        e.message
    );
}

#[test]
fn set_parameters_sends_every_value_and_records_it() {
    let mut r = Rig::connected();
    let p = MotorParams {
        max_velocity: 1500,
        acceleration: 8000,
        deceleration: 6000,
        half_steps: false,
        holding_on: true,
        holding_current: 300,
        running_current: 1200,
        limit0: Some(Limit { bit: 2, high: true }),
        limit1: Some(Limit {
            bit: 4,
            high: false,
        }),
    };
    r.board
        .execute(Op::SetParams {
            motor: 1,
            params: p,
        })
        .expect("applied");
    let s = r.emu(|e| e.settings(1)).expect("motor 1");
    assert_eq!(
        (s.max_velocity, s.acceleration, s.deceleration, s.half_steps),
        (1500, 8000, 6000, false)
    );
    assert_eq!(
        (s.use_holding_current, s.holding_current, s.running_current),
        (true, 300, 1200)
    );
    // Bit 2 at +5 V: AND 4, XOR 0; bit 4 at 0 V: AND 16, XOR 16 (§6.5).
    assert_eq!(s.limit_masks, [4, 0, 16, 16]);
    assert_eq!(r.state()["motors"][1]["params"]["max_velocity"], 1500);
    // A running motor's parameters are not touched: nothing of them is sent.
    r.board
        .execute(Op::Move {
            motor: 1,
            direction: 0,
            steps: 100_000,
        })
        .expect("move");
    let before = acting(&r);
    let e = r
        .board
        .execute(Op::SetParams {
            motor: 1,
            params: MotorParams::DEFAULT,
        })
        .expect_err("running");
    assert_eq!(e.status, 409);
    assert_eq!(acting(&r), before);
}

#[test]
fn moves_runs_stops_and_the_synchronous_move() {
    let mut r = Rig::connected();
    r.board
        .execute(Op::Move {
            motor: 0,
            direction: 1,
            steps: 200,
        })
        .expect("move");
    // 200 steps at the defaults (1000 steps/s, 5000 steps/s²): a trapezoid of
    // 0.2 + 0.2 s ramps would need 200 steps for the ramps alone, so a triangle
    // peaking at √(200·5000) = 1000 steps/s: 0.4 s.
    r.wait(450);
    assert_eq!(r.emu(|e| e.position(0)), -200);
    assert_eq!(r.state()["motors"][0]["position"], -200, "the model agrees");
    r.board
        .execute(Op::Run {
            motor: 2,
            direction: 0,
        })
        .expect("run");
    r.wait(500);
    assert!(r.emu(|e| e.is_running(2)));
    assert_eq!(r.state()["motors"][2]["running"], true);
    let msg = r.board.stop([false, false, true], "test");
    assert!(msg.starts_with("stopped motor 2"), "{msg}");
    assert!(!r.emu(|e| e.is_running(2)));
    let p2 = r.emu(|e| e.position(2));
    assert_eq!(
        r.state()["motors"][2]["position"],
        p2,
        "estimate after a stop"
    );
    r.board
        .execute(Op::SyncMove {
            steps: [100, 200, 300],
            directions: [0, 1, 0],
        })
        .expect("sync");
    r.wait(2000);
    assert_eq!(
        r.emu(|e| [e.position(0), e.position(1), e.position(2)]),
        [-100, -200, p2 + 300]
    );
}

#[test]
fn homing_needs_a_limit_in_that_direction() {
    let mut r = Rig::connected();
    let e = r
        .board
        .execute(Op::Home {
            motor: 0,
            direction: 0,
        })
        .expect_err("no limit");
    assert_eq!(e.status, 409);
    assert!(e.message.contains("no direction 0 limit"), "{}", e.message);
    assert_eq!(r.received(CommandCode::Home), 0);
    r.board
        .execute(Op::SetParams {
            motor: 0,
            params: MotorParams {
                limit0: Some(Limit { bit: 0, high: true }),
                ..MotorParams::DEFAULT
            },
        })
        .expect("params");
    r.board
        .execute(Op::Home {
            motor: 0,
            direction: 0,
        })
        .expect("home");
    r.wait(300);
    assert!(r.emu(|e| e.is_running(0)));
    // At the switch: the seek stops, backs off at 10 steps/s while the switch is on.
    r.emu(|e| e.set_input(0, true));
    r.wait(50);
    assert_eq!(r.state()["motors"][0]["home0"], true);
    assert_eq!(r.state()["inputs"], 1);
}

#[test]
fn the_circle_runs_as_one_chain_and_closes() {
    let mut r = Rig::connected();
    let plan = circle::plan(0, 1, 100, 8, true).expect("plan");
    r.board.execute(Op::Circle(plan)).expect("circle");
    assert_eq!(r.received(CommandCode::SyncMove), 8);
    assert_eq!(
        r.emu(|e| e.chain_len()),
        0,
        "the last chord executed the chain"
    );
    r.wait(100);
    assert!(r.emu(|e| e.is_running(0) && e.is_running(1)));
    let s = r.state();
    assert_eq!(s["circle"].as_array().map(Vec::len), Some(9));
    assert_eq!(s["circle_motors"], serde_json::json!([0, 1]));
    r.wait(5000);
    assert_eq!(r.emu(|e| [e.position(0), e.position(1)]), [0, 0]);
}

#[test]
fn a_stop_ends_a_chain_upload_and_the_rest_is_discarded_next_time() {
    let mut r = Rig::connected();
    r.shared.request_stop(None, "test");
    let plan = circle::plan(0, 1, 100, 8, true).expect("plan");
    let e = r
        .board
        .execute(Op::Circle(plan.clone()))
        .expect_err("stopped");
    assert_eq!(e.status, 409);
    assert_eq!(r.received(CommandCode::SyncMove), 0, "nothing of it sent");
    // Take the stop as the board thread would.
    if let Work::Stop { motors, reason, .. } = r.shared.next_work(Instant::now()) {
        r.board.stop(motors, &reason);
    }
    r.board.execute(Op::Circle(plan)).expect("circle");
    assert_eq!(r.received(CommandCode::SyncMove), 8);
}

#[test]
fn manual_control_changes_speed_and_direction_on_the_fly() {
    let mut r = Rig::connected();
    r.board.manual([Some(300), None, None]);
    // V0,300 then R0,0: the free run accelerates at 5000 steps/s² to 300 steps/s.
    r.wait(200);
    assert_eq!(r.emu(|e| e.velocity(0)), 300.0);
    assert_eq!(r.state()["motors"][0]["manual"], 300);
    // The other way at 200: V0,200,1 (§6.4), decelerate, reverse, accelerate.
    r.board.manual([Some(-200), None, None]);
    r.wait(300);
    assert_eq!(r.emu(|e| e.velocity(0)), -200.0);
    assert_eq!(
        r.emu(|e| e.settings(0).map(|s| s.direction_modifier)),
        Some(true)
    );
    // The middle stops it, and the record's maximum velocity is back on the board.
    r.board.manual([Some(0), None, None]);
    assert!(!r.emu(|e| e.is_running(0)));
    assert_eq!(r.emu(|e| e.settings(0).map(|s| s.max_velocity)), Some(1000));
    assert_eq!(r.state()["motors"][0]["manual"], serde_json::Value::Null);
}

#[test]
fn a_free_run_ended_by_its_limit_ends_manual_control() {
    let mut r = Rig::connected();
    r.board
        .execute(Op::SetParams {
            motor: 1,
            params: MotorParams {
                limit0: Some(Limit { bit: 3, high: true }),
                ..MotorParams::DEFAULT
            },
        })
        .expect("params");
    r.board.manual([None, Some(400), None]);
    r.wait(200);
    assert!(r.emu(|e| e.is_running(1)));
    r.emu(|e| e.set_input(3, true));
    r.wait(10);
    assert!(!r.emu(|e| e.is_running(1)));
    let s = r.state();
    assert_eq!(s["motors"][1]["manual"], serde_json::Value::Null);
    assert_eq!(r.emu(|e| e.settings(1).map(|s| s.max_velocity)), Some(1000));
}

#[test]
fn a_silent_line_and_a_lost_port_are_shown() {
    let mut r = Rig::connected();
    r.line.mode.store(SILENT, Ordering::Relaxed);
    r.board.poll();
    let s = r.state();
    assert_eq!(s["link"], "silent");
    let last = s["events"].as_array().and_then(|e| e.last()).cloned();
    assert!(
        last.is_some_and(|e| e["text"].as_str().is_some_and(|t| t.contains("no answer"))),
        "{s}"
    );
    r.line.mode.store(FINE, Ordering::Relaxed);
    r.board.poll();
    assert_eq!(r.state()["link"], "ok");
    r.line.mode.store(GONE, Ordering::Relaxed);
    r.board.poll();
    let s = r.state();
    assert_eq!(s["link"], "lost");
    assert!(
        s["link_message"]
            .as_str()
            .is_some_and(|t| t.contains("/dev/mc3b is gone")),
        "{s}"
    );
    let e = r
        .board
        .execute(Op::Move {
            motor: 0,
            direction: 0,
            steps: 1,
        })
        .expect_err("no board");
    assert_eq!(e.status, 503);
}

#[test]
fn device_refusals_are_in_the_words_of_section_6_19() {
    let mut r = Rig::connected();
    r.board
        .execute(Op::Run {
            motor: 0,
            direction: 0,
        })
        .expect("run");
    // Moving a running motor: the board answers E1.
    let e = r
        .board
        .execute(Op::Move {
            motor: 0,
            direction: 0,
            steps: 10,
        })
        .expect_err("E1");
    assert_eq!(e.status, 502);
    assert_eq!(
        e.message,
        "the MC3B refused move motor 0 10 steps in direction 0 (M): error 1 (motor running: \
         command must be sent when motor is idle)"
    );
}
