//! One motion group on the virtual card: its settings, its bounded command queue, and the
//! execution of queued commands tick by tick (user manual §2.3, §2.6).
//!
//! Execution model. Every running command has its own time τ. Each tick advances τ by
//! ∫ rate dt, where `rate` is the group's time scale: the override ratio (1.0 = 100 %), 0
//! while held or after an abort. Rate changes ramp linearly ([`RateRamp`]) so speed
//! changes smoothly and position never jumps. The command position is
//! `base + Σ (command.sample(τ) − command.start)` over the running commands; with
//! blending on, the next general motion starts when the running one begins to
//! decelerate, so two commands run at once and their displacements add (docs/decisions.md).
//! A command that ends inside a tick hands the rest of the tick to the next one, so
//! consecutive commands keep exact timing. Whenever the last running command ends, the
//! position becomes its exact planned end: nothing accumulates over millions of moves.

use super::command::{AxisMech, Command, Ctx, Output, Plan, Settings};
use super::snapshot::{round_pulses, GroupSnapshot, Info, Motion};
use crate::config::{GroupDef, AXES};
use crate::error::{McclError, McclResult};
use crate::planner::{Axes, RateRamp};
use crate::vendor::consts as c;
use crate::vendor::COMMAND_INFO;
use std::collections::VecDeque;

pub mod external;
use external::{ExternalExecutor, Host};

/// Commands a queue grows by at least when it is full (doubling from there on).
const QUEUE_MIN_GROWTH: usize = 16;

/// Error record of software over-travel, + axis (docs/vendor-interface.md).
pub const ERR_OVER_TRAVEL: i32 = crate::error_record::ErrorRecord::OverTravel(0).code();

/// A command whose own time is within this of its end has ended (1 ns: far below a tick,
/// far above the rounding of summing millions of ticks).
pub const TIME_EPS: f64 = 1e-9;

/// Converts between real time within a tick and a command's own time: general and PtP
/// motion run at the group's rate, delays in real time (paused while held).
#[derive(Debug, Clone, Copy)]
struct TickClock {
    dt: f64,
    dtau: f64,
    delay_dt: f64,
}

impl TickClock {
    fn per_tick(&self, cmd: &Command) -> f64 {
        if matches!(cmd.plan, Plan::Delay(_)) {
            self.delay_dt
        } else {
            self.dtau
        }
    }

    /// `real` seconds of this tick, in `cmd`'s own time.
    fn own_time(&self, real: f64, cmd: &Command) -> f64 {
        if self.dt > 0.0 {
            real / self.dt * self.per_tick(cmd)
        } else {
            0.0
        }
    }

    /// `own` time of `cmd` within this tick, in real seconds.
    fn real_time(&self, own: f64, cmd: &Command) -> f64 {
        let per = self.per_tick(cmd);
        if per > 0.0 {
            (own / per * self.dt).min(self.dt)
        } else {
            0.0
        }
    }
}

/// A command being executed and its own time.
#[derive(Debug, Clone)]
struct Running {
    cmd: Command,
    tau: f64,
}

/// What the group is doing besides running commands.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Mode {
    /// Running normally.
    Normal,
    /// `MCC_HoldMotion`: decelerating to, or standing at, rate 0.
    Held,
    /// `MCC_HoldMotion(g, TRUE)`: stop when the running command ends.
    HoldAtBlockEnd,
    /// `MCC_AbortMotionEx(t)`: ramping to rate 0; then everything is dropped.
    Aborting,
}

/// A rate change in progress.
#[derive(Debug, Clone, Copy)]
struct Ramp {
    ramp: RateRamp,
    elapsed: f64,
}

/// A group as the card runs it.
#[derive(Debug)]
pub struct GroupState {
    /// Group index (0..95).
    pub index: usize,
    /// The mapping and queue size the group runs with.
    pub def: GroupDef,
    /// Mechanism facts per axis (from the parameters in effect).
    pub axes: [AxisMech; AXES],
    /// Settings that queued commands capture.
    pub settings: Settings,
    /// Blending as the end of the queue will see it (`MCC_CheckBlend`).
    pub blend_queued: bool,
    /// Override ratio, percent.
    pub override_pct: f64,
    /// `MCC_FixSpeed(TRUE)`: the override does not change speeds.
    pub fixed_speed: bool,
    queue: VecDeque<Command>,
    /// End of the last queued command (user coordinates).
    queue_end: Axes,
    running: VecDeque<Running>,
    /// Position of everything finished (user coordinates).
    base: Axes,
    /// Current command position (user coordinates).
    pos: Axes,
    /// Reference position = user position + offset (MCC_DefinePos moves the offset).
    offset: Axes,
    vel: Axes,
    rate: f64,
    ramp: Option<Ramp>,
    /// Override to apply when the next command starts (`MCC_OverrideSpeedEx(r, FALSE)`).
    pending_override: Option<f64>,
    mode: Mode,
    single_block: bool,
    single_block_credit: bool,
    /// Blending as the engine has reached it in the queue.
    blend_on: bool,
    /// In-position check axes enabled by queued markers (used by the in-position check).
    pub inpos_mask: u32,
    error: i32,
    next_index: i32,
    auto_index: bool,
    ld_index: i32,
    last_started: Option<(i32, i32)>,
    status: i32,
    published_info: Option<Info>,
    /// Software over-travel check per axis (`MCC_SetOverTravelCheck`).
    pub ot_check: [bool; AXES],
    /// Tracking error check per axis (`MCC_EnableTrackError` mask).
    pub track_mask: u32,
    /// Tracking error limit per axis, UU (`MCC_SetTrackErrorLimit`).
    pub track_limit: Axes,
    /// In-position settings (`MCC_SetInPos*`).
    pub inpos: InPosSettings,
    /// In-position check of the last command, while it runs.
    inpos_wait: Option<InPosWait>,
    /// `MCC_GetInPosStatus`: 0xFF per axis once in position, until the next command.
    inpos_status: [u8; AXES],
    /// Output changes the queue reached this tick (the engine makes them).
    outputs: Vec<Output>,
    /// Set when the group's commands run outside the card (an MC3B: `external`).
    external: Option<Box<dyn ExternalExecutor>>,
    /// Axes whose channels are being homed (`MCC_Home`), one bit each: the homing drives
    /// their positions and the group takes no command meanwhile.
    homing: u32,
    /// Events for the trace's events file, `Some` only while tracing (`MCCL_TRACE`).
    pub trace_notes: Option<Vec<super::trace::Note>>,
}

/// In-position settings of a group (user manual §2.7.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InPosSettings {
    /// `IPM_*` mode.
    pub mode: u16,
    /// Maximum check time, s.
    pub max_check_s: f64,
    /// Settle time, s (the `IPM_SETTLE_*` modes).
    pub settle_s: f64,
    /// Tolerance per axis, UU.
    pub tolerance: Axes,
}

/// Maximum check time before it is set (ms; the examples manual uses 1000).
pub const DEFAULT_INPOS_CHECK_MS: f64 = 1000.0;

impl Default for InPosSettings {
    fn default() -> Self {
        InPosSettings {
            mode: c::IPM_ONETIME_BLOCK,
            max_check_s: DEFAULT_INPOS_CHECK_MS / 1000.0,
            settle_s: 0.0,
            tolerance: [0.0; AXES],
        }
    }
}

/// An in-position check in progress.
#[derive(Debug, Clone, Copy, PartialEq)]
struct InPosWait {
    mask: u32,
    elapsed: f64,
    settled: f64,
    settings: InPosSettings,
}

impl InPosWait {
    /// Every mode waits for the check; the `BLOCK` modes also stop the queue (with an
    /// error record) when it fails, the `UNBLOCK` modes then go on.
    fn blocks(&self) -> bool {
        true
    }

    fn fails_with_error(&self) -> bool {
        matches!(
            self.settings.mode,
            c::IPM_ONETIME_BLOCK | c::IPM_SETTLE_BLOCK
        )
    }
}

/// Error record of a failed in-position check (docs/vendor-interface.md).
pub const ERR_IN_POSITION: i32 = crate::error_record::ErrorRecord::InPosition.code();

impl GroupState {
    /// A stopped group at position 0.
    pub fn new(index: usize, def: GroupDef, axes: [AxisMech; AXES]) -> GroupState {
        GroupState {
            index,
            def,
            axes,
            settings: Settings::default(),
            blend_queued: false,
            override_pct: 100.0,
            fixed_speed: false,
            // Grows as it fills (`enqueue` reserves fallibly): reserving the queue size up
            // front (464 bytes a command) asked 44.5 GB for 96 queues of 1,000,000 and
            // aborted the program under a memory limit.
            queue: VecDeque::new(),
            queue_end: [0.0; AXES],
            running: VecDeque::new(),
            base: [0.0; AXES],
            pos: [0.0; AXES],
            offset: [0.0; AXES],
            vel: [0.0; AXES],
            rate: 1.0,
            ramp: None,
            pending_override: None,
            mode: Mode::Normal,
            single_block: false,
            single_block_credit: false,
            blend_on: false,
            inpos_mask: 0,
            error: 0,
            next_index: 0,
            auto_index: true,
            ld_index: 0,
            last_started: None,
            status: c::GMS_STOP,
            published_info: None,
            ot_check: [false; AXES],
            track_mask: 0,
            track_limit: [f64::INFINITY; AXES],
            inpos: InPosSettings::default(),
            inpos_wait: None,
            inpos_status: [0; AXES],
            outputs: Vec::new(),
            external: None,
            homing: 0,
            trace_notes: None,
        }
    }

    /// Axes being homed, one bit each.
    pub fn homing(&self) -> u32 {
        self.homing
    }

    /// `MCC_Home` on the simulated machine starts on the channels of axes `mask`: the
    /// group must be idle. A group on an MC3B homes on the device (`begin_external_home`).
    pub fn begin_homing(&mut self, mask: u32) -> McclResult<()> {
        if self.external.is_some() {
            return Err(McclError::NotAccepted);
        }
        if self.busy() {
            return Err(McclError::NotFinished);
        }
        self.homing = mask;
        self.update_status();
        Ok(())
    }

    /// Homing moved axis `i` to reference position `x` (UU) at speed `v` (UU/s).
    pub fn set_homing_axis(&mut self, i: usize, x: f64, v: f64) {
        let p = x - self.offset[i];
        self.pos[i] = p;
        self.base[i] = p;
        self.queue_end[i] = p;
        self.vel[i] = v;
    }

    /// Axis `i` reached its working home: its position, reference and pulses read 0.
    pub fn home_zero_axis(&mut self, i: usize) {
        self.offset[i] = 0.0;
        self.set_homing_axis(i, 0.0, 0.0);
    }

    /// The homing ended (done, aborted or failed): the group is its own again.
    pub fn end_homing(&mut self) {
        self.homing = 0;
        self.vel = [0.0; AXES];
        self.update_status();
    }

    /// Whether a check that needs the machine watches this group even when it stands.
    pub fn has_safety_checks(&self) -> bool {
        self.track_mask != 0 || self.inpos_wait.is_some()
    }

    /// Velocity per axis (UU/s).
    pub fn vel(&self) -> Axes {
        self.vel
    }

    /// Stops at once because a check tripped, dropping the queue; records `record`.
    pub fn stop_for(&mut self, record: Option<i32>) {
        self.stop_here();
        if let Some(code) = record {
            self.set_error(code);
        }
        self.update_status();
    }

    /// Back to the state right after init (`MCC_ResetMotion`, `MCC_UpdateParam`).
    pub fn reset(&mut self, axes: [AxisMech; AXES]) {
        let external = self.external.take();
        let notes = self.trace_notes.take();
        *self = GroupState::new(self.index, self.def, axes);
        self.trace_notes = notes;
        // An MC3B group stays on its device, rezeroed.
        if let Some(mut x) = external {
            x.rezero();
            self.external = Some(x);
            self.external_positions();
        }
    }

    /// The planning context: settings, axes and the end of the queue.
    pub fn ctx(&self) -> Ctx<'_> {
        Ctx {
            settings: &self.settings,
            axes: &self.axes,
            from: self.queue_end,
            offset: self.offset,
        }
    }

    /// Motion status (`GMS_*`).
    pub fn status(&self) -> i32 {
        self.status
    }

    /// Records an event for the trace (nothing but this check when not tracing).
    #[inline]
    fn note(&mut self, n: super::trace::Note) {
        if let Some(v) = self.trace_notes.as_mut() {
            v.push(n);
        }
    }

    /// Notes the running commands as cut short (they are about to be dropped).
    fn note_stopped(&mut self) {
        if let Some(v) = self.trace_notes.as_mut() {
            for r in &self.running {
                v.push(super::trace::Note::End {
                    index: r.cmd.index,
                    ctype: r.cmd.ctype,
                    stopped: true,
                });
            }
        }
    }

    /// Commands waiting in the queue (not counting those running).
    pub fn queued(&self) -> usize {
        self.queue.len()
    }

    /// Whether the group has anything to do.
    pub fn busy(&self) -> bool {
        self.status != c::GMS_STOP || !self.queue.is_empty()
    }

    /// The error record (0 when none).
    pub fn error(&self) -> i32 {
        self.error
    }

    /// Records an error: the group stops executing commands until `MCC_ClearError`.
    pub fn set_error(&mut self, code: i32) {
        if self.error == 0 {
            self.note(super::trace::Note::ErrorSet(code));
            self.error = code;
        }
    }

    /// `MCC_ClearError`.
    pub fn clear_error(&mut self) {
        if self.error != 0 {
            self.note(super::trace::Note::ErrorCleared(self.error));
        }
        self.error = 0;
        self.update_status();
    }

    /// Queues a command; returns its index. `ABORT_NOT_FINISH_ERR` while an abort is
    /// still decelerating, `COMMAND_BUFFER_FULL_ERR` when the queue is full or the memory
    /// to grow it (doubling, up to the queue size) cannot be had.
    pub fn enqueue(&mut self, mut cmd: Command) -> McclResult<i32> {
        if self.homing != 0 {
            return Err(McclError::NotAccepted);
        }
        if let Some(x) = &self.external {
            x.check(&cmd, &self.axes)?;
        }
        if self.mode == Mode::Aborting {
            return Err(McclError::AbortNotFinished);
        }
        if self.queue.len() >= self.def.queue_size {
            return Err(McclError::BufferFull);
        }
        // Memory the queue cannot get is a full queue: an error code, never an abort.
        if self.queue.len() == self.queue.capacity() {
            let room = self.def.queue_size - self.queue.len();
            let want = self.queue.len().max(QUEUE_MIN_GROWTH).min(room);
            if self.queue.try_reserve_exact(want).is_err() {
                return Err(McclError::BufferFull);
            }
        }
        cmd.index = self.next_index;
        if self.auto_index {
            self.next_index = self.next_index.wrapping_add(1) & 0x7FFF_FFFF;
        }
        match cmd.plan {
            Plan::Blend(on) => self.blend_queued = on,
            _ => self.queue_end = cmd.target,
        }
        crate::fault::point("enqueue");
        let idx = cmd.index;
        self.queue.push_back(cmd);
        self.update_status();
        Ok(idx)
    }

    /// Index management (`MCC_ResetCommandIndex`, `MCC_SetCommandIndex`).
    pub fn set_command_index(&mut self, index: i32, manual: bool) {
        self.next_index = index;
        self.auto_index = !manual;
    }

    /// The index the next queued command gets.
    pub fn next_command_index(&self) -> i32 {
        self.next_index
    }

    /// `MCC_ResetCommandIndexLD`.
    pub fn reset_ld_index(&mut self) {
        self.ld_index = 0;
    }

    /// `MCC_HoldMotion`: `HOLD_ILLEGAL_ERR` when nothing runs or it is already held.
    pub fn hold(&mut self, at_block_end: bool) -> McclResult<()> {
        if !self.busy() || self.mode != Mode::Normal {
            return Err(McclError::HoldIllegal);
        }
        // An MC3B cannot pause a synchronous move and resume it: only at a job's end.
        if self.external.is_some() && !at_block_end {
            return Err(McclError::NotAccepted);
        }
        self.note(super::trace::Note::Hold {
            block_end: at_block_end,
        });
        if at_block_end {
            self.mode = Mode::HoldAtBlockEnd;
        } else {
            self.mode = Mode::Held;
            let t = self.current_dec_s();
            self.ramp_to(0.0, t);
        }
        self.update_status();
        Ok(())
    }

    /// `MCC_ContiMotion`: `CONTI_ILLEGAL_ERR` unless held.
    pub fn conti(&mut self) -> McclResult<()> {
        match self.mode {
            Mode::Held | Mode::HoldAtBlockEnd => {
                self.note(super::trace::Note::Continue);
                self.mode = Mode::Normal;
                let target = self.target_rate();
                let t = self.current_acc_s();
                self.ramp_to(target, t);
                self.update_status();
                Ok(())
            }
            _ => Err(McclError::ContiIllegal),
        }
    }

    /// `MCC_AbortMotionEx(t)`: empties the queue and stops within `dec_s` seconds (at
    /// once when 0, or when already held: then the deceleration is ignored, §2.6.2 IV).
    /// With `at_block_end`, the running command finishes and the queue is dropped.
    pub fn abort(&mut self, dec_s: f64, at_block_end: bool) {
        // The MC3B stops at once (`S`); it has no controlled stop.
        let dec_s = if self.external.is_some() { 0.0 } else { dec_s };
        self.note(super::trace::Note::Abort {
            dec_s,
            block_end: at_block_end,
        });
        self.queue.clear();
        self.pending_override = None;
        if at_block_end {
            self.queue_end = self.running.back().map_or(self.pos, |r| r.cmd.target);
            self.update_status();
            return;
        }
        let held = matches!(self.mode, Mode::Held) && self.rate == 0.0;
        if dec_s <= 0.0 || held || self.running.is_empty() {
            self.stop_here();
        } else {
            self.mode = Mode::Aborting;
            self.ramp_to(0.0, dec_s);
        }
        self.update_status();
    }

    fn stop_here(&mut self) {
        if let Some(x) = self.external.as_mut() {
            x.stop();
        }
        self.inpos_wait = None;
        self.note_stopped();
        self.running.clear();
        self.queue.clear();
        self.base = self.pos;
        self.queue_end = self.pos;
        self.vel = [0.0; AXES];
        self.ramp = None;
        self.mode = Mode::Normal;
        self.rate = self.target_rate();
    }

    /// `MCC_OverrideSpeedEx`: the new ratio applies now (ramped with the acc or dec
    /// time) or when the next command starts.
    pub fn override_speed(&mut self, pct: f64, instant: bool) {
        self.override_pct = pct;
        if instant {
            self.pending_override = None;
            if self.mode == Mode::Normal || self.mode == Mode::HoldAtBlockEnd {
                self.retarget_rate();
            }
        } else {
            self.pending_override = Some(pct);
        }
    }

    /// `MCC_ChangeFeedSpeed`: later general motion uses feed `v`; the running general
    /// motion ramps to it through the override ratio (v / its feed).
    pub fn change_feed_speed(&mut self, v: f64) {
        self.settings.feed = v;
        if self.external.is_some() {
            // A running MC3B job keeps its speed: later commands get the new feed.
            return;
        }
        let running_feed = self.running.back().and_then(|r| match r.cmd.plan {
            Plan::Path(_) => Some(r.cmd.info_feed),
            _ => None,
        });
        if let Some(f) = running_feed {
            if f > 0.0 {
                self.override_speed(100.0 * v / f, true);
                self.pending_override = Some(100.0);
            }
        }
    }

    /// `MCC_FixSpeed`.
    pub fn fix_speed(&mut self, fixed: bool) {
        self.fixed_speed = fixed;
        if self.mode == Mode::Normal {
            self.retarget_rate();
        }
    }

    fn retarget_rate(&mut self) {
        let target = self.target_rate();
        let t = if target >= self.rate {
            self.current_acc_s()
        } else {
            self.current_dec_s()
        };
        self.ramp_to(target, t);
    }

    /// Single-block mode: after each command the group waits for `MCC_RunSingleBlock`.
    pub fn set_single_block(&mut self, on: bool) {
        self.single_block = on;
        self.single_block_credit = false;
        self.update_status();
    }

    /// `MCC_RunSingleBlock`: lets one more command run.
    pub fn run_single_block(&mut self) -> McclResult<()> {
        if !self.single_block {
            return Err(McclError::NotAccepted);
        }
        self.single_block_credit = true;
        self.update_status();
        Ok(())
    }

    /// `MCC_EnableBlendInstant`: switches blending now, not through the queue.
    pub fn set_blend_now(&mut self, on: bool) {
        self.blend_on = on;
        self.blend_queued = on;
    }

    /// `MCC_DefinePos`: the current position of `axis` becomes `value` (only when stopped;
    /// `value` must be a position of the axis, `config::range::position`).
    pub fn define_pos(&mut self, axis: usize, value: f64) -> McclResult<()> {
        crate::config::range::position(value, self.axes[axis].factor)?;
        if self.busy() {
            return Err(McclError::NotFinished);
        }
        let shift = value - self.pos[axis];
        self.offset[axis] -= shift;
        self.pos[axis] = value;
        self.base[axis] = value;
        self.queue_end[axis] = value;
        Ok(())
    }

    /// The current position (user coordinates).
    pub fn pos(&self) -> Axes {
        self.pos
    }

    /// `MCC_DefinePosHere`: the command position of axis `i` becomes the position the card
    /// has output (its pulse count in UU); only when stopped.
    pub fn sync_to_output(&mut self, i: usize) -> McclResult<()> {
        if self.busy() {
            return Err(McclError::NotFinished);
        }
        let f = self.axes[i].factor;
        if f != 0.0 {
            let here = self.pulses(i) as f64 / f - self.offset[i];
            self.pos[i] = here;
            self.base[i] = here;
            self.queue_end[i] = here;
        }
        Ok(())
    }

    /// The current reference position of axis `i` (user position + offset).
    pub fn ref_pos(&self, i: usize) -> f64 {
        self.pos[i] + self.offset[i]
    }

    /// Time scale the group runs at when not held.
    fn target_rate(&self) -> f64 {
        if self.fixed_speed {
            1.0
        } else {
            self.override_pct / 100.0
        }
    }

    fn current_acc_s(&self) -> f64 {
        self.running
            .back()
            .map_or(self.settings.acc_ms, |r| r.cmd.acc_ms)
            / 1000.0
    }

    fn current_dec_s(&self) -> f64 {
        self.running
            .back()
            .map_or(self.settings.dec_ms, |r| r.cmd.dec_ms)
            / 1000.0
    }

    fn ramp_to(&mut self, target: f64, secs: f64) {
        // With nothing moving there is no speed to smooth: the new rate holds at once.
        if secs <= 0.0 || (target - self.rate).abs() < 1e-15 || self.running.is_empty() {
            self.rate = target;
            self.ramp = None;
        } else {
            self.ramp = Some(Ramp {
                ramp: RateRamp::new(self.rate, target, secs),
                elapsed: 0.0,
            });
        }
    }

    /// Advances the rate by `dt`; returns ∫ rate dt over the tick.
    fn advance_rate(&mut self, dt: f64) -> f64 {
        match &mut self.ramp {
            None => self.rate * dt,
            Some(r) => {
                let d = r.ramp.integral(r.elapsed, r.elapsed + dt);
                r.elapsed += dt;
                self.rate = r.ramp.rate(r.elapsed);
                if r.ramp.done(r.elapsed) {
                    self.rate = r.ramp.to_rate();
                    self.ramp = None;
                }
                d
            }
        }
    }

    /// Whether a new command may start now.
    fn may_start(&self) -> bool {
        self.error == 0
            && matches!(self.mode, Mode::Normal)
            && (!self.single_block || self.single_block_credit)
            && !self.inpos_wait.is_some_and(|w| w.blocks())
    }

    /// Whether an in-position check is running (the engine feeds it the machine).
    pub fn inpos_waiting(&self) -> bool {
        self.inpos_wait.is_some()
    }

    /// The in-position mask of the check running.
    pub fn inpos_mask_waiting(&self) -> u32 {
        self.inpos_wait.map_or(0, |w| w.mask)
    }

    /// Output changes the queue reached since the last call.
    pub fn take_outputs(&mut self) -> Vec<Output> {
        std::mem::take(&mut self.outputs)
    }

    /// Whether the queue reached output changes since the last [`GroupState::take_outputs`].
    pub fn has_outputs(&self) -> bool {
        !self.outputs.is_empty()
    }

    /// `MCC_GetInPosStatus`.
    pub fn inpos_status(&self) -> [u8; AXES] {
        self.inpos_status
    }

    /// One tick of the in-position check (user manual §2.7.2): `errs[i]` is the position
    /// error of axis `i` (UU, motor against command) for the axes in the check. In
    /// position: every axis within its tolerance (and, in the settle modes, for the
    /// settle time): status 0xFF, the next command may run. Not in position within the
    /// maximum check time: the `BLOCK` modes record 0xF501 and drop the rest of the queue;
    /// the `UNBLOCK` modes let the queue go on without a record.
    pub fn check_inpos(&mut self, errs: &[Option<f64>; AXES], dt: f64) {
        let Some(mut w) = self.inpos_wait else {
            return;
        };
        w.elapsed += dt;
        let within = (0..AXES).all(|i| {
            w.mask & (1 << i) == 0 || errs[i].is_none_or(|e| e.abs() <= w.settings.tolerance[i])
        });
        let settle = matches!(w.settings.mode, c::IPM_SETTLE_BLOCK | c::IPM_SETTLE_UNBLOCK);
        if within {
            w.settled += dt;
        } else {
            w.settled = 0.0;
        }
        let done = within && (!settle || w.settled >= w.settings.settle_s - TIME_EPS);
        if done {
            for i in 0..AXES {
                if w.mask & (1 << i) != 0 {
                    self.inpos_status[i] = 0xFF;
                }
            }
            self.note(super::trace::Note::InPosDone(w.mask));
            self.inpos_wait = None;
        } else if w.elapsed >= w.settings.max_check_s - TIME_EPS {
            self.note(super::trace::Note::InPosFail {
                mask: w.mask,
                error: w.fails_with_error(),
            });
            self.inpos_wait = None;
            if w.fails_with_error() {
                self.stop_here();
                self.set_error(ERR_IN_POSITION);
            }
        } else {
            self.inpos_wait = Some(w);
        }
        self.update_status();
    }

    /// Pops queued switches that are now reached; returns the next motion/delay command.
    fn pop_next(&mut self) -> Option<Command> {
        while let Some(front) = self.queue.front() {
            match front.plan {
                Plan::Blend(on) => {
                    self.blend_on = on;
                    self.queue.pop_front();
                }
                Plan::InPos(on, mask) => {
                    if on {
                        self.inpos_mask |= mask;
                    } else {
                        self.inpos_mask &= !mask;
                    }
                    self.queue.pop_front();
                }
                Plan::Output(o) => {
                    self.outputs.push(o);
                    self.queue.pop_front();
                }
                _ => return self.queue.pop_front(),
            }
        }
        None
    }

    fn start(&mut self, cmd: Command, tau: f64) {
        if cmd.is_motion() {
            self.inpos_status = [0; AXES];
        }
        if let Some(p) = self.pending_override.take() {
            self.override_pct = p;
            if self.mode == Mode::Normal {
                self.retarget_rate();
            }
        }
        self.ld_index = self.ld_index.wrapping_add(1);
        self.last_started = Some((cmd.index, self.ld_index));
        self.note(super::trace::Note::Start {
            index: cmd.index,
            ctype: cmd.ctype,
        });
        if self.single_block {
            self.single_block_credit = false;
        }
        self.running.push_back(Running { cmd, tau });
    }

    /// Runs this group's commands on `executor` from now on (an MC3B: the system attaches
    /// one to every group of the device's card).
    pub fn attach_external(&mut self, executor: Box<dyn ExternalExecutor>) {
        self.external = Some(executor);
        self.external_positions();
    }

    /// Whether this group's commands run outside the card (on an MC3B).
    pub fn is_external(&self) -> bool {
        self.external.is_some()
    }

    /// Whether the external executor is running (or stopping) a job of this group.
    pub fn external_busy(&self) -> bool {
        self.external.as_ref().is_some_and(|x| x.busy())
    }

    /// `MCC_Home` with `orders` (per channel, 255 skips) and the go-home parameters
    /// `cfgs` on a group whose commands run outside the card: the executor's own go home.
    /// `COMMAND_NOTACCEPTED_ERR` for a group on the card and what the executor cannot
    /// home, then `COMMAND_NOTFINISHED_ERR` unless the group is idle; it takes no motion
    /// command until the homing ends.
    pub fn begin_external_home(
        &mut self,
        orders: &[i32; AXES],
        cfgs: &[crate::vendor::SYS_HOME_CONFIG; AXES],
    ) -> McclResult<()> {
        let busy = self.busy();
        let x = self.external.as_mut().ok_or(McclError::NotAccepted)?;
        let mask = x.start_home(orders, cfgs, &self.axes, busy)?;
        self.homing = mask;
        self.update_status();
        Ok(())
    }

    /// `MCC_AbortGoHome` on the external executor: the job running stops and the homing
    /// ends without completing.
    pub fn abort_external_home(&mut self) {
        if let Some(x) = self.external.as_mut() {
            x.abort_home();
        }
    }

    /// The end of an external go home, once: `HOME_DONE` or `HOME_NONE`.
    pub fn take_home_result(&mut self) -> Option<i32> {
        self.external.as_mut()?.take_home_result()
    }

    /// Positions from the external executor (axes it drives), else from what has finished.
    fn external_positions(&mut self) {
        if let Some(x) = &self.external {
            self.pos = x.positions(self.base, &self.offset, &self.axes);
            self.vel = [0.0; AXES];
        }
    }

    /// One tick of a group on an external executor: the executor runs with the group as its [`Host`]. It is
    /// out of `self.external` meanwhile and back before the status is updated, also when
    /// the tick panics (the engine's recovery then stops the device's job).
    fn tick_external(&mut self, dt: f64) {
        let Some(mut x) = self.external.take() else {
            return;
        };
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| x.tick(self, dt)));
        self.external = Some(x);
        if let Err(p) = r {
            std::panic::resume_unwind(p);
        }
        self.update_status();
    }

    /// One interpolation period of `dt` seconds.
    pub fn tick(&mut self, dt: f64) {
        if self.homing != 0 && self.external.is_none() {
            // The homing sets the positions (`set_homing_axis`).
            self.update_status();
            return;
        }
        if self.external.is_some() {
            return self.tick_external(dt);
        }
        // Software over-travel compares with the position before the tick (only needed,
        // and so only copied, when a check is on).
        let before = (self.ot_check != [false; AXES]).then_some(self.pos);
        let dtau = self.advance_rate(dt);
        let delay_dt = if self.mode == Mode::Held { 0.0 } else { dt };
        let clock = TickClock { dt, dtau, delay_dt };
        if self.running.is_empty() {
            // An idle group starts its next command at the start of the tick.
            if self.may_start() {
                if let Some(cmd) = self.pop_next() {
                    let tau = clock.own_time(dt, &cmd);
                    self.start(cmd, tau);
                }
            }
        } else {
            for r in self.running.iter_mut() {
                r.tau += clock.own_time(dt, &r.cmd);
            }
        }
        self.settle(&clock);
        self.finish_abort();
        self.compute_pos_vel();
        if let Some(before) = before {
            self.check_over_travel(&before);
        }
        self.update_status();
    }

    /// Software over-travel (user manual §2.6.1): with the check on, an axis never goes
    /// further out of its work zone (dfLowLimit..dfHighLimit). A tick that would take it
    /// out stops the group where it was, records 0xF301 + axis, and motion waits for
    /// `MCC_ClearError`; a move back into the zone is allowed.
    fn check_over_travel(&mut self, before: &Axes) {
        for i in 0..AXES {
            if !self.ot_check[i] || self.axes[i].channel.is_none() {
                continue;
            }
            let (p, b) = (self.pos[i], before[i]);
            let out = (p > self.axes[i].high && p > b) || (p < self.axes[i].low && p < b);
            if out {
                self.pos = *before;
                self.stop_here();
                self.set_error(ERR_OVER_TRAVEL + i as i32);
                return;
            }
        }
    }

    /// After the running commands advanced: blends in the next command, retires finished
    /// commands and hands the rest of the tick to their successors.
    fn settle(&mut self, clock: &TickClock) {
        // Bounded: each pass starts or retires one command.
        for _ in 0..(self.queue.len() + self.running.len() + 2) * 2 {
            if self.try_blend() {
                continue;
            }
            let Some(first) = self.running.front() else {
                return;
            };
            let dur = first.cmd.duration();
            if first.tau < dur - TIME_EPS {
                return;
            }
            let spare = clock.real_time((first.tau - dur).max(0.0), &first.cmd);
            let Some(done) = self.running.pop_front() else {
                return;
            };
            self.note(super::trace::Note::End {
                index: done.cmd.index,
                ctype: done.cmd.ctype,
                stopped: false,
            });
            if self.running.is_empty() {
                self.base = done.cmd.target;
                if done.cmd.is_motion() && self.inpos_mask != 0 {
                    self.note(super::trace::Note::InPosBegin(self.inpos_mask));
                    self.inpos_wait = Some(InPosWait {
                        mask: self.inpos_mask,
                        elapsed: 0.0,
                        settled: 0.0,
                        settings: self.inpos,
                    });
                    if self.inpos_wait.is_some_and(|w| w.blocks()) {
                        return;
                    }
                }
            } else {
                let s = done.cmd.start();
                for ((b, t), s) in self.base.iter_mut().zip(done.cmd.target).zip(s) {
                    *b += t - s;
                }
                continue;
            }
            if self.mode == Mode::HoldAtBlockEnd {
                self.mode = Mode::Held;
                self.rate = 0.0;
                self.ramp = None;
                return;
            }
            if !self.may_start() {
                return;
            }
            let Some(next) = self.pop_next() else {
                return;
            };
            let tau = clock.own_time(spare, &next);
            self.start(next, tau);
        }
    }

    /// Blending: when the newest general motion has reached its deceleration and the next
    /// queued motion is general too, starts it (docs/decisions.md). Returns whether it did.
    fn try_blend(&mut self) -> bool {
        if !self.blend_on || !self.may_start() {
            return false;
        }
        let Some(last) = self.running.back() else {
            return false;
        };
        let Plan::Path(m) = &last.cmd.plan else {
            return false;
        };
        let ds = m.decel_start();
        if last.tau < ds - TIME_EPS || last.tau >= m.duration() - TIME_EPS || m.duration() <= 0.0 {
            return false;
        }
        let over = (last.tau - ds).max(0.0);
        if !matches!(self.peek_motion(), Some(Plan::Path(_))) {
            return false;
        }
        match self.pop_next() {
            Some(next) => {
                self.start(next, over);
                true
            }
            None => false,
        }
    }

    /// The next queued motion/delay command's plan, looking past queued switches.
    fn peek_motion(&self) -> Option<&Plan> {
        self.queue
            .iter()
            .map(|c| &c.plan)
            .find(|p| !matches!(p, Plan::Blend(_) | Plan::InPos(..) | Plan::Output(_)))
    }

    fn finish_abort(&mut self) {
        if self.mode == Mode::Aborting && self.ramp.is_none() && self.rate == 0.0 {
            self.compute_pos_vel();
            self.stop_here();
        }
    }

    fn compute_pos_vel(&mut self) {
        if self.running.len() == 1 {
            // The usual case, without the sums (the same operations as below).
            let r = &self.running[0];
            let (mut p, mut v) = ([0.0; AXES], [0.0; AXES]);
            r.cmd.sample_into(r.tau, &mut p, &mut v);
            let s = r.cmd.start();
            let scale = if matches!(r.cmd.plan, Plan::Delay(_)) {
                0.0
            } else {
                self.rate
            };
            // Branch-free, so that both loops vectorize. `0.0 +` as in the sums below
            // (it turns -0.0 into 0.0).
            #[allow(clippy::needless_range_loop)] // indexes four arrays; vectorizes
            for i in 0..AXES {
                let moved = self.base[i] + (p[i] - s[i]);
                self.pos[i] = if self.base[i] == s[i] { p[i] } else { moved };
            }
            for (out, v) in self.vel.iter_mut().zip(v) {
                *out = 0.0 + v * scale;
            }
            return;
        }
        let mut pos = self.base;
        let mut vel = [0.0; AXES];
        let only = self.running.len() == 1;
        for r in &self.running {
            let (p, v) = r.cmd.sample(r.tau);
            let s = r.cmd.start();
            let scale = if matches!(r.cmd.plan, Plan::Delay(_)) {
                0.0
            } else {
                self.rate
            };
            for i in 0..AXES {
                if only && self.base[i] == s[i] {
                    pos[i] = p[i];
                } else {
                    pos[i] += p[i] - s[i];
                }
                vel[i] += v[i] * scale;
            }
        }
        self.pos = pos;
        self.vel = vel;
    }

    fn update_status(&mut self) {
        if self.homing != 0 {
            // Homing axes move (or wait for the others) until the homing ends.
            self.status = c::GMS_RUNNING;
            return;
        }
        let active = !self.running.is_empty()
            || !self.queue.is_empty()
            || self.inpos_wait.is_some_and(|w| w.blocks())
            || self.external.as_ref().is_some_and(|x| x.active());
        self.status = if !active && self.mode != Mode::Aborting {
            if matches!(self.mode, Mode::Held | Mode::HoldAtBlockEnd) {
                self.mode = Mode::Normal;
                self.rate = self.target_rate();
                self.ramp = None;
            }
            c::GMS_STOP
        } else if matches!(self.mode, Mode::Held)
            || (self.running.is_empty()
                && (self.error != 0 || (self.single_block && !self.single_block_credit)))
        {
            // Held, or commands waiting that an error or single-block mode keeps back.
            c::GMS_HOLD
        } else if matches!(
            self.running.front().map(|r| &r.cmd.plan),
            Some(Plan::Delay(_))
        ) {
            c::GMS_DELAYING
        } else {
            c::GMS_RUNNING
        };
    }

    /// Tangential speed: the X/Y/Z speed, or the fastest aux axis when X/Y/Z stand still.
    fn path_speed(&self) -> f64 {
        let xyz = (self.vel[0].powi(2) + self.vel[1].powi(2) + self.vel[2].powi(2)).sqrt();
        if xyz > 0.0 {
            xyz
        } else {
            self.vel[3..].iter().fold(0.0f64, |m, v| m.max(v.abs()))
        }
    }

    /// Pulse position of axis `i`: round(reference position x pulses per UU), halves away
    /// from zero.
    pub fn pulses(&self, i: usize) -> i64 {
        round_pulses((self.pos[i] + self.offset[i]) * self.axes[i].factor)
    }

    /// The part of the published state that changes every tick.
    pub fn motion(&self) -> Motion {
        Motion {
            status: self.status,
            pos: self.pos,
            vel: self.vel,
            path_speed: self.path_speed(),
        }
    }

    /// The part of the published state that changes when commands start or end.
    pub fn info(&self) -> Info {
        let mut cmd = COMMAND_INFO {
            nType: -1,
            nCommandIndex: -1,
            ..Default::default()
        };
        if let Some(r) = self.running.back() {
            let phase = match &r.cmd.plan {
                Plan::Path(m) => {
                    if r.tau < m.profile.acc_time().min(m.decel_start()) {
                        0
                    } else if r.tau < m.decel_start() {
                        1
                    } else {
                        2
                    }
                }
                _ => 1,
            };
            cmd = COMMAND_INFO {
                nType: r.cmd.ctype,
                nCommandIndex: r.cmd.index,
                dfFeedSpeed: match r.cmd.plan {
                    Plan::Delay(s) => ((s - r.tau) * 1000.0).max(0.0),
                    _ => r.cmd.info_feed,
                },
                dfPos: r.cmd.target,
                dfAcctime: r.cmd.acc_ms,
                dfDectime: r.cmd.dec_ms,
                nMotionPhase: phase,
                nCommandIndex_LD: self.last_started.map_or(0, |l| l.1),
            };
        }
        Info {
            error: self.error,
            queued: i32::try_from(self.queue.len()).unwrap_or(i32::MAX),
            cmd,
            offset: self.offset,
            factor: self.axes.map(|a| a.factor),
        }
    }

    /// The whole published state (as readers see it).
    pub fn snapshot(&self) -> GroupSnapshot {
        GroupSnapshot::from_parts(&self.motion(), &self.info())
    }

    /// The info part last published, so an unchanged one is not stored again.
    pub fn published_info(&mut self) -> &mut Option<Info> {
        &mut self.published_info
    }
}

/// What an external executor may do with its group (see [`Host`]).
impl Host for GroupState {
    fn axes(&self) -> &[AxisMech; AXES] {
        &self.axes
    }

    fn offset(&self) -> &Axes {
        &self.offset
    }

    fn ot_check(&self) -> &[bool; AXES] {
        &self.ot_check
    }

    fn base(&self) -> Axes {
        self.base
    }

    fn speed_scale(&self) -> f64 {
        if self.fixed_speed {
            1.0
        } else {
            self.override_pct / 100.0
        }
    }

    fn single_block(&self) -> bool {
        self.single_block
    }

    fn may_start(&self) -> bool {
        GroupState::may_start(self)
    }

    fn may_go_on(&self) -> bool {
        self.error == 0 && self.mode == Mode::Normal
    }

    fn held(&self) -> bool {
        self.mode == Mode::Held
    }

    fn queued(&self) -> usize {
        self.queue.len()
    }

    fn front(&self) -> Option<&Command> {
        self.queue.front()
    }

    fn pop_front(&mut self) -> Option<Command> {
        self.queue.pop_front()
    }

    fn apply_switch(&mut self) {
        let Some(cmd) = self.queue.front() else {
            return;
        };
        match cmd.plan {
            Plan::Blend(on) => self.blend_on = on,
            Plan::InPos(on, mask) => {
                if on {
                    self.inpos_mask |= mask;
                } else {
                    self.inpos_mask &= !mask;
                }
            }
            Plan::Output(o) => self.outputs.push(o),
            _ => return,
        }
        self.queue.pop_front();
    }

    fn start(&mut self, cmd: Command) {
        GroupState::start(self, cmd, 0.0);
    }

    fn retire(&mut self, n: usize) {
        for _ in 0..n {
            if let Some(done) = self.running.pop_front() {
                self.base = done.cmd.target;
            }
        }
    }

    fn drop_first(&mut self) {
        self.running.pop_front();
    }

    fn job_ended(&mut self) {
        if self.mode == Mode::HoldAtBlockEnd {
            self.mode = Mode::Held;
        }
    }

    fn stop_here(&mut self) {
        GroupState::stop_here(self);
    }

    fn set_error(&mut self, code: i32) {
        GroupState::set_error(self, code);
    }

    fn clear_running(&mut self) {
        self.running.clear();
    }

    fn zero_offset(&mut self, i: usize) {
        self.offset[i] = 0.0;
    }

    fn set_pos(&mut self, pos: Axes) {
        self.pos = pos;
        self.vel = [0.0; AXES];
    }

    fn rebase(&mut self, mask: u32) {
        for i in (0..AXES).filter(|&i| mask & (1 << i) != 0) {
            self.base[i] = self.pos[i];
            self.queue_end[i] = self.pos[i];
        }
    }
}
