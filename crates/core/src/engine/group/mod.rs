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
//! (the running custom motion's side of its callbacks' stage), `mechanism.rs` (the mapping,
//! the axes and the channels they command), `features.rs` (what a program attaches:
//! executor, filters, kinematics, custom motion), `emitted.rs` (what a tick leaves for
//! the engine). Each concern's state is a part of [`GroupState`] defined in its file.

use super::command::{AxisMech, Ctx, Settings};
use super::track;
use crate::config::{GroupDef, AXES};
use crate::error::{McclError, McclResult};
use crate::planner::Axes;
use crate::vendor::consts as c;

mod commanded;
mod control;
mod cruise;
pub mod custom;
mod emitted;
mod execution;
pub mod external;
mod features;
mod homing;
mod inpos;
pub mod kinematics;
mod mechanism;
mod position_and_speed;
mod post;
mod queue;
mod running;
mod status;

pub use commanded::{commanding_axes, Commanded};
use control::Mode;
use external::ExternalExecutor;
use inpos::InPosWait;
pub use inpos::{InPosSettings, DEFAULT_INPOS_CHECK_MS, ERR_IN_POSITION};
pub use post::{MAX_FILTER_PERIODS, MOVING_AVERAGE_TAPS, REVERSE_HISTORY};
use queue::CommandIndex;

/// Error record of software over-travel, + axis (docs/vendor-interface.md).
pub const ERR_OVER_TRAVEL: i32 = crate::error_record::ErrorRecord::OverTravel(0).code();

/// A command whose own time is within this of its end has ended (1 ns: far below a tick,
/// far above the rounding of summing millions of ticks): the stages of custom motion and
/// joint moves, which run in continuous own time.
pub const TIME_EPS: f64 = 1e-9;

/// A group as the card runs it: its identity and settings, and one part per concern,
/// each in the file of that concern with the methods that keep it.
///
/// `repr(C)` with what every tick reads first (status, homing, the execution, the rate,
/// what it publishes, the channels it commands, the settings), so a tick touches a few
/// cache lines of each group instead of lines spread over its 1.8 KB. What only queuing,
/// checks and status calls read comes after.
#[derive(Debug)]
#[repr(C)]
pub struct GroupState {
    status: i32,
    error: i32,
    /// Axes whose channels are being homed (`MCC_Home`), one bit each: the homing drives
    /// their positions and the group takes no command meanwhile.
    homing: u32,
    /// Group index (0..95).
    pub(in crate::engine) index: usize,
    /// The running commands, the positions and speeds they make (`execution.rs`).
    exec: execution::Execution,
    /// Hold, override and feed (`control.rs`).
    rate: control::Rate,
    /// What was published and when it must be again (`status.rs`).
    publishing: status::Publishing,
    /// The mapping, the axes' mechanism and the channels they command (`mechanism.rs`).
    mech: mechanism::Mechanism,
    /// Settings that queued commands capture (`compose` first, which publishing reads).
    settings: Settings,
    /// The commands waiting and the queue's own state (`queue.rs`).
    queued: queue::Queued,
    /// Over-travel and tracking error checks (`position_and_speed.rs`).
    limits: position_and_speed::Limits,
    /// The in-position check (`inpos.rs`).
    in_pos: inpos::InPosition,
    /// What the program attached: an external executor, filters, kinematics, custom
    /// motion (`features.rs`).
    features: features::Features,
    /// What a tick leaves for the engine: outputs and trace notes (`emitted.rs`).
    emitted: emitted::Emitted,
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
            status: c::GMS_STOP,
            error: 0,
            homing: 0,
            index,
            exec: execution::Execution::new(period_s),
            rate: control::Rate::default(),
            publishing: status::Publishing::default(),
            in_pos: inpos::InPosition::for_axes(&axes),
            mech: mechanism::Mechanism::new(def, axes),
            settings: Settings::default(),
            queued: queue::Queued::default(),
            limits: position_and_speed::Limits::default(),
            features: features::Features::default(),
            emitted: emitted::Emitted::default(),
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
        &self.in_pos.settings
    }

    /// The in-position settings, to change: the next check uses them.
    pub fn inpos_settings_mut(&mut self) -> &mut InPosSettings {
        &mut self.in_pos.settings
    }

    /// The tracking error limit of axis `a`, UU, when its check is on
    /// (`MCC_EnableTrackError`).
    pub fn checked_track_limit(&self, a: usize) -> Option<f64> {
        (self.limits.track_mask & (1 << a) != 0).then(|| self.limits.track_limit[a])
    }

    /// The channels the group's axes command, as every group's mapping decides
    /// (`engine::shared`).
    pub fn set_commanded(&mut self, c: Commanded) {
        self.mech.commanded = c;
    }

    /// Starts noting events for the trace's events file.
    pub fn start_notes(&mut self) {
        self.emitted.trace_notes = Some(Vec::new());
    }

    /// The events noted since they were last taken, while tracing.
    pub fn notes_mut(&mut self) -> Option<&mut Vec<super::note::Note>> {
        self.emitted.trace_notes.as_mut()
    }

    /// The info last published (test builds, to check the published key against it).
    #[cfg(debug_assertions)]
    pub fn published_info(&self) -> Option<&super::snapshot::Info> {
        self.publishing.info.as_ref()
    }

    /// Keeps the info just published (test builds).
    #[cfg(debug_assertions)]
    pub fn keep_published_info(&mut self, info: super::snapshot::Info) {
        self.publishing.info = Some(info);
    }

    /// The tracking error limit of axis `a`, UU.
    pub fn track_limit(&self, a: usize) -> f64 {
        self.limits.track_limit[a]
    }

    /// The group's slot (0..95).
    pub fn index(&self) -> usize {
        self.index
    }

    /// The mapping and queue size the group runs with.
    pub fn def(&self) -> &GroupDef {
        &self.mech.def
    }

    /// Mechanism facts per axis.
    pub fn axes(&self) -> &[AxisMech; AXES] {
        &self.mech.axes
    }

    /// Sets the unit (`UNIT_MM`, `UNIT_INCH`) the group's axes take from the next reset.
    pub fn set_unit(&mut self, unit: std::os::raw::c_int) {
        self.mech.def.unit = unit;
    }

    /// Turns the software over-travel check on or off per axis; an axis the group lacks
    /// stays off.
    pub fn set_over_travel_check(&mut self, on: [bool; AXES]) {
        self.limits.over_travel =
            std::array::from_fn(|i| on[i] && self.mech.axes[i].channel.is_some());
    }

    /// The software over-travel check per axis.
    pub fn over_travel_check(&self) -> [bool; AXES] {
        self.limits.over_travel
    }

    /// Whether blending is on as the end of the queue will see it (`MCC_CheckBlend`).
    pub fn blend_queued(&self) -> bool {
        self.queued.blend
    }

    /// The override ratio, percent.
    pub fn override_pct(&self) -> f64 {
        self.rate.override_pct
    }

    /// Back to the state right after init (`MCC_ResetMotion`, `MCC_UpdateParam`).
    pub fn reset(&mut self, axes: [AxisMech; AXES]) {
        let external = self.features.external.take();
        let notes = self.emitted.trace_notes.take();
        let custom = std::mem::take(&mut self.features.custom);
        let commanded = self.mech.commanded;
        *self = GroupState::new(self.index, self.mech.def, axes, self.exec.period_s);
        self.emitted.trace_notes = notes;
        self.features.custom = custom;
        // The channels it commands depend on every group's mapping, which a reset keeps.
        self.mech.commanded = commanded;
        // An MC3B group stays on its device, rezeroed.
        if let Some(mut x) = external {
            x.rezero();
            self.features.external = Some(x);
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
        if self.rate.mode == Mode::Aborting && self.exec.running.is_empty() {
            // An abort at once has stopped it and is not finished yet: the vendor's
            // library then keeps its position (measured, jog_pulse_after) and restarts
            // only the command indices.
            self.queued.index = CommandIndex::default();
            self.info_touched();
            return;
        }
        let busy = self.busy() || self.homing != 0;
        // A go home it was part of is dropped (`Shared::reset_motion`).
        self.homing = 0;
        self.abort_now(true);
        // Stopped by a reset, not an abort: nothing waits for it to finish.
        self.rate.mode = Mode::Normal;
        self.clear_error();
        self.rate.override_pct = 100.0;
        self.rate.override_next = None;
        self.rate.retarget_pending = false;
        self.queued.index = CommandIndex::default();
        self.exec.offset = [0.0; AXES];
        self.queued.end = [0.0; AXES];
        if let Some(x) = self.features.external.as_mut() {
            x.rezero();
        }
        if busy {
            // `base` keeps the stop point, where the group stays until its next start.
            self.exec.rezero = Rezero::OnStart;
        } else {
            self.in_pos.status = [0xFF; AXES];
            self.exec.rezero = Rezero::NextPeriod;
        }
        self.info_touched();
        self.update_status();
    }

    /// A group made while the card runs starts where its channels' pulse counts are.
    pub fn start_at_channels(&mut self, cards: &[[crate::machine::Channel; AXES]]) {
        for (i, a) in self.mech.axes.iter().enumerate() {
            let Some((card, ch)) = a.channel else {
                continue;
            };
            if let Some(chan) = cards.get(card).and_then(|c| c.get(ch)) {
                if a.factor != 0.0 {
                    let p = chan.command_pulses() as f64 / a.factor;
                    self.exec.pos[i] = p;
                    self.exec.base[i] = p;
                    self.queued.end[i] = p;
                }
            }
        }
        self.info_touched();
    }

    /// The planning context: settings, axes and the end of the queue.
    pub fn ctx(&self) -> Ctx<'_> {
        Ctx {
            settings: &self.settings,
            axes: &self.mech.axes,
            from: self.queued.end,
            offset: self.exec.offset,
            period_s: self.exec.period_s,
        }
    }

    /// The interpolation period, ms.
    pub fn period_ms(&self) -> f64 {
        self.exec.period_s * 1000.0
    }

    /// Motion status (`GMS_*`).
    pub fn status(&self) -> i32 {
        self.status
    }

    /// Records an event for the trace (nothing but this check when not tracing).
    #[inline]
    fn note(&mut self, n: super::note::Note) {
        if let Some(v) = self.emitted.trace_notes.as_mut() {
            v.push(n);
        }
    }

    /// Notes the running commands as cut short (they are about to be dropped, or the
    /// system closes).
    pub fn note_stopped(&mut self) {
        if let Some(v) = self.emitted.trace_notes.as_mut() {
            for r in &self.exec.running {
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
        self.exec.pos
    }

    /// The current reference position of axis `i` (user position + offset).
    pub fn ref_pos(&self, i: usize) -> f64 {
        self.exec.pos[i] + self.exec.offset[i]
    }

    /// `MCC_DefinePos`: the current position of `axis` becomes `value` (only when stopped;
    /// `value` must be a position of the axis, `config::range::position`).
    pub fn define_pos(&mut self, axis: usize, value: f64) -> McclResult<()> {
        crate::config::range::position(value, self.mech.axes[axis].factor)?;
        if self.busy() || self.features.kin.is_some() {
            return Err(McclError::NotFinished);
        }
        let shift = value - self.exec.pos[axis];
        self.exec.offset[axis] -= shift;
        self.info_touched();
        self.exec.pos[axis] = value;
        self.exec.base[axis] = value;
        self.queued.end[axis] = value;
        Ok(())
    }

    /// `MCC_DefinePos`: the position of `axis` becomes `value` in the program's
    /// coordinates, the offset kept (so the pulse count becomes it too); only when
    /// stopped, and `value` a position of the axis.
    pub fn set_pos(&mut self, axis: usize, value: f64) -> McclResult<()> {
        crate::config::range::position(value, self.mech.axes[axis].factor)?;
        crate::config::range::position(
            value + self.exec.offset[axis],
            self.mech.axes[axis].factor,
        )?;
        if self.busy() || self.features.kin.is_some() {
            return Err(McclError::NotFinished);
        }
        self.exec.pos[axis] = value;
        self.exec.base[axis] = value;
        self.queued.end[axis] = value;
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
        if self.busy() || self.features.kin.is_some() {
            return Err(McclError::NotFinished);
        }
        let f = self.mech.axes[i].factor;
        if f != 0.0 {
            let here = self.pulses(i) as f64 / f - self.exec.offset[i];
            self.exec.pos[i] = here;
            self.exec.base[i] = here;
            self.queued.end[i] = here;
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
        self.limits.track_mask |= mask;
    }

    /// Turns the check off for every axis.
    pub fn disable_track_error(&mut self) {
        self.limits.track_mask = 0;
    }

    /// `GROUP_PARAMETER_ERR` unless the group has `axis` (as the vendor's library answers
    /// for an axis past the group's).
    pub fn own_axis(&self, axis: usize) -> McclResult<()> {
        match self.mech.axes.get(axis) {
            Some(a) if a.channel.is_some() => Ok(()),
            _ => Err(McclError::Group),
        }
    }

    /// The tracking error limit of `axis`, UU (>= 0, which the caller checks): a distance
    /// of the axis within the position range ("Ranges"); an error changes nothing.
    pub fn set_track_error_limit(&mut self, axis: usize, limit: f64) -> McclResult<()> {
        self.own_axis(axis)?;
        crate::config::range::position(limit, self.mech.axes[axis].factor)?;
        self.limits.track_limit[axis] = limit;
        Ok(())
    }
}

/// A group of eight unmapped axes, 1000 pulses per UU, feed 10 UU/s, 100 ms
/// acceleration and deceleration, 1 ms periods (the groups' unit tests).
#[cfg(test)]
fn test_group() -> GroupState {
    let def = GroupDef::new([0, 1, 2, 3, 4, 5, 6, 7], 0, 10).expect("group");
    let axis = AxisMech {
        channel: None,
        factor: 1000.0,
        safe_speed: 1.0,
        high: 1e9,
        low: -1e9,
    };
    let mut g = GroupState::new(0, def, [axis; AXES], 0.001);
    g.settings.feed = 10.0;
    g.settings.acc_ms = 100.0;
    g.settings.dec_ms = 100.0;
    g
}
