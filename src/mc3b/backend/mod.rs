//! The MC3B as a backend of the virtual card: a card whose `mc3b_port` is set in
//! `MCCL_SIM` has its channels 0..2 on an MC3B, and `MCC_*` motion of a group on that
//! card runs on the device: [`Executor`] runs a group's queue there, behind the engine's
//! door for executors outside the card (`crate::engine::group::external`).
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
//! [`Emulator`](::mc3b::emulator::Emulator) fed the same acknowledged commands at the
//! same times) — an estimate.
//!
//! Files: `convert.rs` (units, speeds, chords), `job.rs` (jobs, faults, reports),
//! `link.rs` (the group–worker meeting point), `executor.rs` (a group's commands as jobs;
//! the batching in `executor/batch.rs`, its go home in `executor/home.rs`), `worker.rs` (the blocking I/O and the
//! model), `limits.rs` (limit masks), `device.rs` (the worker's thread, opening the
//! devices of a configuration; the system attaches the groups).

use std::time::Duration;

use ::mc3b::emulator::CHAIN_CAPACITY;

mod convert;
mod device;
mod executor;
mod job;
mod limits;
mod link;
mod worker;

pub use convert::{
    chord_count, chord_points, clamp_accel, clamp_velocity, move_length, sagitta, speeds_for,
    sync_speeds, Ramp, Seg, Speeds, MAX_CHORDS,
};
pub use device::{open_devices, reply_timeout, Device};
pub use executor::Executor;
pub use job::{Fault, Job, Outcome, Report};
pub use limits::{limit_masks, motor_limits, LimitMasks};
pub use link::Link;
pub use worker::{connect, connect_with, Worker};

/// Error record of a group whose MC3B did not answer (timeout) or whose serial line
/// failed. Not in the vendor's table; the group stops and runs no command until
/// `MCC_ClearError`.
pub const ERR_MC3B_LINK: i32 = crate::error_record::ErrorRecord::Mc3bLink.code();
/// Error record of a group whose MC3B refused a command (`E0`..`E3`) or answered
/// something that does not fit it.
pub const ERR_MC3B_DEVICE: i32 = crate::error_record::ErrorRecord::Mc3bDevice.code();

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

#[cfg(test)]
pub(crate) mod tests;
