//! The door for a group whose commands run outside the virtual card's interpolator (an
//! MC3B today: `crate::mc3b::backend::Executor`). The engine defines both sides and names
//! no backend: the group holds its executor as a [`ExternalExecutor`] and calls it; the
//! executor reaches the group only through [`Host`], which the group implements.

use super::{GroupState, Mode};
use crate::config::AXES;
use crate::engine::command::Plan;
use crate::engine::command::{AxisMech, Command};
use crate::error::McclError;
use crate::error::McclResult;
use crate::planner::Axes;
use crate::vendor::SYS_HOME_CONFIG;

/// An executor of a group's commands outside the card (attached with
/// [`super::GroupState::attach_external`]). The group calls it when a command is queued,
/// each tick, when it stops or is reset, for its positions, and for a go home.
pub trait ExternalExecutor: Send + std::fmt::Debug {
    /// The refusals of this executor, checked when `cmd` is queued on a group with
    /// `axes` (nothing is queued on an error).
    fn check(&self, cmd: &Command, axes: &[AxisMech; AXES]) -> McclResult<()>;
    /// Whether the device is running (or stopping) a job.
    fn busy(&self) -> bool;
    /// Whether there is work (the group's motion status counts it as running).
    fn active(&self) -> bool;
    /// The group stops here: a running job stops, work not handed out is dropped.
    fn stop(&mut self);
    /// Back to reference position 0 where the device stands (`MCC_ResetMotion`,
    /// `MCC_UpdateParam`); a running job is stopped first.
    fn rezero(&mut self);
    /// One tick of `dt` seconds with the group as `host`. The group updates its status
    /// afterwards.
    fn tick(&mut self, host: &mut dyn Host, dt: f64);
    /// Where the axes stand: from the device for the axes it drives, else `base` (where
    /// what has finished left them); `offset` and `axes` are the group's.
    fn positions(&self, base: Axes, offset: &Axes, axes: &[AxisMech; AXES]) -> Axes;
    /// `MCC_Home` with `orders` (per channel, 255 skips) and the go-home parameters
    /// `cfgs`: checks what the device can home (`COMMAND_NOTACCEPTED_ERR` otherwise),
    /// then, unless `group_busy` (`COMMAND_NOTFINISHED_ERR`), starts it. Returns the
    /// mask of the group's axes homed. Nothing starts on an error.
    fn start_home(
        &mut self,
        orders: &[i32; AXES],
        cfgs: &[SYS_HOME_CONFIG; AXES],
        axes: &[AxisMech; AXES],
        group_busy: bool,
    ) -> McclResult<u32>;
    /// `MCC_AbortGoHome`: the go home stops and ends without completing.
    fn abort_home(&mut self);
    /// The end of a go home, once: `HOME_DONE` or `HOME_NONE` (`crate::engine::homing`).
    fn take_home_result(&mut self) -> Option<i32>;
}

/// What the executor needs of its group, and nothing more: the group's settings, its
/// queue, its running commands and its position. `GroupState` implements it; the executor
/// is taken out of the group while it runs, so none of these calls reaches it.
pub trait Host {
    /// Mechanics of every axis (steps per UU, channel, work zone).
    fn axes(&self) -> &[AxisMech; AXES];
    /// Reference offset per axis, UU.
    fn offset(&self) -> &Axes;
    /// Software over-travel check per axis.
    fn ot_check(&self) -> &[bool; AXES];
    /// Where the finished commands leave the axes.
    fn base(&self) -> Axes;
    /// Factor of every speed handed to the device: the override ratio, 1 when the speed
    /// is fixed.
    fn speed_scale(&self) -> f64;
    /// Single-block mode is on.
    fn single_block(&self) -> bool;
    /// A new command may start now.
    fn may_start(&self) -> bool;
    /// Moves of a started command may go on: no error record, not held.
    fn may_go_on(&self) -> bool;
    /// The group is held (a delay pauses).
    fn held(&self) -> bool;
    /// Commands waiting in the queue.
    fn queued(&self) -> usize;
    /// The first queued command.
    fn front(&self) -> Option<&Command>;
    /// Takes the first queued command off the queue.
    fn pop_front(&mut self) -> Option<Command>;
    /// Takes the queued switch at the front (blending, in-position, output) and applies
    /// it.
    fn apply_switch(&mut self);
    /// `cmd` starts running.
    fn start(&mut self, cmd: Command);
    /// The first `n` running commands finished: the axes' base is their target.
    fn retire(&mut self, n: usize);
    /// The first running command ends without a move (a delay, a PtP of no step).
    fn drop_first(&mut self);
    /// A job ended: a hold at the block end takes effect now.
    fn job_ended(&mut self);
    /// Stops at once, dropping what is queued and running.
    fn stop_here(&mut self);
    /// Records an error.
    fn set_error(&mut self, code: i32);
    /// Nothing runs any more.
    fn clear_running(&mut self);
    /// The reference offset of axis `i` becomes 0 (it reached its working home).
    fn zero_offset(&mut self, i: usize);
    /// The axes stand at `pos`.
    fn set_pos(&mut self, pos: Axes);
    /// Axes `mask` start from where they stand: base and queue end are their position.
    fn rebase(&mut self, mask: u32);
}

impl GroupState {
    /// Runs this group's commands on `executor` from now on (an MC3B: the system attaches
    /// one to every group of the device's card).
    pub fn attach_external(&mut self, executor: Box<dyn ExternalExecutor>) {
        self.features.external = Some(executor);
        self.external_positions();
    }

    /// Whether this group's commands run outside the card (on an MC3B).
    pub fn is_external(&self) -> bool {
        self.features.external.is_some()
    }

    /// Whether the external executor is running (or stopping) a job of this group.
    pub fn external_busy(&self) -> bool {
        self.features.external.as_ref().is_some_and(|x| x.busy())
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
        let x = self
            .features
            .external
            .as_mut()
            .ok_or(McclError::NotAccepted)?;
        let mask = x.start_home(orders, cfgs, &self.mech.axes, busy)?;
        self.homing = mask;
        self.update_status();
        Ok(())
    }

    /// `MCC_AbortGoHome` on the external executor: the job running stops and the homing
    /// ends without completing.
    pub fn abort_external_home(&mut self) {
        if let Some(x) = self.features.external.as_mut() {
            x.abort_home();
        }
    }

    /// The end of an external go home, once: `HOME_DONE` or `HOME_NONE`.
    pub fn take_home_result(&mut self) -> Option<i32> {
        self.features.external.as_mut()?.take_home_result()
    }

    /// Positions from the external executor (axes it drives), else from what has finished.
    pub(super) fn external_positions(&mut self) {
        if let Some(x) = &self.features.external {
            self.exec.pos = x.positions(self.exec.base, &self.exec.offset, &self.mech.axes);
            self.exec.vel = [0.0; AXES];
        }
    }

    /// One tick of a group on an external executor: it runs with the group as its
    /// [`Host`]. It is out of `self.features.external` meanwhile and back before the status is
    /// updated, also when the tick panics (the engine's recovery then stops the device's
    /// job).
    pub(super) fn tick_external(&mut self, dt: f64) {
        let Some(mut x) = self.features.external.take() else {
            return;
        };
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| x.tick(self, dt)));
        self.features.external = Some(x);
        if let Err(p) = r {
            std::panic::resume_unwind(p);
        }
        self.update_status();
    }
}

/// What an external executor may do with its group (see [`Host`]).
impl Host for GroupState {
    fn axes(&self) -> &[AxisMech; AXES] {
        &self.mech.axes
    }

    fn offset(&self) -> &Axes {
        &self.exec.offset
    }

    fn ot_check(&self) -> &[bool; AXES] {
        &self.limits.over_travel
    }

    fn base(&self) -> Axes {
        self.exec.base
    }

    fn speed_scale(&self) -> f64 {
        if self.rate.fixed_speed {
            1.0
        } else {
            self.rate.override_pct / 100.0
        }
    }

    fn single_block(&self) -> bool {
        self.queued.single_block
    }

    fn may_start(&self) -> bool {
        GroupState::may_start(self)
    }

    fn may_go_on(&self) -> bool {
        self.error == 0 && self.rate.mode == Mode::Normal
    }

    fn held(&self) -> bool {
        self.rate.mode == Mode::Held
    }

    fn queued(&self) -> usize {
        self.queued.commands.len()
    }

    fn front(&self) -> Option<&Command> {
        self.queued.commands.front()
    }

    fn pop_front(&mut self) -> Option<Command> {
        self.pop_queued()
    }

    fn apply_switch(&mut self) {
        let Some(cmd) = self.queued.commands.front() else {
            return;
        };
        match cmd.plan {
            Plan::Blend(on) => self.exec.blend_on = on,
            Plan::InPos(on, mask) => {
                if on {
                    self.in_pos.mask |= mask;
                } else {
                    self.in_pos.mask &= !mask;
                }
            }
            Plan::Output(o) => self.emitted.outputs.push(o),
            _ => return,
        }
        self.pop_queued();
    }

    fn start(&mut self, cmd: Command) {
        GroupState::start(self, cmd);
    }

    fn retire(&mut self, n: usize) {
        for _ in 0..n {
            if let Some(done) = self.exec.running.pop_front() {
                self.exec.base = done.cmd.target;
                self.info_touched();
            }
        }
    }

    fn drop_first(&mut self) {
        if self.exec.running.pop_front().is_some() {
            self.info_touched();
        }
    }

    fn job_ended(&mut self) {
        if self.rate.mode == Mode::HoldAtBlockEnd {
            self.rate.mode = Mode::Held;
        }
    }

    fn stop_here(&mut self) {
        GroupState::stop_here(self);
    }

    fn set_error(&mut self, code: i32) {
        GroupState::set_error(self, code);
    }

    fn clear_running(&mut self) {
        self.exec.running.clear();
        self.info_touched();
    }

    fn zero_offset(&mut self, i: usize) {
        self.exec.offset[i] = 0.0;
        self.info_touched();
    }

    fn set_pos(&mut self, pos: Axes) {
        self.exec.pos = pos;
        self.exec.vel = [0.0; AXES];
    }

    fn rebase(&mut self, mask: u32) {
        for i in (0..AXES).filter(|&i| mask & (1 << i) != 0) {
            self.exec.base[i] = self.exec.pos[i];
            self.queued.end[i] = self.exec.pos[i];
        }
    }
}
