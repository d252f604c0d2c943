//! A device model of the MC3B (User's Guide §4 and §6) with an injectable
//! clock: nothing moves until [`Emulator::advance`] is called, so tests are
//! deterministic.
//!
//! The model runs on a 1 kHz tick (the guide's limit sampling rate). At each
//! tick it samples and debounces the limit inputs, then advances every motor
//! along its analytic motion profile (piecewise constant acceleration), then
//! stops any motor whose home condition for its direction of travel holds.
//!
//! Decisions where the guide is vague:
//!
//! * **Position.** Each motor keeps a signed step counter (one count per step
//!   issued, a half step in half-step mode, a full step in full-step mode).
//!   Direction 0 counts up, direction 1 counts down. The device never
//!   reports it; the emulator exposes it for tests ([`Emulator::position`]).
//! * **Addressing.** `<id>I` is always obeyed and sets the ID (§6.1); any
//!   other frame whose ID is not the controller's is ignored without a reply
//!   (it belongs to another controller on a chain).
//! * **Commands during motion.** `A`, `D`, `V` are accepted while the motor
//!   is free-running (`R`) and then take effect on the fly; during any other
//!   motion they answer `E1`. `F`, `R`, `M`, `H`, `G` answer `E1` while the
//!   motor moves. `C`, `K`, `L`, `N`, `S`, `Q`, `B`, `P` are always accepted.
//!   `Y` with execute omitted or 1 needs all three motors idle (`E1`);
//!   `Y` with execute 0 only stores and is always accepted.
//! * **Direction modifier.** The modifier of the last `V` for a motor
//!   (0 when omitted) is remembered; free-running and homing motions travel
//!   in `direction XOR modifier` (§4.6 and the §6.4 example). Moves, rate
//!   moves and synchronous moves ignore it.
//! * **Homes.** A motion never proceeds into an active home: a motor whose
//!   home for its travel direction is active when the motion starts, or
//!   becomes active during it, stops at once (abruptly, like `S`).
//! * **Homing** (§4.14, §6.9): seek at the maximum velocity (with
//!   acceleration) until the home is active, stop, back off in the opposite
//!   direction at 10 steps/s until it is inactive, then approach at 10
//!   steps/s until it is active again, and stop. With no home configured for
//!   the direction, homing runs until stopped. If the opposite home becomes
//!   active during the back-off, homing stops there.
//! * **Rate moves** (§6.10): step k (1-based) is issued `k × rate × 10 µs`
//!   after the command, without acceleration.
//! * **Synchronous moves** (§6.12, §4.16): every motor follows
//!   `x_i(t) = N_i · u(t)`, with `u` a trapezoid from 0 to 1 whose speed,
//!   acceleration and deceleration are the smallest of `vmax_i/N_i`,
//!   `a_i/N_i`, `d_i/N_i` over the moving motors, so all motors finish
//!   together and none exceeds its limits. Chained moves run back to back,
//!   each from rest to rest, the next starting on the tick the previous one
//!   ends. All three motors count as running while a synchronous move runs.
//!   `S` on any motor, or a home reached by any moving motor, stops all three
//!   motors and discards the rest of the chain.
//! * **Chained-move buffer.** A chain is at most 100 moves (§2.2(i), §4.17),
//!   counting the one sent with execute 1: the buffer stores at most
//!   [`CHAIN_CAPACITY`] − 1 = 99, a 100th store answers `E3`, and an execute
//!   always fits. Execute 1 appends its own move, then runs the buffer in order
//!   and empties it.
//! * Limit masks are bytes (0..255). The limit inputs power up at 0 (0 V).

use std::collections::VecDeque;
use std::time::Duration;

use crate::codec::{
    encode_response, Command, CommandCode, CommandParser, ErrorCode, Response, MOTORS,
};

/// Product number answered to `P` (§6.18).
pub const PRODUCT_ID: u32 = 1;
/// Firmware version answered to `P` (decision: 1.00 written as 100).
pub const FIRMWARE_VERSION: u32 = 100;
/// Speed of the homing back-off and approach, steps/s (§4.14).
pub const HOMING_SPEED: f64 = 10.0;
/// Most moves in one chain (§2.2(i), §4.17): [`CHAIN_CAPACITY`] − 1 stored with
/// execute 0 and the one sent with execute 1.
pub const CHAIN_CAPACITY: usize = 100;
/// Limit sampling period (§6.17: 1 kHz).
pub const TICK: Duration = Duration::from_millis(1);
const TICK_S: f64 = 0.001;
const EPS: f64 = 1e-9;

/// Settings of one motor (§6.1 defaults).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotorSettings {
    /// Steps/s.
    pub max_velocity: u32,
    /// Steps/s².
    pub acceleration: u32,
    /// Steps/s².
    pub deceleration: u32,
    /// mA.
    pub running_current: u32,
    /// mA.
    pub holding_current: u32,
    /// Apply the holding current when idle.
    pub use_holding_current: bool,
    /// Half stepping.
    pub half_steps: bool,
    /// `[and0, xor0, and1, xor1]` home masks.
    pub limit_masks: [u8; 4],
    /// Direction modifier of the last `V` command.
    pub direction_modifier: bool,
}

impl Default for MotorSettings {
    fn default() -> Self {
        MotorSettings {
            max_velocity: 1000,
            acceleration: 5000,
            deceleration: 5000,
            running_current: 2000,
            holding_current: 500,
            use_holding_current: false,
            half_steps: true,
            limit_masks: [0; 4],
            direction_modifier: false,
        }
    }
}

/// Piecewise constant-acceleration speed profile, starting at speed `v0`.
#[derive(Debug, Clone, PartialEq)]
struct Profile {
    v0: f64,
    /// `(duration s, acceleration)` segments.
    segs: Vec<(f64, f64)>,
    /// After the segments: keep the final speed forever (true) or stop.
    cruise: bool,
}

impl Profile {
    fn duration(&self) -> f64 {
        self.segs.iter().map(|s| s.0).sum()
    }

    /// `(distance, speed)` at time `t` (s) into the profile.
    fn eval(&self, t: f64) -> (f64, f64) {
        let (mut left, mut x, mut v) = (t.max(0.0), 0.0, self.v0);
        for &(dur, acc) in &self.segs {
            let dt = left.min(dur);
            x += v * dt + 0.5 * acc * dt * dt;
            v = (v + acc * dt).max(0.0);
            left -= dt;
            if left <= 0.0 {
                return (x, v);
            }
        }
        if self.cruise {
            (x + v * left, v)
        } else {
            (x, 0.0)
        }
    }

    /// Rest-to-rest move of `dist` with acceleration `a`, deceleration `d`,
    /// top speed `v`: trapezoid, or triangle when the distance is too short.
    fn trapezoid(dist: f64, a: f64, d: f64, v: f64) -> Profile {
        let mut segs = Vec::new();
        if dist > 0.0 && a > 0.0 && d > 0.0 && v > 0.0 {
            let (da, dd) = (v * v / (2.0 * a), v * v / (2.0 * d));
            if da + dd <= dist {
                segs.push((v / a, a));
                segs.push(((dist - da - dd) / v, 0.0));
                segs.push((v / d, -d));
            } else {
                let vp = (2.0 * dist * a * d / (a + d)).sqrt();
                segs.push((vp / a, a));
                segs.push((vp / d, -d));
            }
        }
        Profile {
            v0: 0.0,
            segs,
            cruise: false,
        }
    }

    /// From speed `v0` to speed `vt`, then cruise.
    fn to_speed(v0: f64, vt: f64, a: f64, d: f64) -> Profile {
        let seg = if vt >= v0 {
            ((vt - v0) / a, a)
        } else {
            ((v0 - vt) / d, -d)
        };
        Profile {
            v0,
            segs: vec![seg],
            cruise: true,
        }
    }

    /// From speed `v0` down to rest.
    fn to_rest(v0: f64, d: f64) -> Profile {
        Profile {
            v0,
            segs: vec![(v0 / d, -d)],
            cruise: false,
        }
    }

    /// Constant speed `v`, for `dist` steps or (None) forever.
    fn constant(v: f64, dist: Option<f64>) -> Profile {
        match dist {
            Some(n) => Profile {
                v0: v,
                segs: vec![(n / v, 0.0)],
                cruise: false,
            },
            None => Profile {
                v0: v,
                segs: vec![],
                cruise: true,
            },
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum HomePhase {
    Seek,
    BackOff,
    Approach,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Move,
    Rate,
    /// Free-running; `cmd_dir` is the direction given to `R`.
    Run {
        cmd_dir: u8,
    },
    /// Homing toward `home_dir` (modifier already applied).
    Home {
        home_dir: u8,
        phase: HomePhase,
    },
}

/// One motor's current motion (not synchronous).
#[derive(Debug, Clone)]
struct Active {
    kind: Kind,
    /// Direction of travel.
    dir: u8,
    start_tick: u64,
    anchor: f64,
    prof: Profile,
    /// Exact step count of a finite motion (for the final position).
    target: Option<f64>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct SyncSeg {
    steps: [u32; 3],
    dirs: [u8; 3],
}

#[derive(Debug, Clone)]
struct SyncRun {
    queue: VecDeque<SyncSeg>,
    seg: SyncSeg,
    start_tick: u64,
    anchors: [f64; 3],
    /// Normalized profile (distance 1).
    prof: Profile,
}

#[derive(Debug, Clone, Default)]
struct Motor {
    settings: MotorSettings,
    x: f64,
    active: Option<Active>,
    energized: bool,
}

fn sign(dir: u8) -> f64 {
    if dir == 0 {
        1.0
    } else {
        -1.0
    }
}

/// Integer step position reached at continuous position `x` moving in `dir`.
fn step_pos(x: f64, dir: u8) -> f64 {
    if dir == 0 {
        (x + EPS).floor()
    } else {
        (x - EPS).ceil()
    }
}

/// The MC3B device model.
#[derive(Debug, Clone)]
pub struct Emulator {
    id: u8,
    motors: [Motor; 3],
    sync: Option<SyncRun>,
    chain: Vec<SyncSeg>,
    raw_inputs: u8,
    inputs: u8,
    debounce_count: u32,
    debounce_counters: [u32; 8],
    tick: u64,
    pending: Duration,
    parser: CommandParser,
    /// Frames handled, per command letter in the order of [`CommandCode::ALL`]: what
    /// the line carried to this controller (not device state; `I` does not reset it).
    received: [u64; CommandCode::ALL.len()],
}

impl Default for Emulator {
    fn default() -> Self {
        Self::new()
    }
}

impl Emulator {
    /// A freshly powered-up MC3B: ID 0, §6.1 defaults, inputs at 0.
    pub fn new() -> Self {
        Emulator {
            id: 0,
            motors: Default::default(),
            sync: None,
            chain: Vec::new(),
            raw_inputs: 0,
            inputs: 0,
            debounce_count: 1,
            debounce_counters: [0; 8],
            tick: 0,
            pending: Duration::ZERO,
            parser: CommandParser::new(),
            received: [0; CommandCode::ALL.len()],
        }
    }

    /// Controller ID.
    pub fn id(&self) -> u8 {
        self.id
    }

    /// Emulated time since creation (whole ticks).
    pub fn now(&self) -> Duration {
        Duration::from_millis(self.tick)
    }

    /// Advance the clock by `dt`, running one 1 kHz tick per millisecond
    /// (a remainder below 1 ms is kept for the next call).
    pub fn advance(&mut self, dt: Duration) {
        self.pending = self.pending.saturating_add(dt);
        while self.pending >= TICK {
            self.pending -= TICK;
            self.step_tick();
        }
    }

    /// Set one limit input (0..5) to high (`true`, 5 V) or low.
    pub fn set_input(&mut self, bit: u8, high: bool) {
        if bit < 8 {
            if high {
                self.raw_inputs |= 1 << bit;
            } else {
                self.raw_inputs &= !(1 << bit);
            }
        }
    }

    /// Set all limit inputs at once.
    pub fn set_inputs(&mut self, bits: u8) {
        self.raw_inputs = bits;
    }

    /// The raw (undebounced) inputs.
    pub fn raw_inputs(&self) -> u8 {
        self.raw_inputs
    }

    /// The debounced inputs (what `B` reports).
    pub fn inputs(&self) -> u8 {
        self.inputs
    }

    /// Settings of motor `m` (None if m > 2).
    pub fn settings(&self, m: usize) -> Option<MotorSettings> {
        self.motors.get(m).map(|mo| mo.settings)
    }

    /// Step counter of motor `m` (0 if m > 2).
    pub fn position(&self, m: usize) -> i64 {
        let Some(mo) = self.motors.get(m) else {
            return 0;
        };
        let dir = mo
            .active
            .as_ref()
            .map(|a| a.dir)
            .or_else(|| self.sync.as_ref().and_then(|s| s.seg.dirs.get(m).copied()));
        match dir {
            Some(d) => step_pos(mo.x, d) as i64,
            None => mo.x.round() as i64,
        }
    }

    /// Signed speed of motor `m` in steps/s (positive in direction 0).
    pub fn velocity(&self, m: usize) -> f64 {
        if let Some(s) = &self.sync {
            let t = (self.tick - s.start_tick) as f64 * TICK_S;
            let n = s.seg.steps.get(m).copied().unwrap_or(0);
            let d = s.seg.dirs.get(m).copied().unwrap_or(0);
            return sign(d) * f64::from(n) * s.prof.eval(t).1;
        }
        match self.motors.get(m).and_then(|mo| mo.active.as_ref()) {
            Some(a) => {
                let t = (self.tick - a.start_tick) as f64 * TICK_S;
                sign(a.dir) * a.prof.eval(t).1
            }
            None => 0.0,
        }
    }

    /// Whether motor `m` is in motion (as `Q` reports it).
    pub fn is_running(&self, m: usize) -> bool {
        self.sync.is_some() || self.motors.get(m).is_some_and(|mo| mo.active.is_some())
    }

    /// Whether a current flows in motor `m` (running or holding).
    pub fn is_energized(&self, m: usize) -> bool {
        self.is_running(m) || self.motors.get(m).is_some_and(|mo| mo.energized)
    }

    /// The limit switch debounce count (`N`, §6.17).
    pub fn debounce_count(&self) -> u32 {
        self.debounce_count
    }

    /// How many well-formed frames with command `code` this controller has handled
    /// (accepted, or refused with `E1` or `E3`) since it was created: what a test reads
    /// to see that nothing was sent. Frames for another controller ID are not counted.
    pub fn received(&self, code: CommandCode) -> u64 {
        CommandCode::ALL
            .iter()
            .position(|&c| c == code)
            .and_then(|i| self.received.get(i))
            .copied()
            .unwrap_or(0)
    }

    /// Number of moves waiting in the chained-move buffer.
    pub fn chain_len(&self) -> usize {
        self.chain.len()
    }

    /// Home condition of §6.5 for motor `m`, direction `dir`, on the
    /// debounced inputs.
    pub fn at_home(&self, m: usize, dir: u8) -> bool {
        self.motors
            .get(m)
            .is_some_and(|mo| Self::home_of(&mo.settings, self.inputs, dir))
    }

    fn home_of(s: &MotorSettings, inputs: u8, dir: u8) -> bool {
        let (and, xor) = if dir == 0 {
            (s.limit_masks[0], s.limit_masks[1])
        } else {
            (s.limit_masks[2], s.limit_masks[3])
        };
        ((inputs & and) ^ xor) != 0
    }

    /// Feed wire bytes; returns the wire bytes of all replies.
    pub fn receive(&mut self, bytes: &[u8]) -> Vec<u8> {
        self.parser.feed(bytes);
        let mut out = Vec::new();
        while let Some(item) = self.parser.next_command() {
            let resp = match item {
                Ok(cmd) => self.handle(&cmd),
                Err(e) => match e.id {
                    Some(id) if id == self.id => Some(Response::Error { id, code: e.code }),
                    _ => None,
                },
            };
            if let Some(r) = resp {
                out.extend_from_slice(&encode_response(&r));
            }
        }
        out
    }

    /// Execute one typed command; `None` when it is not addressed to this
    /// controller.
    pub fn handle(&mut self, cmd: &Command) -> Option<Response> {
        if matches!(cmd, Command::Initialize { .. }) || cmd.id() == self.id {
            let code = cmd.code();
            if let Some(n) = CommandCode::ALL
                .iter()
                .position(|&c| c == code)
                .and_then(|i| self.received.get_mut(i))
            {
                *n += 1;
            }
        }
        if let Command::Initialize { id } = *cmd {
            self.initialize(id);
            return Some(Response::Ack {
                id,
                code: CommandCode::Initialize,
            });
        }
        let id = cmd.id();
        if id != self.id {
            return None;
        }
        Some(match self.execute(cmd) {
            Ok(r) => r,
            Err(code) => Response::Error { id, code },
        })
    }

    fn initialize(&mut self, id: u8) {
        self.id = id;
        for m in &mut self.motors {
            m.x = m.x.round();
            m.active = None;
            m.settings = MotorSettings::default();
            m.energized = false;
        }
        self.sync = None;
        self.chain.clear();
        self.debounce_count = 1;
    }

    fn motor_busy(&self, m: usize) -> bool {
        self.is_running(m)
    }

    fn free_running(&self, m: usize) -> bool {
        self.sync.is_none()
            && self
                .motors
                .get(m)
                .and_then(|mo| mo.active.as_ref())
                .is_some_and(|a| matches!(a.kind, Kind::Run { .. }))
    }

    fn execute(&mut self, cmd: &Command) -> Result<Response, ErrorCode> {
        cmd.validate()?;
        let id = self.id;
        let ack = Response::Ack {
            id,
            code: cmd.code(),
        };
        let idx = |m: u32| -> Result<usize, ErrorCode> {
            if m < MOTORS {
                Ok(m as usize)
            } else {
                Err(ErrorCode::OutOfRange)
            }
        };
        let flag8 = |v: u32| u8::from(v != 0);
        match *cmd {
            Command::Initialize { .. } => Ok(ack),
            Command::SetAcceleration { motor, value, .. }
            | Command::SetDeceleration { motor, value, .. } => {
                let m = idx(motor)?;
                let on_the_fly = self.free_running(m);
                if self.motor_busy(m) && !on_the_fly {
                    return Err(ErrorCode::MotorRunning);
                }
                let s = &mut self.motors[m].settings;
                if matches!(cmd, Command::SetAcceleration { .. }) {
                    s.acceleration = value;
                } else {
                    s.deceleration = value;
                }
                if on_the_fly {
                    self.replan_run(m);
                }
                Ok(ack)
            }
            Command::SetMaxVelocity {
                motor,
                value,
                direction_modifier,
                ..
            } => {
                let m = idx(motor)?;
                let on_the_fly = self.free_running(m);
                if self.motor_busy(m) && !on_the_fly {
                    return Err(ErrorCode::MotorRunning);
                }
                let s = &mut self.motors[m].settings;
                s.max_velocity = value;
                s.direction_modifier = direction_modifier.unwrap_or(0) != 0;
                if on_the_fly {
                    self.replan_run(m);
                }
                Ok(ack)
            }
            Command::SetLimits {
                motor,
                h0_and,
                h0_xor,
                h1_and,
                h1_xor,
                ..
            } => {
                let m = idx(motor)?;
                let b = |v: u32| u8::try_from(v).map_err(|_| ErrorCode::OutOfRange);
                self.motors[m].settings.limit_masks =
                    [b(h0_and)?, b(h0_xor)?, b(h1_and)?, b(h1_xor)?];
                Ok(ack)
            }
            Command::SetHalfStep { motor, half, .. } => {
                let m = idx(motor)?;
                if self.motor_busy(m) {
                    return Err(ErrorCode::MotorRunning);
                }
                self.motors[m].settings.half_steps = half != 0;
                Ok(ack)
            }
            Command::SetHoldingCurrent { motor, enable, .. } => {
                let m = idx(motor)?;
                let mo = &mut self.motors[m];
                mo.settings.use_holding_current = enable != 0;
                mo.energized = enable != 0;
                Ok(ack)
            }
            Command::SetCurrentLimits {
                motor,
                holding,
                running,
                ..
            } => {
                let m = idx(motor)?;
                let s = &mut self.motors[m].settings;
                s.holding_current = holding;
                s.running_current = running;
                Ok(ack)
            }
            Command::SetDebounce { count, .. } => {
                self.debounce_count = count;
                Ok(ack)
            }
            Command::Run {
                motor, direction, ..
            } => {
                let m = idx(motor)?;
                if self.motor_busy(m) {
                    return Err(ErrorCode::MotorRunning);
                }
                let cmd_dir = flag8(direction);
                let dir = cmd_dir ^ u8::from(self.motors[m].settings.direction_modifier);
                let s = self.motors[m].settings;
                let prof = Profile::to_speed(
                    0.0,
                    f64::from(s.max_velocity),
                    f64::from(s.acceleration),
                    f64::from(s.deceleration),
                );
                self.start(m, Kind::Run { cmd_dir }, dir, prof, None);
                Ok(ack)
            }
            Command::Move {
                motor,
                steps,
                direction,
                ..
            } => {
                let m = idx(motor)?;
                if self.motor_busy(m) {
                    return Err(ErrorCode::MotorRunning);
                }
                let s = self.motors[m].settings;
                let n = f64::from(steps);
                let prof = Profile::trapezoid(
                    n,
                    f64::from(s.acceleration),
                    f64::from(s.deceleration),
                    f64::from(s.max_velocity),
                );
                self.start(m, Kind::Move, flag8(direction), prof, Some(n));
                Ok(ack)
            }
            Command::RateMove {
                motor,
                steps,
                direction,
                rate,
                ..
            } => {
                let m = idx(motor)?;
                if self.motor_busy(m) {
                    return Err(ErrorCode::MotorRunning);
                }
                let n = f64::from(steps);
                let v = 100_000.0 / f64::from(rate.max(1));
                self.start(
                    m,
                    Kind::Rate,
                    flag8(direction),
                    Profile::constant(v, Some(n)),
                    Some(n),
                );
                Ok(ack)
            }
            Command::Home {
                motor, direction, ..
            } => {
                let m = idx(motor)?;
                if self.motor_busy(m) {
                    return Err(ErrorCode::MotorRunning);
                }
                let s = self.motors[m].settings;
                let dir = flag8(direction) ^ u8::from(s.direction_modifier);
                let prof = Profile::to_speed(
                    0.0,
                    f64::from(s.max_velocity),
                    f64::from(s.acceleration),
                    f64::from(s.deceleration),
                );
                let kind = Kind::Home {
                    home_dir: dir,
                    phase: HomePhase::Seek,
                };
                self.start(m, kind, dir, prof, None);
                Ok(ack)
            }
            Command::Stop { motor, .. } => {
                let m = idx(motor)?;
                if self.sync.is_some() {
                    self.stop_sync();
                } else {
                    self.stop_motor(m);
                }
                Ok(ack)
            }
            Command::SyncMove {
                steps,
                directions,
                execute,
                ..
            } => {
                let seg = SyncSeg {
                    steps,
                    dirs: [
                        flag8(directions[0]),
                        flag8(directions[1]),
                        flag8(directions[2]),
                    ],
                };
                match execute {
                    Some(0) => {
                        // Room is kept for the move that executes the chain.
                        if self.chain.len() + 1 >= CHAIN_CAPACITY {
                            return Err(ErrorCode::OutOfRange);
                        }
                        self.chain.push(seg);
                    }
                    Some(_) => {
                        if (0..3).any(|m| self.motor_busy(m)) {
                            return Err(ErrorCode::MotorRunning);
                        }
                        if self.chain.len() >= CHAIN_CAPACITY {
                            return Err(ErrorCode::OutOfRange);
                        }
                        self.chain.push(seg);
                        let queue: VecDeque<SyncSeg> = self.chain.drain(..).collect();
                        self.start_sync(queue);
                    }
                    None => {
                        if (0..3).any(|m| self.motor_busy(m)) {
                            return Err(ErrorCode::MotorRunning);
                        }
                        self.chain.clear();
                        self.start_sync(VecDeque::from([seg]));
                    }
                }
                Ok(ack)
            }
            Command::QueryStatus { motor, .. } => {
                let m = idx(motor)?;
                Ok(Response::Status {
                    id,
                    running: self.is_running(m),
                    home0: self.at_home(m, 0),
                    home1: self.at_home(m, 1),
                })
            }
            Command::QueryLimits { .. } => Ok(Response::Limits {
                id,
                bits: self.inputs,
            }),
            Command::QueryProductId { .. } => Ok(Response::ProductId {
                id,
                product: PRODUCT_ID,
                version: FIRMWARE_VERSION,
            }),
        }
    }

    /// Start a single-motor motion now; if the home for its direction is
    /// already active it ends at once without a step (except homing, whose
    /// seek then ends immediately and the back-off begins at the next tick).
    fn start(&mut self, m: usize, kind: Kind, dir: u8, prof: Profile, target: Option<f64>) {
        let inputs = self.inputs;
        let tick = self.tick;
        let Some(mo) = self.motors.get_mut(m) else {
            return;
        };
        let blocked = Self::home_of(&mo.settings, inputs, dir);
        let empty = target.is_some_and(|n| n <= 0.0);
        if (blocked && !matches!(kind, Kind::Home { .. })) || empty {
            mo.active = None;
            mo.energized = mo.settings.use_holding_current;
            return;
        }
        mo.x = mo.x.round();
        mo.active = Some(Active {
            kind,
            dir,
            start_tick: tick,
            anchor: mo.x,
            prof,
            target,
        });
        mo.energized = true;
    }

    fn stop_motor(&mut self, m: usize) {
        if let Some(mo) = self.motors.get_mut(m) {
            if let Some(a) = mo.active.take() {
                mo.x = step_pos(mo.x, a.dir);
            }
            mo.energized = mo.settings.use_holding_current;
        }
    }

    fn stop_sync(&mut self) {
        if let Some(s) = self.sync.take() {
            for (i, mo) in self.motors.iter_mut().enumerate() {
                let d = s.seg.dirs.get(i).copied().unwrap_or(0);
                mo.x = step_pos(mo.x, d);
                mo.energized = mo.settings.use_holding_current;
            }
        }
    }

    /// Re-plan a free-running motor after a change of velocity,
    /// acceleration, deceleration or direction modifier.
    fn replan_run(&mut self, m: usize) {
        let tick = self.tick;
        let Some(mo) = self.motors.get_mut(m) else {
            return;
        };
        let s = mo.settings;
        let Some(a) = mo.active.as_mut() else {
            return;
        };
        let Kind::Run { cmd_dir } = a.kind else {
            return;
        };
        let t = (tick - a.start_tick) as f64 * TICK_S;
        let (dist, v) = a.prof.eval(t);
        a.anchor += sign(a.dir) * dist;
        mo.x = a.anchor;
        a.start_tick = tick;
        let want = cmd_dir ^ u8::from(s.direction_modifier);
        let (acc, dec) = (f64::from(s.acceleration), f64::from(s.deceleration));
        a.prof = if want == a.dir {
            Profile::to_speed(v, f64::from(s.max_velocity), acc, dec)
        } else {
            Profile::to_rest(v, dec)
        };
    }

    fn start_sync(&mut self, queue: VecDeque<SyncSeg>) {
        for mo in &mut self.motors {
            mo.active = None;
            mo.x = mo.x.round();
            mo.energized = true;
        }
        let mut run = SyncRun {
            queue,
            seg: SyncSeg {
                steps: [0; 3],
                dirs: [0; 3],
            },
            start_tick: self.tick,
            anchors: [0.0; 3],
            prof: Profile::trapezoid(0.0, 1.0, 1.0, 1.0),
        };
        if self.next_sync_segment(&mut run) {
            self.sync = Some(run);
        } else {
            self.finish_sync();
        }
    }

    /// Load the next non-empty segment into `run`; false when none is left
    /// or the first one is blocked by an active home.
    fn next_sync_segment(&self, run: &mut SyncRun) -> bool {
        while let Some(seg) = run.queue.pop_front() {
            let moving: Vec<usize> = (0..3).filter(|&i| seg.steps[i] > 0).collect();
            if moving.is_empty() {
                continue;
            }
            if moving
                .iter()
                .any(|&i| Self::home_of(&self.motors[i].settings, self.inputs, seg.dirs[i]))
            {
                return false;
            }
            let (mut uv, mut ua, mut ud) = (f64::INFINITY, f64::INFINITY, f64::INFINITY);
            for &i in &moving {
                let s = &self.motors[i].settings;
                let n = f64::from(seg.steps[i]);
                uv = uv.min(f64::from(s.max_velocity) / n);
                ua = ua.min(f64::from(s.acceleration) / n);
                ud = ud.min(f64::from(s.deceleration) / n);
            }
            run.seg = seg;
            run.start_tick = self.tick;
            for i in 0..3 {
                run.anchors[i] = self.motors[i].x.round();
            }
            run.prof = Profile::trapezoid(1.0, ua, ud, uv);
            return true;
        }
        false
    }

    fn finish_sync(&mut self) {
        self.sync = None;
        for mo in &mut self.motors {
            mo.x = mo.x.round();
            mo.energized = mo.settings.use_holding_current;
        }
    }

    fn debounce(&mut self) {
        for bit in 0..8 {
            let mask = 1u8 << bit;
            if (self.raw_inputs ^ self.inputs) & mask != 0 {
                self.debounce_counters[bit] += 1;
                if self.debounce_counters[bit] >= self.debounce_count {
                    self.inputs ^= mask;
                    self.debounce_counters[bit] = 0;
                }
            } else {
                self.debounce_counters[bit] = 0;
            }
        }
    }

    fn step_tick(&mut self) {
        self.tick += 1;
        self.debounce();
        for m in 0..3 {
            self.tick_motor(m);
        }
        self.tick_sync();
    }

    fn tick_sync(&mut self) {
        let Some(mut run) = self.sync.take() else {
            return;
        };
        let t = (self.tick - run.start_tick) as f64 * TICK_S;
        let (u, _) = run.prof.eval(t);
        let done = t + EPS >= run.prof.duration();
        for i in 0..3 {
            let n = f64::from(run.seg.steps[i]);
            let frac = if done { 1.0 } else { u };
            self.motors[i].x = run.anchors[i] + sign(run.seg.dirs[i]) * n * frac;
        }
        // A home reached by any moving motor stops the whole move.
        let hit = (0..3).any(|i| {
            run.seg.steps[i] > 0
                && Self::home_of(&self.motors[i].settings, self.inputs, run.seg.dirs[i])
        });
        if hit {
            self.sync = Some(run);
            self.stop_sync();
            return;
        }
        if done {
            for i in 0..3 {
                self.motors[i].x = self.motors[i].x.round();
            }
            if self.next_sync_segment(&mut run) {
                self.sync = Some(run);
            } else {
                self.finish_sync();
            }
        } else {
            self.sync = Some(run);
        }
    }

    fn tick_motor(&mut self, m: usize) {
        let tick = self.tick;
        let inputs = self.inputs;
        let Some(mo) = self.motors.get_mut(m) else {
            return;
        };
        let Some(a) = mo.active.take() else {
            return;
        };
        let s = mo.settings;
        let t = (tick - a.start_tick) as f64 * TICK_S;
        let (dist, _) = a.prof.eval(t);
        let done = !a.prof.cruise && t + EPS >= a.prof.duration();
        let dist = match (done, a.target) {
            (true, Some(n)) => n,
            _ => dist,
        };
        mo.x = a.anchor + sign(a.dir) * dist;
        let home = |d: u8| Self::home_of(&s, inputs, d);
        // Homing transitions and limit stops.
        if let Kind::Home { home_dir, phase } = a.kind {
            let next = match phase {
                HomePhase::Seek if home(home_dir) => Some(HomePhase::BackOff),
                HomePhase::BackOff if !home(home_dir) => Some(HomePhase::Approach),
                HomePhase::BackOff if home(a.dir) => {
                    // Opposite home reached while backing off: give up.
                    mo.x = step_pos(mo.x, a.dir);
                    mo.energized = s.use_holding_current;
                    return;
                }
                HomePhase::Approach if home(home_dir) => None,
                _ => {
                    mo.active = Some(a);
                    return;
                }
            };
            mo.x = step_pos(mo.x, a.dir);
            match next {
                Some(phase) => {
                    let dir = if phase == HomePhase::BackOff {
                        home_dir ^ 1
                    } else {
                        home_dir
                    };
                    mo.active = Some(Active {
                        kind: Kind::Home { home_dir, phase },
                        dir,
                        start_tick: tick,
                        anchor: mo.x,
                        prof: Profile::constant(HOMING_SPEED, None),
                        target: None,
                    });
                }
                None => mo.energized = s.use_holding_current,
            }
            return;
        }
        if home(a.dir) {
            mo.x = step_pos(mo.x, a.dir);
            mo.energized = s.use_holding_current;
            return;
        }
        if done {
            if let Kind::Run { cmd_dir } = a.kind {
                // End of a deceleration for a direction change: reverse.
                mo.x = step_pos(mo.x, a.dir);
                let dir = cmd_dir ^ u8::from(s.direction_modifier);
                mo.active = Some(Active {
                    kind: a.kind,
                    dir,
                    start_tick: tick,
                    anchor: mo.x,
                    prof: Profile::to_speed(
                        0.0,
                        f64::from(s.max_velocity),
                        f64::from(s.acceleration),
                        f64::from(s.deceleration),
                    ),
                    target: None,
                });
                return;
            }
            mo.x = mo.x.round();
            mo.energized = s.use_holding_current;
            return;
        }
        mo.active = Some(a);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ms(n: u64) -> Duration {
        Duration::from_millis(n)
    }

    fn send(e: &mut Emulator, s: &str) -> String {
        let mut b = s.as_bytes().to_vec();
        b.push(b'\r');
        String::from_utf8_lossy(&e.receive(&b)).replace('\r', "|")
    }

    #[test]
    fn acknowledgements_and_defaults() {
        let mut e = Emulator::new();
        assert_eq!(send(&mut e, "0I"), "0I|");
        assert_eq!(send(&mut e, "0P"), "0P1,100|");
        assert_eq!(send(&mut e, "0Q1"), "0Q0,0,0|");
        assert_eq!(send(&mut e, "0B"), "0B0|");
        let s = e.settings(2).unwrap_or_default();
        assert_eq!(s, MotorSettings::default());
        assert_eq!(
            (s.max_velocity, s.acceleration, s.deceleration),
            (1000, 5000, 5000)
        );
        assert_eq!((s.running_current, s.holding_current), (2000, 500));
        assert!(s.half_steps && !s.use_holding_current);
        for (c, a) in [
            ("0A0,100", "0A|"),
            ("0D1,100000", "0D|"),
            ("0V2,5000", "0V|"),
            ("0V2,1,1", "0V|"),
            ("0L2,8,0,32,32", "0L|"),
            ("0F0,0", "0F|"),
            ("0C0,1", "0C|"),
            ("0K0,0,2000", "0K|"),
            ("0N100", "0N|"),
            ("0S1", "0S|"),
            ("0Y0,0,0,0,0,0", "0Y|"),
            ("0Y1,0,1,0,1,0,0", "0Y|"),
        ] {
            assert_eq!(send(&mut e, c), a, "{c}");
        }
        assert_eq!(e.chain_len(), 1);
        let s = e.settings(0).unwrap_or_default();
        assert!(!s.half_steps && s.use_holding_current && s.holding_current == 0);
        assert!(e.is_energized(0), "holding current applied immediately");
        // Initialization restores every default and empties the buffer.
        assert_eq!(send(&mut e, "0I"), "0I|");
        assert_eq!(e.settings(0), Some(MotorSettings::default()));
        assert_eq!(e.chain_len(), 0);
    }

    #[test]
    fn errors_e0_to_e3() {
        let mut e = Emulator::new();
        assert_eq!(send(&mut e, "0Z"), "0E0|");
        assert_eq!(send(&mut e, "0A0"), "0E2|");
        assert_eq!(send(&mut e, "0V0,1,0,0"), "0E2|");
        assert_eq!(send(&mut e, "0A0,99"), "0E3|");
        assert_eq!(send(&mut e, "0A0,100001"), "0E3|");
        assert_eq!(send(&mut e, "0V0,0"), "0E3|");
        assert_eq!(send(&mut e, "0V0,5001"), "0E3|");
        assert_eq!(send(&mut e, "0V0,10,2"), "0E3|");
        assert_eq!(send(&mut e, "0N0"), "0E3|");
        assert_eq!(send(&mut e, "0N101"), "0E3|");
        assert_eq!(send(&mut e, "0K0,2001,0"), "0E3|");
        assert_eq!(send(&mut e, "0M3,10,0"), "0E3|");
        assert_eq!(send(&mut e, "0M0,10,2"), "0E3|");
        assert_eq!(send(&mut e, "0G0,10,0,49"), "0E3|");
        assert_eq!(send(&mut e, "0L0,256,0,0,0"), "0E3|");
        // Running motor.
        assert_eq!(send(&mut e, "0M0,1000,0"), "0M|");
        e.advance(ms(10));
        for c in [
            "0M0,1,0",
            "0R0,0",
            "0H0,0",
            "0G0,1,0,50",
            "0F0,1",
            "0A0,200",
        ] {
            assert_eq!(send(&mut e, c), "0E1|", "{c}");
        }
        assert_eq!(send(&mut e, "0V0,200"), "0E1|");
        assert_eq!(send(&mut e, "0Y1,0,0,0,0,0"), "0E1|");
        assert_eq!(send(&mut e, "0Y1,0,0,0,0,0,1"), "0E1|");
        assert_eq!(send(&mut e, "0Y1,0,0,0,0,0,0"), "0Y|", "storing is allowed");
        assert_eq!(send(&mut e, "0C0,1"), "0C|");
        assert_eq!(send(&mut e, "0K0,100,100"), "0K|");
        // Other motors are not affected.
        assert_eq!(send(&mut e, "0M1,5,0"), "0M|");
        // Other IDs are ignored; lines without an ID are ignored.
        assert_eq!(send(&mut e, "1Q0"), "");
        assert_eq!(send(&mut e, "Q0"), "");
        assert_eq!(send(&mut e, "\n\n"), "");
        // Re-initialize with another ID.
        assert_eq!(send(&mut e, "3I"), "3I|");
        assert_eq!(send(&mut e, "0Q0"), "");
        assert_eq!(send(&mut e, "3Q0"), "3Q0,0,0|");
        assert!(!e.is_running(0) && !e.is_running(1));
    }

    #[test]
    fn received_counts_the_frames_of_each_command() {
        let mut e = Emulator::new();
        assert_eq!(send(&mut e, "0V0,6000"), "0E3|");
        assert_eq!(send(&mut e, "0V1,200"), "0V|");
        assert_eq!(send(&mut e, "0Q0"), "0Q0,0,0|");
        assert_eq!(send(&mut e, "1V0,200"), "", "another controller's frame");
        assert_eq!(e.received(CommandCode::Velocity), 2);
        assert_eq!(e.received(CommandCode::QueryStatus), 1);
        assert_eq!(e.received(CommandCode::Move), 0);
        assert_eq!(send(&mut e, "0N7"), "0N|");
        assert_eq!(e.debounce_count(), 7);
        // I resets the device, not the count of what the line carried.
        assert_eq!(send(&mut e, "0I"), "0I|");
        assert_eq!(e.debounce_count(), 1);
        assert_eq!(e.received(CommandCode::Velocity), 2);
        assert_eq!(e.received(CommandCode::Initialize), 1);
    }

    #[test]
    fn trapezoid_move_takes_the_hand_computed_time() {
        // N=2000, a=5000, d=2500, v=1000:
        // accel 1000/5000 = 0.2 s over 100 steps; decel 1000/2500 = 0.4 s
        // over 200 steps; cruise 1700 steps at 1000 steps/s = 1.7 s.
        // Total 2.3 s.
        let mut e = Emulator::new();
        send(&mut e, "0D0,2500");
        assert_eq!(send(&mut e, "0M0,2000,0"), "0M|");
        e.advance(ms(200));
        assert_eq!(e.position(0), 100);
        assert!((e.velocity(0) - 1000.0).abs() < 1e-6);
        e.advance(ms(1700));
        assert_eq!(e.position(0), 1800);
        e.advance(ms(399));
        assert!(e.is_running(0));
        assert_eq!(send(&mut e, "0Q0"), "0Q1,0,0|");
        e.advance(ms(1));
        assert!(!e.is_running(0));
        assert_eq!(e.position(0), 2000);
        assert_eq!(send(&mut e, "0Q0"), "0Q0,0,0|");
    }

    #[test]
    fn short_move_is_a_triangle() {
        // N=100, a=d=5000, v=1000: 100 < 100+100, so triangle with
        // vp = sqrt(2*100*5000*5000/10000) = 707.1 steps/s, t = 2*vp/5000
        // = 0.2828 s -> done at tick 283, still running at 282.
        let mut e = Emulator::new();
        send(&mut e, "0M1,100,1");
        e.advance(ms(141));
        assert!((e.velocity(1) + 705.0).abs() < 5.0, "{}", e.velocity(1));
        e.advance(ms(141));
        assert!(e.is_running(1));
        e.advance(ms(1));
        assert!(!e.is_running(1));
        assert_eq!(e.position(1), -100);
    }

    #[test]
    fn rate_move_has_no_acceleration() {
        // 0G1,100,0,75: one step every 750 us -> 75 ms for 100 steps.
        let mut e = Emulator::new();
        assert_eq!(send(&mut e, "0G1,100,0,75"), "0G|");
        e.advance(ms(3));
        assert_eq!(e.position(1), 4, "3 ms / 0.75 ms = 4 steps");
        assert!((e.velocity(1) - 1333.333).abs() < 0.01);
        e.advance(ms(71));
        assert!(e.is_running(1));
        e.advance(ms(1));
        assert!(!e.is_running(1));
        assert_eq!(e.position(1), 100);
    }

    #[test]
    fn full_and_half_steps_count_steps_issued() {
        let mut e = Emulator::new();
        send(&mut e, "0F0,0");
        send(&mut e, "0G0,10,0,100");
        e.advance(ms(20));
        assert_eq!(e.position(0), 10);
        assert!(!e.settings(0).unwrap_or_default().half_steps);
    }

    #[test]
    fn run_and_on_the_fly_changes_follow_the_guide_example() {
        let mut e = Emulator::new();
        send(&mut e, "0V0,500");
        assert_eq!(send(&mut e, "0R0,1"), "0R|");
        // 500/5000 = 0.1 s to reach 500 steps/s in direction 1.
        e.advance(ms(100));
        assert!((e.velocity(0) + 500.0).abs() < 1e-6);
        // Velocity change on the fly: 500 -> 1000 takes 0.1 s.
        assert_eq!(send(&mut e, "0V0,1000"), "0V|");
        e.advance(ms(50));
        assert!((e.velocity(0) + 750.0).abs() < 1e-6);
        e.advance(ms(50));
        assert!((e.velocity(0) + 1000.0).abs() < 1e-6);
        // Acceleration may change while free-running.
        assert_eq!(send(&mut e, "0A0,10000"), "0A|");
        // Modifier 1: decelerate (0.2 s at 5000) then run in direction 0.
        assert_eq!(send(&mut e, "0V0,1000,1"), "0V|");
        e.advance(ms(100));
        assert!((e.velocity(0) + 500.0).abs() < 1e-6);
        e.advance(ms(100));
        assert!(e.velocity(0).abs() < 1e-6);
        e.advance(ms(50)); // 10000 steps/s^2 for 50 ms
        assert!((e.velocity(0) - 500.0).abs() < 1e-6, "{}", e.velocity(0));
        // Same modifier again: no direction change.
        assert_eq!(send(&mut e, "0V0,1000,1"), "0V|");
        e.advance(ms(100));
        assert!((e.velocity(0) - 1000.0).abs() < 1e-6);
        // Modifier back to 0: reverse again, to direction 1.
        assert_eq!(send(&mut e, "0V0,1000,0"), "0V|");
        e.advance(ms(200 + 100));
        assert!(e.velocity(0) < -999.0);
        assert_eq!(send(&mut e, "0S0"), "0S|");
        assert!(!e.is_running(0));
        assert_eq!(e.velocity(0), 0.0);
    }

    #[test]
    fn limit_masks_and_and_xor_stop_motion() {
        let mut e = Emulator::new();
        // Guide example: motor 2 dir 0 on bit 3 high, dir 1 on bit 5 low.
        send(&mut e, "0L2,8,0,32,32");
        e.advance(ms(1));
        assert_eq!(send(&mut e, "0Q2"), "0Q0,0,1|", "bit 5 low = home 1");
        e.set_input(5, true);
        e.advance(ms(1));
        assert_eq!(send(&mut e, "0Q2"), "0Q0,0,0|");
        assert_eq!(send(&mut e, "0B"), "0B32|");
        send(&mut e, "0V2,5000");
        assert_eq!(send(&mut e, "0R2,0"), "0R|");
        e.advance(ms(500));
        let p = e.position(2);
        assert!(p > 500, "{p}");
        e.set_input(3, true);
        e.advance(ms(1));
        assert!(!e.is_running(2));
        let stopped = e.position(2);
        e.advance(ms(100));
        assert_eq!(e.position(2), stopped);
        assert_eq!(send(&mut e, "0Q2"), "0Q0,1,0|");
        // No motion into the active home: starts and ends at once.
        assert_eq!(send(&mut e, "0M2,10,0"), "0M|");
        assert!(!e.is_running(2));
        e.advance(ms(10));
        assert_eq!(e.position(2), stopped);
        // The other direction is free.
        send(&mut e, "0M2,10,1");
        e.advance(ms(1000));
        assert_eq!(e.position(2), stopped - 10);
    }

    #[test]
    fn debounce_counts_consecutive_1khz_samples() {
        let mut e = Emulator::new();
        send(&mut e, "0N5");
        e.set_input(0, true);
        e.advance(ms(4));
        assert_eq!(e.inputs(), 0);
        e.advance(ms(1));
        assert_eq!(e.inputs(), 1);
        // A glitch shorter than the count is ignored.
        e.set_input(0, false);
        e.advance(ms(3));
        e.set_input(0, true);
        e.advance(ms(10));
        assert_eq!(e.inputs(), 1);
        // Count 1 registers at the next sample.
        send(&mut e, "0N1");
        e.set_input(0, false);
        e.advance(ms(1));
        assert_eq!(e.inputs(), 0);
    }

    #[test]
    fn debounce_delays_the_limit_stop() {
        // 5000 steps/s, debounce 10: the switch is registered 10 ms after it
        // closes, 50 steps later.
        let mut e = Emulator::new();
        send(&mut e, "0A0,100000");
        send(&mut e, "0V0,5000");
        send(&mut e, "0L0,1,0,0,0");
        send(&mut e, "0N10");
        send(&mut e, "0R0,0");
        e.advance(ms(100)); // at speed after 50 ms
        let p0 = e.position(0);
        e.set_input(0, true);
        e.advance(ms(9));
        assert!(e.is_running(0));
        e.advance(ms(1));
        assert!(!e.is_running(0));
        assert_eq!(e.position(0) - p0, 50);
    }

    #[test]
    fn homing_backs_off_and_approaches_at_10_steps_per_second() {
        let mut e = Emulator::new();
        send(&mut e, "0V1,2000");
        send(&mut e, "0L1,0,0,4,4"); // dir 1 home: bit 2 low
        e.set_input(2, true);
        e.advance(ms(1));
        assert_eq!(send(&mut e, "0H1,1"), "0H|");
        e.advance(ms(1000));
        let switch_at = e.position(1);
        e.set_input(2, false); // switch closes
        e.advance(ms(1));
        assert_eq!(send(&mut e, "0Q1"), "0Q1,0,1|", "still homing");
        let hit = e.position(1);
        assert!(hit < switch_at);
        // Back-off: reverse at 10 steps/s (1 step per 100 ms).
        e.advance(ms(300));
        assert_eq!(e.position(1), hit + 3);
        e.set_input(2, true); // switch opens
        e.advance(ms(1));
        assert!(e.is_running(1));
        // Approach at 10 steps/s in the homing direction.
        e.advance(ms(200));
        let before = e.position(1);
        assert_eq!(before, hit + 3 - 2);
        e.set_input(2, false);
        e.advance(ms(1));
        assert!(!e.is_running(1));
        assert_eq!(send(&mut e, "0Q1"), "0Q0,0,1|");
        e.advance(ms(1000));
        assert_eq!(e.position(1), before);
    }

    #[test]
    fn homing_honours_the_direction_modifier() {
        let mut e = Emulator::new();
        send(&mut e, "0V0,1000,1");
        send(&mut e, "0H0,0");
        e.advance(ms(500));
        assert!(e.position(0) < 0, "runs in direction 1");
        send(&mut e, "0S0");
        // Moves ignore the modifier.
        send(&mut e, "0M0,10,0");
        let p = e.position(0);
        e.advance(ms(1000));
        assert_eq!(e.position(0), p + 10);
    }

    #[test]
    fn synchronous_move_finishes_together_within_limits() {
        // Motor 0: 1000 steps, vmax 1000; motor 1: 500 steps, vmax 1000.
        // Normalized limits: v = min(1000/1000, 1000/500) = 1/s,
        // a = d = min(5, 10) = 5/s^2 -> t = 0.2 + 0.8 + 0.2 = 1.2 s
        // (the time motor 0 would need alone). Motor 1 peaks at 500.
        let mut e = Emulator::new();
        assert_eq!(send(&mut e, "0Y1000,0,500,1,0,0"), "0Y|");
        e.advance(ms(600));
        assert!((e.velocity(0) - 1000.0).abs() < 1e-6);
        assert!((e.velocity(1) + 500.0).abs() < 1e-6);
        assert!(e.is_running(2), "all motors busy");
        assert_eq!(send(&mut e, "0M2,1,0"), "0E1|");
        e.advance(ms(599));
        assert!(e.is_running(0) && e.is_running(1));
        e.advance(ms(1));
        assert!(!e.is_running(0) && !e.is_running(1));
        assert_eq!((e.position(0), e.position(1)), (1000, -500));
    }

    #[test]
    fn synchronous_move_respects_the_slowest_motor() {
        // Motor 1 vmax 100 with 1000 steps dominates: v = 0.1/s,
        // a = min(5000/200, 5000/1000) = 5 -> 0.02 s ramps covering
        // 0.001 each, cruise (1 - 0.002)/0.1 = 9.98 s: total 10.02 s.
        let mut e = Emulator::new();
        send(&mut e, "0V1,100");
        send(&mut e, "0Y200,0,1000,0,0,0");
        let mut peak = [0.0f64; 2];
        for _ in 0..10_019 {
            e.advance(ms(1));
            for (i, p) in peak.iter_mut().enumerate() {
                *p = p.max(e.velocity(i).abs());
            }
        }
        assert!(e.is_running(0));
        e.advance(ms(1));
        assert!(!e.is_running(0));
        assert!(
            peak[1] <= 100.0 + 1e-9 && peak[0] <= 20.0 + 1e-9,
            "{peak:?}"
        );
        assert_eq!((e.position(0), e.position(1)), (200, 1000));
    }

    #[test]
    fn chained_45_degree_square_returns_to_start() {
        let mut e = Emulator::new();
        for c in [
            "0Y1000,0,1000,0,0,0,0",
            "0Y1000,0,1000,1,0,0,0",
            "0Y1000,1,1000,1,0,0,0",
        ] {
            assert_eq!(send(&mut e, c), "0Y|");
            e.advance(ms(100));
            assert!(!e.is_running(0), "stored moves do not start");
        }
        assert_eq!(e.chain_len(), 3);
        assert_eq!(send(&mut e, "0Y1000,1,1000,0,0,0,1"), "0Y|");
        assert_eq!(e.chain_len(), 0);
        // Each side: 1.2 s (see above) -> corners at 1.2, 2.4, 3.6, 4.8 s.
        let corners = [(1000, 1000), (2000, 0), (1000, -1000), (0, 0)];
        let mut prev = (0i64, 0i64);
        for (k, c) in corners.iter().enumerate() {
            // Mid-side (peeked on a clone): both motors have moved the same
            // number of steps, so the path is a 45 degree line.
            let mut peek = e.clone();
            peek.advance(ms(300));
            let (dx, dy) = (peek.position(0) - prev.0, peek.position(1) - prev.1);
            assert!(dx.abs() > 0 && dx.abs() == dy.abs(), "side {k}: {dx},{dy}");
            e.advance(ms(1200));
            assert_eq!((e.position(0), e.position(1)), *c, "corner {k}");
            prev = *c;
        }
        assert!(!e.is_running(0) && !e.is_running(1));
    }

    #[test]
    fn stop_and_limit_abort_a_chain() {
        let mut e = Emulator::new();
        send(&mut e, "0L0,1,0,0,0");
        send(&mut e, "0Y1000,0,0,0,0,0,0");
        send(&mut e, "0Y1000,0,0,0,0,0,1");
        e.advance(ms(500));
        e.set_input(0, true);
        e.advance(ms(1));
        assert!(!e.is_running(0));
        let p = e.position(0);
        e.advance(ms(5000));
        assert_eq!(e.position(0), p);
        e.set_input(0, false);
        e.advance(ms(1));
        send(&mut e, "0Y1000,0,1000,0,0,0");
        e.advance(ms(100));
        assert_eq!(send(&mut e, "0S2"), "0S|");
        assert!(!e.is_running(0) && !e.is_running(1));
    }

    #[test]
    fn plain_sync_discards_the_buffer_and_capacity_is_100() {
        // §2.2(i), §4.17: a chain is at most 100 moves: 99 stored with execute 0, the
        // 100th sent with execute 1. The 100th store is refused (E3); the execute still
        // fits and runs all 100.
        let mut e = Emulator::new();
        for k in 0..99 {
            assert_eq!(send(&mut e, "0Y1,0,0,0,0,0,0"), "0Y|", "store {k}");
        }
        assert_eq!(send(&mut e, "0Y1,0,0,0,0,0,0"), "0E3|");
        assert_eq!(e.chain_len(), 99);
        assert_eq!(send(&mut e, "0Y1,0,0,0,0,0,1"), "0Y|");
        assert_eq!(e.chain_len(), 0);
        // 100 moves of one step: each a short triangle (1 step at 5000 steps/s²: about
        // 28 ms), well within 10 s.
        e.advance(ms(10_000));
        assert!(!e.is_running(0));
        assert_eq!(e.position(0), 100);
        // A plain Y (execute omitted) discards what is stored and runs only itself.
        for _ in 0..3 {
            assert_eq!(send(&mut e, "0Y1,0,0,0,0,0,0"), "0Y|");
        }
        assert_eq!(send(&mut e, "0Y5,0,0,0,0,0"), "0Y|");
        assert_eq!(e.chain_len(), 0);
        e.advance(ms(1000));
        assert_eq!(e.position(0), 105);
    }

    #[test]
    fn clock_is_exact_and_keeps_sub_millisecond_remainders() {
        let mut e = Emulator::new();
        e.advance(Duration::from_micros(600));
        assert_eq!(e.now(), Duration::ZERO);
        e.advance(Duration::from_micros(600));
        assert_eq!(e.now(), ms(1));
        e.advance(Duration::from_secs(86));
        assert_eq!(e.now(), ms(86_001));
    }

    #[test]
    fn move_of_max_u32_steps_and_zero_steps() {
        let mut e = Emulator::new();
        send(&mut e, "0M0,0,0");
        assert!(!e.is_running(0));
        send(&mut e, "0V0,5000");
        send(&mut e, "0M0,4294967295,1");
        e.advance(ms(2000));
        assert!(e.is_running(0));
        send(&mut e, "0S0");
        // 1 s ramp to 5000 (2500 steps) + 1 s at 5000 = 7500 steps.
        assert_eq!(e.position(0), -7500);
    }
}
