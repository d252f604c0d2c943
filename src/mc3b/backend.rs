//! The MC3B as a backend of the virtual card: a card whose `mc3b_port` is set in
//! `MCCL_SIM` has its channels 0..2 on an MC3B, and `MCC_*` motion of a group on that
//! card runs on the device (the group side is `crate::engine::group::external`).
//!
//! This module is the device side:
//!
//! * conversions from the virtual card's units to the MC3B's: steps, steps/s,
//!   steps/s², chords of arcs ([`chord_points`], [`sync_speeds`], [`clamp_velocity`]);
//! * the [`Job`]s a group hands over (a batch of synchronous moves, chained when there
//!   are several, or independent moves of a point-to-point command) and the [`Report`]
//!   it gets back;
//! * the [`Link`] between a group (on the engine thread, never blocking) and the
//!   [`Worker`] that owns the serial line and does the blocking I/O on its own thread
//!   ([`Device`]), or in a test that calls [`Worker::run_pending`] itself.
//!
//! The MC3B never reports a position (§6.13 answers running / at home only). The worker
//! counts the steps of every move the device acknowledged and then reported idle for:
//! those are *confirmed*. A move stopped before its end (`S`) made an unknown number of
//! steps: the worker then takes the position from a model of the device (an
//! [`Emulator`] fed the same acknowledged commands at the same times) — an estimate.

use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::Duration;

use parking_lot::{Condvar, Mutex};

use super::client::{open_port, Client, ClientError, Transport};
use super::codec::{Command, ACCEL_RANGE, VELOCITY_RANGE};
use super::emulator::{Emulator, CHAIN_CAPACITY};
use crate::planner::{Axes, Path};

/// Error record of a group whose MC3B did not answer (timeout) or whose serial line
/// failed. Not in the vendor's table; the group stops and runs no command until
/// `MCC_ClearError`.
pub const ERR_MC3B_LINK: i32 = 0xF901;
/// Error record of a group whose MC3B refused a command (`E0`..`E3`) or answered
/// something that does not fit it.
pub const ERR_MC3B_DEVICE: i32 = 0xF902;

/// Largest deviation of a chord from its arc (sagitta), in steps of the finest X/Y/Z
/// axis of the group.
pub const CHORD_TOLERANCE_STEPS: f64 = 1.0;
/// Synchronous moves per batch: the MC3B's chained-move buffer (§2.2, §4.17).
pub const MAX_BATCH: usize = CHAIN_CAPACITY;
/// Pause between two rounds of status queries while a job runs.
pub const POLL_INTERVAL: Duration = Duration::from_millis(10);
/// Number of motors on an MC3B (= channels 0..2 of its card).
pub const MOTORS: usize = 3;
/// Longest single move the MC3B takes (32-bit step count, §6.8).
pub const MAX_STEPS: i64 = u32::MAX as i64;
/// Most chords one arc is cut into (the tolerance is met below this).
pub const MAX_CHORDS: usize = 1_000_000;

/// Maximum velocity, acceleration and deceleration of one motor, as the MC3B takes them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Speeds {
    /// Steps/s, 1..5000.
    pub velocity: u32,
    /// Steps/s², 100..100000.
    pub acceleration: u32,
    /// Steps/s², 100..100000.
    pub deceleration: u32,
}

impl Speeds {
    /// The §6.1 defaults (what the device has after `I`).
    pub const DEFAULT: Speeds = Speeds {
        velocity: 1000,
        acceleration: 5000,
        deceleration: 5000,
    };
}

/// A speed in steps/s as the MC3B takes it: rounded to a whole number, within 1..5000.
pub fn clamp_velocity(v: f64) -> u32 {
    clamp_round(v, VELOCITY_RANGE)
}

/// An acceleration in steps/s² as the MC3B takes it: rounded, within 100..100000.
pub fn clamp_accel(a: f64) -> u32 {
    clamp_round(a, ACCEL_RANGE)
}

fn clamp_round(x: f64, (lo, hi): (u32, u32)) -> u32 {
    if x.is_nan() {
        return lo;
    }
    let r = x.round().clamp(f64::from(lo), f64::from(hi));
    // In range by the clamp.
    r as u32
}

/// How the motors of a batch ramp.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ramp {
    /// Each motor reaches its speed in `acc_s` and stops from it in `dec_s` seconds (the
    /// command's acc/dec time; 0 = as fast as the MC3B can).
    Times {
        /// Acceleration time, s.
        acc_s: f64,
        /// Deceleration time, s.
        dec_s: f64,
    },
    /// The MC3B's largest acceleration and deceleration (chords of arcs).
    Fastest,
}

/// One synchronous move: signed steps per motor (direction 0 counts up) and the time it
/// should take at its command's feed speed (its length / feed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seg {
    /// Steps of motors 0..2.
    pub steps: [i64; MOTORS],
    /// Time at the feed speed, s (without acceleration).
    pub secs: f64,
}

/// The per-motor settings of a batch of synchronous moves, and the speed factor the
/// feed speed was scaled by.
///
/// The MC3B runs every move of a chain with the same settings and gives each move the
/// largest speed at which no motor exceeds its maximum velocity (§4.16). The speed each
/// motor needs in segment `s` is `w = |n| / secs`; the maximum velocity of a motor is
/// the largest `w` it needs, divided by the largest overshoot over the batch (how much
/// faster than its feed a segment would run), so no segment runs faster than its feed
/// speed; segments whose direction makes another motor the limiting one run slower (a
/// chain around a circle: between 1/√2 and 1 of the feed). `scale` multiplies every
/// speed (the override ratio). Accelerations follow `ramp`. Motors that do not move get
/// `None`.
pub fn sync_speeds(segs: &[Seg], ramp: Ramp, scale: f64) -> [Option<Speeds>; MOTORS] {
    let need = |s: &Seg, m: usize| {
        if s.secs > 0.0 {
            s.steps[m].unsigned_abs() as f64 / s.secs
        } else {
            f64::INFINITY
        }
    };
    let mut want = [0.0f64; MOTORS];
    let mut moves = [false; MOTORS];
    for s in segs {
        for m in 0..MOTORS {
            if s.steps[m] != 0 {
                moves[m] = true;
                want[m] = want[m].max(need(s, m));
            }
        }
    }
    let mut worst = 1.0f64;
    for s in segs {
        let mut rho = f64::INFINITY;
        for (m, w) in want.iter().enumerate() {
            if s.steps[m] != 0 && w.is_finite() {
                rho = rho.min(w / need(s, m));
            }
        }
        if rho.is_finite() {
            worst = worst.max(rho);
        }
    }
    let scale = if scale.is_finite() && scale > 0.0 {
        scale
    } else {
        1.0
    };
    std::array::from_fn(|m| {
        moves[m].then(|| {
            let v = want[m] / worst * scale;
            speeds_for(v, ramp)
        })
    })
}

/// The settings of a motor that should run at `v` steps/s with `ramp`.
pub fn speeds_for(v: f64, ramp: Ramp) -> Speeds {
    let velocity = clamp_velocity(v);
    let vf = f64::from(velocity);
    let (acceleration, deceleration) = match ramp {
        Ramp::Fastest => (ACCEL_RANGE.1, ACCEL_RANGE.1),
        Ramp::Times { acc_s, dec_s } => (
            if acc_s > 0.0 {
                clamp_accel(vf / acc_s)
            } else {
                ACCEL_RANGE.1
            },
            if dec_s > 0.0 {
                clamp_accel(vf / dec_s)
            } else {
                ACCEL_RANGE.1
            },
        ),
    };
    Speeds {
        velocity,
        acceleration,
        deceleration,
    }
}

/// Number of equal-angle chords of an arc of `radius` sweeping `sweep` radians whose
/// sagitta `r (1 − cos(α/2))` is at most `tol` (chords never span more than 90°).
pub fn chord_count(radius: f64, sweep: f64, tol: f64) -> usize {
    let sweep = sweep.abs();
    if !(radius > 0.0 && sweep > 0.0 && tol > 0.0 && radius.is_finite() && sweep.is_finite()) {
        return 1;
    }
    let alpha = if tol >= radius {
        std::f64::consts::FRAC_PI_2
    } else {
        (2.0 * (1.0 - tol / radius).acos()).min(std::f64::consts::FRAC_PI_2)
    };
    let n = (sweep / alpha).ceil();
    if n.is_finite() && n >= 1.0 {
        (n as usize).min(MAX_CHORDS)
    } else {
        1
    }
}

/// Largest distance between an arc and its `n` equal chords: `r (1 − cos(sweep / 2n))`.
pub fn sagitta(radius: f64, sweep: f64, n: usize) -> f64 {
    radius * (1.0 - (sweep.abs() / (2.0 * n.max(1) as f64)).cos())
}

/// The end points of the straight moves a path becomes: a line is one move to its end;
/// an arc, circle or helix is cut into [`chord_count`] chords of equal angle (sagitta at
/// most `tol` UU), the last one ending exactly at the path's end.
pub fn chord_points(path: &Path, tol: f64) -> Vec<Axes> {
    match path {
        Path::Line(_) => vec![path.end()],
        Path::Arc(a) | Path::Helix(a) => {
            let n = chord_count(a.radius(), a.sweep(), tol);
            let len = path.length();
            (1..=n)
                .map(|j| {
                    if j == n {
                        path.end()
                    } else {
                        path.point(len * j as f64 / n as f64)
                    }
                })
                .collect()
        }
    }
}

/// Length a feed speed applies to between two points: X/Y/Z distance, or the longest
/// U..B travel when X/Y/Z stand still (as the planner measures paths).
pub fn move_length(from: &Axes, to: &Axes) -> f64 {
    let xyz = (0..3)
        .map(|i| (to[i] - from[i]).powi(2))
        .sum::<f64>()
        .sqrt();
    if xyz > 0.0 {
        xyz
    } else {
        (3..from.len())
            .map(|i| (to[i] - from[i]).abs())
            .fold(0.0, f64::max)
    }
}

/// What a group hands to the device.
#[derive(Debug, Clone, PartialEq)]
pub enum Job {
    /// Synchronous moves (`Y`): one runs at once, several are chained (1..=100).
    Sync {
        /// The moves, none all zero.
        segs: Vec<[i64; MOTORS]>,
        /// Settings of the motors that move.
        speeds: [Option<Speeds>; MOTORS],
    },
    /// One independent move per motor (`M`), started back to back (point-to-point).
    Independent {
        /// Signed steps per motor (0 = that motor stays).
        steps: [i64; MOTORS],
        /// Settings of the motors that move.
        speeds: [Option<Speeds>; MOTORS],
    },
    /// The MC3B's own homing (`H`, §4.14, §6.9) of the motors given a direction 0/1:
    /// seek the limit switch of that direction at the maximum velocity, back off and
    /// approach it again at 10 steps/s. Ends when every one of them is idle.
    Home {
        /// Direction per motor (`None`: that motor stays).
        dirs: [Option<u32>; MOTORS],
        /// Settings of the motors that home.
        speeds: [Option<Speeds>; MOTORS],
    },
}

impl Job {
    /// Steps the job moves each motor by, in total.
    pub fn total(&self) -> [i64; MOTORS] {
        match self {
            Job::Sync { segs, .. } => segs.iter().fold([0; MOTORS], |mut t, s| {
                for m in 0..MOTORS {
                    t[m] += s[m];
                }
                t
            }),
            Job::Independent { steps, .. } => *steps,
            // Where a homing ends is the device's to find: no planned travel.
            Job::Home { .. } => [0; MOTORS],
        }
    }

    fn speeds(&self) -> &[Option<Speeds>; MOTORS] {
        match self {
            Job::Sync { speeds, .. }
            | Job::Independent { speeds, .. }
            | Job::Home { speeds, .. } => speeds,
        }
    }

    /// The direction (0 up, 1 down) each motor travels last in the job, if it moves.
    fn last_dirs(&self) -> [Option<u32>; MOTORS] {
        let mut d = [None; MOTORS];
        match self {
            Job::Sync { segs, .. } => {
                for s in segs {
                    for m in 0..MOTORS {
                        if s[m] != 0 {
                            d[m] = Some(u32::from(s[m] < 0));
                        }
                    }
                }
            }
            Job::Independent { steps, .. } => {
                for m in 0..MOTORS {
                    if steps[m] != 0 {
                        d[m] = Some(u32::from(steps[m] < 0));
                    }
                }
            }
            Job::Home { dirs, .. } => d = *dirs,
        }
        d
    }

    fn moving(&self) -> [bool; MOTORS] {
        let mut m = [false; MOTORS];
        match self {
            Job::Sync { segs, .. } => {
                for s in segs {
                    for i in 0..MOTORS {
                        m[i] |= s[i] != 0;
                    }
                }
            }
            Job::Independent { steps, .. } => {
                for i in 0..MOTORS {
                    m[i] = steps[i] != 0;
                }
            }
            Job::Home { dirs, .. } => {
                for i in 0..MOTORS {
                    m[i] = dirs[i].is_some();
                }
            }
        }
        m
    }
}

/// Why a job failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fault {
    /// No reply in time, or the serial line failed ([`ERR_MC3B_LINK`]).
    Link,
    /// The device refused a command or answered out of turn ([`ERR_MC3B_DEVICE`]).
    Device,
    /// Motor `0` ended a move at its limit switch for the direction it travelled: the
    /// MC3B stopped it there, short of the move's end (where exactly it cannot say).
    /// The group records 0xF701 + the axis on that motor.
    Limit(usize),
}

impl Fault {
    /// The group's error record.
    pub fn record(self) -> i32 {
        match self {
            Fault::Link => ERR_MC3B_LINK,
            Fault::Device => ERR_MC3B_DEVICE,
            Fault::Limit(_) => crate::engine::safety::ERR_LIMIT,
        }
    }

    fn of(e: &ClientError) -> Fault {
        match e {
            ClientError::Timeout | ClientError::Io(_) => Fault::Link,
            ClientError::Device(_) | ClientError::Unexpected(_) | ClientError::Garbled(_) => {
                Fault::Device
            }
        }
    }
}

/// How a job ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// Every move ran to its end: the device reported every moving motor idle.
    Done,
    /// Stopped on request (`S`) before its end; the position is an estimate.
    Stopped,
    /// The device or the line failed; the position is an estimate.
    Failed(Fault),
}

/// The answer to a job.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Report {
    /// The job's id.
    pub id: u64,
    /// How it ended.
    pub outcome: Outcome,
    /// Device steps of motors 0..2 since the link was opened: confirmed after
    /// [`Outcome::Done`], estimated otherwise.
    pub position: [i64; MOTORS],
}

#[derive(Debug, Default)]
struct LinkState {
    job: Option<(u64, Job)>,
    stop: Option<u64>,
    report: Option<Report>,
    shutdown: bool,
}

/// The meeting point of a group and its device's worker. Every call holds a short lock
/// and never waits for the device.
#[derive(Debug, Default)]
pub struct Link {
    state: Mutex<LinkState>,
    wake: Condvar,
}

impl Link {
    /// Hands `job` to the worker (replacing a job it has not taken yet).
    pub fn post(&self, id: u64, job: Job) {
        let mut s = self.state.lock();
        s.job = Some((id, job));
        self.wake.notify_all();
    }

    /// Asks the worker to stop job `id` now (`S` on its motors); it still reports.
    pub fn request_stop(&self, id: u64) {
        let mut s = self.state.lock();
        s.stop = Some(id);
        self.wake.notify_all();
    }

    /// The report of job `id`, once there is one.
    pub fn take_report(&self, id: u64) -> Option<Report> {
        let mut s = self.state.lock();
        if s.report.is_some_and(|r| r.id == id) {
            s.report.take()
        } else {
            None
        }
    }

    /// Makes the worker stop what it runs and end.
    pub fn shutdown(&self) {
        let mut s = self.state.lock();
        s.shutdown = true;
        self.wake.notify_all();
    }

    fn stop_wanted(&self, id: u64) -> bool {
        let s = self.state.lock();
        s.shutdown || s.stop == Some(id)
    }

    fn shut_down(&self) -> bool {
        self.state.lock().shutdown
    }

    /// The next job; with `block`, waits for one. `None` at shutdown (or, without
    /// `block`, when there is none).
    fn next_job(&self, block: bool) -> Option<(u64, Job)> {
        let mut s = self.state.lock();
        loop {
            if s.shutdown {
                return None;
            }
            if let Some(j) = s.job.take() {
                return Some(j);
            }
            if !block {
                return None;
            }
            self.wake.wait(&mut s);
        }
    }

    fn report(&self, r: Report) {
        let mut s = self.state.lock();
        if s.stop == Some(r.id) {
            s.stop = None;
        }
        s.report = Some(r);
    }

    /// Waits up to `d` or until a stop of `id` or a shutdown is asked for.
    fn pause(&self, id: u64, d: Duration) {
        let mut s = self.state.lock();
        if s.shutdown || s.stop == Some(id) {
            return;
        }
        let _ = self.wake.wait_for(&mut s, d);
    }
}

/// The device side: owns the client, runs jobs one at a time, keeps the step count and
/// the model used for estimates.
pub struct Worker<T: Transport> {
    client: Client<T>,
    link: Arc<Link>,
    /// The device as we believe it: fed every acknowledged command at its time.
    model: Emulator,
    model_at: Duration,
    /// Settings the device has per motor.
    sent: [Speeds; MOTORS],
    /// Device steps since the link was opened (confirmed, or estimated after a stop).
    steps: [i64; MOTORS],
    /// The chained-move buffer may hold moves (an upload was cut short).
    chain_dirty: bool,
    /// The last job failed: the device may not be as the model says (a motor may
    /// still run). The next job first queries every motor.
    suspect: bool,
}

/// Controller ID of the MC3B (no daisy chaining, §4.2).
const ID: u8 = 0;

/// The home (limit) masks of one motor as §6.5 sends them: AND and XOR for direction 0,
/// then for direction 1. All 0: no limit switch.
pub type LimitMasks = [u32; 4];

/// The masks of a motor whose direction-0 and direction-1 limit switches are the MC3B
/// inputs `bits` (0..5, -1 none), each active at the level in `high` (`true`: +5 V).
pub fn limit_masks(bits: [i8; 2], high: [Option<bool>; 2]) -> LimitMasks {
    let pair = |bit: i8, level: Option<bool>| match (u8::try_from(bit), level) {
        (Ok(b @ 0..=5), Some(l)) => super::mcl::limit_masks(i32::from(b), l).unwrap_or((0, 0)),
        _ => (0, 0),
    };
    let (a0, x0) = pair(bits[0], high[0]);
    let (a1, x1) = pair(bits[1], high[1]);
    [a0, x0, a1, x1]
}

/// Opens the conversation with an MC3B on `transport`: `0I` (motors off, defaults) and
/// `0P` (product 1). Returns the link to give groups and the worker to run.
pub fn connect<T: Transport>(
    transport: T,
    timeout: Duration,
) -> Result<(Arc<Link>, Worker<T>), String> {
    connect_with(transport, timeout, &[[0; 4]; MOTORS])
}

/// [`connect`], then sets the limit masks of every motor that has limit switches (`L`).
pub fn connect_with<T: Transport>(
    transport: T,
    timeout: Duration,
    limits: &[LimitMasks; MOTORS],
) -> Result<(Arc<Link>, Worker<T>), String> {
    let mut client = Client::new(transport, timeout);
    client
        .initialize(ID)
        .map_err(|e| format!("initialize (0I): {e}"))?;
    let (product, _) = client
        .product_id(ID)
        .map_err(|e| format!("product query (0P): {e}"))?;
    if product != super::emulator::PRODUCT_ID {
        return Err(format!("product {product} answered, not an MC3B (1)"));
    }
    let link = Arc::new(Link::default());
    let now = client.transport().now();
    let mut model = Emulator::new();
    let _ = model.handle(&Command::Initialize { id: ID });
    for (m, l) in limits.iter().enumerate() {
        if l.iter().all(|&x| x == 0) {
            continue;
        }
        let cmd = Command::SetLimits {
            id: ID,
            motor: m as u32,
            h0_and: l[0],
            h0_xor: l[1],
            h1_and: l[2],
            h1_xor: l[3],
        };
        client
            .command(&cmd)
            .map_err(|e| format!("limit masks of motor {m} (0L): {e}"))?;
        let _ = model.handle(&cmd);
    }
    let worker = Worker {
        client,
        link: link.clone(),
        model,
        model_at: now,
        sent: [Speeds::DEFAULT; MOTORS],
        steps: [0; MOTORS],
        chain_dirty: false,
        suspect: false,
    };
    Ok((link, worker))
}

impl<T: Transport> Worker<T> {
    /// Runs jobs until the link shuts down.
    pub fn run(mut self) {
        while let Some((id, job)) = self.link.next_job(true) {
            self.run_one(id, &job);
        }
    }

    /// Runs the job waiting on the link, if any, to its end (tests drive the worker so,
    /// over an in-process emulator, deterministically). Returns whether there was one.
    pub fn run_pending(&mut self) -> bool {
        match self.link.next_job(false) {
            Some((id, job)) => {
                self.run_one(id, &job);
                true
            }
            None => false,
        }
    }

    /// Runs a job and reports it; a panic inside still reports (a failure), so the
    /// group never waits for a report that cannot come.
    fn run_one(&mut self, id: u64, job: &Job) {
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.execute(id, job)))
            .unwrap_or(Report {
                id,
                outcome: Outcome::Failed(Fault::Device),
                position: self.steps,
            });
        self.link.report(r);
    }

    /// The transport (tests look at the emulator behind it).
    pub fn transport(&mut self) -> &mut T {
        self.client.transport()
    }

    /// Device steps as the worker counts them.
    pub fn steps(&self) -> [i64; MOTORS] {
        self.steps
    }

    fn catch_up(&mut self) {
        let now = self.client.transport().now();
        if now > self.model_at {
            self.model.advance(now - self.model_at);
            self.model_at = now;
        }
    }

    /// Sends `cmd`, waits for its acknowledgement, and applies it to the model at the
    /// time the device got it. When no good reply came but the line still works, the
    /// line is resynchronized first: a reply that was only late (a loaded host) is
    /// found there and the command counts as acknowledged, so the model never misses
    /// a command the device carried out.
    fn send(&mut self, cmd: Command) -> Result<(), ClientError> {
        match self.client.command(&cmd) {
            Ok(()) => {}
            Err(e @ ClientError::Io(_)) => return Err(e),
            Err(e) => self.client.settle(&cmd, e)?,
        }
        let at = self.client.sent_at();
        if at > self.model_at {
            self.model.advance(at - self.model_at);
            self.model_at = at;
        }
        let _ = self.model.handle(&cmd);
        Ok(())
    }

    /// `Q` of motor `m`; a lost or unreadable answer is asked for once more (the
    /// query changes nothing), after the line is back in step.
    fn status(&mut self, m: usize) -> Result<super::client::MotorStatus, ClientError> {
        match self.client.query_status(ID, m as u32) {
            Err(e) if e.fate_unknown() && !matches!(e, ClientError::Io(_)) => {
                self.client.query_status(ID, m as u32)
            }
            r => r,
        }
    }

    /// Before a job that needs the device at rest: every motor must be idle. One that
    /// runs (a stop after an earlier failure did not get through) is stopped, and the
    /// job fails: nothing of it is sent.
    fn ensure_idle(&mut self) -> Result<(), ClientError> {
        let mut running = [false; MOTORS];
        for (m, r) in running.iter_mut().enumerate() {
            *r = self.status(m)?.running;
        }
        if running.iter().any(|&r| r) {
            self.stop_motors(&running)?;
            return Err(ClientError::Device(super::codec::ErrorCode::MotorRunning));
        }
        self.suspect = false;
        Ok(())
    }

    fn model_pos(&self) -> [i64; MOTORS] {
        std::array::from_fn(|m| self.model.position(m))
    }

    fn execute(&mut self, id: u64, job: &Job) -> Report {
        let start = self.steps;
        self.catch_up();
        let model0 = self.model_pos();
        let outcome = match self.run_job(id, job) {
            Ok(o) => o,
            Err(e) => {
                let fault = Fault::of(&e);
                self.stop_after_error(job, fault);
                Outcome::Failed(fault)
            }
        };
        if matches!(outcome, Outcome::Failed(Fault::Link | Fault::Device)) {
            self.suspect = true;
        }
        if let Job::Home { dirs, .. } = job {
            // The model has no limit inputs: it would seek for ever. Where the homing
            // ended is the group's new origin; the model goes on from there, standing.
            for (m, d) in dirs.iter().enumerate() {
                if d.is_some() {
                    self.catch_up();
                    let _ = self.model.handle(&Command::Stop {
                        id: ID,
                        motor: m as u32,
                    });
                }
            }
        }
        self.steps = if outcome == Outcome::Done {
            let t = job.total();
            std::array::from_fn(|m| start[m] + t[m])
        } else {
            self.catch_up();
            let now = self.model_pos();
            std::array::from_fn(|m| start[m] + now[m] - model0[m])
        };
        Report {
            id,
            outcome,
            position: self.steps,
        }
    }

    fn set_speeds(&mut self, m: usize, sp: Speeds) -> Result<(), ClientError> {
        let motor = m as u32;
        let old = self.sent[m];
        if old.velocity != sp.velocity {
            self.send(Command::SetMaxVelocity {
                id: ID,
                motor,
                value: sp.velocity,
                direction_modifier: None,
            })?;
            self.sent[m].velocity = sp.velocity;
        }
        if old.acceleration != sp.acceleration {
            self.send(Command::SetAcceleration {
                id: ID,
                motor,
                value: sp.acceleration,
            })?;
            self.sent[m].acceleration = sp.acceleration;
        }
        if old.deceleration != sp.deceleration {
            self.send(Command::SetDeceleration {
                id: ID,
                motor,
                value: sp.deceleration,
            })?;
            self.sent[m].deceleration = sp.deceleration;
        }
        Ok(())
    }

    fn sync_cmd(seg: &[i64; MOTORS], execute: Option<u32>) -> Command {
        Command::SyncMove {
            id: ID,
            // Jobs never hold moves beyond MAX_STEPS (the group refuses them).
            steps: seg.map(|n| u32::try_from(n.unsigned_abs()).unwrap_or(u32::MAX)),
            directions: seg.map(|n| u32::from(n < 0)),
            execute,
        }
    }

    /// Empties the chained-move buffer: a plain `Y` with no steps runs at once and
    /// discards what is stored (§6.12).
    fn clear_chain(&mut self) -> Result<(), ClientError> {
        self.send(Self::sync_cmd(&[0; MOTORS], None))?;
        self.chain_dirty = false;
        Ok(())
    }

    fn run_job(&mut self, id: u64, job: &Job) -> Result<Outcome, ClientError> {
        let moving = job.moving();
        if !moving.iter().any(|&b| b) {
            return Ok(Outcome::Done);
        }
        // A chain needs all three motors idle (§4.16) and takes a while to upload: ask
        // first rather than have its execute refused after the moves are stored.
        // After a failure the device may differ from the model: ask before any job.
        if self.suspect || matches!(job, Job::Sync { segs, .. } if segs.len() > 1) {
            self.ensure_idle()?;
        }
        let speeds = *job.speeds();
        for (m, sp) in speeds.iter().enumerate() {
            if let Some(sp) = sp {
                self.set_speeds(m, *sp)?;
            }
        }
        if self.link.stop_wanted(id) {
            return Ok(Outcome::Stopped);
        }
        match job {
            Job::Sync { segs, .. } => {
                if self.chain_dirty {
                    self.clear_chain()?;
                }
                if let [only] = segs.as_slice() {
                    self.send(Self::sync_cmd(only, None))?;
                } else {
                    let last = segs.len().saturating_sub(1);
                    for (i, seg) in segs.iter().enumerate() {
                        if i == last {
                            self.send(Self::sync_cmd(seg, Some(1)))?;
                            self.chain_dirty = false;
                        } else {
                            self.chain_dirty = true;
                            self.send(Self::sync_cmd(seg, Some(0)))?;
                            if self.link.stop_wanted(id) {
                                // Nothing moves yet: drop what is stored.
                                self.clear_chain()?;
                                return Ok(Outcome::Stopped);
                            }
                        }
                    }
                }
            }
            Job::Independent { steps, .. } => {
                for (m, &n) in steps.iter().enumerate() {
                    if n == 0 {
                        continue;
                    }
                    if self.link.stop_wanted(id) {
                        self.stop_motors(&moving)?;
                        return Ok(Outcome::Stopped);
                    }
                    self.send(Command::Move {
                        id: ID,
                        motor: m as u32,
                        steps: u32::try_from(n.unsigned_abs()).unwrap_or(u32::MAX),
                        direction: u32::from(n < 0),
                    })?;
                }
            }
            Job::Home { dirs, .. } => {
                for (m, d) in dirs.iter().enumerate() {
                    let Some(direction) = *d else {
                        continue;
                    };
                    if self.link.stop_wanted(id) {
                        self.stop_motors(&moving)?;
                        return Ok(Outcome::Stopped);
                    }
                    self.send(Command::Home {
                        id: ID,
                        motor: m as u32,
                        direction,
                    })?;
                }
            }
        }
        let dirs = job.last_dirs();
        loop {
            if self.link.stop_wanted(id) {
                self.stop_motors(&moving)?;
                return Ok(Outcome::Stopped);
            }
            let mut running = false;
            let mut at_limit = None;
            for (m, &mv) in moving.iter().enumerate() {
                if !mv {
                    continue;
                }
                let st = self.status(m)?;
                if st.running {
                    running = true;
                    break;
                }
                let home = match dirs[m] {
                    Some(0) => st.home0,
                    Some(_) => st.home1,
                    None => false,
                };
                if home && at_limit.is_none() {
                    at_limit = Some(m);
                }
            }
            if !running {
                // A move that ends on the limit switch ahead was stopped by it (§6.5: no
                // motion proceeds beyond a home); a homing ends there by design.
                return Ok(match at_limit {
                    Some(m) if !matches!(job, Job::Home { .. }) => Outcome::Failed(Fault::Limit(m)),
                    _ => Outcome::Done,
                });
            }
            self.pause(id);
        }
    }

    fn pause(&mut self, id: u64) {
        if self.client.transport().is_realtime() {
            self.link.pause(id, POLL_INTERVAL);
        } else {
            self.client.transport().idle(POLL_INTERVAL);
        }
    }

    fn stop_motors(&mut self, moving: &[bool; MOTORS]) -> Result<(), ClientError> {
        for (m, &mv) in moving.iter().enumerate() {
            if mv {
                self.send(Command::Stop {
                    id: ID,
                    motor: m as u32,
                })?;
            }
        }
        Ok(())
    }

    /// After a failure: `S` to every motor of the job, best effort (a line that timed out
    /// once is not waited for again).
    fn stop_after_error(&mut self, job: &Job, fault: Fault) {
        let moving = job.moving();
        for (m, &mv) in moving.iter().enumerate() {
            if !mv {
                continue;
            }
            let r = self.send(Command::Stop {
                id: ID,
                motor: m as u32,
            });
            if fault == Fault::Link && r.is_err() {
                break;
            }
        }
        self.chain_dirty = true;
    }
}

/// An MC3B behind a card: the worker on its own thread. Dropping it stops a running job
/// (`S`) and ends the thread; the port closes with it.
#[derive(Debug)]
pub struct Device {
    card: usize,
    link: Arc<Link>,
    thread: Option<JoinHandle<()>>,
    limits: [LimitMasks; MOTORS],
}

impl Device {
    /// Opens the serial port at `path` (19200 8N1), greets the MC3B and starts the
    /// worker. The error says what failed.
    /// `limits` are the motors' limit masks (`L`), set before anything moves.
    pub fn open(
        card: usize,
        path: &str,
        timeout: Duration,
        limits: &[LimitMasks; MOTORS],
    ) -> Result<Device, String> {
        let port = open_port(path, timeout).map_err(|e| format!("cannot open {path}: {e}"))?;
        Device::start(card, Box::new(port), timeout, limits).map_err(|e| format!("{path}: {e}"))
    }

    /// [`Device::open`] over any transport.
    pub fn start(
        card: usize,
        transport: Box<dyn Transport + Send>,
        timeout: Duration,
        limits: &[LimitMasks; MOTORS],
    ) -> Result<Device, String> {
        let (link, worker) = connect_with(transport, timeout, limits)?;
        if link.shut_down() {
            return Err("link closed".into());
        }
        let thread = std::thread::Builder::new()
            .name(format!("mccl-mc3b-{card}"))
            .spawn(move || worker.run())
            .map_err(|e| format!("cannot start the MC3B thread: {e}"))?;
        Ok(Device {
            card,
            link,
            thread: Some(thread),
            limits: *limits,
        })
    }

    /// The limit masks set on the device's motors.
    pub fn limits(&self) -> [LimitMasks; MOTORS] {
        self.limits
    }

    /// The card whose channels 0..2 this MC3B is.
    pub fn card(&self) -> usize {
        self.card
    }

    /// The link groups on this card use.
    pub fn link(&self) -> Arc<Link> {
        self.link.clone()
    }
}

impl Drop for Device {
    fn drop(&mut self) {
        self.link.shutdown();
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

/// Reply timeout of the backend: `MCL_TIMEOUT_MS` (a positive integer of ms, as for the
/// `mcl_*` library) or 500 ms.
pub fn reply_timeout() -> Duration {
    super::client::timeout_from_env()
}

/// Opens the MC3B of every card of `sim` (among the first `cards`) that names an
/// `mc3b_port`, for the groups that will run. Refused, with a message on stderr: two
/// groups driving channels 0..2 of one MC3B (`GROUP_PARAMETER_ERR`: the device runs one
/// job at a time), a port that cannot be opened or an MC3B that does not answer
/// (`INITIAL_MOTION_ERR`).
pub fn open_devices(
    sim: &crate::sim::config::SimConfig,
    cards: usize,
    groups: &[(usize, crate::config::GroupDef)],
    mac: &crate::config::MacTable,
) -> crate::error::McclResult<Vec<Device>> {
    use crate::error::McclError;
    let mut devices = Vec::new();
    for (card, mac) in mac.iter().enumerate().take(cards) {
        let Some(path) = sim.card(card).mc3b_port.as_deref() else {
            continue;
        };
        let drivers: Vec<usize> = groups
            .iter()
            .filter(|(_, g)| {
                g.card.0 == card && g.channels.iter().flatten().any(|ch| ch.0 < MOTORS)
            })
            .map(|(i, _)| *i)
            .collect();
        if let [a, b, ..] = drivers.as_slice() {
            eprintln!(
                "MCCL: MCC_InitSystem failed: card {card} is an MC3B ({path}): groups {a} and \
                 {b} both drive its channels 0..2 (one group per MC3B)"
            );
            return Err(McclError::Group);
        }
        let limits: [LimitMasks; MOTORS] =
            std::array::from_fn(|m| motor_limits(sim.channel(card, m), &mac[m]));
        match Device::open(card, path, reply_timeout(), &limits) {
            Ok(d) => devices.push(d),
            Err(msg) => {
                eprintln!("MCCL: MCC_InitSystem failed: card {card} (MC3B): {msg}");
                return Err(McclError::NotInitialized);
            }
        }
    }
    Ok(devices)
}

/// The limit masks of the motor on a channel: its configured `mc3b_limit_bits` (+, −),
/// each active at the level of the program's wiring setting (`SL_NORMAL_OPEN`: +5 V,
/// `SL_NORMAL_CLOSE`: 0 V, `SL_UNUSED`: no switch). Direction 0 counts steps up, so the +
/// switch is direction 0's unless the channel's output is reversed (`wPosToEncoderDir`).
pub fn motor_limits(
    ch: &crate::sim::config::ChannelSim,
    mac: &crate::vendor::SYS_MAC_PARAM,
) -> LimitMasks {
    use crate::vendor::consts as c;
    let Some([plus, minus]) = ch.mc3b_limit_bits else {
        return [0; 4];
    };
    let level = |mode: u16| match mode {
        c::SL_NORMAL_OPEN => Some(true),
        c::SL_NORMAL_CLOSE => Some(false),
        _ => None,
    };
    let (up, down) = (
        level(mac.wOverTravelUpSensorMode),
        level(mac.wOverTravelDownSensorMode),
    );
    if mac.wPosToEncoderDir == 1 {
        limit_masks([minus, plus], [down, up])
    } else {
        limit_masks([plus, minus], [up, down])
    }
}

#[cfg(test)]
pub(crate) mod tests;
