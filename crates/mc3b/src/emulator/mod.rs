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

use std::time::Duration;

use crate::codec::{CommandCode, CommandParser};

mod commands;
mod motor;
mod profile;
mod settings;
mod sync;

use motor::{sign, step_pos, Kind, Motor};
use profile::Profile;
pub use settings::MotorSettings;
use sync::{SyncRun, SyncSeg};

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
}

#[cfg(test)]
mod tests;
