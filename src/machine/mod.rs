//! The simulated machine behind the virtual card's channels: what each motor does with
//! the pulses it is sent (an ideal plant, or a first-order lag that makes tracking
//! error), the encoder that follows it, the home sensor and limit switches it passes, the
//! encoder index pulses, gap compensation (user manual §2.7.5) and the emergency-stop
//! input. Positions of sensors are in the axis's user units measured from where the
//! motor was at `MCC_InitSystem` (machine coordinates).

pub mod compensation;
pub mod deferred;
pub mod triggers;

use crate::config::{encoder_multiplier, AXES};
use crate::error::McclResult;
use crate::vendor::consts as c;
use crate::vendor::{SYS_COMP_PARAM, SYS_ENCODER_CONFIG, SYS_MAC_PARAM};
use compensation::Compensation;
use deferred::Deferred;

/// Default and largest pulse speed and acceleration limits (ZH manual §2.6.4).
pub const MAX_PULSE_LIMIT: i32 = i32::MAX;

/// The pulse limits before `MCC_SetMaxPulseSpeed`/`MCC_SetMaxPulseAcc`: 1,000,000, as the
/// vendor's library reads right after init.
pub const DEFAULT_PULSE_LIMIT: i32 = 1_000_000;

/// What the simulation configuration says about one channel.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ChannelSpec {
    /// Home sensor active region `[from, to]` (UU).
    pub home: Option<(f64, f64)>,
    /// + limit switch active at position >= this (UU).
    pub limit_plus: Option<f64>,
    /// − limit switch active at position <= this (UU).
    pub limit_minus: Option<f64>,
    /// Encoder counts (x4) between index pulses; `None`: one per motor turn (dwPPR).
    pub index_spacing: Option<u32>,
    /// Counts (x4) from 0 to the first index pulse.
    pub index_phase: u32,
    /// First-order lag time constant of the plant (s); `None`: ideal.
    pub lag_s: Option<f64>,
    /// The home sensor is a normally-closed contact: its input is low while hit.
    pub home_nc: bool,
}

impl ChannelSpec {
    /// The channel as the simulation configuration describes it.
    pub fn from_sim(c: &crate::sim::config::ChannelSim) -> ChannelSpec {
        ChannelSpec {
            home: c.home,
            limit_plus: c.limit_plus,
            limit_minus: c.limit_minus,
            index_spacing: c.index_spacing,
            index_phase: c.index_phase,
            lag_s: match c.plant {
                crate::sim::config::Plant::Ideal => None,
                crate::sim::config::Plant::Lag { tau_s } => Some(tau_s),
            },
            home_nc: c.home_nc,
        }
    }
}

/// A sensor the program or a test can force through `MCCL_Sim.h`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sensor {
    /// The home sensor.
    Home,
    /// The + limit switch.
    LimitPlus,
    /// The − limit switch.
    LimitMinus,
}

/// Sensor inputs of one channel after wiring, as the card sees them.
///
/// Aligned to 4 bytes so that the copies and comparisons a channel's step makes are one
/// 32-bit move each.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[repr(C, align(4))]
pub struct SensorLevels {
    /// Home sensor active.
    pub home: bool,
    /// + limit switch active.
    pub plus: bool,
    /// − limit switch active.
    pub minus: bool,
}

/// `x.floor() as i64` without a call to libm's `floor` (x86-64 without SSE4.1 has no
/// rounding instruction): the same result for every `f64`, since `as` truncates toward
/// zero and saturates (NaN gives 0).
fn floor_i64(x: f64) -> i64 {
    let t = x as i64;
    if (t as f64) > x {
        t.saturating_sub(1)
    } else {
        t
    }
}

/// Interval bounds below this in magnitude are exact in an `f64` (and nothing computed
/// from them overflows).
const CELL_LIMIT: i64 = 1 << 52;

/// The index interval `k` of the last position looked up on the channel's grid
/// (`spacing`, `phase`; a new grid drops the cell), and its bounds as motor positions:
/// every `x` in `lo <= x < hi` has `(floor(x) - phase).div_euclid(spacing) == k`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct IndexCell {
    k: i64,
    lo: f64,
    hi: f64,
}

impl IndexCell {
    /// No interval: holds no position (the bounds are the wrong way round), so the next
    /// lookup computes one.
    const NONE: IndexCell = IndexCell {
        k: 0,
        lo: f64::INFINITY,
        hi: f64::NEG_INFINITY,
    };

    /// The cell of interval `k`, when its bounds are exact.
    fn new(spacing: i64, phase: i64, k: i64) -> Option<IndexCell> {
        let lo = k.checked_mul(spacing)?.checked_add(phase)?;
        let hi = lo.checked_add(spacing)?;
        (lo > -CELL_LIMIT && hi < CELL_LIMIT).then_some(IndexCell {
            k,
            lo: lo as f64,
            hi: hi as f64,
        })
    }

    /// Whether `x` is inside (false for NaN).
    fn holds(&self, x: f64) -> bool {
        x >= self.lo && x < self.hi
    }
}

/// One channel of the card and the motor, encoder and sensors behind it.
///
/// `repr(C)` with the fields every step reads and writes first, together, and the
/// settings only setters and status calls read after them.
#[derive(Debug, Clone)]
#[repr(C)]
pub struct Channel {
    /// Pulses the program commanded (before compensation).
    cmd: i64,
    /// The command for the coming step: what [`Channel::command`] set during this tick
    /// (the group or homing driving the channel), else `cmd` (every step and counter
    /// restart sets both), so that a channel nobody commands holds.
    next: i64,
    /// The last step changed nothing, and another with the same command would change
    /// nothing either ([`Channel::step_commanded`] skips it). Cleared by whatever changes
    /// what a step reads: the counter's frame (`restart_counter`), the sensors
    /// (`update_sensors`, which placing, forcing and new parameters go through), the
    /// index grid (`set_grid`), the compensation and the plant.
    resting: bool,
    /// The period of the step that found the channel resting.
    resting_dt: f64,
    /// An ideal motor (no plant lag) with no compensation and no sensor that follows it:
    /// a step is [`Channel::step_ideal`]. Kept by [`Channel::refresh_ideal`] wherever
    /// the compensation, the plant or the sensors change.
    ideal: bool,
    /// Pulses output (command + compensation).
    out: i64,
    prev_out: i64,
    prev_delta: i64,
    /// Motor position in pulses from where the command counter was last zeroed.
    actual: f64,
    /// Motor position (pulses, machine coordinates) where the counter was last zeroed.
    base: f64,
    /// Index pulses passed in the last step.
    pub index_events: u32,
    /// Motor positions (pulses, machine frame) at the start and end of the last step.
    last_move: (f64, f64),
    /// The index interval of the last position looked up (`index_interval`), or
    /// [`IndexCell::NONE`].
    cell: IndexCell,
    /// Steps recorded and not yet made ([`deferred`]).
    deferred: Deferred,
    levels: SensorLevels,
    prev_levels: SensorLevels,
    /// Levels at the end of the last step: a level forced between steps shows as an edge.
    step_levels: SensorLevels,
    forced: [Option<bool>; 3],
    /// The index grid (spacing, phase) in x4 counts, from `spec` and `mac.dwPPR`, kept
    /// with the fields every step reads ([`Channel::refresh_grid`]).
    grid: (i64, i64),
    /// Whether a sensor is placed or forced: only then do the levels follow the motor
    /// ([`Channel::refresh_sensors`]).
    sensors: bool,
    /// Compensation tables in effect.
    comp: Compensation,
    /// Simulation configuration.
    spec: ChannelSpec,
    mac: SYS_MAC_PARAM,
    enc: SYS_ENCODER_CONFIG,
    /// Encoder input rate set by `MCC_SetENCInputRate` (overrides the configuration).
    pub input_rate: Option<u16>,
    /// `MCC_SetENCGearRate`.
    pub gear_rate: f64,
    /// Encoder count = raw count + `enc_offset`.
    enc_offset: i64,
    /// The tables last set (boxed: 2 KiB that only a reset reads, kept out of the way of
    /// the fields every step uses).
    comp_param: Box<SYS_COMP_PARAM>,
    /// Physical sensor levels (before the program's wiring setting).
    raw: [bool; 3],
    /// The last index pulse passed, as a raw count.
    pub last_index_count: Option<i64>,
    /// Latched limit switch activity (`MCC_GetLatchedLimitSwitchStatus`): + and −.
    pub latched: [bool; 2],
    /// Most pulses per interpolation period (`MCC_SetMaxPulseSpeed`).
    pub max_speed: i32,
    /// Most change of pulses per period between periods (`MCC_SetMaxPulseAcc`).
    pub max_acc: i32,
}

impl Channel {
    /// A channel at position 0.
    pub fn new(spec: ChannelSpec, mac: SYS_MAC_PARAM, enc: SYS_ENCODER_CONFIG) -> Channel {
        let mut ch = Channel {
            spec,
            mac,
            enc,
            input_rate: None,
            gear_rate: 1.0,
            cmd: 0,
            next: 0,
            resting: false,
            resting_dt: 0.0,
            ideal: false,
            out: 0,
            prev_out: 0,
            prev_delta: 0,
            actual: 0.0,
            base: 0.0,
            enc_offset: 0,
            comp: Compensation::default(),
            comp_param: Box::new(compensation::off()),
            forced: [None; 3],
            grid: (1, 0),
            sensors: false,
            raw: [false; 3],
            index_events: 0,
            last_index_count: None,
            last_move: (0.0, 0.0),
            cell: IndexCell::NONE,
            deferred: Deferred::NONE,
            latched: [false; 2],
            max_speed: DEFAULT_PULSE_LIMIT,
            max_acc: DEFAULT_PULSE_LIMIT,
            levels: SensorLevels::default(),
            prev_levels: SensorLevels::default(),
            step_levels: SensorLevels::default(),
        };
        ch.refresh_grid();
        ch.refresh_sensors();
        ch.update_sensors();
        ch.prev_levels = ch.levels;
        ch.step_levels = ch.levels;
        ch
    }

    /// Pulses per UU (signed: negative when wPosToEncoderDir reverses the output).
    pub fn factor(&self) -> f64 {
        let f = crate::config::conv_factor(&self.mac);
        if self.mac.wPosToEncoderDir != 0 {
            -f
        } else {
            f
        }
    }

    /// The motor's position in UU of the axis (machine coordinates).
    pub fn position(&self) -> f64 {
        self.assert_up_to_date();
        let f = self.factor();
        if f == 0.0 {
            0.0
        } else {
            (self.actual + self.base) / f
        }
    }

    /// `MCC_ResetMotion`/`MCC_UpdateParam`: the command counter restarts from 0 where the
    /// motor stands; the motor, its encoder count and the sensors do not move.
    pub fn rezero(&mut self) {
        let count = self.encoder();
        self.restart_counter(self.actual, count);
    }

    /// The command counter restarts from 0 `shift` pulses up the motor's frame (the
    /// motor, its sensors and its machine position do not move); the encoder then reads
    /// `count` and compensation starts again from its home point.
    fn restart_counter(&mut self, shift: f64, count: i64) {
        self.resting = false;
        self.base += shift;
        self.actual -= shift;
        self.cmd = 0;
        self.next = 0;
        self.out = 0;
        self.prev_out = 0;
        self.prev_delta = 0;
        self.comp = Compensation::new(&self.comp_param);
        self.refresh_ideal();
        self.set_encoder(count);
        self.update_sensors();
    }

    /// Go home's end (user manual §2.8): the commanded position becomes the working home,
    /// pulse 0 of the command counter, and the encoder reads 0 there. The motor does not
    /// move (a lagging one keeps its following error); compensation restarts from its
    /// home point (`wHome_No`).
    pub fn home_here(&mut self) {
        self.restart_counter(self.out as f64, 0);
    }

    /// The motor's position in pulses.
    pub fn actual_pulses(&self) -> f64 {
        self.assert_up_to_date();
        self.actual
    }

    /// Pulses output so far (command + compensation).
    pub fn output_pulses(&self) -> i64 {
        self.out
    }

    /// Pulses commanded (without compensation).
    pub fn command_pulses(&self) -> i64 {
        self.assert_up_to_date();
        self.cmd
    }

    /// Following error in pulses: output − motor (what `MCC_GetErrorCount` reports).
    pub fn error_count(&self) -> i64 {
        self.assert_up_to_date();
        (self.out as f64 - self.actual).round() as i64
    }

    /// Pulses output in the last tick, and the change from the tick before (per-period
    /// pulse speed and acceleration).
    pub fn pulse_rate(&self) -> (i64, i64) {
        self.assert_up_to_date();
        let d = self.out - self.prev_out;
        (d, d - self.prev_delta)
    }

    fn multiplier(&self) -> f64 {
        if self.enc.wType == c::ENC_TYPE_NO {
            return 0.0;
        }
        let rate = self.input_rate.unwrap_or(self.enc.wInputRate);
        f64::from(encoder_multiplier(rate)) / 4.0
    }

    fn raw_count(&self) -> i64 {
        let dir = if (self.enc.wABSwap == 1) ^ (self.enc.wAInverse == 1) ^ (self.enc.wBInverse == 1)
        {
            -1.0
        } else {
            1.0
        };
        ((self.actual + self.base) * self.multiplier() * self.gear_rate * dir).round() as i64
    }

    /// The encoder count the motor would show at `pulses` (motor pulses since the counter
    /// was last zeroed): what a latch captures at an index pulse.
    pub fn count_at(&self, pulses: i64) -> i64 {
        let dir = if (self.enc.wABSwap == 1) ^ (self.enc.wAInverse == 1) ^ (self.enc.wBInverse == 1)
        {
            -1.0
        } else {
            1.0
        };
        ((pulses as f64) * self.multiplier() * self.gear_rate * dir).round() as i64
            + self.enc_offset
    }

    /// The encoder count (`MCC_GetENCValue`).
    pub fn encoder(&self) -> i64 {
        self.assert_up_to_date();
        self.raw_count() + self.enc_offset
    }

    /// `MCC_SetENCValue`: the count becomes `v` here.
    pub fn set_encoder(&mut self, v: i64) {
        self.enc_offset = v - self.raw_count();
    }

    /// `MCC_SetENCInputRate`: counts per encoder cycle (1, 2 or 4; 3 also means x4);
    /// the count keeps its value at the change.
    pub fn set_input_rate(&mut self, rate: u16) {
        let v = self.encoder();
        self.input_rate = Some(rate);
        self.set_encoder(v);
    }

    /// `MCC_SetENCGearRate`: counts per motor pulse at x4; the count keeps its value at
    /// the change.
    pub fn set_gear_rate(&mut self, r: f64) {
        let v = self.encoder();
        self.gear_rate = r;
        self.set_encoder(v);
    }

    /// New mechanism and encoder parameters (`MCC_UpdateParam`).
    pub fn set_params(&mut self, mac: SYS_MAC_PARAM, enc: SYS_ENCODER_CONFIG) {
        let count = self.encoder();
        self.mac = mac;
        self.enc = enc;
        self.refresh_grid();
        self.input_rate = None;
        self.set_encoder(count);
        self.update_sensors();
    }

    /// The compensation pulses added to the command set this tick (0 without
    /// compensation), as the next step adds them.
    pub fn compensation_now(&mut self) -> i32 {
        if self.comp.active() {
            let c = self.comp.offset(self.next);
            c.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
        } else {
            0
        }
    }

    /// New compensation tables (`MCC_UpdateCompParam`).
    pub fn set_compensation(&mut self, p: &SYS_COMP_PARAM) {
        self.resting = false;
        *self.comp_param = *p;
        self.comp = Compensation::new(p);
        self.refresh_ideal();
    }

    /// Forces a sensor's physical level (`Some`) or lets the position decide (`None`).
    pub fn force(&mut self, s: Sensor, level: Option<bool>) {
        self.forced[s as usize] = level;
        self.refresh_sensors();
        self.update_sensors();
    }

    /// `MCCL_SimPlaceSensor`: [`Channel::place`], refused (`PARAMETER_ERR`, nothing
    /// changed) where the channel could never count to: `from` and `to` must be
    /// positions of the channel ([`crate::config::range::position`]).
    pub fn place_sensor(&mut self, s: Sensor, from: f64, to: f64) -> McclResult<()> {
        let f = self.factor();
        crate::config::range::position(from, f)?;
        crate::config::range::position(to, f)?;
        self.place(s, from, to);
        Ok(())
    }

    /// Moves a sensor: the home region, or a limit switch's position (`from`).
    pub fn place(&mut self, s: Sensor, from: f64, to: f64) {
        match s {
            Sensor::Home => self.spec.home = Some((from, to)),
            Sensor::LimitPlus => self.spec.limit_plus = Some(from),
            Sensor::LimitMinus => self.spec.limit_minus = Some(from),
        }
        self.refresh_sensors();
        self.update_sensors();
    }

    /// Sensor inputs after the program's wiring setting (NO/NC/unused).
    pub fn levels(&self) -> SensorLevels {
        self.levels
    }

    /// Limit switch `side` (0: +, 1: −) as the wiring setting reads it now.
    pub fn limit_switch(&self, side: usize) -> bool {
        if side == 0 {
            self.levels.plus
        } else {
            self.levels.minus
        }
    }

    /// Whether limit switch `side` has been active since its latch was last cleared.
    pub fn latched_limit(&self, side: usize) -> bool {
        self.latched[side]
    }

    /// Clears the latch of limit switch `side`; it latches again at once while the
    /// switch is active.
    pub fn clear_latched_limit(&mut self, side: usize) {
        self.latched[side] = self.limit_switch(side);
    }

    /// Sensor inputs of the previous step (for edge detection).
    pub fn prev_levels(&self) -> SensorLevels {
        self.assert_up_to_date();
        self.prev_levels
    }

    /// Physical level of a sensor: a normally-open switch closes (level high) when hit.
    pub fn raw_level(&self, s: Sensor) -> bool {
        self.raw[s as usize]
    }

    fn update_sensors(&mut self) {
        self.resting = false;
        let x = self.position();
        let hit = [
            self.spec.home.is_some_and(|(a, b)| x >= a && x <= b),
            self.spec.limit_plus.is_some_and(|p| x >= p),
            self.spec.limit_minus.is_some_and(|m| x <= m),
        ];
        for (i, h) in hit.into_iter().enumerate() {
            self.raw[i] = self.forced[i].unwrap_or(h);
        }
        // The program's wiring setting: NO reads the level, NC its inverse (a wrong
        // setting reads "active" while nothing is hit, as the manual describes).
        let wired = |level: bool, mode: u16| match mode {
            c::SL_NORMAL_OPEN => level,
            c::SL_NORMAL_CLOSE => !level,
            _ => false,
        };
        self.levels = SensorLevels {
            home: self.raw[0],
            plus: wired(self.raw[1], self.mac.wOverTravelUpSensorMode),
            minus: wired(self.raw[2], self.mac.wOverTravelDownSensorMode),
        };
        if self.levels.plus {
            self.latched[0] = true;
        }
        if self.levels.minus {
            self.latched[1] = true;
        }
    }

    /// The home sensor as the card reads it with the go-home wiring `mode`: the input is
    /// high while a normally-open contact is hit (low for a normally-closed one,
    /// `home_contact = "nc"`); `SL_NORMAL_OPEN` reads high as active, `SL_NORMAL_CLOSE`
    /// low. A setting that does not match the contact reads active while nothing is hit.
    pub fn home_level(&self, mode: u16) -> bool {
        let input = self.raw[0] != self.spec.home_nc;
        match mode {
            c::SL_NORMAL_CLOSE => !input,
            _ => input,
        }
    }

    fn index_grid(&self) -> (i64, i64) {
        self.grid
    }

    /// Recomputes the index grid after `spec` or `mac` changed; a new grid drops the
    /// cached index interval.
    fn refresh_grid(&mut self) {
        let spacing = i64::from(self.spec.index_spacing.unwrap_or(self.mac.dwPPR).max(1));
        self.set_grid((spacing, i64::from(self.spec.index_phase)));
    }

    /// Index grid `(spacing, phase)`; a new one drops the cached index interval.
    fn set_grid(&mut self, grid: (i64, i64)) {
        if grid != self.grid {
            self.grid = grid;
            self.cell = IndexCell::NONE;
            self.resting = false;
        }
    }

    /// Recomputes [`Channel::sensors`] after a sensor was placed or forced.
    fn refresh_sensors(&mut self) {
        self.sensors = self.spec.home.is_some()
            || self.spec.limit_plus.is_some()
            || self.spec.limit_minus.is_some()
            || self.forced.iter().any(Option::is_some);
        self.refresh_ideal();
    }

    /// Debug builds: a reader of what the steps make finds no step deferred (the engine
    /// brings channels up to date before anything but its own tick can read them,
    /// [`deferred`]).
    #[inline(always)]
    fn assert_up_to_date(&self) {
        debug_assert!(!self.deferring(), "a channel read with its steps deferred");
    }

    /// Recomputes [`Channel::ideal`] after the compensation, the plant or the sensors
    /// changed.
    fn refresh_ideal(&mut self) {
        self.ideal = self.ideal_now();
    }

    /// What [`Channel::ideal`] should be.
    fn ideal_now(&self) -> bool {
        !self.comp.active() && !self.lags() && !self.sensors
    }

    /// Whether the plant is a first-order lag (a positive time constant).
    fn lags(&self) -> bool {
        matches!(self.spec.lag_s, Some(tau) if tau > 0.0)
    }

    /// The plant: a first-order lag of `lag_s` seconds, or ideal (`None`) — what a
    /// `[plant]` table of the simulation configuration sets.
    pub fn set_plant_lag(&mut self, lag_s: Option<f64>) {
        self.resting = false;
        self.spec.lag_s = lag_s;
        self.refresh_ideal();
    }

    /// The `n`th (from 0) index pulse the motor passed in the last step, in the pulse
    /// frame of the command counter (what a latch captures), or `None` when it passed
    /// fewer than `n + 1`. Pulses are passed in the order of the motion.
    pub fn index_passed(&self, n: u32) -> Option<i64> {
        let (spacing, phase) = self.index_grid();
        let k = |x: f64| (x.floor() as i64 - phase).div_euclid(spacing);
        let (from, to) = self.last_move;
        let (a, b) = (k(from), k(to));
        let n = i64::from(n);
        let idx = if b > a {
            // Moving up: pulses a+1 ..= b.
            (a + 1 + n <= b).then_some(a + 1 + n)
        } else {
            // Moving down: pulses a, a-1, ..., b+1.
            (a - n > b).then_some(a - n)
        }?;
        Some(idx * spacing + phase - self.base as i64)
    }

    /// Sets the pulses the coming [`Channel::step_commanded`] moves to (the last call in
    /// a tick wins).
    pub fn command(&mut self, pulses: i64) {
        self.next = pulses;
    }

    /// One step of `dt` seconds to the pulses set by [`Channel::command`] this tick, or
    /// holding the last command when none was set.
    ///
    /// A channel at rest (see `resting`) held at its command is not stepped: the step
    /// would leave every field as it is. Most channels of a machine stand still most of
    /// the time; this keeps a tick from touching them.
    #[inline]
    pub fn step_commanded(&mut self, dt: f64) {
        let cmd = self.next;
        if self.resting && cmd == self.cmd && dt == self.resting_dt {
            return;
        }
        self.step(cmd, dt);
    }

    /// One interpolation period: the channel is commanded `cmd` pulses; the motor follows
    /// (ideal or lagging), the encoder and sensors follow the motor.
    #[inline]
    pub fn step(&mut self, cmd: i64, dt: f64) {
        debug_assert_eq!(self.ideal, self.ideal_now(), "Channel::ideal is stale");
        if self.ideal {
            self.step_ideal(cmd, dt);
        } else {
            self.step_general(cmd, dt);
        }
    }

    /// [`Channel::step`] of an ideal channel ([`Channel::ideal`]): the same fields
    /// written with the same values as [`Channel::step_general`] writes them when the
    /// output is the command, the motor is where the output is and no sensor follows
    /// the motor. Most channels of a running machine are such, and this is every tick's
    /// cost for each of them.
    #[inline]
    fn step_ideal(&mut self, cmd: i64, dt: f64) {
        self.begin_step(cmd);
        self.out = cmd;
        let before = self.actual;
        self.actual = cmd as f64;
        self.count_index(before + self.base, self.actual + self.base);
        self.end_step(dt, true);
    }

    /// [`Channel::step`] of any channel: compensation, a lagging plant, sensors.
    #[inline(never)]
    fn step_general(&mut self, cmd: i64, dt: f64) {
        self.begin_step(cmd);
        self.out = if self.comp.active() {
            cmd + self.comp.offset(cmd)
        } else {
            cmd
        };
        let before = self.actual;
        let target = self.out as f64;
        self.actual = match self.spec.lag_s {
            Some(tau) if tau > 0.0 => target + (self.actual - target) * (-dt / tau).exp(),
            _ => target,
        };
        self.count_index(before + self.base, self.actual + self.base);
        // Sensors only change with position if there are any (or one is forced).
        if self.sensors {
            self.update_sensors();
        }
        self.end_step(dt, !self.comp.active());
    }

    /// The start of every step: the output's history moves on one period (pulse speed
    /// and acceleration) and `cmd` becomes the command.
    #[inline(always)]
    fn begin_step(&mut self, cmd: i64) {
        self.prev_levels = self.step_levels;
        self.prev_delta = self.out - self.prev_out;
        self.prev_out = self.out;
        self.cmd = cmd;
        self.next = cmd;
    }

    /// The end of every step, once the output, the motor, the index count and the levels
    /// are up to date: whether the channel now rests (`comp_still`: no compensation state
    /// follows the motion).
    ///
    /// Resting is a fixed point of `step` with this command and period: the output stood
    /// still for two steps (no pulse speed or acceleration), the motor did not move (the
    /// plant's next position depends only on this one, the command and the period; a lag
    /// ends on a fixed point of its floating-point iteration, which need not be the
    /// command), so no index pulse and the same sensor levels.
    #[inline(always)]
    fn end_step(&mut self, dt: f64, comp_still: bool) {
        self.step_levels = self.levels;
        self.resting = comp_still
            && self.out == self.prev_out
            && self.prev_delta == 0
            && self.last_move.0 == self.last_move.1
            && self.prev_levels == self.step_levels;
        // Read only while resting (`step_commanded`): a moving channel skips the store.
        if self.resting {
            self.resting_dt = dt;
        }
    }

    /// Sets the motor where the command is (for a channel that is stopped and reset).
    pub fn settle(&mut self) {
        self.actual = self.out as f64;
        self.update_sensors();
    }

    /// `(floor(x) - phase).div_euclid(spacing)` on the channel's grid: the index interval
    /// of motor position `x`.
    /// A motor that stays within the interval of the last lookup (nearly every step: index
    /// pulses are a motor turn apart) gets it by two comparisons: with integer bounds
    /// `lo <= x < hi` means `lo <= floor(x) <= hi - 1`.
    fn index_interval(&mut self, x: f64) -> i64 {
        let (spacing, phase) = self.grid;
        if self.cell.holds(x) {
            return self.cell.k;
        }
        let k = (floor_i64(x) - phase).div_euclid(spacing);
        self.cell = IndexCell::new(spacing, phase, k).unwrap_or(IndexCell::NONE);
        k
    }

    #[inline]
    fn count_index(&mut self, from: f64, to: f64) {
        self.index_events = 0;
        self.last_move = (from, to);
        // Whole-pulse positions (the ideal plant) use integer arithmetic; a lagging motor
        // between pulses rounds down to the pulse it has passed.
        if self.cell.holds(from) && self.cell.holds(to) {
            // Both ends in one interval (a motor that stood still too, nearly always: the
            // interval is the one its last move ended in): no index pulse passed.
            return;
        }
        self.count_index_across(from, to);
    }

    /// [`Channel::count_index`] of a move that leaves the last index interval looked up.
    #[inline(never)]
    fn count_index_across(&mut self, from: f64, to: f64) {
        // Index pulses in x4 counts of the motor position: one count per pulse.
        let (spacing, phase) = self.index_grid();
        let (a, b) = (self.index_interval(from), self.index_interval(to));
        if a != b {
            self.index_events = u32::try_from((a - b).unsigned_abs()).unwrap_or(u32::MAX);
            // Moving up the last index passed is the highest, moving down the lowest.
            let last = if b > a { b } else { b + 1 };
            self.last_index_count = Some(last * spacing + phase - self.base as i64);
        }
    }
}

/// Card settings that the simulation keeps and reports (user manual §2.7.1, §2.9).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct CardSettings {
    /// P, I, D and feed-forward gains per channel (0..255).
    pub gains: [[u16; AXES]; 4],
    /// I and D gain clock dividers.
    pub dividers: [u32; 2],
    /// LED outputs, one bit per channel.
    pub leds: u8,
    /// Limit, home, GPIO and encoder input filter clocks (kept: the simulated inputs
    /// neither bounce nor pick up noise).
    pub filters: [u16; 4],
    /// Closed-loop error counter thresholds (+, −) per channel.
    pub error_threshold: [(u16, u16); AXES],
}

/// A loop gain of a card's channels (index in [`CardSettings::gains`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Gain {
    /// Proportional (`MCC_SetPGain`).
    P = 0,
    /// Integral (`MCC_SetIGain`).
    I = 1,
    /// Derivative (`MCC_SetDGain`).
    D = 2,
    /// Feed-forward (`MCC_SetFGain`).
    FeedForward = 3,
}

/// One gain for each of a card's 8 channels, each 0..255.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Gains([u16; AXES]);

impl Gains {
    /// The gains `v` (`PARAMETER_ERR` when one is above 255).
    pub fn new(v: [u16; AXES]) -> McclResult<Gains> {
        if v.iter().any(|&g| g > 255) {
            return Err(crate::error::McclError::Parameter);
        }
        Ok(Gains(v))
    }
}

/// An input filter clock of a card (index in [`CardSettings::filters`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FilterClock {
    /// The limit switch inputs (`MCC_SetLimitFilterClk`).
    Limit = 0,
    /// The home sensor inputs (`MCC_SetHomeFilterClk`).
    Home = 1,
    /// The general-purpose inputs (`MCC_SetGpioFilterClk`).
    Gpio = 2,
    /// The encoder inputs (`MCC_SetENCFilterClock`).
    Encoder = 3,
}

impl CardSettings {
    /// Keeps gain `k` of every channel (kept and reported: the simulated plant is set by
    /// the configuration).
    pub fn set_gains(&mut self, k: Gain, g: Gains) {
        self.gains[k as usize] = g.0;
    }

    /// Gain `k` of every channel.
    pub fn gains(&self, k: Gain) -> [u16; AXES] {
        self.gains[k as usize]
    }

    /// Keeps filter clock `k` (any value: the manuals give no range).
    pub fn set_filter_clock(&mut self, k: FilterClock, value: u16) {
        self.filters[k as usize] = value;
    }

    /// Sets the LED output of channel `ch` (0..7) on or off.
    pub fn set_led(&mut self, ch: usize, on: bool) {
        let bit = 1u8 << ch;
        if on {
            self.leds |= bit;
        } else {
            self.leds &= !bit;
        }
    }
}

/// Every card's channels and emergency-stop input.
#[derive(Debug, Clone)]
pub struct Machine {
    /// Channels per card.
    pub cards: Vec<[Channel; AXES]>,
    /// Emergency-stop input per card (true: pressed).
    pub emergency: Vec<bool>,
    /// Per-card settings.
    pub settings: Vec<CardSettings>,
    /// Per-card encoder compare, latch, index, local-input and trigger-out state.
    pub triggers: Vec<triggers::CardTriggers>,
    /// Some channel's pulse speed or acceleration limit is below the default.
    pub pulse_limits_set: bool,
    /// Some channel compensates ([`Machine::apply_compensation`]).
    compensating: bool,
    /// The steps channels defer, while some may ([`deferred`]).
    deferred: Option<deferred::DeferredSteps>,
    /// The channels known to record their deferred steps ([`deferred::Recording`]).
    recording: deferred::Recording,
}

/// Which pulse limit of the channels (user manual §2.7.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PulseLimit {
    /// Most pulses per interpolation period (`MCC_SetMaxPulseSpeed`).
    Speed,
    /// Most change of pulses from one period to the next (`MCC_SetMaxPulseAcc`).
    Acc,
}

impl Machine {
    /// Sets limit `kind` of every channel of card `cd` (each 1..=[`MAX_PULSE_LIMIT`],
    /// checked by the caller) and notes whether any channel's limit is now below the
    /// default, so that the engine checks them.
    pub fn set_pulse_limits(&mut self, cd: usize, kind: PulseLimit, v: [i32; AXES]) {
        for (ch, x) in self.cards[cd].iter_mut().zip(v) {
            match kind {
                PulseLimit::Speed => ch.max_speed = x,
                PulseLimit::Acc => ch.max_acc = x,
            }
        }
        self.pulse_limits_set = self
            .cards
            .iter()
            .flatten()
            .any(|c| c.max_speed < DEFAULT_PULSE_LIMIT || c.max_acc < DEFAULT_PULSE_LIMIT);
    }

    /// Limit `kind` of every channel of card `cd`.
    pub fn pulse_limits(&self, cd: usize, kind: PulseLimit) -> [i32; AXES] {
        std::array::from_fn(|ch| match kind {
            PulseLimit::Speed => self.cards[cd][ch].max_speed,
            PulseLimit::Acc => self.cards[cd][ch].max_acc,
        })
    }

    /// What LED `ch` of card `cd` shows: its trigger-out value while a trigger holds it,
    /// else what `MCC_SetLedLightOn`/`Off` set.
    pub fn led_lit(&self, cd: usize, ch: usize) -> bool {
        let own = self.settings.get(cd).is_some_and(|s| s.leds >> ch & 1 == 1);
        self.triggers
            .get(cd)
            .and_then(|t| t.led_trig_level.get(ch).copied().flatten())
            .unwrap_or(own)
    }

    /// `MCC_UpdateCompParam`: every channel with a compensation table set in `comp`
    /// (per card, per channel) takes it; the others keep theirs.
    pub fn apply_compensation(&mut self, comp: &[[Option<SYS_COMP_PARAM>; AXES]]) {
        for (chans, tables) in self.cards.iter_mut().zip(comp) {
            for (chan, p) in chans.iter_mut().zip(tables) {
                if let Some(p) = p {
                    chan.set_compensation(p);
                }
            }
        }
        self.compensating = self.cards.iter().flatten().any(|c| c.comp.active());
    }

    /// Whether a channel compensates (`MCC_UpdateCompParam`).
    pub fn compensating(&self) -> bool {
        self.compensating
    }

    /// The servo-on output of channel `ch` of card `cd` (`servo_on`: the card's servo-on
    /// bits, bit n channel n): while a trigger-out holds the point, its trigger value
    /// (1 = servo off) overrides it.
    pub fn servo_output(&self, cd: usize, ch: usize, servo_on: u32) -> bool {
        match self
            .triggers
            .get(cd)
            .and_then(|t| t.trig_level.get(ch).copied().flatten())
        {
            Some(off) => !off,
            None => servo_on >> ch & 1 == 1,
        }
    }

    /// A machine for `n` cards from the parameters in effect and the specs.
    pub fn new(
        mac: &crate::config::MacTable,
        enc: &[[SYS_ENCODER_CONFIG; AXES]; crate::config::CARDS],
        specs: impl Fn(usize, usize) -> ChannelSpec,
        emergency: impl Fn(usize) -> bool,
        n: usize,
    ) -> Machine {
        Machine {
            cards: (0..n)
                .map(|c| {
                    std::array::from_fn(|ch| Channel::new(specs(c, ch), mac[c][ch], enc[c][ch]))
                })
                .collect(),
            emergency: (0..n).map(emergency).collect(),
            settings: vec![CardSettings::default(); n],
            triggers: vec![triggers::CardTriggers::default(); n],
            pulse_limits_set: false,
            compensating: false,
            deferred: None,
            recording: deferred::Recording::default(),
        }
    }

    /// Channel `ch` of card `card`.
    pub fn channel(&self, card: usize, ch: usize) -> Option<&Channel> {
        self.cards.get(card).and_then(|c| c.get(ch))
    }

    /// Channel `ch` of card `card`.
    pub fn channel_mut(&mut self, card: usize, ch: usize) -> Option<&mut Channel> {
        self.cards.get_mut(card).and_then(|c| c.get_mut(ch))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::{default_encoder_config, default_mac_param};

    fn ch(spec: ChannelSpec) -> Channel {
        Channel::new(spec, default_mac_param(), default_encoder_config())
    }

    /// What a step shows: the fields `step` writes, and the readings derived from them.
    fn shown(
        c: &Channel,
    ) -> (
        i64,
        i64,
        i64,
        f64,
        SensorLevels,
        SensorLevels,
        (i64, i64),
        u32,
    ) {
        (
            c.cmd,
            c.out,
            c.encoder(),
            c.actual,
            c.levels,
            c.prev_levels,
            c.pulse_rate(),
            c.index_events,
        )
    }

    #[test]
    fn a_channel_at_rest_skips_steps_that_would_change_nothing() {
        // Two channels with a 10 ms lag, one stepped through `step_commanded` (which skips
        // steps at rest), one always through `step`: a move of 1000 pulses, then the
        // command held while the motor closes in (by e^(-1 ms / 10 ms) a step, until
        // the floating-point iteration stands still a few ULP of 1000 short, after some
        // hundreds of steps), then held at rest. Every step shows the same on both, and
        // the steps from the first at rest on are skipped.
        let spec = ChannelSpec {
            lag_s: Some(0.01),
            ..ChannelSpec::default()
        };
        let (mut a, mut b) = (ch(spec), ch(spec));
        let mut first_rest = None;
        for n in 0..3000 {
            let cmd = if n < 10 { 100 * (n + 1) } else { 1000 };
            a.command(cmd);
            a.step_commanded(0.001);
            b.step(cmd, 0.001);
            assert_eq!(shown(&a), shown(&b), "step {n}");
            if a.resting && first_rest.is_none() {
                first_rest = Some(n);
            }
        }
        let n = first_rest.unwrap_or_else(|| {
            panic!(
                "the motor comes to rest: {:?} {:?} {} {}",
                shown(&a),
                a.last_move,
                a.prev_out,
                a.prev_delta
            )
        });
        assert!(n > 300 && n < 3000, "{n}");
        assert!((a.actual - 1000.0).abs() < 1e-9, "{}", a.actual);
    }

    #[test]
    fn the_ideal_step_writes_what_the_general_step_writes() {
        // Two copies of an ideal channel (dwPPR 4: an index pulse every 4 counts), one
        // stepped by `step` (which takes the ideal path), one by `step_general`, through
        // moves up and down across index pulses, a stop, a standstill, a counter restart
        // and a wiring change that turns the − limit input active with nothing hit (NC on
        // an open contact, so the levels change between steps without a sensor placed).
        // Every field is the same after every step (`Debug` prints them all).
        let mac = SYS_MAC_PARAM {
            dwPPR: 4,
            ..default_mac_param()
        };
        let mut a = Channel::new(ChannelSpec::default(), mac, default_encoder_config());
        assert!(a.ideal, "no lag, no compensation, no sensor");
        let mut b = a.clone();
        let cmds = [0, 3, 9, 17, 17, 17, 5, -7, -7, -7, 1_000_001, 1_000_001, 2];
        for (n, &cmd) in cmds.iter().enumerate() {
            if n == 8 {
                a.rezero();
                b.rezero();
            }
            if n == 11 {
                let nc = SYS_MAC_PARAM {
                    wOverTravelDownSensorMode: c::SL_NORMAL_CLOSE,
                    ..mac
                };
                a.set_params(nc, default_encoder_config());
                b.set_params(nc, default_encoder_config());
            }
            a.step(cmd, 0.001);
            b.step_general(cmd, 0.001);
            assert_eq!(format!("{a:?}"), format!("{b:?}"), "step {n}");
            if n == 11 {
                assert!(
                    a.levels().minus && !a.prev_levels().minus,
                    "the wiring edge"
                );
            }
        }
        // The restart at -7 put counter 0 at machine count -7: the last move, down from
        // counter 1,000,001 to 2 (machine -5), passed the machine's pulse at -4 last,
        // counter 3.
        assert_eq!(a.last_index_count, Some(3));
    }

    #[test]
    fn ideal_follows_what_a_step_depends_on() {
        // Each change that makes a step do more than the ideal path clears `ideal`, and
        // its undoing sets it again.
        let mut c = ch(ChannelSpec::default());
        assert!(c.ideal);
        c.set_plant_lag(Some(0.01));
        assert!(!c.ideal, "a lagging plant");
        c.set_plant_lag(None);
        assert!(c.ideal);
        c.force(Sensor::Home, Some(true));
        assert!(!c.ideal, "a forced sensor");
        c.force(Sensor::Home, None);
        assert!(c.ideal);
        c.place(Sensor::LimitPlus, 5.0, 5.0);
        assert!(!c.ideal, "a placed sensor");
        let mut d = ch(ChannelSpec::default());
        let mut comp = compensation::off();
        comp.dwInterval = 100;
        d.set_compensation(&comp);
        assert!(!d.ideal, "compensation");
        d.set_compensation(&compensation::off());
        assert!(d.ideal);
    }

    #[test]
    fn a_sensor_forced_at_rest_shows_as_one_edge() {
        // At rest at 0, the home sensor forced active between steps: the next step shows the
        // edge (previous level low, level high), the one after shows no edge.
        let mut c = ch(ChannelSpec::default());
        for _ in 0..3 {
            c.step_commanded(0.001);
        }
        assert!(c.resting);
        c.force(Sensor::Home, Some(true));
        c.step_commanded(0.001);
        assert!(!c.prev_levels().home && c.levels().home);
        c.step_commanded(0.001);
        assert!(
            c.prev_levels().home && c.levels().home,
            "the edge shows once"
        );
    }

    #[test]
    fn new_mechanism_parameters_count_index_pulses_on_the_new_grid() {
        // dwPPR 500: index pulses at counts 0, 500, ...; a motor at 10 sits in [0, 500).
        let mut c = ch(ChannelSpec::default());
        c.step(10, 0.001);
        assert_eq!(c.index_events, 0);
        // dwPPR 4: index pulses at 0, 4, 8, 12, ...; 10 -> 13 passes the one at 12. The
        // interval cached on the old grid, [0, 500), holds both ends and must not be used.
        let mac = SYS_MAC_PARAM {
            dwPPR: 4,
            ..default_mac_param()
        };
        c.set_params(mac, default_encoder_config());
        c.step(13, 0.001);
        assert_eq!(c.index_events, 1);
        assert_eq!(c.last_index_count, Some(12));
    }

    #[test]
    fn a_motor_standing_still_passes_no_index_pulse_on_a_new_grid() {
        // dwPPR 500, phase 100: 0 -> 600 passes the index pulses at 100 and 600.
        let mut c = ch(ChannelSpec {
            index_phase: 100,
            ..Default::default()
        });
        c.step(600, 0.001);
        assert_eq!((c.index_events, c.last_index_count), (2, Some(600)));
        // A new grid drops the cached interval; standing at 600 (a move from 600 to 600)
        // is looked up on the new grid and still passes nothing.
        let mac = SYS_MAC_PARAM {
            dwPPR: 4,
            ..default_mac_param()
        };
        c.set_params(mac, default_encoder_config());
        c.step(600, 0.001);
        assert_eq!((c.index_events, c.last_index_count), (0, Some(600)));
        c.step(600, 0.001);
        assert_eq!(c.index_events, 0);
    }

    #[test]
    fn ideal_encoder_counts_one_per_pulse_at_x4() {
        let mut c = ch(ChannelSpec::default());
        c.step(1234, 0.001);
        assert_eq!(c.encoder(), 1234);
        c.input_rate = Some(2);
        assert_eq!(c.encoder(), 617, "x2: half");
        c.input_rate = Some(1);
        assert_eq!(c.encoder(), 309, "x1: a quarter (1234/4 = 308.5, rounded)");
        c.set_encoder(0);
        assert_eq!(c.encoder(), 0);
        c.step(1234 + 400, 0.001);
        assert_eq!(c.encoder(), 100, "400 pulses at x1");
        assert_eq!(c.position(), 1634.0 / 500.0);
    }

    #[test]
    fn ab_swap_reverses_the_count() {
        let mut e = default_encoder_config();
        e.wABSwap = 1;
        let mut c = Channel::new(ChannelSpec::default(), default_mac_param(), e);
        c.step(100, 0.001);
        assert_eq!(c.encoder(), -100);
    }

    #[test]
    fn lag_plant_follows_exponentially() {
        // tau = 10 ms, dt = 1 ms: after one step the motor covers 1 - e^-0.1 of the way.
        let mut c = ch(ChannelSpec {
            lag_s: Some(0.01),
            ..Default::default()
        });
        c.step(1000, 0.001);
        let expect = 1000.0 * (1.0 - (-0.1f64).exp());
        assert!((c.actual_pulses() - expect).abs() < 1e-9);
        assert_eq!(c.error_count(), (1000.0 - expect).round() as i64);
    }

    #[test]
    fn sensors_and_wiring() {
        let mut m = default_mac_param();
        m.wOverTravelUpSensorMode = c::SL_NORMAL_OPEN;
        m.wOverTravelDownSensorMode = c::SL_NORMAL_CLOSE;
        let spec = ChannelSpec {
            home: Some((-0.5, 0.5)),
            limit_plus: Some(10.0),
            limit_minus: Some(-10.0),
            ..Default::default()
        };
        let mut c = Channel::new(spec, m, default_encoder_config());
        assert!(c.levels().home);
        assert!(!c.levels().plus);
        assert!(
            c.levels().minus,
            "NC setting on a normally-open switch reads active"
        );
        c.step(10 * 500, 0.001); // 10 UU
        assert!(c.levels().plus && !c.levels().home);
        assert!(c.latched[0]);
        c.step(0, 0.001);
        assert!(!c.levels().plus && c.latched[0], "latched until cleared");
        c.force(Sensor::LimitPlus, Some(true));
        assert!(c.levels().plus);
        c.force(Sensor::LimitPlus, None);
        assert!(!c.levels().plus);
        assert!(c.home_level(c::SL_NORMAL_OPEN) && !c.home_level(c::SL_NORMAL_CLOSE));
    }

    #[test]
    fn floor_i64_is_floor_as_i64() {
        let xs = [
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            -1.5,
            2.5e-300,
            -2.5e-300,
            4503599627370495.5,
            -4503599627370495.5,
            9007199254740993.0,
            -9007199254740993.0,
            9.223372036854775e18,
            -9.223372036854775e18,
            9.3e18,
            -9.3e18,
            1e300,
            -1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
        ];
        for x in xs {
            assert_eq!(floor_i64(x), x.floor() as i64, "{x:e}");
            assert_eq!(floor_i64(x + 0.25), (x + 0.25).floor() as i64, "{x:e}");
            assert_eq!(floor_i64(x - 0.25), (x - 0.25).floor() as i64, "{x:e}");
        }
    }

    #[test]
    fn index_interval_matches_the_division() {
        let mut c = ch(ChannelSpec::default());
        // A pseudo-random walk with small, fractional and large steps, several grids.
        let mut x: f64 = 0.0;
        let mut seed: u64 = 12345;
        for n in 0..40_000 {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let step = match n % 7 {
                0 => ((seed >> 40) as i64 - (1 << 23)) as f64,
                1 => ((seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 3.0,
                _ => ((seed >> 58) as i64 - 32) as f64,
            };
            x += step;
            let (spacing, phase) = match n / 10_000 {
                0 => (500, 0),
                1 => (500, 100),
                2 => (1, 0),
                _ => (4096, 7),
            };
            c.set_grid((spacing, phase));
            assert_eq!(
                c.index_interval(x),
                (x.floor() as i64 - phase).div_euclid(spacing),
                "x {x}, spacing {spacing}, phase {phase}"
            );
        }
        for x in [
            -9.2e18,
            4503599627370496.0,
            -4503599627370497.0,
            9.2e18,
            f64::NAN,
            7.5,
            8.0,
            -0.5,
            f64::INFINITY,
            499.999,
            500.0,
        ] {
            c.set_grid((500, 3));
            for _ in 0..2 {
                assert_eq!(
                    c.index_interval(x),
                    (x.floor() as i64 - 3).div_euclid(500),
                    "{x}"
                );
            }
        }
    }

    #[test]
    fn index_pulses_every_turn() {
        // dwPPR 500: an index every 500 counts, phase 100: at 100, 600, 1100, ...
        let mut c = ch(ChannelSpec {
            index_phase: 100,
            ..Default::default()
        });
        c.step(99, 0.001);
        assert_eq!(c.index_events, 0);
        c.step(100, 0.001);
        assert_eq!(c.index_events, 1);
        assert_eq!(c.last_index_count, Some(100));
        c.step(1200, 0.001);
        assert_eq!(c.index_events, 2);
        assert_eq!(c.last_index_count, Some(1100));
        c.step(50, 0.001); // down past 1100, 600 and 100
        assert_eq!(c.index_events, 3);
        assert_eq!(c.last_index_count, Some(100));
    }
}
