//! The device side of the backend: the [`Worker`] owns the client, runs jobs one at a
//! time, counts confirmed steps and keeps the model of the device that estimates the
//! position after a stop.

use std::sync::Arc;
use std::time::Duration;

use super::convert::Speeds;
use super::job::{Fault, Job, Outcome, Report};
use super::limits::LimitMasks;
use super::link::Link;
use super::{MOTORS, POLL_INTERVAL};
use ::mc3b::client::{Client, ClientError, MotorStatus, Transport};
use ::mc3b::codec::{Command, ErrorCode};
use ::mc3b::emulator::{Emulator, PRODUCT_ID};

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
    if product != PRODUCT_ID {
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

    pub(super) fn catch_up(&mut self) {
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
    fn status(&mut self, m: usize) -> Result<MotorStatus, ClientError> {
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
            return Err(ClientError::Device(ErrorCode::MotorRunning));
        }
        self.suspect = false;
        Ok(())
    }

    pub(super) fn model_pos(&self) -> [i64; MOTORS] {
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
