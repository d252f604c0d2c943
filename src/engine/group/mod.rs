//! One motion group on the virtual card: its settings, its bounded command queue, and the
//! execution of queued commands tick by tick (user manual §2.3, §2.6).
//!
//! Execution model: the vendor's library, measured with its own DLL (`execution.rs`).
//! Commands run on the grid of periods; each motion follows a profile of whole periods
//! ([`crate::planner::TickProfile`]) along its track (`engine/track.rs`: a path, or one axis's
//! travel), and hold, continue, override and timed aborts re-plan what is left of it
//! from the speed of the last period (`control.rs`). The command position is the base
//! plus what every running command moved; with blending on two general motions run at
//! once and their displacements add. When the last running command ends, the position
//! becomes its exact planned end: nothing accumulates over millions of moves.
//!
//! Files, one concept each: `queue.rs` (queuing, indices, single block), `execution.rs`
//! (the running commands tick by tick), `running.rs` (one command being executed),
//! `position_and_speed.rs` (the position and speeds a period shows, over-travel),
//! `control.rs` (hold, continue,
//! abort, override, feed), `inpos.rs` (the in-position check), `status.rs` (motion
//! status and the published parts), `homing.rs` (the group while `MCC_Home` drives it),
//! `external.rs` (the door to an executor outside the card, e.g. the MC3B), `custom.rs`
//! (the running custom motion's side of its callbacks' stage).

use super::command::{AxisMech, Command, Ctx, Output, Settings};
use super::track;
use crate::config::{GroupDef, AXES};
use crate::error::{McclError, McclResult};
use crate::planner::Axes;
use crate::vendor::consts as c;
use std::collections::VecDeque;

mod commanded;
mod control;
pub mod custom;
mod execution;
pub mod external;
mod homing;
mod inpos;
pub mod kinematics;
mod position_and_speed;
mod post;
mod queue;
mod running;
mod status;

pub(crate) use commanded::Commanded;
use control::Mode;
use external::ExternalExecutor;
use inpos::InPosWait;
pub use inpos::{InPosSettings, DEFAULT_INPOS_CHECK_MS, ERR_IN_POSITION};
pub use post::{MAX_FILTER_PERIODS, MOVING_AVERAGE_TAPS, REVERSE_HISTORY};
use queue::CommandIndex;
use running::Running;

/// Error record of software over-travel, + axis (docs/vendor-interface.md).
pub const ERR_OVER_TRAVEL: i32 = crate::error_record::ErrorRecord::OverTravel(0).code();

/// A command whose own time is within this of its end has ended (1 ns: far below a tick,
/// far above the rounding of summing millions of ticks): the stages of custom motion and
/// joint moves, which run in continuous own time.
pub const TIME_EPS: f64 = 1e-9;

/// A group as the card runs it.
///
/// `repr(C)` with the fields every tick reads first (status, flags, the running
/// commands, the channels it commands, the rate, the positions), so a tick touches a few
/// cache lines of each group instead of lines spread over its 1.8 KB. Among
/// them, the published key and the settings (the compose mask first), which a tick that
/// publishes reads too. What only queuing and status calls read comes after.
#[derive(Debug)]
#[repr(C)]
pub struct GroupState {
    status: i32,
    error: i32,
    /// Axes whose channels are being homed (`MCC_Home`), one bit each: the homing drives
    /// their positions and the group takes no command meanwhile.
    homing: u32,
    mode: Mode,
    /// Blending as the engine has reached it in the queue.
    blend_on: bool,
    single_block: bool,
    single_block_credit: bool,
    /// In-position check axes enabled by queued markers (used by the in-position check).
    pub(in crate::engine) inpos_mask: u32,
    /// Tracking error check per axis (`MCC_EnableTrackError` mask).
    pub(in crate::engine) track_mask: u32,
    /// Software over-travel check per axis (`MCC_SetOverTravelCheck`).
    pub(in crate::engine) ot_check: [bool; AXES],
    /// Group index (0..95).
    pub(in crate::engine) index: usize,
    /// Changes of the info other than its running command's phase and feed: a command
    /// queued, taken from the queue, started or ended, the queue dropped, the error
    /// record set or cleared, the running command's end or the offset changed
    /// ([`GroupState::info_touched`]).
    info_changes: u64,
    /// The own time of the newest running command (the back of `running`), kept by every
    /// writer of an own time, for the published key's check
    /// ([`GroupState::info_changed`]): finding the back of the deque cost it 11
    /// instructions a publication. Meaningless while nothing runs.
    newest_own_time: f64,
    /// The info last published, kept in test builds to check the key against it.
    #[cfg(debug_assertions)]
    pub(in crate::engine) published_info: Option<super::snapshot::Info>,
    /// Set when the group's commands run outside the card (an MC3B: `external`).
    external: Option<Box<dyn ExternalExecutor>>,
    /// After-interpolation filters and reverse interpolation (`post.rs`); `None` until
    /// the program uses one.
    post: Option<Box<post::Post>>,
    /// Robot kinematics (`MCC_SetKinematicTrans`, `kinematics.rs`): the channels carry
    /// joints, the commands and positions are Cartesian.
    kin: Option<Box<kinematics::Kinematics>>,
    running: VecDeque<Running>,
    queue: VecDeque<Command>,
    /// The axes whose pulses command a channel, with the channel (set when the engine
    /// starts, `engine::shared`: it depends on every group's mapping).
    pub(in crate::engine) commanded: Commanded,
    /// The info key last published and how long it holds ([`GroupState::info_changed`]).
    published_key: status::PublishedKey,
    /// Settings that queued commands capture (`compose` first, which publishing reads).
    pub(in crate::engine) settings: Settings,
    /// Output changes the queue reached this tick (the engine makes them).
    outputs: Vec<Output>,
    /// Events for the trace's events file, `Some` only while tracing (`MCCL_TRACE`).
    pub(in crate::engine) trace_notes: Option<Vec<super::note::Note>>,
    /// Periods the status still reads `GMS_RUNNING` with nothing running (the vendor's
    /// library shows one after the last command).
    lag: u8,
    /// The period that just ran read running for `lag` (see [`GroupState::tick`]).
    lag_shown: bool,
    /// A jog by pulses: its displacement and the periods it still keeps the group running.
    jump: Option<(Axes, u8)>,
    /// The feed speed of the last period (`MCC_GetCurFeedSpeed`).
    feed_now: f64,
    /// An override set since the last period and whether it is instant
    /// (`MCC_OverrideSpeedEx`): in effect from the next period.
    override_next: Option<(f64, bool)>,
    /// The interpolation period, seconds.
    period_s: f64,
    /// Position of everything finished (user coordinates).
    base: Axes,
    /// Current command position (user coordinates).
    pos: Axes,
    vel: Axes,
    /// Reference position = user position + offset (MCC_DefinePos moves the offset).
    offset: Axes,
    /// In-position check of the last command, while it runs.
    inpos_wait: Option<InPosWait>,
    /// The mapping and queue size the group runs with.
    pub(in crate::engine) def: GroupDef,
    /// Mechanism facts per axis (from the parameters in effect).
    pub(in crate::engine) axes: [AxisMech; AXES],
    /// Blending as the end of the queue will see it (`MCC_CheckBlend`).
    pub(in crate::engine) blend_queued: bool,
    /// Override ratio, percent.
    pub(in crate::engine) override_pct: f64,
    /// `MCC_FixSpeed(TRUE)`: the override does not change speeds.
    pub(in crate::engine) fixed_speed: bool,
    /// End of the last queued command (user coordinates).
    queue_end: Axes,
    /// Command indices (`queue.rs`).
    cmd_index: CommandIndex,
    /// Tracking error limit per axis, UU (`MCC_SetTrackErrorLimit`).
    pub(in crate::engine) track_limit: Axes,
    /// In-position settings (`MCC_SetInPos*`).
    pub(in crate::engine) inpos: InPosSettings,
    /// `MCC_GetInPosStatus`: 0xFF per axis once in position, until the next command.
    inpos_status: [u8; AXES],
    /// Custom commands started and not cleaned up yet (`custom.rs`).
    custom: custom::CustomSide,
    /// Compensation pulses per axis ([`GroupState::read_compensation`]).
    comp: [i32; AXES],
    /// When the pulse counters of the commanded channels restart from 0
    /// ([`GroupState::reset_motion`]).
    rezero: Rezero,
}

/// When a reset group's position and its channels' pulse counters restart from 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Rezero {
    /// Nothing pending.
    No,
    /// At the start of the next period (a group reset at rest).
    NextPeriod,
    /// When the next command starts (a group reset while busy shows where it stopped
    /// until then).
    OnStart,
    /// The position is 0: the channels restart as they are commanded next.
    Channels,
}

impl GroupState {
    /// A stopped group at position 0.
    pub fn new(index: usize, def: GroupDef, axes: [AxisMech; AXES], period_s: f64) -> GroupState {
        GroupState {
            index,
            def,
            axes,
            commanded: Commanded::default(),
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
            lag: 0,
            lag_shown: false,
            jump: None,
            feed_now: 0.0,
            override_next: None,
            period_s,
            mode: Mode::Normal,
            single_block: false,
            single_block_credit: false,
            blend_on: false,
            inpos_mask: 0,
            error: 0,
            cmd_index: CommandIndex::default(),
            status: c::GMS_STOP,
            published_key: status::PublishedKey::NONE,
            info_changes: 0,
            newest_own_time: 0.0,
            #[cfg(debug_assertions)]
            published_info: None,
            ot_check: [false; AXES],
            track_mask: 0,
            track_limit: [f64::INFINITY; AXES],
            inpos: InPosSettings::for_axes(&axes),
            inpos_wait: None,
            // The vendor's library reads 255 for every axis right after init.
            inpos_status: [0xFF; AXES],
            outputs: Vec::new(),
            external: None,
            homing: 0,
            trace_notes: None,
            custom: custom::CustomSide::default(),
            rezero: Rezero::No,
            comp: [0; AXES],
            post: None,
            kin: None,
        }
    }

    /// The motion settings queued commands capture (a plain record: every value allowed
    /// by its setter's checks is valid).
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The motion settings, to change: commands queued from now on capture them.
    pub fn settings_mut(&mut self) -> &mut Settings {
        &mut self.settings
    }

    /// The in-position settings (`MCC_SetInPos*`).
    pub fn inpos_settings(&self) -> &InPosSettings {
        &self.inpos
    }

    /// The in-position settings, to change: the next check uses them.
    pub fn inpos_settings_mut(&mut self) -> &mut InPosSettings {
        &mut self.inpos
    }

    /// The tracking error limit of axis `a`, UU.
    pub fn track_limit(&self, a: usize) -> f64 {
        self.track_limit[a]
    }

    /// The group's slot (0..95).
    pub fn index(&self) -> usize {
        self.index
    }

    /// The mapping and queue size the group runs with.
    pub fn def(&self) -> &GroupDef {
        &self.def
    }

    /// Mechanism facts per axis.
    pub fn axes(&self) -> &[AxisMech; AXES] {
        &self.axes
    }

    /// Sets the unit (`UNIT_MM`, `UNIT_INCH`) the group's axes take from the next reset.
    pub fn set_unit(&mut self, unit: std::os::raw::c_int) {
        self.def.unit = unit;
    }

    /// Turns the software over-travel check on or off per axis; an axis the group lacks
    /// stays off.
    pub fn set_over_travel_check(&mut self, on: [bool; AXES]) {
        self.ot_check = std::array::from_fn(|i| on[i] && self.axes[i].channel.is_some());
    }

    /// The software over-travel check per axis.
    pub fn over_travel_check(&self) -> [bool; AXES] {
        self.ot_check
    }

    /// Whether blending is on as the end of the queue will see it (`MCC_CheckBlend`).
    pub fn blend_queued(&self) -> bool {
        self.blend_queued
    }

    /// The override ratio, percent.
    pub fn override_pct(&self) -> f64 {
        self.override_pct
    }

    /// Back to the state right after init (`MCC_ResetMotion`, `MCC_UpdateParam`).
    pub fn reset(&mut self, axes: [AxisMech; AXES]) {
        let external = self.external.take();
        let notes = self.trace_notes.take();
        let custom = std::mem::take(&mut self.custom);
        let commanded = self.commanded;
        *self = GroupState::new(self.index, self.def, axes, self.period_s);
        self.trace_notes = notes;
        self.custom = custom;
        // The channels it commands depend on every group's mapping, which a reset keeps.
        self.commanded = commanded;
        // An MC3B group stays on its device, rezeroed.
        if let Some(mut x) = external {
            x.rezero();
            self.external = Some(x);
            self.external_positions();
        }
    }

    /// `MCC_ResetMotion`: the group returns to its state right after init, keeping its
    /// settings (feed, profiles, coordinates, blending, checks): what runs stops at once
    /// and the queue, error record, hold, override, offsets and command indices go, and
    /// its positions and the pulse counters of its channels restart from 0. As the
    /// vendor's library does it: a group at rest reads 0 from the next period; a busy one
    /// (the call then answers `COMMAND_NOTACCEPTED_ERR` and still resets) keeps showing
    /// where it stopped, with one more running period, until its next command starts
    /// from 0.
    pub fn reset_motion(&mut self) {
        if self.mode == Mode::Aborting && self.running.is_empty() {
            // An abort at once has stopped it and is not finished yet: the vendor's
            // library then keeps its position (measured, jog_pulse_after) and restarts
            // only the command indices.
            self.cmd_index = CommandIndex::default();
            self.info_touched();
            return;
        }
        let busy = self.busy() || self.homing != 0;
        // A go home it was part of is dropped (`Shared::reset_motion`).
        self.homing = 0;
        self.abort_now(true);
        // Stopped by a reset, not an abort: nothing waits for it to finish.
        self.mode = Mode::Normal;
        self.clear_error();
        self.override_pct = 100.0;
        self.override_next = None;
        self.cmd_index = CommandIndex::default();
        self.offset = [0.0; AXES];
        self.queue_end = [0.0; AXES];
        if let Some(x) = self.external.as_mut() {
            x.rezero();
        }
        if busy {
            // `base` keeps the stop point, where the group stays until its next start.
            self.rezero = Rezero::OnStart;
        } else {
            self.inpos_status = [0xFF; AXES];
            self.rezero = Rezero::NextPeriod;
        }
        self.info_touched();
        self.update_status();
    }

    /// A group made while the card runs starts where its channels' pulse counts are.
    pub fn start_at_channels(&mut self, cards: &[[crate::machine::Channel; AXES]]) {
        for (i, a) in self.axes.iter().enumerate() {
            let Some((card, ch)) = a.channel else {
                continue;
            };
            if let Some(chan) = cards.get(card).and_then(|c| c.get(ch)) {
                if a.factor != 0.0 {
                    let p = chan.command_pulses() as f64 / a.factor;
                    self.pos[i] = p;
                    self.base[i] = p;
                    self.queue_end[i] = p;
                }
            }
        }
        self.info_touched();
    }

    /// The planning context: settings, axes and the end of the queue.
    pub fn ctx(&self) -> Ctx<'_> {
        Ctx {
            settings: &self.settings,
            axes: &self.axes,
            from: self.queue_end,
            offset: self.offset,
            period_s: self.period_s,
        }
    }

    /// The interpolation period, ms.
    pub fn period_ms(&self) -> f64 {
        self.period_s * 1000.0
    }

    /// Motion status (`GMS_*`).
    pub fn status(&self) -> i32 {
        self.status
    }

    /// Records an event for the trace (nothing but this check when not tracing).
    #[inline]
    fn note(&mut self, n: super::note::Note) {
        if let Some(v) = self.trace_notes.as_mut() {
            v.push(n);
        }
    }

    /// Notes the running commands as cut short (they are about to be dropped, or the
    /// system closes).
    pub(crate) fn note_stopped(&mut self) {
        if let Some(v) = self.trace_notes.as_mut() {
            for r in &self.running {
                v.push(super::note::Note::End {
                    index: r.cmd.index,
                    ctype: r.cmd.ctype,
                    stopped: true,
                });
            }
        }
    }

    /// The error record (0 when none).
    pub fn error(&self) -> i32 {
        self.error
    }

    /// Records an error: the group stops executing commands until `MCC_ClearError`.
    pub fn set_error(&mut self, code: i32) {
        if self.error == 0 {
            self.note(super::note::Note::ErrorSet(code));
            self.error = code;
            self.info_touched();
        }
    }

    /// `MCC_ClearError`.
    pub fn clear_error(&mut self) {
        if self.error != 0 {
            self.note(super::note::Note::ErrorCleared(self.error));
            self.info_touched();
        }
        self.error = 0;
        self.update_status();
    }

    /// Stops at once because a check tripped, dropping the queue; records `record`.
    pub fn stop_for(&mut self, record: Option<i32>) {
        self.stop_here();
        if let Some(code) = record {
            self.set_error(code);
        }
        self.update_status();
    }

    /// Velocity per axis (UU/s).
    pub fn vel(&self) -> Axes {
        self.out_vel()
    }

    /// The current position (user coordinates).
    pub fn pos(&self) -> Axes {
        self.pos
    }

    /// The current reference position of axis `i` (user position + offset).
    pub fn ref_pos(&self, i: usize) -> f64 {
        self.pos[i] + self.offset[i]
    }

    /// `MCC_DefinePos`: the current position of `axis` becomes `value` (only when stopped;
    /// `value` must be a position of the axis, `config::range::position`).
    pub fn define_pos(&mut self, axis: usize, value: f64) -> McclResult<()> {
        crate::config::range::position(value, self.axes[axis].factor)?;
        if self.busy() || self.kin.is_some() {
            return Err(McclError::NotFinished);
        }
        let shift = value - self.pos[axis];
        self.offset[axis] -= shift;
        self.info_touched();
        self.pos[axis] = value;
        self.base[axis] = value;
        self.queue_end[axis] = value;
        Ok(())
    }

    /// `MCC_DefinePos`: the position of `axis` becomes `value` in the program's
    /// coordinates, the offset kept (so the pulse count becomes it too); only when
    /// stopped, and `value` a position of the axis.
    pub fn set_pos(&mut self, axis: usize, value: f64) -> McclResult<()> {
        crate::config::range::position(value, self.axes[axis].factor)?;
        crate::config::range::position(value + self.offset[axis], self.axes[axis].factor)?;
        if self.busy() || self.kin.is_some() {
            return Err(McclError::NotFinished);
        }
        self.pos[axis] = value;
        self.base[axis] = value;
        self.queue_end[axis] = value;
        self.info_touched();
        Ok(())
    }

    /// `MCC_DefinePosHere` for the axes of `mask` (a valid axis mask, which the caller
    /// checks): each one's command position becomes the position the card has output;
    /// only when stopped (`COMMAND_NOTFINISHED_ERR`).
    pub fn define_pos_here(&mut self, mask: u32) -> McclResult<()> {
        if self.busy() {
            return Err(McclError::NotFinished);
        }
        for i in (0..AXES).filter(|i| mask & (1 << i) != 0) {
            self.sync_to_output(i)?;
        }
        Ok(())
    }

    /// `MCC_DefinePosHere`: the command position of axis `i` becomes the position the card
    /// has output (its pulse count in UU); only when stopped.
    pub fn sync_to_output(&mut self, i: usize) -> McclResult<()> {
        if self.busy() || self.kin.is_some() {
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
}

/// The tracking error check (user manual §2.7): which axes it watches and their limits;
/// the check itself runs with the engine's safety checks (`engine::safety`).
impl GroupState {
    /// Turns the check on for the axes of `mask` (a valid axis mask, which the caller
    /// checks), besides those already on.
    pub fn enable_track_error(&mut self, mask: u32) {
        self.track_mask |= mask;
    }

    /// Turns the check off for every axis.
    pub fn disable_track_error(&mut self) {
        self.track_mask = 0;
    }

    /// `GROUP_PARAMETER_ERR` unless the group has `axis` (as the vendor's library answers
    /// for an axis past the group's).
    pub fn own_axis(&self, axis: usize) -> McclResult<()> {
        match self.axes.get(axis) {
            Some(a) if a.channel.is_some() => Ok(()),
            _ => Err(McclError::Group),
        }
    }

    /// The tracking error limit of `axis`, UU (>= 0, which the caller checks): a distance
    /// of the axis within the position range ("Ranges"); an error changes nothing.
    pub fn set_track_error_limit(&mut self, axis: usize, limit: f64) -> McclResult<()> {
        self.own_axis(axis)?;
        crate::config::range::position(limit, self.axes[axis].factor)?;
        self.track_limit[axis] = limit;
        Ok(())
    }
}
