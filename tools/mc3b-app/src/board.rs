//! The board thread: the only one that talks to the serial line. It carries out the
//! page's operations one at a time, stops before anything else, polls the motor status
//! and the limit inputs, keeps the record of the settings the board acknowledged, and
//! publishes the state for the page.
//!
//! Decisions where the guide is silent:
//! * **Polling.** `Q0`, `Q1`, `Q2` and `B` every [`POLL_PERIOD`] (the guide's application
//!   about once a second). One round is 44 characters on the line, about 23 ms at 19200
//!   baud: under an eighth of the line, so commands never wait long behind it.
//! * **Positions.** The MC3B never reports one (§6.13). The page shows an estimate: a
//!   model of the device (the project's emulator) fed every acknowledged command at the
//!   time it was sent and the limit inputs the board reports; a motor the board reports
//!   idle is stopped in the model too. Against `mc3b-emu` the estimate is exact to a
//!   step or two; against a real board it is as good as that model.
//! * **Line trouble.** No answer within the reply timeout: the line is *silent* (shown,
//!   polling goes on, the client brings the line back in step, §6 has no sequence
//!   numbers). The port itself failing (unplugged adapter, closed pty): *lost*, the port
//!   is closed and the page asks for a port again.
//! * **Safety.** Every stop goes out before any other command; a chain upload checks
//!   for one between its moves. Leaving a port, and ending the application, send `0I`
//!   (motors off, as `mcl_deinitialize`, §4.3).

use std::collections::VecDeque;
use std::sync::Arc;
use std::time::{Duration, Instant};

use mc3b::client::{Client, ClientError, MotorStatus, Transport};
use mc3b::codec::Command;
use mc3b::emulator::{Emulator, PRODUCT_ID};
use mc3b::serial::open_port;
use serde::Serialize;

use crate::checks::{FieldError, Op, MOTORS};
use crate::circle::CirclePlan;
use crate::params::{MotorParams, ID};
use crate::shared::{Refusal, Reply, Shared, Work, HEARTBEAT_TIMEOUT};

/// Time between two polls of the board.
pub const POLL_PERIOD: Duration = Duration::from_millis(200);
/// While a motor moves, the state is published at least this often (the estimated
/// positions move).
pub const MOVING_PUBLISH: Duration = Duration::from_millis(100);
/// Events kept for the page.
const EVENTS_KEPT: usize = 40;

/// Opens a serial device by path: a real port at 19200 8N1, or (tests) anything else.
pub type Opener = Box<dyn Fn(&str, Duration) -> Result<Box<dyn Transport + Send>, String> + Send>;

/// The opener of real serial ports.
pub fn serial_opener() -> Opener {
    Box::new(|path, timeout| {
        open_port(path, timeout)
            .map(|p| Box::new(p) as Box<dyn Transport + Send>)
            .map_err(|e| e.to_string())
    })
}

/// A motor in manual control (§5.5): free-running since `R` in `run_dir`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct FreeRun {
    run_dir: u32,
    speed: i32,
}

/// A circle under way, for the drawing.
#[derive(Debug, Clone)]
struct CircleRun {
    plan: CirclePlan,
    start: [i64; 2],
}

/// An open port with an MC3B on it.
struct Conn {
    path: String,
    firmware: u32,
    client: Client<Box<dyn Transport + Send>>,
    /// The device as the application believes it (see the module docs).
    model: Emulator,
    model_at: Duration,
    params: [MotorParams; MOTORS],
    debounce: u32,
    /// The chained-move buffer may hold moves of an upload cut short.
    chain_dirty: bool,
    status: [Option<MotorStatus>; MOTORS],
    inputs: Option<u8>,
    manual: [Option<FreeRun>; MOTORS],
    moved_since_poll: bool,
    last_answer: Instant,
    silent_since: Option<Instant>,
    circle: Option<CircleRun>,
}

/// One line of the page's event log.
#[derive(Debug, Clone, Serialize)]
struct Event {
    id: u64,
    level: &'static str,
    text: String,
    t_ms: u64,
}

/// What the line to the board is like, for the page.
#[derive(Debug, Clone, PartialEq)]
enum LinkState {
    /// No port chosen.
    None,
    /// Answers come.
    Ok,
    /// No answer since this long.
    Silent,
    /// The port failed and was closed.
    Lost(String),
}

/// The board thread's state.
pub struct Board {
    shared: Arc<Shared>,
    opener: Opener,
    timeout: Duration,
    conn: Option<Conn>,
    link: LinkState,
    last_port: Option<String>,
    events: VecDeque<Event>,
    next_event: u64,
    started: Instant,
    next_poll: Instant,
}

/// The page's view of one motor.
#[derive(Serialize)]
struct MotorView {
    running: Option<bool>,
    home0: Option<bool>,
    home1: Option<bool>,
    position: i64,
    speed: f64,
    manual: Option<i32>,
    params: MotorParams,
}

/// The published state.
#[derive(Serialize)]
struct View<'a> {
    link: &'a str,
    port: Option<&'a str>,
    firmware: Option<String>,
    link_message: Option<&'a str>,
    last_answer_ms: Option<u64>,
    inputs: Option<u8>,
    debounce: u32,
    motors: Vec<MotorView>,
    busy: Option<&'a str>,
    circle: Option<Vec<[i64; 2]>>,
    circle_motors: Option<[u32; 2]>,
    events: Vec<&'a Event>,
    heartbeat_ms: u64,
    poll_ms: u64,
}

/// A client error in words: the device's refusals in the words of §6.19.
fn words(e: &ClientError, what: &str, timeout: Duration) -> String {
    match e {
        ClientError::Device(code) => format!(
            "the MC3B refused {what}: error {} ({})",
            code.number(),
            code.meaning()
        ),
        ClientError::Timeout => format!(
            "no answer from the MC3B to {what} within {} ms: the line is silent (cable, \
             power?)",
            timeout.as_millis()
        ),
        ClientError::Io(io) => format!("the serial port failed during {what}: {io}"),
        ClientError::Unexpected(r) => {
            format!("the MC3B answered {what} with something that does not fit it ({r:?})")
        }
        ClientError::Garbled(p) => format!("unreadable answer from the MC3B to {what} ({p})"),
    }
}

fn board_refusal(message: String) -> Refusal {
    Refusal::new(502, message)
}

impl Board {
    /// A board thread's state, with no port open yet.
    pub fn new(shared: Arc<Shared>, opener: Opener, timeout: Duration) -> Board {
        let now = Instant::now();
        Board {
            shared,
            opener,
            timeout,
            conn: None,
            link: LinkState::None,
            last_port: None,
            events: VecDeque::new(),
            next_event: 1,
            started: now,
            next_poll: now,
        }
    }

    /// Runs until the application ends; then the motors are turned off (`0I`).
    pub fn run(mut self) {
        self.publish();
        loop {
            let moving = self.conn.as_ref().is_some_and(|c| {
                c.status.iter().flatten().any(|s| s.running) || c.moved_since_poll
            });
            let until = if self.conn.is_some() {
                if moving {
                    self.next_poll.min(Instant::now() + MOVING_PUBLISH)
                } else {
                    self.next_poll
                }
            } else {
                Instant::now() + Duration::from_secs(1)
            };
            match self.shared.next_work(until) {
                Work::Shutdown => {
                    self.leave("the application ends");
                    self.publish();
                    return;
                }
                Work::Stop {
                    motors,
                    reason,
                    gen,
                } => {
                    let r = self.stop(motors, &reason);
                    self.publish();
                    self.shared.stop_finished(gen, r);
                }
                Work::Manual(targets) => self.manual(targets),
                Work::Op(op, tx) => {
                    let r =
                        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.execute(op)))
                            .unwrap_or_else(|_| Err(Refusal::new(500, "internal error (a panic)")));
                    self.shared.set_busy(None);
                    let _ = tx.send(r);
                }
                Work::Idle => {
                    if self.conn.is_some() && Instant::now() >= self.next_poll {
                        self.poll();
                    }
                }
            }
            self.publish();
        }
    }

    fn event(&mut self, level: &'static str, text: String) {
        let e = Event {
            id: self.next_event,
            level,
            text,
            t_ms: self.started.elapsed().as_millis() as u64,
        };
        self.next_event += 1;
        self.events.push_back(e);
        while self.events.len() > EVENTS_KEPT {
            self.events.pop_front();
        }
    }

    /// Publishes the state for the page.
    fn publish(&mut self) {
        let conn = self.conn.as_ref();
        let motors = (0..MOTORS)
            .map(|m| {
                let st = conn.and_then(|c| c.status[m]);
                MotorView {
                    running: st.map(|s| s.running),
                    home0: st.map(|s| s.home0),
                    home1: st.map(|s| s.home1),
                    position: conn.map_or(0, |c| c.model.position(m)),
                    speed: conn.map_or(0.0, |c| (c.model.velocity(m) * 10.0).round() / 10.0),
                    manual: conn.and_then(|c| c.manual[m].map(|f| f.speed)),
                    params: conn.map_or(MotorParams::DEFAULT, |c| c.params[m]),
                }
            })
            .collect();
        let (link, link_message) = match &self.link {
            LinkState::None => ("none", None),
            LinkState::Ok => ("ok", None),
            LinkState::Silent => ("silent", None),
            LinkState::Lost(m) => ("lost", Some(m.as_str())),
        };
        let circle = conn.and_then(|c| c.circle.as_ref());
        let busy = self.shared.busy();
        let view = View {
            link,
            port: conn.map(|c| c.path.as_str()).or(self.last_port.as_deref()),
            firmware: conn.map(|c| format!("{}.{:02}", c.firmware / 100, c.firmware % 100)),
            link_message,
            last_answer_ms: conn.map(|c| c.last_answer.elapsed().as_millis() as u64),
            inputs: conn.and_then(|c| c.inputs),
            debounce: conn.map_or(1, |c| c.debounce),
            motors,
            busy: busy.as_deref(),
            circle: circle.map(|r| {
                r.plan
                    .points
                    .iter()
                    .map(|p| [r.start[0] + p[0], r.start[1] + p[1]])
                    .collect()
            }),
            circle_motors: circle.map(|r| [r.plan.x_motor, r.plan.y_motor]),
            events: self.events.iter().collect(),
            heartbeat_ms: HEARTBEAT_TIMEOUT.as_millis() as u64,
            poll_ms: POLL_PERIOD.as_millis() as u64,
        };
        let json = serde_json::to_string(&view).unwrap_or_else(|_| "{}".into());
        let params = conn.map_or([MotorParams::DEFAULT; MOTORS], |c| c.params);
        let may_move = conn.is_some_and(|c| {
            c.moved_since_poll
                || c.manual.iter().any(Option::is_some)
                || c.status.iter().any(|s| s.is_none_or(|s| s.running))
        });
        self.shared
            .publish(json, params, self.conn.is_some(), may_move);
    }

    /// Sends `cmd` and waits for its acknowledgement; feeds it to the model at the time
    /// the board got it. A reply that only came late is found by bringing the line back
    /// in step, and then counts as an acknowledgement. A failed port closes the
    /// connection (the link is lost).
    fn send(&mut self, cmd: Command, what: &str) -> Result<(), String> {
        let timeout = self.timeout;
        let Some(c) = self.conn.as_mut() else {
            return Err("no MC3B connected".into());
        };
        let r = match c.client.command(&cmd) {
            Ok(()) => Ok(()),
            Err(e @ ClientError::Io(_)) => Err(e),
            Err(e) => c.client.settle(&cmd, e),
        };
        match r {
            Ok(()) => {
                let at = c.client.sent_at();
                if at > c.model_at {
                    c.model.advance(at - c.model_at);
                    c.model_at = at;
                }
                let _ = c.model.handle(&cmd);
                self.answered();
                Ok(())
            }
            Err(e) => {
                let msg = words(&e, what, timeout);
                self.failed(&e, &msg);
                Err(msg)
            }
        }
    }

    /// The board answered: the line is fine.
    fn answered(&mut self) {
        let back = matches!(self.link, LinkState::Silent);
        if let Some(c) = self.conn.as_mut() {
            c.last_answer = Instant::now();
            c.silent_since = None;
        }
        self.link = LinkState::Ok;
        if back {
            self.event("info", "the MC3B answers again".into());
        }
    }

    /// A command or query failed with `e`: a silent line is shown as such, a failed
    /// port closes the connection.
    fn failed(&mut self, e: &ClientError, msg: &str) {
        match e {
            ClientError::Io(io) => {
                let path = self
                    .conn
                    .as_ref()
                    .map(|c| c.path.clone())
                    .unwrap_or_default();
                let text = format!("the port {path} is gone ({io}): choose a port again to go on");
                self.conn = None;
                self.link = LinkState::Lost(text.clone());
                self.event("error", text);
            }
            ClientError::Timeout => {
                let first = self.link != LinkState::Silent;
                if let Some(c) = self.conn.as_mut() {
                    c.silent_since.get_or_insert_with(Instant::now);
                }
                self.link = LinkState::Silent;
                if first {
                    self.event("error", msg.to_string());
                }
            }
            _ => {}
        }
    }

    /// `Q` of motor `m`.
    fn query(&mut self, m: usize) -> Result<MotorStatus, String> {
        let timeout = self.timeout;
        let Some(c) = self.conn.as_mut() else {
            return Err("no MC3B connected".into());
        };
        match c.client.query_status(ID, m as u32) {
            Ok(s) => {
                c.status[m] = Some(s);
                self.answered();
                Ok(s)
            }
            Err(e) => {
                let msg = words(&e, &format!("the status query of motor {m} (Q)"), timeout);
                self.failed(&e, &msg);
                Err(msg)
            }
        }
    }

    /// Polls the three motors and the limit inputs; reconciles the model and the
    /// manual control with what the board says.
    fn poll(&mut self) {
        self.next_poll = Instant::now() + POLL_PERIOD;
        if let Some(c) = self.conn.as_mut() {
            c.moved_since_poll = false;
        }
        for m in 0..MOTORS {
            if self.shared.stop_pending() {
                return;
            }
            if self.query(m).is_err() {
                return;
            }
        }
        let timeout = self.timeout;
        let Some(c) = self.conn.as_mut() else { return };
        match c.client.query_limits(ID) {
            Ok(bits) => {
                c.inputs = Some(bits);
                self.answered();
            }
            Err(e) => {
                let msg = words(&e, "the limit input query (B)", timeout);
                self.failed(&e, &msg);
                return;
            }
        }
        self.reconcile();
    }

    /// Brings the model and the manual control in line with the board's answers.
    fn reconcile(&mut self) {
        let mut ended = Vec::new();
        let Some(c) = self.conn.as_mut() else { return };
        let now = c.client.transport().now();
        if now > c.model_at {
            c.model.advance(now - c.model_at);
            c.model_at = now;
        }
        if let Some(bits) = c.inputs {
            c.model.set_inputs(bits);
        }
        for m in 0..MOTORS {
            let running = c.status[m].is_some_and(|s| s.running);
            if !running && c.model.is_running(m) {
                let _ = c.model.handle(&Command::Stop {
                    id: ID,
                    motor: m as u32,
                });
            }
            if !running && c.manual[m].is_some() {
                c.manual[m] = None;
                ended.push(m);
            }
        }
        for m in ended {
            self.event(
                "info",
                format!("motor {m} stopped by itself (a limit switch?): manual control ended"),
            );
            self.restore_velocity(m);
        }
    }

    /// After manual control the board's maximum velocity is the record's again.
    fn restore_velocity(&mut self, m: usize) {
        let Some(v) = self.conn.as_ref().map(|c| c.params[m].max_velocity) else {
            return;
        };
        let cmd = Command::SetMaxVelocity {
            id: ID,
            motor: m as u32,
            value: v,
            direction_modifier: None,
        };
        if let Err(e) = self.send(cmd, &format!("the maximum velocity of motor {m} (V)")) {
            self.event("error", e);
        }
    }

    /// Stops the flagged motors (`S`), best effort each; ends their manual control.
    fn stop(&mut self, motors: [bool; MOTORS], reason: &str) -> String {
        if self.conn.is_none() {
            return "no MC3B connected: nothing to stop".into();
        }
        let mut stopped = Vec::new();
        let mut errors = Vec::new();
        for (m, _) in motors.iter().enumerate().filter(|(_, &f)| f) {
            let cmd = Command::Stop {
                id: ID,
                motor: m as u32,
            };
            match self.send(cmd, &format!("stop motor {m} (S)")) {
                Ok(()) => stopped.push(m.to_string()),
                Err(e) => errors.push(e),
            }
            if self.conn.is_none() {
                break;
            }
        }
        for (m, _) in motors.iter().enumerate().filter(|(_, &f)| f) {
            let was_manual = self
                .conn
                .as_mut()
                .and_then(|c| c.manual.get_mut(m).and_then(Option::take))
                .is_some();
            if was_manual {
                self.restore_velocity(m);
            }
        }
        let text = if errors.is_empty() {
            format!("stopped motor {} ({reason})", stopped.join(", "))
        } else {
            format!(
                "stop ({reason}): stopped motor {}; {}",
                if stopped.is_empty() {
                    "none".to_string()
                } else {
                    stopped.join(", ")
                },
                errors.join("; ")
            )
        };
        self.event(
            if errors.is_empty() { "info" } else { "error" },
            text.clone(),
        );
        if self.conn.is_some() {
            self.poll();
        }
        text
    }

    /// Brings manual control to the sliders' speeds (§5.5: free-running, §4.12, with
    /// on-the-fly changes of velocity and direction, §4.6, §6.4). Speed 0 stops the
    /// motor. Failures go to the event log (the slider's request has been answered).
    fn manual(&mut self, targets: [Option<i32>; MOTORS]) {
        for (m, t) in targets.iter().enumerate() {
            let Some(speed) = *t else { continue };
            if let Err(e) = self.manual_one(m, speed) {
                self.event("error", format!("manual control of motor {m}: {e}"));
            }
        }
    }

    fn manual_one(&mut self, m: usize, speed: i32) -> Result<(), String> {
        let Some(c) = self.conn.as_ref() else {
            return Err("no MC3B connected".into());
        };
        let current = c.manual[m];
        let running = c.status[m].is_some_and(|s| s.running);
        let mi = m as u32;
        if speed == 0 {
            if current.is_some() {
                self.send(
                    Command::Stop { id: ID, motor: mi },
                    &format!("stop motor {m} (S)"),
                )?;
                if let Some(c) = self.conn.as_mut() {
                    c.manual[m] = None;
                }
                self.restore_velocity(m);
            }
            return Ok(());
        }
        let dir = u32::from(speed < 0);
        let v = speed.unsigned_abs().max(1);
        match current {
            None => {
                if running {
                    return Err(format!(
                        "motor {m} is running (not under manual control): stop it first"
                    ));
                }
                self.shared.set_may_move();
                self.send(
                    Command::SetMaxVelocity {
                        id: ID,
                        motor: mi,
                        value: v,
                        direction_modifier: None,
                    },
                    &format!("the speed of motor {m} (V)"),
                )?;
                self.mark_moved();
                self.send(
                    Command::Run {
                        id: ID,
                        motor: mi,
                        direction: dir,
                    },
                    &format!("free run of motor {m} (R)"),
                )?;
                if let Some(c) = self.conn.as_mut() {
                    c.manual[m] = Some(FreeRun {
                        run_dir: dir,
                        speed,
                    });
                }
            }
            Some(fr) => {
                // §6.4: modifier 1 runs opposite to the direction R was given.
                let modifier = u32::from(dir != fr.run_dir);
                self.send(
                    Command::SetMaxVelocity {
                        id: ID,
                        motor: mi,
                        value: v,
                        direction_modifier: Some(modifier),
                    },
                    &format!("the speed of motor {m} (V)"),
                )?;
                if let Some(c) = self.conn.as_mut() {
                    c.manual[m] = Some(FreeRun { speed, ..fr });
                }
            }
        }
        Ok(())
    }

    fn mark_moved(&mut self) {
        if let Some(c) = self.conn.as_mut() {
            c.moved_since_poll = true;
        }
        self.shared.set_may_move();
    }

    fn connected(&self) -> Result<(), Refusal> {
        if self.conn.is_some() {
            Ok(())
        } else {
            Err(Refusal::new(
                503,
                "no MC3B connected: choose its port first (port selection)",
            ))
        }
    }

    fn in_manual(&self, m: u32) -> Result<(), Refusal> {
        if self
            .conn
            .as_ref()
            .is_some_and(|c| c.manual[m as usize].is_some())
        {
            return Err(Refusal::new(
                409,
                format!("motor {m} is under manual control: close manual control first"),
            ));
        }
        Ok(())
    }

    /// Sends one motion command of an operation.
    fn motion(&mut self, cmd: Command, what: &str) -> Reply {
        self.mark_moved();
        self.send(cmd, what).map_err(board_refusal)?;
        self.next_poll = Instant::now();
        Ok(format!("{what}: started"))
    }

    /// Carries out a checked operation.
    fn execute(&mut self, op: Op) -> Reply {
        match op {
            Op::Connect(path) => self.connect(&path),
            Op::Disconnect => {
                self.connected()?;
                let path = self.conn.as_ref().map(|c| c.path.clone());
                self.leave("disconnected by the user");
                self.link = LinkState::None;
                self.last_port = path;
                Ok("port closed; the motors are off".into())
            }
            Op::Debounce(count) => {
                self.connected()?;
                self.send(
                    Command::SetDebounce { id: ID, count },
                    "the debounce count (N)",
                )
                .map_err(board_refusal)?;
                if let Some(c) = self.conn.as_mut() {
                    c.debounce = count;
                }
                Ok(format!("debounce count {count}"))
            }
            Op::Run { motor, direction } => {
                self.connected()?;
                self.in_manual(motor)?;
                self.motion(
                    Command::Run {
                        id: ID,
                        motor,
                        direction,
                    },
                    &format!("run motor {motor} in direction {direction} (R)"),
                )
            }
            Op::Home { motor, direction } => {
                self.connected()?;
                self.in_manual(motor)?;
                let has_limit = self
                    .conn
                    .as_ref()
                    .is_some_and(|c| c.params[motor as usize].limit(direction).is_some());
                if !has_limit {
                    return Err(Refusal {
                        status: 409,
                        message: format!(
                            "motor {motor} has no direction {direction} limit (set parameters): \
                             homing would run until stopped"
                        ),
                        fields: vec![FieldError {
                            field: format!("home.{motor}"),
                            message: "no limit switch in that direction".into(),
                        }],
                    });
                }
                self.motion(
                    Command::Home {
                        id: ID,
                        motor,
                        direction,
                    },
                    &format!("home motor {motor} in direction {direction} (H)"),
                )
            }
            Op::Move {
                motor,
                direction,
                steps,
            } => {
                self.connected()?;
                self.in_manual(motor)?;
                self.motion(
                    Command::Move {
                        id: ID,
                        motor,
                        steps,
                        direction,
                    },
                    &format!("move motor {motor} {steps} steps in direction {direction} (M)"),
                )
            }
            Op::SyncMove { steps, directions } => {
                self.connected()?;
                for m in 0..MOTORS as u32 {
                    self.in_manual(m)?;
                }
                // Without <execute> the move runs now and discards the chained-move
                // buffer (§6.12): nothing stored earlier can run with it.
                let r = self.motion(
                    Command::SyncMove {
                        id: ID,
                        steps,
                        directions,
                        execute: None,
                    },
                    "the synchronous move (Y)",
                )?;
                if let Some(c) = self.conn.as_mut() {
                    c.chain_dirty = false;
                }
                Ok(r)
            }
            Op::SetParams { motor, params } => self.set_params(motor, params),
            Op::Circle(plan) => self.circle(plan),
        }
    }

    /// Port selection (§5.1): open `path`, look for the MC3B (`P`, §6.18) and initialize
    /// it (`I`, §6.1: motors off, the defaults).
    fn connect(&mut self, path: &str) -> Reply {
        if self.conn.is_some() {
            self.leave(&format!("switching to {path}"));
        }
        self.last_port = Some(path.to_string());
        let transport = (self.opener)(path, self.timeout).map_err(|e| Refusal {
            status: 400,
            message: format!("cannot open {path}: {e}"),
            fields: vec![FieldError {
                field: "port".into(),
                message: format!("cannot open {path}: {e}"),
            }],
        })?;
        let mut client = Client::new(transport, self.timeout);
        let timeout = self.timeout;
        // A controller answers P at its ID; one whose ID an earlier program changed
        // answers only I (obeyed at any ID, §6.1), so try that before giving up. The
        // client would first bring the line back in step with a P that nobody answers:
        // a fresh client sends the I as it is.
        let found = match client.product_id(ID) {
            Err(e) if !matches!(e, ClientError::Io(_)) => {
                client = Client::new(client.into_transport(), timeout);
                client
                    .initialize(ID)
                    .and_then(|()| client.product_id(ID))
                    .map(|p| (p, true))
            }
            r => r.map(|p| (p, false)),
        };
        let ((product, firmware), initialized) = match found {
            Ok(f) => f,
            Err(ClientError::Timeout) => {
                return Err(board_refusal(format!(
                    "nothing answers on {path}: no MC3B replied to 0P or 0I within {} ms \
                     (§6.18); check that it is powered and on this port",
                    timeout.as_millis()
                )))
            }
            Err(e) => return Err(board_refusal(words(&e, "the product query (P)", timeout))),
        };
        if product != PRODUCT_ID {
            return Err(board_refusal(format!(
                "the device on {path} answers product {product}: not an MC3B (product 1, \
                 §6.18)"
            )));
        }
        if !initialized {
            client
                .initialize(ID)
                .map_err(|e| board_refusal(words(&e, "the initialization (I)", timeout)))?;
        }
        let now = client.transport().now();
        let mut model = Emulator::new();
        let _ = model.handle(&Command::Initialize { id: ID });
        self.conn = Some(Conn {
            path: path.to_string(),
            firmware,
            client,
            model,
            model_at: now,
            params: [MotorParams::DEFAULT; MOTORS],
            debounce: 1,
            chain_dirty: false,
            status: [None; MOTORS],
            inputs: None,
            manual: [None; MOTORS],
            moved_since_poll: false,
            last_answer: Instant::now(),
            silent_since: None,
            circle: None,
        });
        self.link = LinkState::Ok;
        let text = format!(
            "MC3B found on {path} (firmware {}.{:02}) and initialized: motors off, §6.1 defaults",
            firmware / 100,
            firmware % 100
        );
        self.event("info", text.clone());
        self.poll();
        Ok(text)
    }

    /// Turns the motors off (`0I`, best effort) and closes the port.
    fn leave(&mut self, why: &str) {
        let Some(mut c) = self.conn.take() else {
            return;
        };
        let r = c.client.initialize(ID);
        let text = match r {
            Ok(()) => format!("{}: motors off (0I), port closed ({why})", c.path),
            Err(e) => format!(
                "{}: port closed ({why}); turning the motors off failed: {}",
                c.path,
                words(&e, "the initialization (I)", self.timeout)
            ),
        };
        self.event("info", text);
    }

    /// The set parameters dialog's OK (§5.3): every value, in the order V, A, D, F, C,
    /// K, L, once the motor is idle (the board refuses V, A, D, F while it moves).
    fn set_params(&mut self, motor: u32, params: MotorParams) -> Reply {
        self.connected()?;
        let m = motor as usize;
        let st = self.query(m).map_err(board_refusal)?;
        if st.running {
            return Err(Refusal::new(
                409,
                format!(
                    "motor {motor} is running: stop it before changing its parameters (the \
                     MC3B takes them only from an idle motor, §4.4-§4.7)"
                ),
            ));
        }
        let mut applied = Vec::new();
        for (what, cmd) in params.commands(motor) {
            match self.send(cmd.clone(), &format!("the {what} of motor {motor}")) {
                Ok(()) => {
                    if let Some(c) = self.conn.as_mut() {
                        c.params[m].apply(&cmd);
                    }
                    applied.push(what);
                }
                Err(e) => {
                    let done = if applied.is_empty() {
                        "nothing applied".to_string()
                    } else {
                        format!("applied: {}", applied.join(", "))
                    };
                    self.event("error", format!("set parameters of motor {motor}: {e}"));
                    return Err(board_refusal(format!("{e}; {done}; the rest not sent")));
                }
            }
        }
        let text = format!("parameters of motor {motor} applied");
        self.event("info", text.clone());
        Ok(text)
    }

    /// The chained synchronous move (§5.4, §4.17): all three motors idle (§4.16), the
    /// buffer cleared of an earlier upload cut short, the chords stored with execute 0
    /// and the last sent with execute 1. A stop during the upload ends it; what was
    /// stored is discarded before the next chain.
    fn circle(&mut self, plan: CirclePlan) -> Reply {
        self.connected()?;
        for m in 0..MOTORS {
            self.in_manual(m as u32)?;
            if self.query(m).map_err(board_refusal)?.running {
                return Err(Refusal::new(
                    409,
                    format!(
                        "motor {m} is running: a chained move needs all three motors idle \
                         (§4.16)"
                    ),
                ));
            }
        }
        if self.conn.as_ref().is_some_and(|c| c.chain_dirty) {
            self.send(
                Command::SyncMove {
                    id: ID,
                    steps: [0; 3],
                    directions: [0; 3],
                    execute: None,
                },
                "discarding the chained-move buffer (Y without execute)",
            )
            .map_err(board_refusal)?;
            if let Some(c) = self.conn.as_mut() {
                c.chain_dirty = false;
            }
        }
        let moves = plan.moves();
        let n = moves.len();
        let (xm, ym) = (plan.x_motor as usize, plan.y_motor as usize);
        if let Some(c) = self.conn.as_mut() {
            c.circle = Some(CircleRun {
                start: [c.model.position(xm), c.model.position(ym)],
                plan: plan.clone(),
            });
        }
        for (k, mv) in moves.iter().enumerate() {
            if self.shared.stop_pending() {
                return Err(Refusal::new(
                    409,
                    format!(
                        "stopped during the upload after {k} of {n} chords: nothing of the \
                         chain runs (the stored chords are discarded before the next chain)"
                    ),
                ));
            }
            if k % 10 == 0 {
                self.shared
                    .set_busy(Some(format!("the circle's upload ({k} of {n} chords)")));
                self.publish();
            }
            let mut steps = [0u32; 3];
            let mut dirs = [0u32; 3];
            steps[xm] = mv[0].0;
            dirs[xm] = mv[0].1;
            steps[ym] = mv[1].0;
            dirs[ym] = mv[1].1;
            let last = k + 1 == n;
            if last {
                self.mark_moved();
            }
            if let Some(c) = self.conn.as_mut() {
                // From the first store on, the buffer may hold chords until the last
                // one's execute.
                c.chain_dirty = true;
            }
            let cmd = Command::SyncMove {
                id: ID,
                steps,
                directions: dirs,
                execute: Some(u32::from(last)),
            };
            self.send(cmd, &format!("chord {} of {n} (Y)", k + 1))
                .map_err(board_refusal)?;
        }
        if let Some(c) = self.conn.as_mut() {
            c.chain_dirty = false;
        }
        self.next_poll = Instant::now();
        let text = format!(
            "circle of radius {} steps in {n} chords on motors {xm} (X) and {ym} (Y): running",
            plan.radius
        );
        self.event("info", text.clone());
        Ok(text)
    }
}

#[cfg(test)]
mod tests;
