//! The group's bounded command queue: queuing (indices, growth, refusals), single-block
//! mode, and taking the next command off it (the switches it passes on the way).

use super::GroupState;
use super::Mode;
use crate::engine::command::{Command, Output, Plan};
use crate::error::{McclError, McclResult};
use crate::vendor::consts as c;

/// Commands a queue grows by at least when it is full (doubling from there on).
const QUEUE_MIN_GROWTH: usize = 16;

/// The indices of a group's commands (`MCC_SetCommandIndex`, `MCC_GetCommandInfo`).
#[derive(Debug, Clone, Copy)]
pub(super) struct CommandIndex {
    /// The index the next queued command gets.
    pub(super) next: i32,
    /// Whether each queued command counts the index up; off after
    /// `MCC_SetCommandIndex` with manual numbering (every command gets the index set).
    pub(super) auto: bool,
    /// Commands started since `MCC_ResetCommandIndexLD` (`nCommandIndex_LD`).
    pub(super) ld: i32,
    /// The last command started: its index and its `ld` count.
    pub(super) last_started: Option<(i32, i32)>,
}

impl Default for CommandIndex {
    fn default() -> Self {
        CommandIndex {
            next: 0,
            auto: true,
            ld: 0,
            last_started: None,
        }
    }
}

impl GroupState {
    /// Commands waiting in the queue (not counting those running).
    pub fn queued(&self) -> usize {
        self.queue.len()
    }

    /// Whether a command runs (a jog by pulses included).
    pub fn commands_running(&self) -> bool {
        !self.running.is_empty() || self.jump.is_some()
    }

    /// Whether the group has anything to do.
    pub fn busy(&self) -> bool {
        self.status != c::GMS_STOP || !self.queue.is_empty()
    }

    /// Queues a command; returns its index. `ABORT_NOT_FINISH_ERR` while an abort is
    /// still decelerating, `COMMAND_BUFFER_FULL_ERR` when the queue is full or the memory
    /// to grow it (doubling, up to the queue size) cannot be had.
    pub fn enqueue(&mut self, mut cmd: Command) -> McclResult<i32> {
        if self.homing != 0 || crate::engine::custom::in_callback() == Some(self.index) {
            return Err(McclError::NotAccepted);
        }
        if let Some(x) = &self.external {
            x.check(&cmd, &self.axes)?;
        }
        if self.mode == Mode::Aborting {
            return Err(McclError::AbortNotFinished);
        }
        // With an error record the vendor's library refuses every command until
        // `MCC_ClearError`.
        if self.error != 0 {
            return Err(McclError::RunTime);
        }
        if self.queue.len() >= self.def.queue_size {
            // The vendor's library counts the refused command's index too.
            self.skip_command_index();
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
        cmd.index = self.cmd_index.next;
        if self.cmd_index.auto {
            self.cmd_index.next = self.cmd_index.next.wrapping_add(1) & 0x7FFF_FFFF;
        }
        match cmd.plan {
            Plan::Blend(on) => self.blend_queued = on,
            _ => self.queue_end = cmd.target,
        }
        crate::fault::point("enqueue");
        let idx = cmd.index;
        // An arc of no length (an angle of 0): the vendor's library takes it and runs
        // nothing.
        if matches!(&cmd.plan, Plan::Path(m)
            if m.profile.is_empty() && !matches!(m.path, crate::planner::Path::Line(_)))
        {
            return Ok(idx);
        }
        self.queue.push_back(cmd);
        self.info_touched();
        self.update_status();
        Ok(idx)
    }

    /// The next index is used up without a command.
    fn skip_command_index(&mut self) {
        if self.cmd_index.auto {
            self.cmd_index.next = self.cmd_index.next.wrapping_add(1) & 0x7FFF_FFFF;
        }
    }

    /// Index management (`MCC_ResetCommandIndex`, `MCC_SetCommandIndex`).
    pub fn set_command_index(&mut self, index: i32, manual: bool) {
        self.cmd_index.next = index;
        self.cmd_index.auto = !manual;
    }

    /// The index the next queued command gets.
    pub fn next_command_index(&self) -> i32 {
        self.cmd_index.next
    }

    /// The index of the last command started (`MCC_GetCommandIndex`, as the vendor's
    /// library answers: a command queued and not started yet does not count; 0 before
    /// any).
    pub fn last_command_index(&self) -> i32 {
        self.cmd_index.last_started.map_or(0, |(i, _)| i)
    }

    /// `MCC_ResetCommandIndexLD`.
    pub fn reset_ld_index(&mut self) {
        self.cmd_index.ld = 0;
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

    /// Whether a new command may start now.
    pub(super) fn may_start(&self) -> bool {
        self.error == 0
            && matches!(self.mode, Mode::Normal)
            && (!self.single_block || self.single_block_credit)
            && !self.inpos_wait.is_some_and(|w| w.blocks())
            && self.kinematics_ready()
    }

    /// Pops queued switches that act at once (in-position, outputs); returns the next
    /// command to run. A blending switch runs as a command of one period (the vendor's
    /// library shows it as the current command) and takes effect as it starts.
    pub(super) fn pop_next(&mut self) -> Option<Command> {
        while let Some(front) = self.queue.front() {
            match front.plan {
                Plan::Blend(on) => {
                    self.blend_on = on;
                    return self.pop_queued();
                }
                Plan::InPos(on, mask) => {
                    if on {
                        self.inpos_mask |= mask;
                    } else {
                        self.inpos_mask &= !mask;
                    }
                    // A command of one period too (`COMMAND_INFO` types 11 and 12).
                    return self.pop_queued();
                }
                Plan::Output(o) => self.outputs.push(o),
                _ => return self.pop_queued(),
            }
            self.pop_queued();
        }
        None
    }

    /// Takes the front of the queue (its length is part of the published info).
    pub(super) fn pop_queued(&mut self) -> Option<Command> {
        let cmd = self.queue.pop_front();
        if cmd.is_some() {
            self.info_touched();
        }
        cmd
    }

    /// Drops every queued command (its length is part of the published info).
    pub(super) fn clear_queue(&mut self) {
        if !self.queue.is_empty() {
            self.queue.clear();
            self.info_touched();
        }
    }

    /// The next queued command's plan, looking past the switches that act at once
    /// (in-position, outputs; a blending switch is a command of its own).
    pub(super) fn peek_motion(&self) -> Option<&Plan> {
        self.queue
            .iter()
            .map(|c| &c.plan)
            .find(|p| !matches!(p, Plan::Output(_)))
    }

    /// Output changes the queue reached since the last call.
    pub fn take_outputs(&mut self) -> Vec<Output> {
        std::mem::take(&mut self.outputs)
    }

    /// Whether the queue reached output changes since the last [`GroupState::take_outputs`].
    pub fn has_outputs(&self) -> bool {
        !self.outputs.is_empty()
    }
}
