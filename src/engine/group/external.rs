//! The calls an MC3B executor makes on its group.

use crate::config::AXES;
use crate::engine::command::{AxisMech, Command};
use crate::planner::Axes;

/// What the executor needs of its group, and nothing more: the group's settings, its
/// queue, its running commands and its position. `GroupState` implements it; the executor
/// is taken out of the group while it runs, so none of these calls reaches it.
pub(in crate::engine::group) trait Host {
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
