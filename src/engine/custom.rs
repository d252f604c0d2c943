//! Custom motion (`MCC_CustomMotion`, `MCC_CustomMotionEx`, `MCC_InfiniteMotion`) as the
//! library runs it process-wide: the count of custom commands alive, their ids, and the
//! mark of a thread running a callback. The commands themselves, and the stage's steps,
//! are the core's [`mccl_core::engine::custom`] (re-exported here).

pub use mccl_core::engine::custom::*;

use crate::vendor::{CUSTOM_CLEANUP, CUSTOM_START_MOTION};
use std::cell::Cell;
use std::os::raw::c_void;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

/// Custom motion commands alive anywhere (queued, running or awaiting cleanup): while
/// none is, the stage costs one atomic load a tick.
static LIVE: AtomicUsize = AtomicUsize::new(0);

/// Whether a custom command of any system may have callbacks to run (see `LIVE`).
pub(in crate::engine) fn live() -> bool {
    LIVE.load(Ordering::Acquire) != 0
}
static NEXT_ID: AtomicU64 = AtomicU64::new(1);

/// A spec with a fresh id, counted as alive until dropped ([`CustomSpec::new`]).
#[allow(clippy::too_many_arguments)]
pub fn new_spec(
    start: CUSTOM_START_MOTION,
    interp: Interp,
    cleanup: CUSTOM_CLEANUP,
    blending: Option<Blending>,
    buffer: *mut c_void,
    override_motion: bool,
    mask: u32,
    absolute: bool,
) -> Option<CustomSpec> {
    // No id is used up by a refused spec.
    start?;
    CustomSpec::new(
        NEXT_ID.fetch_add(1, Ordering::Relaxed),
        &LIVE,
        start,
        interp,
        cleanup,
        blending,
        buffer,
        override_motion,
        mask,
        absolute,
    )
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
