//! The virtual card's engine: one thread per running system that ticks every interpolation
//! period on the [`Clock`](crate::clock::Clock), advances every group, and publishes
//! snapshots that status calls read without taking any lock.
//!
//! Locks: the groups share one mutex ([`Shared::group`] maps it to one group), so the
//! tick takes a single lock for all of them; a program's call holds it only to queue or
//! change its group. Under a virtual clock the engine thread keeps the machine's and the
//! groups' locks from one tick to the next while nothing in between needs them (no
//! routine, no trace, no other thread waiting: `Shared::quiet_between_ticks`); another
//! thread that wants one is counted and gets it at the next tick. The engine thread never
//! holds either while user code runs, so a callback may call any MCC_* function. Order:
//! `system::SYSTEM`, the machine, then the groups.
//!
//! The groups themselves and the tick (planning, tracks, custom motion, kinematics,
//! snapshots, one group and its parts, the go home, the safety checks, one tick of a
//! card) are the core's `mccl_core::engine`, re-exported here under the same names.
//! Files here, one concept each, their uses a DAG: `custom.rs` (custom motion's
//! process-wide count, ids and callback mark), `kinematics.rs` (registrations waiting
//! for the next init), the types [`Shared`] holds (`isr.rs`, `cycle.rs`, `view.rs`,
//! `trace.rs`), `shared/` ([`Shared`] and its methods, one concern a file), `tick.rs`
//! (the core's tick with the locks held and this engine's hooks), `cruise.rs` (the plan
//! of cruise ticks), `poll.rs` (polls that let virtual time run), `running.rs`
//! ([`Engine`]: the thread's start, loop, stop and join), `thread.rs` (real-time
//! settings of the thread).

mod cruise;
pub mod custom;
pub mod cycle;
pub mod isr;
pub mod kinematics;
mod poll;
mod running;
mod shared;
pub mod thread;
mod tick;
pub mod trace;
pub mod view;

pub use mccl_core::engine::{
    axes_of, card, command, custom_move, group, homing, note, safety, snapshot, track,
};
pub use poll::SPIN_POLLS;
pub use running::{on_retired_engine_thread, Engine};
pub use shared::{Shared, DEFAULT_PULSE_STOCK};
pub use tick::PUBLISH_EVERY;
