//! The group's bounded command queue: queuing (indices, growth, refusals), single-block
//! mode, and taking the next command off it (the switches it passes on the way).

use super::GroupState;
use super::Mode;
use crate::engine::command::{Command, Output, Plan};
use crate::error::{McclError, McclResult};
use crate::planner::Axes;
use crate::vendor::consts as c;
use std::collections::VecDeque;

/// The commands waiting to run and the queue's own state.
#[derive(Debug, Default)]
pub(super) struct Queued {
    /// The commands, oldest first. Grows as it fills (`enqueue` reserves fallibly):
    /// reserving the queue size up front (464 bytes a command) asked 44.5 GB for 96
    /// queues of 1,000,000 and aborted the program under a memory limit.
    pub(super) commands: VecDeque<Command>,
    /// End of the last queued command (user coordinates).
    pub(super) end: Axes,
    /// Command indices.
    pub(super) index: CommandIndex,
    /// Single block mode (`MCC_EnableSingleBlock`).
    pub(super) single_block: bool,
    /// Single block: one command may start.
    pub(super) single_block_credit: bool,
    /// Blending as the end of the queue will see it (`MCC_CheckBlend`).
    pub(super) blend: bool,
}

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
        self.queued.commands.len()
    }

    /// Whether a command runs (a jog by pulses included).
    pub fn commands_running(&self) -> bool {
        !self.exec.running.is_empty() || self.exec.jump.is_some()
    }

    /// Whether the group has anything to do.
    pub fn busy(&self) -> bool {
        self.status != c::GMS_STOP || !self.queued.commands.is_empty()
    }

    /// Queues a command; returns its index. `ABORT_NOT_FINISH_ERR` while an abort is
    /// still decelerating, `COMMAND_BUFFER_FULL_ERR` when the queue is full or the memory
    /// to grow it (doubling, up to the queue size) cannot be had.
    pub fn enqueue(&mut self, cmd: Command) -> McclResult<i32> {
        self.enqueue_probed(cmd, |_| {})
    }

    /// [`GroupState::enqueue`], calling `probe("enqueue")` half-way through changing the
    /// queue: a test that panics there checks that a panic leaves a defined state (the
    /// library passes its fault points, which compile to nothing outside its tests).
    pub fn enqueue_probed(
        &mut self,
        mut cmd: Command,
        probe: impl FnOnce(&'static str),
    ) -> McclResult<i32> {
        if self.homing != 0 {
            return Err(McclError::NotAccepted);
        }
        if let Some(x) = &self.features.external {
            x.check(&cmd, &self.mech.axes)?;
        }
        if self.rate.mode == Mode::Aborting {
            return Err(McclError::AbortNotFinished);
        }
        // With an error record the vendor's library refuses every command until
        // `MCC_ClearError`.
        if self.error != 0 {
            return Err(McclError::RunTime);
        }
        if self.queued.commands.len() >= self.mech.def.queue_size {
            // The vendor's library counts the refused command's index too.
            self.skip_command_index();
            return Err(McclError::BufferFull);
        }
        // Memory the queue cannot get is a full queue: an error code, never an abort.
        if self.queued.commands.len() == self.queued.commands.capacity() {
            let room = self.mech.def.queue_size - self.queued.commands.len();
            let want = self.queued.commands.len().max(QUEUE_MIN_GROWTH).min(room);
            if self.queued.commands.try_reserve_exact(want).is_err() {
                return Err(McclError::BufferFull);
            }
        }
        cmd.index = self.queued.index.next;
        if self.queued.index.auto {
            self.queued.index.next = self.queued.index.next.wrapping_add(1) & 0x7FFF_FFFF;
        }
        match cmd.plan {
            Plan::Blend(on) => self.queued.blend = on,
            _ => self.queued.end = cmd.target,
        }
        probe("enqueue");
        let idx = cmd.index;
        // An arc of no length (an angle of 0): the vendor's library takes it and runs
        // nothing.
        if matches!(&cmd.plan, Plan::Path(m)
            if m.profile.is_empty() && !matches!(m.path, crate::planner::Path::Line(_)))
        {
            return Ok(idx);
        }
        self.queued.commands.push_back(cmd);
        self.info_touched();
        self.update_status();
        Ok(idx)
    }

    /// The next index is used up without a command.
    fn skip_command_index(&mut self) {
        if self.queued.index.auto {
            self.queued.index.next = self.queued.index.next.wrapping_add(1) & 0x7FFF_FFFF;
        }
    }

    /// Index management (`MCC_ResetCommandIndex`, `MCC_SetCommandIndex`).
    pub fn set_command_index(&mut self, index: i32, manual: bool) {
        self.queued.index.next = index;
        self.queued.index.auto = !manual;
    }

    /// The index the next queued command gets.
    pub fn next_command_index(&self) -> i32 {
        self.queued.index.next
    }

    /// The index of the last command started (`MCC_GetCommandIndex`, as the vendor's
    /// library answers: a command queued and not started yet does not count; 0 before
    /// any).
    pub fn last_command_index(&self) -> i32 {
        self.queued.index.last_started.map_or(0, |(i, _)| i)
    }

    /// `MCC_ResetCommandIndexLD`.
    pub fn reset_ld_index(&mut self) {
        self.queued.index.ld = 0;
    }

    /// Single-block mode: after each command the group waits for `MCC_RunSingleBlock`.
    pub fn set_single_block(&mut self, on: bool) {
        self.queued.single_block = on;
        self.queued.single_block_credit = false;
        self.update_status();
    }

    /// `MCC_RunSingleBlock`: lets one more command run.
    pub fn run_single_block(&mut self) -> McclResult<()> {
        if !self.queued.single_block {
            return Err(McclError::NotAccepted);
        }
        self.queued.single_block_credit = true;
        self.update_status();
        Ok(())
    }

    /// `MCC_EnableBlendInstant`: switches blending now, not through the queue.
    pub fn set_blend_now(&mut self, on: bool) {
        self.exec.blend_on = on;
        self.queued.blend = on;
    }

    /// Whether a new command may start now.
    pub(super) fn may_start(&self) -> bool {
        self.error == 0
            && matches!(self.rate.mode, Mode::Normal)
            && (!self.queued.single_block || self.queued.single_block_credit)
            && !self.in_pos.wait.is_some_and(|w| w.blocks())
            && self.kinematics_ready()
    }

    /// Pops queued switches that act at once (in-position, outputs); returns the next
    /// command to run. A blending switch runs as a command of one period (the vendor's
    /// library shows it as the current command) and takes effect as it starts.
    pub(super) fn pop_next(&mut self) -> Option<Command> {
        while let Some(front) = self.queued.commands.front() {
            match front.plan {
                Plan::Blend(on) => {
                    self.exec.blend_on = on;
                    return self.pop_queued();
                }
                Plan::InPos(on, mask) => {
                    if on {
                        self.in_pos.mask |= mask;
                    } else {
                        self.in_pos.mask &= !mask;
                    }
                    // A command of one period too (`COMMAND_INFO` types 11 and 12).
                    return self.pop_queued();
                }
                Plan::Output(o) => self.emitted.outputs.push(o),
                _ => return self.pop_queued(),
            }
            self.pop_queued();
        }
        None
    }

    /// Takes the front of the queue (its length is part of the published info).
    pub(super) fn pop_queued(&mut self) -> Option<Command> {
        let cmd = self.queued.commands.pop_front();
        if cmd.is_some() {
            self.info_touched();
        }
        cmd
    }

    /// Drops every queued command (its length is part of the published info).
    pub(super) fn clear_queue(&mut self) {
        if !self.queued.commands.is_empty() {
            self.queued.commands.clear();
            self.info_touched();
        }
    }

    /// The next queued command's plan, looking past the switches that act at once
    /// (in-position, outputs; a blending switch is a command of its own).
    pub(super) fn peek_motion(&self) -> Option<&Plan> {
        self.queued
            .commands
            .iter()
            .map(|c| &c.plan)
            .find(|p| !matches!(p, Plan::Output(_)))
    }

    /// Output changes the queue reached since the last call.
    pub fn take_outputs(&mut self) -> Vec<Output> {
        std::mem::take(&mut self.emitted.outputs)
    }

    /// Whether the queue reached output changes since the last [`GroupState::take_outputs`].
    pub fn has_outputs(&self) -> bool {
        !self.emitted.outputs.is_empty()
    }
}
