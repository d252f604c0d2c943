//! A group whose channels are an MC3B (`mc3b_port` in `MCCL_SIM`): its queued commands
//! run on the device instead of the virtual card's interpolator.
//!
//! Each tick, while the device is idle, the group takes the next commands off its queue
//! and hands them to the device as one job ([`crate::mc3b::backend`]):
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

use super::{GroupState, Mode, ERR_OVER_TRAVEL, TIME_EPS};
use crate::config::AXES;
use crate::engine::command::{Command, Plan};
use crate::engine::snapshot::round_pulses;
use crate::error::{McclError, McclResult};
use crate::mc3b::backend::{
    self, Job, Link, Outcome, Ramp, Seg, Speeds, CHORD_TOLERANCE_STEPS, MAX_BATCH, MAX_STEPS,
    MOTORS,
};
use crate::planner::{Axes, Path};
use std::collections::VecDeque;
use std::sync::Arc;

/// What a synchronous move shares with the others of its batch.
#[derive(Debug, Clone, Copy, PartialEq)]
enum SegKind {
    /// A line: feed speed and acc/dec times of its command.
    Line { feed: f64, acc_ms: f64, dec_ms: f64 },
    /// A chord of an arc: the feed speed; the MC3B's fastest ramps.
    Chord { feed: f64 },
}

impl SegKind {
    fn ramp(self) -> Ramp {
        match self {
            SegKind::Line { acc_ms, dec_ms, .. } => Ramp::Times {
                acc_s: acc_ms / 1000.0,
                dec_s: dec_ms / 1000.0,
            },
            SegKind::Chord { .. } => Ramp::Fastest,
        }
    }

    fn feed(self) -> f64 {
        match self {
            SegKind::Line { feed, .. } | SegKind::Chord { feed } => feed,
        }
    }
}

/// A synchronous move of a started command, not handed to the device yet.
#[derive(Debug, Clone, Copy)]
struct Pending {
    seg: Seg,
    kind: SegKind,
    /// The last move of its command.
    ends_cmd: bool,
}

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

/// The MC3B side of a group.
#[derive(Debug)]
pub struct External {
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

/// A go home on the MC3B: its own homing (`H`) per order of channels, then the moves to
/// the working homes; the motors' positions read 0 at the end.
#[derive(Debug)]
struct HomeRun {
    /// Jobs still to run, in order.
    stages: VecDeque<Job>,
    /// The job running.
    current: Option<u64>,
    /// The motors homed.
    motors: [bool; MOTORS],
    /// `MCC_AbortGoHome` asked for a stop.
    aborted: bool,
    /// How it ended ([`HOME_DONE`], [`HOME_NONE`]), for the engine to take.
    result: Option<i32>,
}

use crate::engine::homing::{HOME_DONE, HOME_NONE};

impl External {
    /// Back to reference position 0 where the device is (`MCC_ResetMotion`,
    /// `MCC_UpdateParam`); a running job is stopped first.
    fn rezeroed(mut self) -> External {
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
        self
    }
}

/// What one attempt to start work did.
enum Fill {
    /// A job or a delay started, or nothing can start now.
    Done,
    /// Commands that need no step ended at once: try again.
    Retired,
}

impl GroupState {
    /// Runs this group's motion on the MC3B behind `link` from now on. Axes on channels
    /// 0..2 are its motors 0..2; motion of axes on channels 3..7 is refused.
    pub fn attach_mc3b(&mut self, link: Arc<Link>) {
        let mut motor = [None; AXES];
        let mut blocked = 0;
        for (i, a) in self.axes.iter().enumerate() {
            if let Some((_, ch)) = a.channel {
                if ch < MOTORS {
                    motor[i] = Some(ch);
                } else {
                    blocked |= 1 << i;
                }
            }
        }
        self.external = Some(External {
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
        });
        self.external_positions();
    }

    /// Whether this group runs on an MC3B.
    pub fn is_external(&self) -> bool {
        self.external.is_some()
    }

    /// Whether the MC3B is running (or stopping) a job of this group.
    pub fn external_busy(&self) -> bool {
        self.external
            .as_ref()
            .is_some_and(|x| matches!(x.phase, Phase::Busy { .. } | Phase::Stopping { .. }))
    }

    /// Whether the MC3B side has work (for the motion status).
    pub(super) fn external_active(&self) -> bool {
        self.external
            .as_ref()
            .is_some_and(|x| x.phase != Phase::Idle || !x.pending.is_empty())
    }

    /// Keeps the external part over a reset, rezeroed.
    pub(super) fn keep_external(&mut self, ext: Option<External>) {
        if let Some(x) = ext {
            self.external = Some(x.rezeroed());
            self.external_positions();
        }
    }

    /// The refusals of an MC3B group, checked when a command is queued:
    /// `ABORT_NOT_FINISH_ERR` while a stop is confirmed; `COMMAND_NOTACCEPTED_ERR` for
    /// blending and in-position checks (the MC3B has neither); `PARAMETER_ERR` for motion
    /// of an axis on channels 3..7 or a move of more than 2³²−1 steps.
    pub(super) fn check_external(&self, cmd: &Command) -> McclResult<()> {
        let Some(x) = &self.external else {
            return Ok(());
        };
        if matches!(x.phase, Phase::Stopping { .. }) {
            return Err(McclError::AbortNotFinished);
        }
        let points = match &cmd.plan {
            Plan::Blend(true) | Plan::InPos(true, _) => return Err(McclError::NotAccepted),
            Plan::Path(m) => backend::chord_points(&m.path, self.chord_tolerance()),
            Plan::Ptp(_) => vec![cmd.target],
            _ => return Ok(()),
        };
        let mut prev = cmd.start();
        for p in &points {
            for i in 0..AXES {
                let d = p[i] - prev[i];
                if d != 0.0 && x.blocked & (1 << i) != 0 {
                    return Err(McclError::Parameter);
                }
                if x.motor[i].is_some() && (d * self.axes[i].factor).abs() > MAX_STEPS as f64 {
                    return Err(McclError::Parameter);
                }
            }
            prev = *p;
        }
        Ok(())
    }

    /// From `stop_here`: a running job stops (`S`), pending moves are dropped.
    pub(super) fn stop_external(&mut self) {
        let Some(x) = self.external.as_mut() else {
            return;
        };
        match x.phase {
            Phase::Busy { id, .. } => {
                x.link.request_stop(id);
                x.phase = Phase::Stopping { id };
            }
            Phase::Delay { .. } => x.phase = Phase::Idle,
            Phase::Idle | Phase::Stopping { .. } => {}
        }
        x.pending.clear();
        x.planned = x.steps;
    }

    /// The error record of a failed job: a limit stop names the axis on its motor.
    fn fault_record(&self, f: backend::Fault) -> i32 {
        match (f, &self.external) {
            (backend::Fault::Limit(m), Some(x)) => {
                let axis = x.motor.iter().position(|&mm| mm == Some(m)).unwrap_or(0);
                f.record() + axis as i32
            }
            _ => f.record(),
        }
    }

    /// The MC3B's limit switches as the device was set up: per motor, direction 0 and 1.
    pub fn set_mc3b_limits(&mut self, limits: [[bool; 2]; MOTORS]) {
        if let Some(x) = self.external.as_mut() {
            x.limits = limits;
        }
    }

    /// The jobs of `MCC_Home` with `orders` (per channel, 255 skips) and the go-home
    /// parameters `cfgs` on this MC3B group: the device's homing (`H`) per order, then
    /// one move of every motor by its `dfOffset` (phase 3); with the axes mask and the
    /// motors homed. `COMMAND_NOTACCEPTED_ERR` for a mode other than 9 and 16 (the MC3B
    /// has no home sensor or index input; its homing is their search of the limit
    /// switch), a homed channel this group does not drive on the device, or a motor with
    /// no limit switch in the search direction (it would seek for ever).
    #[allow(clippy::type_complexity)]
    pub fn plan_mc3b_home(
        &self,
        orders: &[i32; AXES],
        cfgs: &[crate::vendor::SYS_HOME_CONFIG; AXES],
    ) -> McclResult<(u32, Vec<Job>, [bool; MOTORS])> {
        use crate::engine::homing::ORDER_SKIP;
        let x = self.external.as_ref().ok_or(McclError::NotAccepted)?;
        if orders[MOTORS..].iter().any(|&o| o != ORDER_SKIP) {
            return Err(McclError::NotAccepted);
        }
        // Per motor: order, direction, speeds, phase-3 steps.
        let mut plan: [Option<(i32, u32, Speeds, i64)>; MOTORS] = [None; MOTORS];
        let mut mask = 0u32;
        for m in 0..MOTORS {
            if orders[m] == ORDER_SKIP {
                continue;
            }
            let i = x
                .motor
                .iter()
                .position(|&mm| mm == Some(m))
                .ok_or(McclError::NotAccepted)?;
            let h = &cfgs[m];
            if h.wMode != 9 && h.wMode != 16 {
                return Err(McclError::NotAccepted);
            }
            let k = self.axes[i].factor;
            // Direction 0 counts steps up.
            let up = (h.wDirection == 0) == (k > 0.0);
            if !x.limits[m][usize::from(!up)] {
                return Err(McclError::NotAccepted);
            }
            let speeds = backend::speeds_for(
                h.dfHighSpeed * k.abs(),
                Ramp::Times {
                    acc_s: h.dfAccTime / 1000.0,
                    dec_s: h.dfDecTime / 1000.0,
                },
            );
            plan[m] = Some((
                orders[m],
                u32::from(!up),
                speeds,
                round_pulses(h.dfOffset * k),
            ));
            mask |= 1 << i;
        }
        let mut used: Vec<i32> = plan.iter().flatten().map(|p| p.0).collect();
        used.sort_unstable();
        used.dedup();
        let mut stages = Vec::new();
        for o in used {
            let pick = |m: usize| plan[m].filter(|p| p.0 == o);
            stages.push(Job::Home {
                dirs: std::array::from_fn(|m| pick(m).map(|p| p.1)),
                speeds: std::array::from_fn(|m| pick(m).map(|p| p.2)),
            });
        }
        let offsets: [i64; MOTORS] = std::array::from_fn(|m| plan[m].map_or(0, |p| p.3));
        if offsets.iter().any(|&n| n != 0) {
            stages.push(Job::Independent {
                steps: offsets,
                speeds: std::array::from_fn(|m| plan[m].map(|p| p.2)),
            });
        }
        Ok((mask, stages, plan.map(|p| p.is_some())))
    }

    /// `MCC_Home` on the MC3B: runs `stages` (homings, then the moves to the working
    /// homes) on the device; axes `mask` are homed (motors `motors`). The group must be
    /// idle; it takes no motion command until the homing ends.
    pub fn begin_mc3b_home(
        &mut self,
        mask: u32,
        stages: Vec<Job>,
        motors: [bool; MOTORS],
    ) -> McclResult<()> {
        if self.external.is_none() {
            return Err(McclError::NotAccepted);
        }
        if self.busy() {
            return Err(McclError::NotFinished);
        }
        if let Some(x) = self.external.as_mut() {
            x.home = Some(HomeRun {
                stages: stages.into(),
                current: None,
                motors,
                aborted: false,
                result: None,
            });
        }
        self.homing = mask;
        self.update_status();
        Ok(())
    }

    /// `MCC_AbortGoHome` on the MC3B: the job running stops (`S`, at once: the MC3B has
    /// no controlled stop) and the homing ends without completing.
    pub fn abort_mc3b_home(&mut self) {
        if let Some(x) = self.external.as_mut() {
            if let Some(h) = x.home.as_mut() {
                h.aborted = true;
                if let Some(id) = h.current {
                    x.link.request_stop(id);
                }
            }
        }
    }

    /// The end of an MC3B go home, once: [`HOME_DONE`] or [`HOME_NONE`].
    pub fn take_home_result(&mut self) -> Option<i32> {
        let x = self.external.as_mut()?;
        let r = x.home.as_ref()?.result?;
        x.home = None;
        Some(r)
    }

    /// Runs the go home in progress; returns whether there is one (then nothing else
    /// runs this tick).
    fn tick_home(&mut self) -> bool {
        let mut record = None;
        let mut zeroed = [false; MOTORS];
        {
            let Some(x) = self.external.as_mut() else {
                return false;
            };
            let Some(h) = x.home.as_mut() else {
                return false;
            };
            if h.result.is_some() {
                return true;
            }
            if let Some(id) = h.current {
                let Some(r) = x.link.take_report(id) else {
                    return true;
                };
                x.steps = r.position;
                x.planned = r.position;
                x.phase = Phase::Idle;
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
                        let id = x.next_id;
                        x.next_id = x.next_id.wrapping_add(1);
                        x.link.post(id, job);
                        x.phase = Phase::Busy { id, retire: 0 };
                        h.current = Some(id);
                    }
                    None => {
                        // At the working homes: they are position 0 from now on.
                        for (m, z) in zeroed.iter_mut().enumerate() {
                            if h.motors[m] {
                                x.origin[m] = x.steps[m];
                                *z = true;
                            }
                        }
                        h.result = Some(HOME_DONE);
                    }
                }
            }
        }
        if let Some(f) = record {
            let code = self.fault_record(f);
            self.set_error(code);
        }
        let motor = self.external.as_ref().map(|x| x.motor);
        for i in 0..AXES {
            if let Some(Some(m)) = motor.map(|mm| mm[i]) {
                if zeroed[m] {
                    self.offset[i] = 0.0;
                }
            }
        }
        self.external_positions();
        for i in 0..AXES {
            if motor.is_some_and(|mm| mm[i].is_some()) {
                self.base[i] = self.pos[i];
                self.queue_end[i] = self.pos[i];
            }
        }
        true
    }

    /// One tick of an MC3B group: takes the device's report, runs a delay, starts the
    /// next job, and takes the position from the device's steps.
    pub(super) fn tick_external(&mut self, dt: f64) {
        if self.tick_home() {
            self.update_status();
            return;
        }
        self.take_report();
        // A delay that starts now counts this tick; one that ends lets the next job start.
        self.hand_out();
        if self.run_delay(dt) {
            self.hand_out();
        }
        self.external_positions();
        self.update_status();
    }

    fn hand_out(&mut self) {
        if self.may_hand_out() {
            // Bounded: each pass starts something or retires at least one command.
            for _ in 0..self.queue.len() + 2 {
                match self.fill_batch() {
                    Fill::Done => break,
                    Fill::Retired => {}
                }
            }
        }
    }

    /// Idle, and either moves of a started command are left (they go on as long as no
    /// error or hold stops the group) or a new command may start.
    fn may_hand_out(&self) -> bool {
        let Some(x) = &self.external else {
            return false;
        };
        if x.phase != Phase::Idle {
            return false;
        }
        if x.pending.is_empty() {
            self.may_start()
        } else {
            self.error == 0 && self.mode == Mode::Normal
        }
    }

    fn take_report(&mut self) {
        let Some(x) = self.external.as_mut() else {
            return;
        };
        let (Phase::Busy { id, .. } | Phase::Stopping { id }) = x.phase else {
            return;
        };
        let Some(r) = x.link.take_report(id) else {
            return;
        };
        x.steps = r.position;
        if x.rezero {
            x.origin = r.position;
            x.rezero = false;
        }
        let phase = x.phase;
        x.phase = Phase::Idle;
        match (phase, r.outcome) {
            (Phase::Busy { retire, .. }, Outcome::Done) => {
                for _ in 0..retire {
                    if let Some(done) = self.running.pop_front() {
                        self.base = done.cmd.target;
                    }
                }
                if self.mode == Mode::HoldAtBlockEnd {
                    self.mode = Mode::Held;
                }
            }
            (_, Outcome::Failed(f)) => {
                let record = self.fault_record(f);
                self.stop_here();
                self.set_error(record);
                self.after_stop();
            }
            _ => self.after_stop(),
        }
    }

    /// After a stop: the estimated position is where the group stands.
    fn after_stop(&mut self) {
        if let Some(x) = self.external.as_mut() {
            x.pending.clear();
            x.planned = x.steps;
        }
        self.running.clear();
        self.external_positions();
        self.base = self.pos;
        self.queue_end = self.pos;
    }

    /// Runs a delay for `dt`; returns whether it ended.
    fn run_delay(&mut self, dt: f64) -> bool {
        let held = self.mode == Mode::Held;
        let Some(x) = self.external.as_mut() else {
            return false;
        };
        let Phase::Delay { left } = &mut x.phase else {
            return false;
        };
        if !held {
            *left -= dt;
        }
        if *left > TIME_EPS {
            return false;
        }
        x.phase = Phase::Idle;
        self.running.pop_front();
        true
    }

    /// Chord tolerance in UU: [`CHORD_TOLERANCE_STEPS`] steps of the finest X/Y/Z axis.
    fn chord_tolerance(&self) -> f64 {
        let k = self.axes[..3]
            .iter()
            .map(|a| a.factor.abs())
            .fold(0.0, f64::max);
        if k > 0.0 {
            CHORD_TOLERANCE_STEPS / k
        } else {
            1e-3
        }
    }

    /// Device steps of the motors at position `p` (user coordinates); motors the group
    /// does not drive stay where the handed-out moves leave them.
    fn device_steps(&self, p: &Axes) -> [i64; MOTORS] {
        let Some(x) = &self.external else {
            return [0; MOTORS];
        };
        let mut s = x.planned;
        for (i, motor) in x.motor.iter().enumerate() {
            if let Some(m) = *motor {
                s[m] = x.origin[m] + round_pulses((p[i] + self.offset[i]) * self.axes[i].factor);
            }
        }
        s
    }

    /// The first axis whose work zone a command leaves going further out (software
    /// over-travel check on), visiting `points` from `start`.
    fn leaves_zone(&self, start: &Axes, points: &[Axes]) -> Option<usize> {
        (0..AXES).find(|&i| {
            if !self.ot_check[i] || self.axes[i].channel.is_none() {
                return false;
            }
            let (hi, lo) = (self.axes[i].high, self.axes[i].low);
            let mut prev = start[i];
            points.iter().any(|p| {
                let out = (p[i] > hi && p[i] > prev) || (p[i] < lo && p[i] < prev);
                prev = p[i];
                out
            })
        })
    }

    /// Over-travel before a command starts: like the virtual card, the group stops with
    /// 0xF301 + axis instead of moving further out.
    fn over_travel(&mut self, axis: usize) {
        self.stop_here();
        self.set_error(ERR_OVER_TRAVEL + axis as i32);
    }

    fn next_id(&mut self) -> u64 {
        let Some(x) = self.external.as_mut() else {
            return 0;
        };
        let id = x.next_id;
        x.next_id = x.next_id.wrapping_add(1);
        id
    }

    fn post(&mut self, job: Job, retire: usize) {
        let id = self.next_id();
        if let Some(x) = self.external.as_mut() {
            x.link.post(id, job);
            x.phase = Phase::Busy { id, retire };
        }
    }

    fn speed_scale(&self) -> f64 {
        if self.fixed_speed {
            1.0
        } else {
            self.override_pct / 100.0
        }
    }

    /// Takes moves and commands for one job and hands it to the device.
    fn fill_batch(&mut self) -> Fill {
        let tol = self.chord_tolerance();
        let mut batch: Vec<Pending> = Vec::new();
        let mut retire = 0usize;
        loop {
            if batch.len() >= MAX_BATCH {
                break;
            }
            let front = self
                .external
                .as_ref()
                .and_then(|x| x.pending.front().copied());
            if let Some(p) = front {
                if batch.first().is_some_and(|b| b.kind != p.kind) {
                    break;
                }
                if let Some(x) = self.external.as_mut() {
                    x.pending.pop_front();
                }
                retire += usize::from(p.ends_cmd);
                batch.push(p);
                continue;
            }
            // Single block: one command per job.
            if !batch.is_empty() && self.single_block {
                break;
            }
            let Some(cmd) = self.queue.front() else {
                break;
            };
            match &cmd.plan {
                Plan::Blend(on) => {
                    self.blend_on = *on;
                    self.queue.pop_front();
                }
                Plan::InPos(on, mask) => {
                    if *on {
                        self.inpos_mask |= mask;
                    } else {
                        self.inpos_mask &= !mask;
                    }
                    self.queue.pop_front();
                }
                Plan::Output(o) => {
                    if !batch.is_empty() {
                        break;
                    }
                    let o = *o;
                    self.outputs.push(o);
                    self.queue.pop_front();
                }
                Plan::Path(m) => {
                    let kind = match m.path {
                        Path::Line(_) => SegKind::Line {
                            feed: cmd.info_feed,
                            acc_ms: cmd.acc_ms,
                            dec_ms: cmd.dec_ms,
                        },
                        Path::Arc(_) | Path::Helix(_) => SegKind::Chord {
                            feed: cmd.info_feed,
                        },
                    };
                    if batch.first().is_some_and(|b| b.kind != kind) {
                        break;
                    }
                    let points = backend::chord_points(&m.path, tol);
                    if let Some(axis) = self.leaves_zone(&m.path.start(), &points) {
                        if batch.is_empty() {
                            self.over_travel(axis);
                            return Fill::Done;
                        }
                        break;
                    }
                    let Some(cmd) = self.queue.pop_front() else {
                        break;
                    };
                    self.expand(&cmd, &points, kind);
                    self.start(cmd, 0.0);
                }
                Plan::Ptp(_) | Plan::Delay(_) if !batch.is_empty() => break,
                Plan::Ptp(_) => {
                    if let Some(axis) = self.leaves_zone(&cmd.start(), &[cmd.target]) {
                        self.over_travel(axis);
                        return Fill::Done;
                    }
                    let Some(cmd) = self.queue.pop_front() else {
                        break;
                    };
                    let job = self.ptp_job(&cmd);
                    self.start(cmd, 0.0);
                    if job.total() == [0; MOTORS] {
                        self.running.pop_front();
                        return Fill::Retired;
                    }
                    self.post(job, 1);
                    return Fill::Done;
                }
                Plan::Delay(s) => {
                    let left = *s;
                    let Some(cmd) = self.queue.pop_front() else {
                        break;
                    };
                    self.start(cmd, 0.0);
                    if let Some(x) = self.external.as_mut() {
                        x.phase = Phase::Delay { left };
                    }
                    return Fill::Done;
                }
            }
        }
        let Some(first) = batch.first() else {
            return Fill::Done;
        };
        let segs: Vec<Seg> = batch.iter().map(|p| p.seg).collect();
        let speeds = backend::sync_speeds(&segs, first.kind.ramp(), self.speed_scale());
        let moves: Vec<[i64; MOTORS]> = segs
            .iter()
            .map(|s| s.steps)
            .filter(|s| *s != [0; MOTORS])
            .collect();
        if moves.is_empty() {
            for _ in 0..retire {
                if let Some(done) = self.running.pop_front() {
                    self.base = done.cmd.target;
                }
            }
            return Fill::Retired;
        }
        self.post(
            Job::Sync {
                segs: moves,
                speeds,
            },
            retire,
        );
        Fill::Done
    }

    /// The synchronous moves of a path command through `points`.
    fn expand(&mut self, cmd: &Command, points: &[Axes], kind: SegKind) {
        let feed = kind.feed();
        let mut prev = cmd.start();
        let n = points.len();
        let mut out = Vec::with_capacity(n);
        for (j, p) in points.iter().enumerate() {
            let dev = self.device_steps(p);
            let Some(x) = self.external.as_mut() else {
                return;
            };
            let steps: [i64; MOTORS] = std::array::from_fn(|m| dev[m] - x.planned[m]);
            x.planned = dev;
            let len = backend::move_length(&prev, p);
            let secs = if feed > 0.0 { len / feed } else { 0.0 };
            out.push(Pending {
                seg: Seg { steps, secs },
                kind,
                ends_cmd: j + 1 == n,
            });
            prev = *p;
        }
        if let Some(x) = self.external.as_mut() {
            x.pending.extend(out);
        }
    }

    /// A point-to-point command as one independent move per motor: each at its axis's
    /// speed (max safe speed × ratio, re-planned for `MCC_SyncPtP`) and acc/dec times.
    fn ptp_job(&mut self, cmd: &Command) -> Job {
        let dev = self.device_steps(&cmd.target);
        let scale = self.speed_scale();
        let Some(x) = self.external.as_mut() else {
            return Job::Independent {
                steps: [0; MOTORS],
                speeds: [None; MOTORS],
            };
        };
        let steps: [i64; MOTORS] = std::array::from_fn(|m| dev[m] - x.planned[m]);
        x.planned = dev;
        let mut speeds: [Option<Speeds>; MOTORS] = [None; MOTORS];
        if let Plan::Ptp(p) = &cmd.plan {
            for i in 0..AXES {
                let (Some(m), Some(prof)) = (x.motor[i], p.axis_profile(i)) else {
                    continue;
                };
                if steps[m] == 0 {
                    continue;
                }
                let k = self.axes[i].factor.abs();
                let feed = prof.feed();
                let peak = prof.peak_speed();
                // The set times: a short move keeps the acceleration and lowers the peak.
                let t = |actual: f64| {
                    if peak > 0.0 {
                        actual * feed / peak
                    } else {
                        0.0
                    }
                };
                let ramp = Ramp::Times {
                    acc_s: t(prof.acc_time()),
                    dec_s: t(prof.dec_time()),
                };
                speeds[m] = Some(backend::speeds_for(feed * k * scale, ramp));
            }
        }
        Job::Independent { steps, speeds }
    }

    /// Positions from the device's steps (axes on motors), else from what has finished.
    fn external_positions(&mut self) {
        let Some(x) = &self.external else {
            return;
        };
        let mut pos = self.base;
        for (i, p) in pos.iter_mut().enumerate() {
            if let Some(m) = x.motor[i] {
                let f = self.axes[i].factor;
                if f != 0.0 {
                    *p = (x.steps[m] - x.origin[m]) as f64 / f - self.offset[i];
                }
            }
        }
        self.pos = pos;
        self.vel = [0.0; AXES];
    }
}

#[cfg(test)]
mod tests;
