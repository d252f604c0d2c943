//! Custom motion (`MCC_CustomMotion`, `MCC_CustomMotionEx`, `MCC_InfiniteMotion`) as the
//! library runs it process-wide: the count of custom commands alive, their ids, and the
//! mark of a thread running a callback. The commands themselves, and the stage's steps,
//! are the core's [`mccl_core::engine::custom`] (re-exported here).

pub use mccl_core::engine::custom::*;

use std::cell::Cell;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

/// Custom motion commands alive anywhere (queued, running or awaiting cleanup): while
/// none is, the stage costs one atomic load a tick.
static LIVE: AtomicUsize = AtomicUsize::new(0);

/// Whether a custom command of any system may have callbacks to run (see `LIVE`).
pub(in crate::engine) fn live() -> bool {
    LIVE.load(Ordering::Acquire) != 0
}
static NEXT_ID: AtomicU64 = AtomicU64::new(1);

/// A fresh id for a custom command ([`CustomSpec::new`]).
pub fn next_id() -> u64 {
    NEXT_ID.fetch_add(1, Ordering::Relaxed)
}

/// The count of custom commands alive that every [`CustomSpec`] is counted in.
pub fn live_count() -> &'static AtomicUsize {
    &LIVE
}

thread_local! {
    /// The group whose custom-motion callback this thread is running, if any.
    static IN_CALLBACK: Cell<Option<usize>> = const { Cell::new(None) };
}

/// The group whose callback the calling thread is running for the library: a custom
/// motion's, or a kinematics initialiser or forward kinematics run while the card starts.
pub fn in_callback() -> Option<usize> {
    IN_CALLBACK.with(Cell::get)
}

/// Runs `f`, the program's code, marked as a callback of `group` ([`in_callback`]).
pub(crate) fn as_callback<R>(group: usize, f: impl FnOnce() -> R) -> R {
    let prev = IN_CALLBACK.with(|c| c.replace(Some(group)));
    let r = f();
    IN_CALLBACK.with(|c| c.set(prev));
    r
}
