//! What a group hands to the device ([`Job`]) and what it gets back ([`Report`]).

use super::convert::Speeds;
use super::{ERR_MC3B_DEVICE, ERR_MC3B_LINK, MOTORS};
use ::mc3b::client::ClientError;

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

    pub(super) fn speeds(&self) -> &[Option<Speeds>; MOTORS] {
        match self {
            Job::Sync { speeds, .. }
            | Job::Independent { speeds, .. }
            | Job::Home { speeds, .. } => speeds,
        }
    }

    /// The direction (0 up, 1 down) each motor travels last in the job, if it moves.
    pub(super) fn last_dirs(&self) -> [Option<u32>; MOTORS] {
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

    pub(super) fn moving(&self) -> [bool; MOTORS] {
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
            Fault::Limit(_) => crate::error_record::ErrorRecord::Limit(0).code(),
        }
    }

    pub(super) fn of(e: &ClientError) -> Fault {
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
