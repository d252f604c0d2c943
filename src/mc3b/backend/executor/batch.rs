//! Batching: which queued commands go to the device as one job (synchronous moves that
//! share feed and ramps, chained up to the device's buffer; one point-to-point command
//! as independent moves), the chords of arcs, and the refusals found on the way.

use super::{Executor, Phase};
use crate::config::AXES;
use crate::engine::command::{AxisMech, Command, Plan};
use crate::engine::group::external::Host;
use crate::mc3b::backend::{
    self, Job, Ramp, Seg, Speeds, CHORD_TOLERANCE_STEPS, MAX_BATCH, MOTORS,
};
use crate::planner::{Axes, Path};

/// What a synchronous move shares with the others of its batch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum SegKind {
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
pub(super) struct Pending {
    seg: Seg,
    kind: SegKind,
    /// The last move of its command.
    ends_cmd: bool,
}

/// What one attempt to start work did.
pub(super) enum Fill {
    /// A job or a delay started, or nothing can start now.
    Done,
    /// Commands that need no step ended at once: try again.
    Retired,
}

/// The next queued command as the batching sees it.
pub(super) enum Next {
    /// A blending or in-position switch.
    Switch,
    /// An output change.
    Output,
    /// A line or an arc (its moves share `kind`).
    Path(SegKind),
    /// A point-to-point command.
    Ptp { start: Axes, target: Axes },
    /// A delay of `s` seconds.
    Delay(f64),
}

/// Chord tolerance in UU: [`CHORD_TOLERANCE_STEPS`] steps of the finest X/Y/Z axis.
pub(super) fn chord_tolerance(axes: &[AxisMech; AXES]) -> f64 {
    let k = axes[..3].iter().map(|a| a.factor.abs()).fold(0.0, f64::max);
    if k > 0.0 {
        CHORD_TOLERANCE_STEPS / k
    } else {
        1e-3
    }
}

/// The first axis whose work zone a command leaves going further out (software
/// over-travel check on), visiting `points` from `start`.
pub(super) fn leaves_zone(host: &dyn Host, start: &Axes, points: &[Axes]) -> Option<usize> {
    let (axes, ot_check) = (host.axes(), host.ot_check());
    (0..AXES).find(|&i| {
        if !ot_check[i] || axes[i].channel.is_none() {
            return false;
        }
        let (hi, lo) = (axes[i].high, axes[i].low);
        let mut prev = start[i];
        points.iter().any(|p| {
            let out = (p[i] > hi && p[i] > prev) || (p[i] < lo && p[i] < prev);
            prev = p[i];
            out
        })
    })
}

impl Executor {
    /// The first queued command as the batching sees it.
    pub(super) fn peek(&self, host: &dyn Host) -> Option<Next> {
        let cmd = host.front()?;
        Some(match &cmd.plan {
            // Custom motion is refused when queued (`check`), so never reaches here.
            Plan::Blend(_) | Plan::InPos(..) | Plan::Custom(_) | Plan::Fault(_) => Next::Switch,
            Plan::Output(_) => Next::Output,
            Plan::Path(m) => Next::Path(match m.path {
                Path::Line(_) => SegKind::Line {
                    feed: cmd.info_feed,
                    acc_ms: cmd.acc_ms,
                    dec_ms: cmd.dec_ms,
                },
                Path::Arc(_) | Path::Helix(_) | Path::Cone(_) => SegKind::Chord {
                    feed: cmd.info_feed,
                },
            }),
            Plan::Ptp(_) => Next::Ptp {
                start: cmd.start(),
                target: cmd.target,
            },
            Plan::Delay(_) => Next::Delay(cmd.info_feed / 1000.0),
        })
    }

    /// Takes moves and commands for one job and hands it to the device.
    pub(super) fn fill_batch(&mut self, host: &mut dyn Host) -> Fill {
        let tol = chord_tolerance(host.axes());
        let mut batch: Vec<Pending> = Vec::new();
        let mut retire = 0usize;
        loop {
            if batch.len() >= MAX_BATCH {
                break;
            }
            if let Some(p) = self.pending.front().copied() {
                if batch.first().is_some_and(|b| b.kind != p.kind) {
                    break;
                }
                self.pending.pop_front();
                retire += usize::from(p.ends_cmd);
                batch.push(p);
                continue;
            }
            // Single block: one command per job.
            if !batch.is_empty() && host.single_block() {
                break;
            }
            let Some(next) = self.peek(host) else {
                break;
            };
            match next {
                Next::Switch => host.apply_switch(),
                Next::Output => {
                    if !batch.is_empty() {
                        break;
                    }
                    host.apply_switch();
                }
                Next::Path(kind) => {
                    if batch.first().is_some_and(|b| b.kind != kind) {
                        break;
                    }
                    let Some((start, points)) = host.front().and_then(|c| match &c.plan {
                        Plan::Path(m) => {
                            Some((m.path.start(), backend::chord_points(&m.path, tol)))
                        }
                        _ => None,
                    }) else {
                        break;
                    };
                    if let Some(axis) = leaves_zone(host, &start, &points) {
                        if batch.is_empty() {
                            self.over_travel(host, axis);
                            return Fill::Done;
                        }
                        break;
                    }
                    let Some(cmd) = host.pop_front() else {
                        break;
                    };
                    self.expand(host, &cmd, &points, kind);
                    host.start(cmd);
                }
                Next::Ptp { .. } | Next::Delay(_) if !batch.is_empty() => break,
                Next::Ptp { start, target } => {
                    if let Some(axis) = leaves_zone(host, &start, &[target]) {
                        self.over_travel(host, axis);
                        return Fill::Done;
                    }
                    let Some(cmd) = host.pop_front() else {
                        break;
                    };
                    let job = self.ptp_job(host, &cmd);
                    host.start(cmd);
                    if job.total() == [0; MOTORS] {
                        host.drop_first();
                        return Fill::Retired;
                    }
                    self.post(job, 1);
                    return Fill::Done;
                }
                Next::Delay(left) => {
                    let Some(cmd) = host.pop_front() else {
                        break;
                    };
                    host.start(cmd);
                    self.phase = Phase::Delay { left };
                    return Fill::Done;
                }
            }
        }
        let Some(first) = batch.first() else {
            return Fill::Done;
        };
        let segs: Vec<Seg> = batch.iter().map(|p| p.seg).collect();
        let speeds = backend::sync_speeds(&segs, first.kind.ramp(), host.speed_scale());
        let moves: Vec<[i64; MOTORS]> = segs
            .iter()
            .map(|s| s.steps)
            .filter(|s| *s != [0; MOTORS])
            .collect();
        if moves.is_empty() {
            host.retire(retire);
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
    pub(super) fn expand(
        &mut self,
        host: &dyn Host,
        cmd: &Command,
        points: &[Axes],
        kind: SegKind,
    ) {
        let feed = kind.feed();
        let mut prev = cmd.start();
        let n = points.len();
        let mut out = Vec::with_capacity(n);
        for (j, p) in points.iter().enumerate() {
            let dev = self.device_steps(host, p);
            let steps: [i64; MOTORS] = std::array::from_fn(|m| dev[m] - self.planned[m]);
            self.planned = dev;
            let len = backend::move_length(&prev, p);
            let secs = if feed > 0.0 { len / feed } else { 0.0 };
            out.push(Pending {
                seg: Seg { steps, secs },
                kind,
                ends_cmd: j + 1 == n,
            });
            prev = *p;
        }
        self.pending.extend(out);
    }

    /// A point-to-point command as one independent move per motor: each at its axis's
    /// speed (max safe speed × ratio, re-planned for `MCC_SyncPtP`) and acc/dec times.
    pub(super) fn ptp_job(&mut self, host: &dyn Host, cmd: &Command) -> Job {
        let dev = self.device_steps(host, &cmd.target);
        let scale = host.speed_scale();
        let steps: [i64; MOTORS] = std::array::from_fn(|m| dev[m] - self.planned[m]);
        self.planned = dev;
        let mut speeds: [Option<Speeds>; MOTORS] = [None; MOTORS];
        if let Plan::Ptp(p) = &cmd.plan {
            for i in 0..AXES {
                let Some(m) = self.motor[i] else {
                    continue;
                };
                if steps[m] == 0 {
                    continue;
                }
                let prof = p.profile(i);
                let k = host.axes()[i].factor.abs();
                // The peak the axis reaches over its ramps (a short move keeps the ramps
                // and lowers the peak, as planned on the card).
                let t = prof.period();
                let ramp = Ramp::Times {
                    acc_s: f64::from(prof.acc_periods()) * t,
                    dec_s: f64::from(prof.dec_periods()) * t,
                };
                speeds[m] = Some(backend::speeds_for(prof.speed() * k * scale, ramp));
            }
        }
        Job::Independent { steps, speeds }
    }
}
