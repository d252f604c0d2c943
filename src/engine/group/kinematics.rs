//! A kinematic group's joints (`MCC_SetKinematicTrans`) and its side of the kinematics
//! stage: what the stage reads under the group's lock (`GroupState::kinematics_job`),
//! the callbacks it runs without the lock ([`Job::call`]), and what it stores afterwards
//! (`GroupState::kinematics_done`). The model is in [`crate::engine::kinematics`].

use super::GroupState;
use crate::config::AXES;
use crate::engine::command::{Command, Plan};
use crate::engine::kinematics::{JointMove, KinFns, KIN_AXES};
use crate::error::{McclError, McclResult};
use crate::error_record::ErrorRecord;
use crate::planner::{Axes, Path, PathMove};
use crate::vendor::consts as c;
use crate::vendor::{DWORD, PRE_PROCESS_MOTION_COMMAND};
use std::os::raw::c_int;
use std::sync::atomic::{AtomicU64, Ordering};

/// Error record of a failed forward kinematics (0xF105).
pub const ERR_FORWARD: i32 = ErrorRecord::ForwardKinematics.code();
/// Error record of a failed inverse kinematics (0xF106).
pub const ERR_INVERSE: i32 = ErrorRecord::InverseKinematics.code();

/// Tells registrations apart, so a result computed for a replaced registration is
/// dropped.
static GENERATION: AtomicU64 = AtomicU64::new(1);

/// The kinematics of a group.
#[derive(Debug)]
pub struct Kinematics {
    fns: KinFns,
    pre: PRE_PROCESS_MOTION_COMMAND,
    generation: u64,
    /// The joints the channels carry now.
    joints: Axes,
    /// The joints the next tick applies (computed by the stage).
    next: Option<Axes>,
    /// The Cartesian point of the latest joints (`None` inside a joint move).
    cart: Option<Axes>,
    /// The posture handed to the kinematics (each V6 command sets it when it starts;
    /// the callbacks may change it).
    posture: DWORD,
    /// A joint move seen running: its joint target and Cartesian end.
    joint_move: Option<(Axes, Axes)>,
    /// The joints at the end of the queue when that end is a joint target:
    /// `(Cartesian queue end, joints)`.
    queued_joints: Option<(Axes, Axes)>,
    /// The queued command the pre-process callback has seen: (commands started then,
    /// index, target after the offset).
    pre_done: Option<(i32, i32, Axes)>,
}

/// What the stage does for one group outside its lock.
#[derive(Debug)]
pub struct Job {
    group: usize,
    generation: u64,
    fns: KinFns,
    posture: DWORD,
    step: Step,
    pre: Option<PreRequest>,
}

#[derive(Debug)]
enum Step {
    None,
    /// Joints given directly (a joint move), with their Cartesian point when known.
    Direct(Axes, Option<Axes>),
    /// The inverse kinematics of `cart`, from the previous joints.
    Inverse {
        cart: Axes,
        prev: Axes,
    },
    /// A joint move stopped part-way: the Cartesian point of the joints, the group
    /// standing at `at`.
    Forward {
        joints: Axes,
        at: Axes,
    },
}

#[derive(Debug)]
struct PreRequest {
    f: PRE_PROCESS_MOTION_COMMAND,
    id: (i32, i32, Axes),
    cur: Axes,
}

/// What the callbacks returned.
#[derive(Debug)]
pub struct Done {
    generation: u64,
    posture: DWORD,
    step: StepDone,
    pre: Option<((i32, i32, Axes), Axes)>,
}

#[derive(Debug)]
enum StepDone {
    None,
    Direct(Axes, Option<Axes>),
    Inverse(Axes, Option<Axes>),
    Forward(Axes, Option<Axes>),
}

impl Job {
    /// Runs the callbacks (no lock may be held).
    pub fn call(self) -> Done {
        let mut posture = self.posture;
        let pre = self.pre.and_then(|p| {
            let f = p.f?;
            let mut off = [0.0; AXES];
            // SAFETY: a C function pointer the program registered with this signature;
            // each array holds AXES doubles, the extension lives as long as `fns`.
            unsafe {
                f(
                    c_int::try_from(self.group).unwrap_or(0),
                    KIN_AXES,
                    p.cur.as_ptr(),
                    p.id.2.as_ptr(),
                    off.as_mut_ptr(),
                    self.fns.ext.ptr(),
                )
            };
            Some((p.id, off))
        });
        let step = match self.step {
            Step::None => StepDone::None,
            Step::Direct(j, c) => StepDone::Direct(j, c),
            Step::Inverse { cart, prev } => {
                let r = self.fns.inverse(self.group, &cart, &prev, &mut posture);
                StepDone::Inverse(cart, r)
            }
            Step::Forward { joints, at } => {
                let r = self.fns.forward(self.group, &joints, &mut posture);
                StepDone::Forward(at, r)
            }
        };
        Done {
            generation: self.generation,
            posture,
            step,
            pre,
        }
    }
}

/// The identity of a queued command for the pre-process callback.
fn pre_id(ld: i32, cmd: &Command) -> (i32, i32, Axes) {
    (ld, cmd.index, cmd.target)
}

impl GroupState {
    /// Whether the group is kinematic.
    pub fn is_kinematic(&self) -> bool {
        self.kin.is_some()
    }

    /// The joints the channels carry: a kinematic group's joints, else the reference
    /// positions of the axes.
    pub fn current_joints(&self) -> Axes {
        match &self.kin {
            Some(k) => k.joints,
            None => std::array::from_fn(|i| self.ref_pos(i)),
        }
    }

    /// For `MCC_GetCurPos`: the kinematics, the joints out now, the posture and the
    /// registration's generation; `None` for a group that is not kinematic.
    pub fn kinematics_reading(&self) -> Option<(KinFns, Axes, DWORD, u64)> {
        self.kin
            .as_ref()
            .map(|k| (k.fns.clone(), k.joints, k.posture, k.generation))
    }

    /// The forward kinematics failed in a reading of registration `generation`: the
    /// group stops with 0xF105 (it no longer knows where the tool is).
    pub fn forward_failed(&mut self, generation: u64) {
        if self
            .kin
            .as_ref()
            .is_some_and(|k| k.generation == generation)
        {
            self.stop_for(Some(ERR_FORWARD));
        }
    }

    /// `MCC_SetKinematicTrans`, after the extension was initialised and the forward
    /// kinematics gave `cart` for `joints` (read with [`GroupState::current_joints`]
    /// before, without the lock): the group becomes kinematic, its channels keep
    /// `joints`, its command position becomes `cart`. Refused while it moves or homes
    /// (`COMMAND_NOTFINISHED_ERR`), if its joints moved meanwhile (the same), or on an
    /// MC3B (`COMMAND_NOTACCEPTED_ERR`).
    pub fn set_kinematics(
        &mut self,
        fns: KinFns,
        joints: Axes,
        cart: Axes,
        posture: DWORD,
    ) -> McclResult<()> {
        if self.external.is_some() {
            return Err(McclError::NotAccepted);
        }
        if self.busy() || self.homing != 0 || self.current_joints() != joints {
            return Err(McclError::NotFinished);
        }
        let pre = self.kin.as_ref().and_then(|k| k.pre);
        self.kin = Some(Box::new(Kinematics {
            fns,
            pre,
            generation: GENERATION.fetch_add(1, Ordering::Relaxed),
            joints,
            next: None,
            cart: Some(cart),
            posture,
            joint_move: None,
            queued_joints: None,
            pre_done: None,
        }));
        self.offset = [0.0; AXES];
        self.info_touched();
        self.pos = cart;
        self.base = cart;
        self.queue_end = cart;
        self.vel = [0.0; AXES];
        Ok(())
    }

    /// `MCC_SetPreProcessMotionCommandCallback` (NULL removes it);
    /// `COMMAND_NOTACCEPTED_ERR` on a group that is not kinematic.
    pub fn set_preprocess(&mut self, f: PRE_PROCESS_MOTION_COMMAND) -> McclResult<()> {
        let k = self.kin.as_mut().ok_or(McclError::NotAccepted)?;
        k.pre = f;
        k.pre_done = None;
        Ok(())
    }

    /// The joints a joint move queued now starts from, when known: the joints at the
    /// end of the queue (the group at rest, or the queue ending with a joint move).
    pub fn queue_end_joints(&self) -> Option<Axes> {
        let k = self.kin.as_ref()?;
        if self.queue.is_empty() && self.running.is_empty() && k.joint_move.is_none() {
            return Some(k.next.unwrap_or(k.joints));
        }
        k.queued_joints
            .filter(|(c, _)| *c == self.queue_end)
            .map(|(_, j)| j)
    }

    /// Queues `cmd`, a joint move to `target` (`MCC_PtP_V6`).
    pub fn enqueue_joint_move(&mut self, cmd: Command, target: Axes) -> McclResult<i32> {
        let end = cmd.target;
        let i = self.enqueue(cmd)?;
        if let Some(k) = self.kin.as_mut() {
            k.queued_joints = Some((end, target));
        }
        Ok(i)
    }

    /// Called as `cmd` starts: a V6 command sets the posture; a joint move is planned
    /// from the joints where it starts (a plan that fails — it cannot, as its numbers
    /// were checked when it was queued — stops the group as a fault of the library).
    pub(super) fn kinematics_start(&mut self, mut cmd: Command) -> Command {
        let Some(k) = self.kin.as_mut() else {
            return cmd;
        };
        if let Some(p) = cmd.posture {
            k.posture = p;
        }
        let from = k.next.unwrap_or(k.joints);
        if let Plan::Joint(j) = &mut cmd.plan {
            match j.plan(&from) {
                Ok(m) => j.planned = Some(m),
                Err(_) => self.set_error(crate::engine::safety::ERR_INTERNAL),
            }
        }
        cmd
    }

    /// Whether the front command may start: with a pre-process callback, a Cartesian
    /// move waits until the callback has seen it (the stage after the tick calls it).
    pub(super) fn kinematics_ready(&self) -> bool {
        let Some(k) = &self.kin else {
            return true;
        };
        if k.pre.is_none() {
            return true;
        }
        match self.front_moving() {
            Some(cmd) if matches!(cmd.plan, Plan::Path(_)) => {
                k.pre_done == Some(pre_id(self.cmd_index.ld, cmd))
            }
            _ => true,
        }
    }

    /// The first queued command that is not a switch.
    fn front_moving(&self) -> Option<&Command> {
        self.queue
            .iter()
            .find(|c| !matches!(c.plan, Plan::Blend(_) | Plan::InPos(..) | Plan::Output(_)))
    }

    /// In the tick, after the group's own tick: the joints the stage computed go out;
    /// while the joints still owe the planner's position, the group is not stopped.
    pub fn kinematics_apply(&mut self) {
        let Some(k) = self.kin.as_mut() else {
            return;
        };
        if let Some(j) = k.next.take() {
            k.joints = j;
        }
        self.running_while_owed();
    }

    /// A group whose joints have not yet reached its planner's position is running.
    fn running_while_owed(&mut self) {
        let Some(k) = self.kin.as_ref() else {
            return;
        };
        let owed = k.next.is_some() || k.cart != Some(self.pos) || k.joint_move.is_some();
        if owed && self.status == c::GMS_STOP && self.error == 0 {
            self.status = c::GMS_RUNNING;
        }
    }

    /// The pulses of axis `i` of a kinematic group: its joint's.
    pub(super) fn kinematics_pulses(&self, i: usize) -> Option<i64> {
        self.kin
            .as_ref()
            .map(|k| crate::engine::snapshot::round_pulses(k.joints[i] * self.axes[i].factor))
    }

    /// The pulses of a kinematic group's joints (`None` for another group).
    pub fn kinematics_joint_pulses(&self) -> Option<[i64; AXES]> {
        self.kin.as_ref()?;
        Some(std::array::from_fn(|i| self.pulses(i)))
    }

    /// The stage, under the lock: what to compute for the next tick.
    pub(crate) fn kinematics_job(&mut self) -> Option<Job> {
        if self.kin.as_ref().is_some_and(|k| k.pre.is_some()) {
            self.rebase_front();
        }
        let joint_running = self.running.iter().find_map(|r| match &r.cmd.plan {
            Plan::Joint(j) => Some((
                j.target,
                j.cart_end,
                j.joints_at(r.periods),
                r.periods >= j.periods(),
            )),
            _ => None,
        });
        let pre = self.pre_request();
        let pos = self.pos;
        let k = self.kin.as_mut()?;
        let latest = k.next.unwrap_or(k.joints);
        let step = if let Some((target, cart_end, joints, done)) = joint_running {
            k.joint_move = Some((target, cart_end));
            Step::Direct(joints, done.then_some(cart_end))
        } else if let Some((target, cart_end)) = k.joint_move.take() {
            if pos == cart_end {
                Step::Direct(target, Some(cart_end))
            } else {
                Step::Forward {
                    joints: latest,
                    at: pos,
                }
            }
        } else if k.cart != Some(pos) {
            Step::Inverse {
                cart: pos,
                prev: latest,
            }
        } else {
            Step::None
        };
        if matches!(step, Step::None) && pre.is_none() {
            return None;
        }
        Some(Job {
            group: self.index,
            generation: k.generation,
            fns: k.fns.clone(),
            posture: k.posture,
            step,
            pre,
        })
    }

    fn pre_request(&self) -> Option<PreRequest> {
        let k = self.kin.as_ref()?;
        k.pre?;
        let cmd = self.front_moving()?;
        if !matches!(cmd.plan, Plan::Path(_)) {
            return None;
        }
        let id = pre_id(self.cmd_index.ld, cmd);
        if k.pre_done == Some(id) {
            return None;
        }
        Some(PreRequest {
            f: k.pre,
            id,
            cur: self.pos,
        })
    }

    /// The stage, under the lock again: stores what the callbacks returned (dropped if
    /// the registration changed or the group moved meanwhile).
    pub(crate) fn kinematics_done(&mut self, d: Done) {
        let Some(k) = self.kin.as_mut() else {
            return;
        };
        if k.generation != d.generation {
            return;
        }
        k.posture = d.posture;
        match d.step {
            StepDone::None => {}
            StepDone::Direct(j, cart) => {
                k.next = Some(j);
                k.cart = cart;
            }
            StepDone::Inverse(cart, Some(j)) => {
                if self.pos == cart {
                    k.next = Some(j);
                    k.cart = Some(cart);
                }
            }
            StepDone::Inverse(cart, None) => {
                if self.pos == cart {
                    // Unreachable: stop; the joints stay, the planner goes back to the
                    // last point they reached.
                    let good = k.cart;
                    self.stop_for(Some(ERR_INVERSE));
                    if let Some(g) = good {
                        self.rest_at(g);
                    }
                }
            }
            StepDone::Forward(at, r) => {
                if self.pos == at && self.running.is_empty() && self.queue.is_empty() {
                    match r {
                        Some(cart) => {
                            k.cart = Some(cart);
                            self.rest_at(cart);
                        }
                        None => {
                            k.cart = Some(at);
                            self.stop_for(Some(ERR_FORWARD));
                        }
                    }
                }
            }
        }
        if let Some((id, off)) = d.pre {
            self.apply_offset(id, off);
        }
        self.update_status();
        self.running_while_owed();
    }

    /// With offsets, a queued delay or joint move starts where the command before it
    /// actually ends (a delay holds that position).
    fn rebase_front(&mut self) {
        let start = self.actual_start();
        let Some(cmd) = self
            .queue
            .iter_mut()
            .find(|c| !matches!(c.plan, Plan::Blend(_) | Plan::InPos(..) | Plan::Output(_)))
        else {
            return;
        };
        match &mut cmd.plan {
            Plan::Delay(_) => cmd.target = start,
            Plan::Joint(j) => j.cart_start = start,
            _ => {}
        }
    }

    /// The group stands at Cartesian `cart` (its planner's position and queue end).
    fn rest_at(&mut self, cart: Axes) {
        self.pos = cart;
        self.base = cart;
        self.queue_end = cart;
        self.vel = [0.0; AXES];
    }

    /// Where the front queued command actually starts: the end of the running commands
    /// (each planned from where the one before it ended), or where the group stands.
    fn actual_start(&self) -> Axes {
        self.running.back().map_or(self.base, |r| r.cmd.target)
    }

    /// The pre-process callback returned `off` for the command `id`: a line is planned
    /// again from where it actually starts to its target + `off`; an arc or circle keeps
    /// its shape and starts where the tool is (moved by the offset when the offset is
    /// the one of the command before it). A non-finite offset counts as 0.
    fn apply_offset(&mut self, id: (i32, i32, Axes), off: Axes) {
        let off = if off.iter().all(|x| x.is_finite()) {
            off
        } else {
            [0.0; AXES]
        };
        let start = self.actual_start();
        let ld = self.cmd_index.ld;
        let Some(pos) = self
            .queue
            .iter()
            .position(|c| !matches!(c.plan, Plan::Blend(_) | Plan::InPos(..) | Plan::Output(_)))
        else {
            return;
        };
        let cmd = &mut self.queue[pos];
        if pre_id(ld, cmd) != id {
            return;
        }
        if let Plan::Path(m) = &cmd.plan {
            let target: Axes = std::array::from_fn(|i| cmd.target[i] + off[i]);
            let s = m.path.start();
            let path = match &m.path {
                Path::Line(_) => Path::try_line(&start, &target).ok(),
                p => Some(p.translated(&std::array::from_fn(|i| start[i] - s[i]))),
            };
            let (feed, ramps, shapes, t) = (m.feed, m.ramps, m.shapes, m.profile.period());
            let planned = path.map(|path| PathMove::new(path, feed, ramps, shapes, t));
            if let Some(mv) = planned {
                cmd.target = mv.path.end();
                cmd.plan = Plan::Path(mv);
            }
        }
        let done = pre_id(ld, cmd);
        if let Some(k) = self.kin.as_mut() {
            k.pre_done = Some(done);
        }
    }
}

/// A queued joint move's command (`MCC_PtP_V6`): the plan is made when it starts.
pub fn joint_command(j: JointMove, ratio: f64, acc_ms: f64, dec_ms: f64) -> Command {
    Command {
        index: 0,
        ctype: crate::engine::command::ctype::PTP,
        info_feed: ratio,
        target: j.cart_end,
        acc_ms,
        dec_ms,
        posture: None,
        plan: Plan::Joint(Box::new(j)),
    }
}
