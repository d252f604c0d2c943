//! A group whose channels are an MC3B (`mc3b_port` in `MCCL_SIM`): its queued commands
//! run on the device instead of the virtual card's interpolator.
//!
//! Each tick, while the device is idle, the executor takes the next commands off the
//! group's queue and hands them to the device as one job ([`super::Job`]):
//!
//! * lines and the chords of arcs, circles and helices become synchronous moves; the
//!   consecutive ones that share feed speed and acc/dec times go into one chained batch
//!   of at most 100 moves (an arc of more chords continues in the next batch);
//! * a point-to-point command (`MCC_PtP`, `MCC_SyncPtP`, every jog) becomes one
//!   independent move per motor;
//! * a delay waits on the engine's clock; queued output changes happen between batches.
//!
//! Positions come from the steps the device confirmed: while a job runs the group
//! reports where it started; when the device reports every moving motor idle the
//! group's axes are at the job's end (whole steps) and its commands are finished. After
//! a stop (`MCC_AbortMotion`, a safety check) the position is the worker's estimate.
//!
//! [`Executor`] owns this state. The group reaches it only through the engine's
//! [`ExternalExecutor`] trait (check a command, tick, stop, positions, go home), and it
//! reaches the group's queue, running commands and position only through the [`Host`]
//! calls the group implements; the system attaches it to the groups of an MC3B's card.

mod batch;
mod home;

use crate::config::AXES;
use crate::engine::command::{AxisMech, Command, Plan};
use crate::engine::group::external::{ExternalExecutor, Host};
use crate::engine::group::{ERR_OVER_TRAVEL, TIME_EPS};
use crate::engine::homing::{HOME_DONE, HOME_NONE};
use crate::engine::snapshot::round_pulses;
use crate::error::{McclError, McclResult};
use crate::mc3b::backend::{self, Job, Link, Outcome, MAX_STEPS, MOTORS};
use crate::planner::Axes;
use batch::{chord_tolerance, Fill, Pending};
use home::HomeRun;
use std::collections::VecDeque;
use std::sync::Arc;

#[derive(Debug, Clone, Copy, PartialEq)]
enum Phase {
    /// Nothing handed out.
    Idle,
    /// Job `id` runs; `retire` commands end with it.
    Busy { id: u64, retire: usize },
    /// Job `id` was asked to stop; waiting for its report.
    Stopping { id: u64 },
    /// A queued delay runs (seconds left).
    Delay { left: f64 },
}

/// The MC3B executor of a group: it owns everything about the device's side (the link,
/// the step counts, the moves not handed out yet, the job or delay running, a go home)
/// and reaches the group only through [`Host`].
#[derive(Debug)]
pub struct Executor {
    link: Arc<Link>,
    /// Motor (= channel 0..2) per group axis.
    motor: [Option<usize>; AXES],
    /// Axes on channels 3..7 of the card: the MC3B has no such motor.
    blocked: u32,
    /// Device steps at reference position 0.
    origin: [i64; MOTORS],
    /// Device steps as last confirmed (or estimated after a stop).
    steps: [i64; MOTORS],
    /// Device steps at the end of the moves handed out or pending.
    planned: [i64; MOTORS],
    pending: VecDeque<Pending>,
    phase: Phase,
    next_id: u64,
    /// Take the position of the report awaited as the new origin (`MCC_ResetMotion`).
    rezero: bool,
    /// Per motor: a limit switch is set for direction 0 and for direction 1.
    limits: [[bool; 2]; MOTORS],
    /// A go home in progress on the device (`MCC_Home`).
    home: Option<HomeRun>,
}

/// Every axis, one bit each.
const ALL_AXES: u32 = (1 << AXES) - 1;

impl Executor {
    /// The executor of a group whose axes are `axes`, on the MC3B behind `link`: axes on
    /// channels 0..2 are its motors 0..2; motion of axes on channels 3..7 is refused.
    pub fn new(link: Arc<Link>, axes: &[AxisMech; AXES]) -> Executor {
        let mut motor = [None; AXES];
        let mut blocked = 0;
        for (i, a) in axes.iter().enumerate() {
            if let Some((_, ch)) = a.channel {
                if ch < MOTORS {
                    motor[i] = Some(ch);
                } else {
                    blocked |= 1 << i;
                }
            }
        }
        Executor {
            link,
            motor,
            blocked,
            origin: [0; MOTORS],
            steps: [0; MOTORS],
            planned: [0; MOTORS],
            pending: VecDeque::new(),
            phase: Phase::Idle,
            next_id: 1,
            rezero: false,
            limits: [[false; 2]; MOTORS],
            home: None,
        }
    }

    /// [`Executor::stop`], then the group's own stop.
    fn stop_group(&mut self, host: &mut dyn Host) {
        self.stop();
        host.stop_here();
    }

    /// The error record of a failed job: a limit stop names the axis on its motor.
    fn fault_record(&self, f: backend::Fault) -> i32 {
        match f {
            backend::Fault::Limit(m) => {
                let axis = self.motor.iter().position(|&mm| mm == Some(m)).unwrap_or(0);
                f.record() + axis as i32
            }
            _ => f.record(),
        }
    }

    /// The MC3B's limit switches as the device was set up: per motor, direction 0 and 1.
    pub fn set_limits(&mut self, limits: [[bool; 2]; MOTORS]) {
        self.limits = limits;
    }

    /// The jobs of `MCC_Home` on this group's MC3B (see `home::plan`).
    #[allow(clippy::type_complexity)]
    pub fn plan_home(
        &self,
        orders: &[i32; AXES],
        cfgs: &[crate::vendor::SYS_HOME_CONFIG; AXES],
        axes: &[AxisMech; AXES],
    ) -> McclResult<(u32, Vec<Job>, [bool; MOTORS])> {
        home::plan(&self.motor, &self.limits, orders, cfgs, axes)
    }

    /// A go home starts: `stages` (homings, then the moves to the working homes) run on
    /// the device; `motors` are homed.
    fn begin_home(&mut self, stages: Vec<Job>, motors: [bool; MOTORS]) {
        self.home = Some(HomeRun {
            stages: stages.into(),
            current: None,
            motors,
            aborted: false,
            result: None,
        });
    }

    /// Runs the go home in progress; returns whether there is one (then nothing else
    /// runs this tick).
    fn tick_home(&mut self, host: &mut dyn Host) -> bool {
        let mut record = None;
        let mut zeroed = [false; MOTORS];
        {
            let Some(h) = self.home.as_mut() else {
                return false;
            };
            if h.result.is_some() {
                return true;
            }
            if let Some(id) = h.current {
                let Some(r) = self.link.take_report(id) else {
                    return true;
                };
                self.steps = r.position;
                self.planned = r.position;
                self.phase = Phase::Idle;
                h.current = None;
                match r.outcome {
                    Outcome::Done => {}
                    Outcome::Stopped => h.result = Some(HOME_NONE),
                    Outcome::Failed(f) => {
                        record = Some(f);
                        h.result = Some(HOME_NONE);
                    }
                }
            }
            if h.result.is_none() && h.aborted {
                h.result = Some(HOME_NONE);
            }
            if h.result.is_none() {
                match h.stages.pop_front() {
                    Some(job) => {
                        let id = self.next_id;
                        self.next_id = self.next_id.wrapping_add(1);
                        self.link.post(id, job);
                        self.phase = Phase::Busy { id, retire: 0 };
                        h.current = Some(id);
                    }
                    None => {
                        // At the working homes: they are position 0 from now on.
                        for (m, z) in zeroed.iter_mut().enumerate() {
                            if h.motors[m] {
                                self.origin[m] = self.steps[m];
                                *z = true;
                            }
                        }
                        h.result = Some(HOME_DONE);
                    }
                }
            }
        }
        if let Some(f) = record {
            host.set_error(self.fault_record(f));
        }
        for i in 0..AXES {
            if let Some(m) = self.motor[i] {
                if zeroed[m] {
                    host.zero_offset(i);
                }
            }
        }
        self.show_positions(host);
        let on_motors = (0..AXES)
            .filter(|&i| self.motor[i].is_some())
            .fold(0u32, |mask, i| mask | 1 << i);
        host.rebase(on_motors);
        true
    }

    fn hand_out(&mut self, host: &mut dyn Host) {
        if self.may_hand_out(host) {
            // Bounded: each pass starts something or retires at least one command.
            for _ in 0..host.queued() + 2 {
                match self.fill_batch(host) {
                    Fill::Done => break,
                    Fill::Retired => {}
                }
            }
        }
    }

    /// Idle, and either moves of a started command are left (they go on as long as no
    /// error or hold stops the group) or a new command may start.
    fn may_hand_out(&self, host: &dyn Host) -> bool {
        if self.phase != Phase::Idle {
            return false;
        }
        if self.pending.is_empty() {
            host.may_start()
        } else {
            host.may_go_on()
        }
    }

    fn take_report(&mut self, host: &mut dyn Host) {
        let (Phase::Busy { id, .. } | Phase::Stopping { id }) = self.phase else {
            return;
        };
        let Some(r) = self.link.take_report(id) else {
            return;
        };
        self.steps = r.position;
        if self.rezero {
            self.origin = r.position;
            self.rezero = false;
        }
        let phase = self.phase;
        self.phase = Phase::Idle;
        match (phase, r.outcome) {
            (Phase::Busy { retire, .. }, Outcome::Done) => {
                host.retire(retire);
                host.job_ended();
            }
            (_, Outcome::Failed(f)) => {
                let record = self.fault_record(f);
                self.stop_group(host);
                host.set_error(record);
                self.after_stop(host);
            }
            _ => self.after_stop(host),
        }
    }

    /// After a stop: the estimated position is where the group stands.
    fn after_stop(&mut self, host: &mut dyn Host) {
        self.pending.clear();
        self.planned = self.steps;
        host.clear_running();
        self.show_positions(host);
        host.rebase(ALL_AXES);
    }

    /// Runs a delay for `dt`; returns whether it ended.
    fn run_delay(&mut self, host: &mut dyn Host, dt: f64) -> bool {
        let held = host.held();
        let Phase::Delay { left } = &mut self.phase else {
            return false;
        };
        if !held {
            *left -= dt;
        }
        if *left > TIME_EPS {
            return false;
        }
        self.phase = Phase::Idle;
        host.drop_first();
        true
    }

    /// Device steps of the motors at position `p` (user coordinates); motors the group
    /// does not drive stay where the handed-out moves leave them.
    fn device_steps(&self, host: &dyn Host, p: &Axes) -> [i64; MOTORS] {
        let (axes, offset) = (host.axes(), host.offset());
        let mut s = self.planned;
        for (i, motor) in self.motor.iter().enumerate() {
            if let Some(m) = *motor {
                s[m] = self.origin[m] + round_pulses((p[i] + offset[i]) * axes[i].factor);
            }
        }
        s
    }

    /// Over-travel before a command starts: like the virtual card, the group stops with
    /// 0xF301 + axis instead of moving further out.
    fn over_travel(&mut self, host: &mut dyn Host, axis: usize) {
        self.stop_group(host);
        host.set_error(ERR_OVER_TRAVEL + axis as i32);
    }

    fn post(&mut self, job: Job, retire: usize) {
        let id = self.next_id;
        self.next_id = self.next_id.wrapping_add(1);
        self.link.post(id, job);
        self.phase = Phase::Busy { id, retire };
    }

    /// The group's axes stand where [`Executor::positions`] says.
    fn show_positions(&self, host: &mut dyn Host) {
        let pos = self.positions(host.base(), host.offset(), host.axes());
        host.set_pos(pos);
    }
}

/// The group calls its MC3B through the engine's door for executors outside the card.
impl ExternalExecutor for Executor {
    /// The refusals of an MC3B group, checked when a command is queued:
    /// `ABORT_NOT_FINISH_ERR` while a stop is confirmed; `COMMAND_NOTACCEPTED_ERR` for
    /// blending and in-position checks (the MC3B has neither); `PARAMETER_ERR` for motion
    /// of an axis on channels 3..7 or a move of more than 2³²−1 steps.
    fn check(&self, cmd: &Command, axes: &[AxisMech; AXES]) -> McclResult<()> {
        if matches!(self.phase, Phase::Stopping { .. }) {
            return Err(McclError::AbortNotFinished);
        }
        let points = match &cmd.plan {
            // Custom motion needs a position every period, which the MC3B cannot take.
            Plan::Blend(true) | Plan::InPos(true, _) | Plan::Custom(_) => {
                return Err(McclError::NotAccepted)
            }
            // A curve with no geometry: the device has nothing to run.
            Plan::Fault(_) => return Err(McclError::Parameter),
            Plan::Path(m) => backend::chord_points(&m.path, chord_tolerance(axes)),
            Plan::Ptp(_) => vec![cmd.target],
            _ => return Ok(()),
        };
        let mut prev = cmd.start();
        for p in &points {
            for i in 0..AXES {
                let d = p[i] - prev[i];
                if d != 0.0 && self.blocked & (1 << i) != 0 {
                    return Err(McclError::Parameter);
                }
                if self.motor[i].is_some() && (d * axes[i].factor).abs() > MAX_STEPS as f64 {
                    return Err(McclError::Parameter);
                }
            }
            prev = *p;
        }
        Ok(())
    }

    /// Whether the MC3B is running (or stopping) a job.
    fn busy(&self) -> bool {
        matches!(self.phase, Phase::Busy { .. } | Phase::Stopping { .. })
    }

    /// Whether there is work (for the motion status).
    fn active(&self) -> bool {
        self.phase != Phase::Idle || !self.pending.is_empty()
    }

    /// The group stops here: a running job stops (`S`), pending moves are dropped.
    fn stop(&mut self) {
        match self.phase {
            Phase::Busy { id, .. } => {
                self.link.request_stop(id);
                self.phase = Phase::Stopping { id };
            }
            Phase::Delay { .. } => self.phase = Phase::Idle,
            Phase::Idle | Phase::Stopping { .. } => {}
        }
        self.pending.clear();
        self.planned = self.steps;
    }

    /// Back to reference position 0 where the device is (`MCC_ResetMotion`,
    /// `MCC_UpdateParam`); a running job is stopped first.
    fn rezero(&mut self) {
        self.pending.clear();
        self.home = None;
        match self.phase {
            Phase::Busy { id, .. } | Phase::Stopping { id } => {
                self.link.request_stop(id);
                self.phase = Phase::Stopping { id };
                self.rezero = true;
            }
            Phase::Idle | Phase::Delay { .. } => {
                self.phase = Phase::Idle;
                self.origin = self.steps;
            }
        }
        self.planned = self.steps;
    }

    /// One tick: takes the device's report, runs a delay, starts the next job, and takes
    /// the position from the device's steps. The group updates its status afterwards.
    fn tick(&mut self, host: &mut dyn Host, dt: f64) {
        if self.tick_home(host) {
            return;
        }
        self.take_report(host);
        // A delay that starts now counts this tick; one that ends lets the next job start.
        self.hand_out(host);
        if self.run_delay(host, dt) {
            self.hand_out(host);
        }
        self.show_positions(host);
    }

    /// Positions from the device's steps (axes on motors), else `base` (where what has
    /// finished left them).
    fn positions(&self, base: Axes, offset: &Axes, axes: &[AxisMech; AXES]) -> Axes {
        let mut pos = base;
        for (i, p) in pos.iter_mut().enumerate() {
            if let Some(m) = self.motor[i] {
                let f = axes[i].factor;
                if f != 0.0 {
                    *p = (self.steps[m] - self.origin[m]) as f64 / f - offset[i];
                }
            }
        }
        pos
    }

    fn start_home(
        &mut self,
        orders: &[i32; AXES],
        cfgs: &[crate::vendor::SYS_HOME_CONFIG; AXES],
        axes: &[AxisMech; AXES],
        group_busy: bool,
    ) -> McclResult<u32> {
        let (mask, stages, motors) = self.plan_home(orders, cfgs, axes)?;
        if group_busy {
            return Err(McclError::NotFinished);
        }
        self.begin_home(stages, motors);
        Ok(mask)
    }

    /// `MCC_AbortGoHome`: the job running stops (`S`, at once: the MC3B has no
    /// controlled stop) and the homing ends without completing.
    fn abort_home(&mut self) {
        if let Some(h) = self.home.as_mut() {
            h.aborted = true;
            if let Some(id) = h.current {
                self.link.request_stop(id);
            }
        }
    }

    /// The end of a go home, once: [`HOME_DONE`] or [`HOME_NONE`].
    fn take_home_result(&mut self) -> Option<i32> {
        let r = self.home.as_ref()?.result?;
        self.home = None;
        Some(r)
    }
}

#[cfg(test)]
mod tests;
