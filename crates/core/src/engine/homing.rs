//! Go home on the virtual card (user manual §2.8, both languages; examples manual §15).
//!
//! `MCC_Home(order0..order7, card)` homes the channels of one card. Channels with the same
//! order (0..7) home together, lower orders first; 255 skips a channel. Every mode runs
//! three phases (§2.8.2): 1 searches the home sensor or limit switch, 2 the index pulse,
//! 3 moves from the machine home to the working home by `dfOffset`. The channels of one
//! order finish a phase together: one that is done waits (decelerating if it was moving)
//! until every other is done; modes without phase 2 wait there too.
//!
//! Each mode is a list of [`Step`]s (§2.8.1): a direction (the configured one or its
//! reverse), a speed (`dfHighSpeed`/`dfLowSpeed`), the event that ends it, and how it
//! ends: a deceleration over `dfDecTime`, an emergency stop (at once, where the event
//! was seen), or going straight on into the next step. Speeds change at `speed/dfAccTime`
//! (up) and `speed/dfDecTime` (down). Events are seen in the tick after the motion that
//! caused them (the card reads its inputs once per interpolation period), so an
//! emergency stop stands at the first sample past the edge. "Entering" and "leaving" the
//! home sensor are edges seen during the step; a limit switch counts while it is active.
//! Index pulses are counted from 0 from the start of the step that searches them
//! (`nIndexCount`); the returns of modes 13–15 go back exactly to the pulse's position
//! (the card latches it).
//!
//! Modes that search the home sensor (3–8, 12–14) first look where they start (§2.8.1
//! Case 2 and 3): starting inside the sensor, or meeting the limit switch ahead before
//! the sensor, the channel runs to that limit switch at high speed (emergency stop),
//! returns through the sensor at high speed and decelerates once past it, then homes as
//! in Case 1. Meeting the limit again, or the opposite limit on the way back, fails the
//! homing: the channel stops at once, the others decelerate, and the groups driving it
//! record 0xF701 + axis. The emergency-stop input stops every channel at once and the
//! groups record 0xF102.
//!
//! Positions here are in the channel's user units in the frame of its command counter
//! (pulses / pulses-per-UU), so the pulses sent are `round(x × factor)`.

mod program;

use program::RECOVER;
pub use program::{program, uses_home_sensor, Speed, Step, Then, Until};

use crate::config::AXES;
use crate::engine::group::GroupState;
use crate::error::{McclError, McclResult};
use crate::machine::Channel;
use crate::planner::Axis1D;
use crate::vendor::consts as c;
use crate::vendor::SYS_HOME_CONFIG;

/// `MCC_Home` order that leaves a channel out.
pub const ORDER_SKIP: i32 = 255;

/// The go-home order of each channel of a card, checked: 0..=7 (lower orders first,
/// equal orders together) or [`ORDER_SKIP`]; anything else is `PARAMETER_ERR`.
pub fn home_orders(orders: [i32; AXES]) -> McclResult<[i32; AXES]> {
    if orders
        .iter()
        .any(|&o| !(0..=7).contains(&o) && o != ORDER_SKIP)
    {
        return Err(McclError::Parameter);
    }
    Ok(orders)
}

/// Go-home status: homing in progress (`MCC_GetGoHomeStatus`).
pub const HOME_BUSY: i32 = 0;
/// Go-home status: every channel homed.
pub const HOME_DONE: i32 = 1;
/// Go-home status after `MCC_ResetMotion`: the vendor's library then reads 0, as during a
/// go home, though nothing homes; kept apart from [`HOME_BUSY`] so that nothing waits for
/// it, and read as 0 ([`home_status_read`]).
pub const HOME_AFTER_RESET: i32 = i32::MIN + 1;

/// The go-home status a program reads for the stored one.
pub fn home_status_read(stored: i32) -> i32 {
    if stored == HOME_AFTER_RESET {
        HOME_BUSY
    } else {
        stored
    }
}

/// Go-home status: no homing has completed since `MCC_Home` was last called (never
/// called, aborted, stopped by the emergency-stop input or failed).
pub const HOME_NONE: i32 = c::HOME_COMMAND_NOTCALLED_ERR;

/// What a channel is doing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum State {
    /// Its order has not come yet (or it is left out).
    Waiting,
    /// Running step `i` of its mode (`recover`: of the Case 2/3 recovery);
    /// `stopping`: the step's event came and it decelerates before the next step.
    Run {
        i: usize,
        recover: bool,
        stopping: bool,
    },
    /// Done with phase `n` (1 or 2), waiting for the other channels of its order.
    PhaseDone(u8),
    /// Phase 3: moving to the working home.
    Offset,
    /// At the working home, zeroed.
    Done,
}

/// The rate (UU/s²) that changes a speed by `speed` in `secs`; at once for no time.
fn rate_over(speed: f64, secs: f64) -> f64 {
    if secs > 0.0 {
        speed / secs
    } else {
        f64::INFINITY
    }
}

/// One channel being homed.
#[derive(Debug, Clone)]
struct HomeAxis {
    ch: usize,
    order: i32,
    cfg: SYS_HOME_CONFIG,
    /// Pulses per UU (signed).
    factor: f64,
    kin: Axis1D,
    state: State,
    /// Edge detection of the current step: the sensor was seen in the opposite state.
    armed: bool,
    /// Index pulses seen by the current index search.
    index_seen: u32,
    /// Where the index pulse was found (UU).
    index_pos: Option<f64>,
    /// The recovery ran already (a second Case 3 fails).
    recovered: bool,
    /// Done with a phase while moving: the stop to wait standing was commanded.
    parked: bool,
    /// The speed of the step running (or last run), UU/s: decelerations run at
    /// `step_speed / dfDecTime` (the manual's time from that speed to 0).
    step_speed: f64,
}

impl HomeAxis {
    /// +1 for the configured direction positive (`wDirection` 0), −1 negative.
    fn dir(&self) -> f64 {
        if self.cfg.wDirection == 0 {
            1.0
        } else {
            -1.0
        }
    }

    fn speed(&self, s: Speed) -> f64 {
        match s {
            Speed::High => self.cfg.dfHighSpeed,
            Speed::Low => self.cfg.dfLowSpeed,
        }
    }

    fn acc_s(&self) -> f64 {
        self.cfg.dfAccTime / 1000.0
    }

    fn dec_s(&self) -> f64 {
        self.cfg.dfDecTime / 1000.0
    }

    /// The deceleration: from the step's speed to 0 in `dfDecTime` (§2.8.1), so a slower
    /// axis stops sooner at the same rate.
    fn decel_rate(&self) -> f64 {
        rate_over(self.step_speed.max(self.kin.v().abs()), self.dec_s())
    }

    fn step(&self) -> Option<Step> {
        match self.state {
            State::Run { i, recover, .. } => {
                if recover {
                    RECOVER.get(i).copied()
                } else {
                    program(self.cfg.wMode).get(i).copied()
                }
            }
            _ => None,
        }
    }

    fn home(&self, chan: &Channel) -> bool {
        chan.home_level(self.cfg.wSensorMode)
    }

    fn limit(chan: &Channel, dir: f64) -> bool {
        let l = chan.levels();
        if dir > 0.0 {
            l.plus
        } else {
            l.minus
        }
    }

    /// Starts step `i` (of the recovery when `recover`) from the current motion.
    fn begin(&mut self, i: usize, recover: bool, chan: &Channel) {
        self.parked = false;
        self.state = State::Run {
            i,
            recover,
            stopping: false,
        };
        let Some(s) = self.step() else {
            return;
        };
        let dir = if s.forward { self.dir() } else { -self.dir() };
        let speed = self.speed(s.speed);
        self.armed = match s.until {
            Until::EnterHome => !self.home(chan),
            Until::LeaveHome => self.home(chan),
            _ => true,
        };
        match s.until {
            Until::ReturnToIndex => {
                self.step_speed = speed;
                let target = self.index_pos.unwrap_or(self.kin.x());
                let (acc, dec) = (self.acc_s(), self.dec_s());
                if !self.kin.move_to(target, speed, acc, dec) {
                    self.kin.halt();
                }
            }
            _ => {
                if s.until == Until::Index {
                    self.index_seen = 0;
                }
                let v = self.kin.v();
                let target = dir * speed;
                let faster = v * target < 0.0 || v.abs() < speed;
                let rate = if faster {
                    rate_over(speed, self.acc_s())
                } else {
                    // Slowing from the last step's speed (mode 5: high to low).
                    self.decel_rate()
                };
                self.step_speed = speed;
                self.kin.run(target, rate);
            }
        }
    }

    /// After step `i` ended: the next step of the same phase, or the phase is done.
    fn next(&mut self, i: usize, recover: bool, chan: &Channel) {
        if recover {
            if i + 1 < RECOVER.len() {
                self.begin(i + 1, true, chan);
            } else {
                self.begin(0, false, chan);
            }
            return;
        }
        let prog = program(self.cfg.wMode);
        let phase = prog.get(i).map_or(1, |s| s.phase);
        match prog.get(i + 1) {
            Some(s) if s.phase == phase => self.begin(i + 1, false, chan),
            _ => self.state = State::PhaseDone(phase),
        }
    }

    /// Looks at the inputs after the last tick's motion; returns an error record when the
    /// homing of this channel fails.
    fn look(&mut self, chan: &Channel) -> Option<i32> {
        let State::Run {
            i,
            recover,
            stopping,
        } = self.state
        else {
            return None;
        };
        let s = self.step()?;
        if stopping {
            if self.kin.at_rest() {
                self.next(i, recover, chan);
            }
            return None;
        }
        let dir = if s.forward { self.dir() } else { -self.dir() };
        let home = self.home(chan);
        let met = match s.until {
            Until::EnterHome | Until::LeaveHome => {
                let want = s.until == Until::EnterHome;
                if home == want && self.armed {
                    true
                } else {
                    if home != want {
                        self.armed = true;
                    }
                    false
                }
            }
            Until::Limit => Self::limit(chan, dir),
            Until::LeaveLimit => !Self::limit(chan, -dir),
            Until::Index => {
                let want = u32::try_from(self.cfg.nIndexCount).unwrap_or(0);
                let mut found = None;
                for k in 0..chan.index_events() {
                    if self.index_seen == want && found.is_none() {
                        found = chan.index_passed(k);
                    }
                    self.index_seen = self.index_seen.saturating_add(1);
                }
                if let Some(p) = found {
                    self.index_pos = Some(p as f64 / self.factor);
                }
                found.is_some()
            }
            Until::ReturnToIndex => self.kin.at_rest(),
        };
        if !met && s.until != Until::Limit && s.until != Until::LeaveLimit {
            // A limit switch ahead while searching a sensor or an index pulse.
            if Self::limit(chan, dir) && self.kin.v() * dir > 0.0 {
                let first_search = !recover && i == 0 && uses_home_sensor(self.cfg.wMode);
                self.kin.halt();
                if first_search && !self.recovered {
                    // Case 3: the limit came before the home sensor.
                    self.recovered = true;
                    self.begin(1, true, chan);
                    return None;
                }
                return Some(crate::engine::safety::ERR_LIMIT);
            }
        }
        if !met {
            return None;
        }
        match s.then {
            Then::Halt => {
                self.kin.halt();
                self.next(i, recover, chan);
            }
            Then::Continue => self.next(i, recover, chan),
            Then::Decel => {
                let rate = self.decel_rate();
                self.kin.stop(rate);
                if self.kin.at_rest() {
                    self.next(i, recover, chan);
                } else {
                    self.state = State::Run {
                        i,
                        recover,
                        stopping: true,
                    };
                }
            }
        }
        None
    }

    /// Starts phase `n` (2 or 3) of this channel.
    fn start_phase(&mut self, n: u8, chan: &Channel) {
        if n == 3 {
            let target = self.kin.x() + self.cfg.dfOffset;
            let (speed, acc, dec) = (self.cfg.dfHighSpeed, self.acc_s(), self.dec_s());
            self.step_speed = speed;
            if !self.kin.move_to(target, speed, acc, dec) {
                self.kin.halt();
            }
            self.state = State::Offset;
            return;
        }
        let prog = program(self.cfg.wMode);
        match prog.iter().position(|s| s.phase == n) {
            Some(i) => self.begin(i, false, chan),
            None => {
                // No steps in this phase: a channel still moving stops here.
                if !self.kin.at_rest() && !self.parked {
                    let rate = self.decel_rate();
                    self.kin.stop(rate);
                }
                self.parked = true;
                self.state = State::PhaseDone(n);
            }
        }
    }
}

/// Per channel of the homing card, after a tick.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AxisOut {
    /// Commanded position (UU, command-counter frame) and speed (UU/s); `None` for a
    /// channel that is not homed.
    pub pos: Option<(f64, f64)>,
    /// Reached its working home this tick: its counters read 0 now.
    pub zeroed: bool,
    /// The error record its groups get (homing failed on a limit, emergency stop).
    pub record: Option<i32>,
}

/// What one tick of homing did.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct HomeTick {
    /// The card being homed.
    pub card: usize,
    /// Per channel.
    pub axes: [AxisOut; AXES],
    /// The homing ended in this tick with this status ([`HOME_DONE`] or [`HOME_NONE`]).
    pub finished: Option<i32>,
    /// The order (-1 after the last) and phase (1..3) running, for the trace.
    pub phase: (i32, u8),
}

/// A go home of one card in progress.
#[derive(Debug, Clone)]
pub struct Homing {
    card: usize,
    axes: Vec<HomeAxis>,
    /// The orders in use, ascending, and the one running.
    orders: Vec<i32>,
    current: usize,
    /// The phase the channels of the current order are in (1..3).
    phase: u8,
    /// Ending: every channel decelerates (abort, failure) and then the status is this.
    ending: Option<i32>,
}

impl Homing {
    /// Homing of `card` with `orders[ch]` (0..7, or [`ORDER_SKIP`]) and the go-home
    /// parameters per channel, starting from where the channels' commands are.
    pub fn new(
        card: usize,
        orders: [i32; AXES],
        cfgs: &[SYS_HOME_CONFIG; AXES],
        chans: &[Channel; AXES],
    ) -> Homing {
        let mut axes = Vec::new();
        for ch in 0..AXES {
            if orders[ch] == ORDER_SKIP {
                continue;
            }
            let factor = chans[ch].factor();
            let x = if factor != 0.0 {
                chans[ch].command_pulses() as f64 / factor
            } else {
                0.0
            };
            axes.push(HomeAxis {
                ch,
                order: orders[ch],
                cfg: cfgs[ch],
                factor,
                kin: Axis1D::at(x),
                state: State::Waiting,
                armed: false,
                index_seen: 0,
                index_pos: None,
                recovered: false,
                parked: false,
                step_speed: 0.0,
            });
        }
        let mut used: Vec<i32> = axes.iter().map(|a| a.order).collect();
        used.sort_unstable();
        used.dedup();
        let mut h = Homing {
            card,
            axes,
            orders: used,
            current: 0,
            phase: 1,
            ending: None,
        };
        h.start_order(chans);
        h
    }

    /// The card being homed.
    pub fn card(&self) -> usize {
        self.card
    }

    /// Channels being homed, one bit each.
    pub fn channel_mask(&self) -> u8 {
        self.axes.iter().fold(0, |m, a| m | 1 << a.ch)
    }

    /// `MCC_AbortGoHome`: every channel decelerates to a stop over its `dfDecTime`; the
    /// homing then ends without completing.
    pub fn abort(&mut self) {
        self.end_all(HOME_NONE, None);
    }

    fn end_all(&mut self, status: i32, halted: Option<usize>) {
        if self.ending.is_none() {
            self.ending = Some(status);
        }
        for a in &mut self.axes {
            if Some(a.ch) == halted {
                a.kin.halt();
            } else {
                let rate = a.decel_rate();
                a.kin.stop(rate);
            }
            a.state = State::Waiting;
        }
    }

    fn start_order(&mut self, chans: &[Channel; AXES]) {
        self.phase = 1;
        let Some(&order) = self.orders.get(self.current) else {
            return;
        };
        for a in self.axes.iter_mut().filter(|a| a.order == order) {
            let chan = &chans[a.ch];
            if uses_home_sensor(a.cfg.wMode) && a.home(chan) {
                // Case 2: starting inside the home sensor.
                a.recovered = true;
                a.begin(0, true, chan);
            } else {
                a.begin(0, false, chan);
            }
        }
    }

    /// One interpolation period of `dt` seconds: looks at the inputs the last tick's
    /// motion produced, moves on, and says where each channel is to be. The caller sends
    /// the pulses and updates the groups; `chans` are the card's channels.
    pub fn tick(&mut self, chans: &mut [Channel; AXES], emergency: bool, dt: f64) -> HomeTick {
        let mut out = HomeTick {
            card: self.card,
            ..HomeTick::default()
        };
        // Phase 3 ends: the channels that arrived last tick are zeroed now (their motors
        // have stepped to the working home).
        for a in &mut self.axes {
            if a.state == State::Offset && a.kin.at_rest() {
                chans[a.ch].home_here();
                a.kin = Axis1D::at(0.0);
                a.state = State::Done;
                out.axes[a.ch].zeroed = true;
            }
        }
        if emergency && self.ending.is_none() {
            for a in &mut self.axes {
                a.kin.halt();
                a.state = State::Waiting;
                out.axes[a.ch].record = Some(crate::engine::safety::ERR_EMERGENCY);
            }
            self.ending = Some(HOME_NONE);
        }
        if self.ending.is_none() {
            let mut failed = None;
            for a in &mut self.axes {
                if let Some(rec) = a.look(&chans[a.ch]) {
                    out.axes[a.ch].record = Some(rec + a.ch as i32);
                    failed = Some(a.ch);
                    break;
                }
            }
            if let Some(ch) = failed {
                self.end_all(HOME_NONE, Some(ch));
            } else {
                self.sync(chans);
            }
        }
        for a in &mut self.axes {
            a.kin.advance(dt);
            let (x, v) = a.kin.state();
            out.axes[a.ch].pos = Some((x, v));
        }
        if let Some(status) = self.ending {
            if self.axes.iter().all(|a| a.kin.at_rest()) {
                out.finished = Some(status);
            }
        } else if self.current >= self.orders.len() {
            out.finished = Some(HOME_DONE);
        }
        out.phase = (
            self.orders.get(self.current).copied().unwrap_or(-1),
            self.phase,
        );
        out
    }

    /// Phase synchronisation of the current order (§2.8.2 caution 2).
    fn sync(&mut self, chans: &[Channel; AXES]) {
        let Some(&order) = self.orders.get(self.current) else {
            return;
        };
        let phase = self.phase;
        let mine = |a: &HomeAxis| a.order == order;
        if phase == 3 {
            if self
                .axes
                .iter()
                .filter(|a| mine(a))
                .all(|a| a.state == State::Done)
            {
                self.current += 1;
                self.start_order(chans);
            }
            return;
        }
        let all_done = self
            .axes
            .iter()
            .filter(|a| mine(a))
            .all(|a| a.state == State::PhaseDone(phase));
        if all_done {
            self.phase = phase + 1;
            for a in self.axes.iter_mut().filter(|a| a.order == order) {
                a.start_phase(phase + 1, &chans[a.ch]);
            }
            // A phase without steps for anyone (modes 3, 4, 9, 12, 16 only): go on at once.
            self.sync(chans);
        } else {
            // Channels done with the phase wait standing.
            for a in self.axes.iter_mut().filter(|a| a.order == order) {
                if a.state == State::PhaseDone(phase) && !a.kin.at_rest() && !a.parked {
                    let rate = a.decel_rate();
                    a.kin.stop(rate);
                    a.parked = true;
                }
            }
        }
    }
}

/// Applies a tick of homing to a group that drives homed channels: their positions and
/// speeds, the zeroing at the working home, error records, and the end of the homing.
pub fn apply_homing(g: &mut GroupState, h: &HomeTick) {
    if g.homing() == 0 {
        return;
    }
    for i in 0..AXES {
        if g.homing() & (1 << i) == 0 {
            continue;
        }
        let Some((card, ch)) = g.axes()[i].channel else {
            continue;
        };
        let Some(a) = h.axes.get(ch).filter(|_| card == h.card) else {
            continue;
        };
        if a.zeroed {
            g.home_zero_axis(i);
        }
        if let Some((x, v)) = a.pos {
            g.set_homing_axis(i, x, v);
        }
        if let Some(record) = a.record {
            g.set_error(record);
        }
    }
    if h.finished.is_some() {
        g.end_homing();
    }
}

#[cfg(test)]
mod order_tests {
    use super::*;

    #[test]
    fn home_orders_are_0_to_7_or_skip() {
        let ok = [0, 1, 7, ORDER_SKIP, 3, 3, ORDER_SKIP, 0];
        assert_eq!(home_orders(ok), Ok(ok));
        for bad in [8, -1, 254, 256] {
            let mut o = ok;
            o[4] = bad;
            assert_eq!(home_orders(o), Err(McclError::Parameter), "{bad}");
        }
    }
}
