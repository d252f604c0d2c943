//! A kinematic group's joints (`MCC_SetKinematicTrans`) and its side of the kinematics
//! stage: which space its planner is in, what the stage reads under the group's lock
//! (`GroupState::kinematics_job`), the callbacks it runs without the lock ([`Job::call`]),
//! and what it stores afterwards (`GroupState::kinematics_done`). The model is in
//! [`crate::engine::kinematics`].
//!
//! # The planner's two spaces
//!
//! In joint space (after the kinematics are applied, and for point-to-point moves) the
//! group's positions are its joints: a PtP runs as on any group, and what it publishes
//! is the joints' own positions, speeds and command. In Cartesian space (for path
//! commands) its positions are the tool's, and it publishes the joints the stage computed
//! from them instead (`GroupState::kinematics_published`). The group's queue end is
//! Cartesian in both (path commands are resolved and planned against it; a joint move
//! queued sets it to the forward kinematics of its target).
//!
//! The space changes only while nothing runs, when the next command to start needs the
//! other one; that command waits until then (`GroupState::kinematics_ready`):
//!
//! * to joint space, under the lock (no callback needed): the planner's position becomes
//!   the joints out now; the PtP is planned again from there if it was queued from other
//!   joints;
//! * to Cartesian space, in the stage: the forward kinematics of the joints is where the
//!   tool is; the path command is planned again from there if it was queued from another
//!   point (a line keeps its target, a curve its shape), so that the joints never jump.

use super::GroupState;
use crate::config::AXES;
use crate::engine::command::{Command, Plan};
use crate::engine::kinematics::{KinFns, KIN_AXES};
use crate::engine::snapshot::{whole_pulses, Motion};
use crate::error::{McclError, McclResult};
use crate::error_record::ErrorRecord;
use crate::planner::{Axes, Path, PathMove, PtpMove};
use crate::vendor::consts as c;
use crate::vendor::{DWORD, PRE_PROCESS_MOTION_COMMAND};
use std::os::raw::c_int;

/// Error record of a failed forward kinematics (0xF105).
pub const ERR_FORWARD: i32 = ErrorRecord::ForwardKinematics.code();
/// Error record of a failed inverse kinematics (0xF106).
pub const ERR_INVERSE: i32 = ErrorRecord::InverseKinematics.code();

/// The space a kinematic group's planner works in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Space {
    /// Positions are joints (point-to-point moves).
    Joint,
    /// Positions are the tool's (path commands).
    Cartesian,
}

/// The kinematics of a group.
#[derive(Debug)]
pub struct Kinematics {
    fns: KinFns,
    pre: PRE_PROCESS_MOTION_COMMAND,
    generation: u64,
    space: Space,
    /// The joints the channels carry now.
    joints: Axes,
    /// The joints the next tick applies (computed by the stage, Cartesian space).
    next: Option<Axes>,
    /// In Cartesian space, the Cartesian point of the latest joints.
    cart: Option<Axes>,
    /// The joints' speeds over the last period (UU/s) and their composed speed, what the
    /// group publishes in Cartesian space.
    vel: Axes,
    feed: f64,
    /// In joint space, the joints whose Cartesian point is the queue end, when the group
    /// stopped somewhere else (an abort, an error): the stage finds where the tool is.
    queue_end_stale: bool,
    /// The posture handed to the kinematics (each V6 command sets it when it starts;
    /// the callbacks may change it).
    posture: DWORD,
    /// The joints at the end of the queue when that end is a joint move:
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
    /// The inverse kinematics of `cart`, from the previous joints.
    Inverse {
        cart: Axes,
        prev: Axes,
    },
    /// The forward kinematics of the joints the group stands at: for the path command
    /// at the front (`switch`), or for the queue end.
    Forward {
        joints: Axes,
        switch: bool,
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
    Inverse(Axes, Option<Axes>),
    Forward {
        joints: Axes,
        switch: bool,
        cart: Option<Axes>,
    },
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
            Step::Inverse { cart, prev } => {
                let r = self.fns.inverse(self.group, &cart, &prev, &mut posture);
                StepDone::Inverse(cart, r)
            }
            Step::Forward { joints, switch } => {
                let cart = self.fns.forward(self.group, &joints, &mut posture);
                StepDone::Forward {
                    joints,
                    switch,
                    cart,
                }
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

/// Whether a command moves the tool in Cartesian space on a kinematic group (a path
/// command or a custom motion); a PtP moves the joints, the rest moves nothing.
fn cartesian(plan: &Plan) -> bool {
    matches!(plan, Plan::Path(_) | Plan::Custom(_))
}

impl GroupState {
    /// Whether the group is kinematic.
    pub fn is_kinematic(&self) -> bool {
        self.features.kin.is_some()
    }

    /// The joints the channels carry: a kinematic group's joints, else the reference
    /// positions of the axes.
    pub fn current_joints(&self) -> Axes {
        match &self.features.kin {
            Some(k) => k.joints,
            None => std::array::from_fn(|i| self.ref_pos(i)),
        }
    }

    /// The kinematics of the group and its posture (`None` for a group that is not
    /// kinematic).
    pub fn kinematics_fns(&self) -> Option<(KinFns, DWORD)> {
        self.features
            .kin
            .as_ref()
            .map(|k| (k.fns.clone(), k.posture))
    }

    /// What a kinematic group in Cartesian space publishes: the joints, their speeds and
    /// composed speed (in joint space its own positions are the joints, and it publishes
    /// them as any group). `None` otherwise.
    pub(super) fn kinematics_published(&self) -> Option<Motion> {
        let k = self.features.kin.as_ref()?;
        (k.space == Space::Cartesian).then_some(Motion {
            status: self.status,
            pos: k.joints,
            vel: k.vel,
            feed: k.feed,
        })
    }

    /// The kinematics registered before init take effect (the forward kinematics gave
    /// `cart` for `joints`, read with [`GroupState::current_joints`] before, without the
    /// lock): the group becomes kinematic in joint space, standing at `joints`, with its
    /// queue end at `cart`. Refused while it moves or homes (`COMMAND_NOTFINISHED_ERR`),
    /// if its joints moved meanwhile (the same), or on an MC3B (`COMMAND_NOTACCEPTED_ERR`).
    /// `generation` tells this registration apart from every other the caller applies,
    /// so that a result computed for a replaced one is dropped.
    pub fn set_kinematics(
        &mut self,
        fns: KinFns,
        generation: u64,
        joints: Axes,
        cart: Axes,
        posture: DWORD,
    ) -> McclResult<()> {
        if self.features.external.is_some() {
            return Err(McclError::NotAccepted);
        }
        if self.busy() || self.homing != 0 || self.current_joints() != joints {
            return Err(McclError::NotFinished);
        }
        self.features.kin = Some(Box::new(Kinematics {
            fns,
            pre: None,
            generation,
            space: Space::Joint,
            joints,
            next: None,
            cart: None,
            vel: [0.0; AXES],
            feed: 0.0,
            queue_end_stale: false,
            posture,
            queued_joints: None,
            pre_done: None,
        }));
        self.exec.offset = [0.0; AXES];
        self.info_touched();
        self.exec.pos = joints;
        self.exec.base = joints;
        self.queued.end = cart;
        self.exec.vel = [0.0; AXES];
        Ok(())
    }

    /// `MCC_SetPreProcessMotionCommandCallback` (NULL removes it);
    /// `COMMAND_NOTACCEPTED_ERR` on a group that is not kinematic.
    pub fn set_preprocess(&mut self, f: PRE_PROCESS_MOTION_COMMAND) -> McclResult<()> {
        let k = self.features.kin.as_mut().ok_or(McclError::NotAccepted)?;
        k.pre = f;
        k.pre_done = None;
        Ok(())
    }

    /// The joints a joint move queued now starts from, when known: the joints at the
    /// end of the queue (the group at rest, or the queue ending with a joint move).
    pub fn queue_end_joints(&self) -> Option<Axes> {
        let k = self.features.kin.as_ref()?;
        if self.queued.commands.is_empty() && self.exec.running.is_empty() {
            return Some(k.next.unwrap_or(k.joints));
        }
        k.queued_joints
            .filter(|(c, _)| *c == self.queued.end)
            .map(|(_, j)| j)
    }

    /// Queues `cmd`, a point-to-point move of the joints to `target` (planned from the
    /// joints at the queue end when known), whose tool point there is `cart_end`: the
    /// queue's (Cartesian) end becomes `cart_end`. A group at rest changes to joint
    /// space at once.
    pub fn enqueue_joint_move(
        &mut self,
        cmd: Command,
        target: Axes,
        cart_end: Axes,
    ) -> McclResult<i32> {
        let i = self.enqueue(cmd)?;
        self.queued.end = cart_end;
        if let Some(k) = self.features.kin.as_mut() {
            k.queued_joints = Some((cart_end, target));
        }
        if self.exec.running.is_empty() {
            self.enter_joint_space();
        }
        Ok(i)
    }

    /// Nothing runs and the next command moves the joints: the planner's position becomes
    /// the joints out now (or due next).
    fn enter_joint_space(&mut self) {
        let Some(k) = self.features.kin.as_mut() else {
            return;
        };
        if k.space == Space::Joint {
            return;
        }
        let joints = k.next.take().unwrap_or(k.joints);
        k.space = Space::Joint;
        k.cart = None;
        k.queue_end_stale = false;
        self.exec.pos = joints;
        self.exec.base = joints;
        self.exec.vel = [0.0; AXES];
    }

    /// Called as `cmd` starts: a V6 command sets the posture; a PtP (in joint space, see
    /// [`GroupState::kinematics_ready`]) queued from other joints than where the group
    /// stands moves each joint by what it was queued to move, from there, with the
    /// speeds, ramps and shapes it was queued with: never a jump, and a jog moves its
    /// joint by its distance. (`MCC_PtP_V6` and `MCC_PtP` plan from the joints at the
    /// queue end, so theirs start where they were planned.) A plan that fails — it
    /// cannot, as its numbers were checked when it was queued — stops the group as a
    /// fault of the library.
    pub(super) fn kinematics_start(&mut self, mut cmd: Command) -> Command {
        let Some(k) = self.features.kin.as_mut() else {
            return cmd;
        };
        if let Some(p) = cmd.posture {
            k.posture = p;
        }
        let from = self.exec.pos;
        let ratio = cmd.info_feed;
        let (acc_ms, dec_ms) = (cmd.acc_ms, cmd.dec_ms);
        let mut replanned_end = None;
        if let Plan::Ptp(p) = &mut cmd.plan {
            let (s, e) = (p.start(), p.end());
            if s != from {
                let period_ms = self.exec.period_s * 1000.0;
                let periods = |ms: f64| (ms / period_ms).round() as u32;
                let speed: Axes =
                    std::array::from_fn(|i| self.mech.axes[i].safe_speed * ratio / 100.0);
                let ramps = [(periods(acc_ms), periods(dec_ms)); AXES];
                let shapes = [p.shapes(); AXES];
                let end: Axes = std::array::from_fn(|i| from[i] + (e[i] - s[i]));
                let sync = p.is_sync();
                match PtpMove::new(
                    &from,
                    &end,
                    &speed,
                    &ramps,
                    &shapes,
                    self.exec.period_s,
                    sync,
                ) {
                    Ok(m) => {
                        replanned_end = Some(m.end());
                        *p = m;
                    }
                    Err(_) => self.set_error(crate::error_record::ErrorRecord::Internal.code()),
                }
            }
        }
        if let Some(end) = replanned_end {
            cmd.target = end;
        }
        cmd
    }

    /// Whether the front command may start: one that needs the other space waits until
    /// nothing runs and the group has changed to it (into joint space after the tick
    /// that ends what runs, see [`GroupState::kinematics_apply`]; into Cartesian space in
    /// the stage); with a pre-process callback, a path command waits until the callback
    /// has seen it.
    pub(super) fn kinematics_ready(&self) -> bool {
        let Some(k) = &self.features.kin else {
            return true;
        };
        let Some(cmd) = self.front_moving() else {
            return true;
        };
        match (&cmd.plan, k.space) {
            (Plan::Ptp(_), Space::Cartesian) => false,
            (plan, Space::Joint) if cartesian(plan) => false,
            (Plan::Path(_), Space::Cartesian) if k.pre.is_some() => {
                k.pre_done == Some(pre_id(self.queued.index.ld, cmd))
            }
            _ => true,
        }
    }

    /// The first queued command that is not a switch.
    fn front_moving(&self) -> Option<&Command> {
        self.queued
            .commands
            .iter()
            .find(|c| !matches!(c.plan, Plan::Blend(_) | Plan::InPos(..) | Plan::Output(_)))
    }

    /// In Cartesian space, whether the joints still owe the planner's position.
    fn kinematics_owed(&self) -> bool {
        self.features.kin.as_ref().is_some_and(|k| {
            k.space == Space::Cartesian && (k.next.is_some() || k.cart != Some(self.exec.pos))
        })
    }

    /// In the tick, after the group's own tick: the joints go out (in joint space the
    /// group's positions, in Cartesian space those the stage computed), with their speeds
    /// over the period; while the joints still owe the planner's position, the group is
    /// not stopped.
    pub fn kinematics_apply(&mut self) {
        let pos: Axes = std::array::from_fn(|i| self.exec.pos[i] + self.exec.offset[i]);
        let (dt, compose) = (self.exec.period_s, self.settings.compose);
        let Some(k) = self.features.kin.as_mut() else {
            return;
        };
        let before = k.joints;
        match k.space {
            Space::Joint => {
                k.joints = pos;
                k.next = None;
            }
            Space::Cartesian => {
                if let Some(j) = k.next.take() {
                    k.joints = j;
                }
            }
        }
        if dt > 0.0 {
            k.vel = std::array::from_fn(|i| (k.joints[i] - before[i]) / dt);
            k.feed = crate::planner::compose::composed_speed(&k.vel, compose);
        }
        if k.space == Space::Joint && k.joints != before {
            // Wherever this move ends, the stage finds the tool there if the group
            // stops short of the queue end.
            k.queue_end_stale = true;
        }
        let ptp_next = self
            .front_moving()
            .is_some_and(|c| matches!(c.plan, Plan::Ptp(_)));
        if ptp_next && self.exec.running.is_empty() && !self.kinematics_owed() {
            self.enter_joint_space();
        }
        self.running_while_owed();
    }

    /// A group whose joints have not yet reached its planner's position is running.
    fn running_while_owed(&mut self) {
        if self.kinematics_owed() && self.status == c::GMS_STOP && self.error == 0 {
            self.status = c::GMS_RUNNING;
        }
    }

    /// The pulses of axis `i` of a kinematic group: its joint's.
    pub(super) fn kinematics_pulses(&self, i: usize) -> Option<i64> {
        self.features
            .kin
            .as_ref()
            .map(|k| whole_pulses(k.joints[i] * self.mech.axes[i].factor))
    }

    /// The stage, under the lock: what to compute for the next tick.
    pub fn kinematics_job(&mut self) -> Option<Job> {
        let k = self.features.kin.as_ref()?;
        let (space, pre_set) = (k.space, k.pre.is_some());
        let idle = self.exec.running.is_empty();
        let front_path = self.front_moving().is_some_and(|c| cartesian(&c.plan));
        if space == Space::Cartesian && pre_set {
            self.rebase_front();
        }
        let pre = if space == Space::Cartesian {
            self.pre_request()
        } else {
            None
        };
        let pos = self.exec.pos;
        let queue_empty = self.queued.commands.is_empty();
        let k = self.features.kin.as_mut()?;
        let latest = k.next.unwrap_or(k.joints);
        let step = match space {
            Space::Cartesian if k.cart != Some(pos) => Step::Inverse {
                cart: pos,
                prev: latest,
            },
            Space::Cartesian => Step::None,
            Space::Joint if idle && front_path => Step::Forward {
                joints: k.joints,
                switch: true,
            },
            Space::Joint if idle && queue_empty && k.queue_end_stale => Step::Forward {
                joints: k.joints,
                switch: false,
            },
            Space::Joint => Step::None,
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
        let k = self.features.kin.as_ref()?;
        k.pre?;
        let cmd = self.front_moving()?;
        if !matches!(cmd.plan, Plan::Path(_)) {
            return None;
        }
        let id = pre_id(self.queued.index.ld, cmd);
        if k.pre_done == Some(id) {
            return None;
        }
        Some(PreRequest {
            f: k.pre,
            id,
            cur: self.exec.pos,
        })
    }

    /// The stage, under the lock again: stores what the callbacks returned (dropped if
    /// the registration changed or the group moved meanwhile).
    pub fn kinematics_done(&mut self, d: Done) {
        let idle = self.exec.running.is_empty();
        let queue_empty = self.queued.commands.is_empty();
        let front_path = self.front_moving().is_some_and(|c| cartesian(&c.plan));
        let Some(k) = self.features.kin.as_mut() else {
            return;
        };
        if k.generation != d.generation {
            return;
        }
        k.posture = d.posture;
        match d.step {
            StepDone::None => {}
            StepDone::Inverse(cart, Some(j)) => {
                if k.space == Space::Cartesian && self.exec.pos == cart {
                    k.next = Some(j);
                    k.cart = Some(cart);
                }
            }
            StepDone::Inverse(cart, None) => {
                if k.space == Space::Cartesian && self.exec.pos == cart {
                    // Unreachable: stop; the joints stay, the planner goes back to the
                    // last point they reached.
                    let good = k.cart;
                    self.stop_for(Some(ERR_INVERSE));
                    if let Some(g) = good {
                        self.rest_at(g);
                    }
                }
            }
            StepDone::Forward {
                joints,
                switch,
                cart,
            } => {
                let here = k.space == Space::Joint && idle && k.joints == joints;
                match (here, switch, cart) {
                    (false, _, _) => {}
                    (true, _, None) => self.stop_for(Some(ERR_FORWARD)),
                    (true, true, Some(cart)) if front_path => self.enter_cartesian_space(cart),
                    (true, false, Some(cart)) if queue_empty => {
                        k.queue_end_stale = false;
                        self.queued.end = cart;
                    }
                    _ => {}
                }
            }
        }
        if let Some((id, off)) = d.pre {
            self.apply_offset(id, off);
        }
        self.running_while_owed();
    }

    /// Nothing runs and the next command is a path command: the planner stands where
    /// the tool is, `cart` (the forward kinematics of the joints), and that command is
    /// planned again from there if it was queued from another point.
    fn enter_cartesian_space(&mut self, cart: Axes) {
        let Some(k) = self.features.kin.as_mut() else {
            return;
        };
        k.space = Space::Cartesian;
        k.cart = Some(cart);
        k.next = None;
        k.queue_end_stale = false;
        self.rest_at_keeping_queue(cart);
        let Some(pos) = self.queued.commands.iter().position(|c| cartesian(&c.plan)) else {
            return;
        };
        if self.queued.commands[pos].start() != cart {
            let moved = replanned(&self.queued.commands[pos], &cart, &[0.0; AXES]);
            if let Some((target, plan)) = moved {
                let cmd = &mut self.queued.commands[pos];
                cmd.target = target;
                cmd.plan = plan;
            }
        }
    }

    /// With offsets, a queued delay starts where the command before it actually ends
    /// (it holds that position).
    fn rebase_front(&mut self) {
        let start = self.actual_start();
        let Some(cmd) = self
            .queued
            .commands
            .iter_mut()
            .find(|c| !matches!(c.plan, Plan::Blend(_) | Plan::InPos(..) | Plan::Output(_)))
        else {
            return;
        };
        if let Plan::Delay(_) = cmd.plan {
            cmd.target = start;
        }
    }

    /// The group stands at Cartesian `cart` (its planner's position and queue end).
    fn rest_at(&mut self, cart: Axes) {
        self.rest_at_keeping_queue(cart);
        self.queued.end = cart;
    }

    /// The planner stands at `cart`; the queue end stays.
    fn rest_at_keeping_queue(&mut self, cart: Axes) {
        self.exec.pos = cart;
        self.exec.base = cart;
        self.exec.vel = [0.0; AXES];
    }

    /// Where the front queued command actually starts: the end of the running commands
    /// (each planned from where the one before it ended), or where the group stands.
    fn actual_start(&self) -> Axes {
        self.exec
            .running
            .back()
            .map_or(self.exec.base, |r| r.cmd.target)
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
        let ld = self.queued.index.ld;
        let Some(pos) =
            self.queued.commands.iter().position(|c| {
                !matches!(c.plan, Plan::Blend(_) | Plan::InPos(..) | Plan::Output(_))
            })
        else {
            return;
        };
        let cmd = &mut self.queued.commands[pos];
        if pre_id(ld, cmd) != id {
            return;
        }
        if let Some((target, plan)) = replanned(cmd, &start, &off) {
            cmd.target = target;
            cmd.plan = plan;
        }
        let done = pre_id(ld, cmd);
        if let Some(k) = self.features.kin.as_mut() {
            k.pre_done = Some(done);
        }
    }
}

/// A path command planned again to start at `start`: a line to its target + `off`, an
/// arc or circle translated (it keeps its shape); its new target and plan. `None` for
/// another command, or a line that can no longer be planned (it stays as it was).
fn replanned(cmd: &Command, start: &Axes, off: &Axes) -> Option<(Axes, Plan)> {
    let Plan::Path(m) = &cmd.plan else {
        return None;
    };
    let target: Axes = std::array::from_fn(|i| cmd.target[i] + off[i]);
    let s = m.path.start();
    let path = match &m.path {
        Path::Line(_) => Path::try_line(start, &target).ok()?,
        p => p.translated(&std::array::from_fn(|i| start[i] - s[i])),
    };
    let (feed, ramps, shapes, t) = (m.feed, m.ramps, m.shapes, m.profile.period());
    let mv = PathMove::new(path, feed, ramps, shapes, t);
    Some((mv.path.end(), Plan::Path(mv)))
}
