//! Routines called once per interpolation period, after the tick and after the interrupt
//! routines (`crate::engine::isr`), on the engine thread with no library lock held:
//!
//! 1. every group's INTERP routine of reverse interpolation (`MCC_SetReverseInterpRoutine`)
//!    that the tick made due, in group-slot order; its return value steers the group's
//!    next tick (`group/post.rs`);
//! 2. the cycle routine (`MCC_SetCycleInterruptRoutine`), one per system.
//!
//! Like the interrupt routines they may call any `MCC_*` function; after one closed the
//! system (the clock stopped) no further routine of that tick runs.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// The per-period routines of a running system.
#[derive(Debug, Default)]
pub struct CycleRoutines {
    /// `MCC_SetCycleInterruptRoutine`'s routine (0: none).
    cycle: AtomicUsize,
    /// Set once any group has had an INTERP routine: only then does the engine look
    /// for due calls (it locks each group for that).
    reverse: AtomicBool,
}

/// `CYCLE_INTERRUPT_ISR`.
type RawCycle = unsafe extern "system" fn();
/// `INTERP`.
type RawInterp = unsafe extern "system" fn(
    std::os::raw::c_int,
    std::os::raw::c_int,
    std::os::raw::c_int,
    *mut std::os::raw::c_void,
) -> std::os::raw::c_int;

impl CycleRoutines {
    /// Registers the cycle routine at address `f` (0 unregisters).
    pub fn set_cycle(&self, f: usize) {
        self.cycle.store(f, Ordering::Release);
    }

    /// Notes that a group has an INTERP routine from now on.
    pub fn arm_reverse(&self) {
        self.reverse.store(true, Ordering::Release);
    }

    /// Whether a routine of this module may run (they read positions: snapshots must
    /// then be published every tick).
    pub fn any(&self) -> bool {
        self.cycle.load(Ordering::Acquire) != 0 || self.reverse.load(Ordering::Acquire)
    }

    /// Whether any group has had an INTERP routine.
    pub(in crate::engine) fn reverse_armed(&self) -> bool {
        self.reverse.load(Ordering::Acquire)
    }

    /// Calls the cycle routine, if one is registered. Call with no lock held.
    pub(in crate::engine) fn call_cycle(&self) {
        let f = self.cycle.load(Ordering::Acquire);
        if f != 0 {
            // SAFETY: `f` was stored from a non-null `CYCLE_INTERRUPT_ISR`, a C function
            // taking nothing and returning nothing; C routines cannot unwind into Rust.
            unsafe {
                let f = std::mem::transmute::<usize, RawCycle>(f);
                f();
            }
        }
    }
}

/// Calls the INTERP routine at address `f` for command `cmd` of `group` at `time`, with
/// no buffer (the registration has none); returns its decision.
///
/// # Safety
/// `f` must have been stored from a non-null `INTERP`, a C function with that signature.
pub(in crate::engine) unsafe fn call_interp(
    f: usize,
    group: std::os::raw::c_int,
    cmd: std::os::raw::c_int,
    time: std::os::raw::c_int,
) -> std::os::raw::c_int {
    // SAFETY: `f` is an `INTERP` (this function's contract); the buffer argument is NULL,
    // which the registration allows; C routines cannot unwind into Rust.
    unsafe {
        let f = std::mem::transmute::<usize, RawInterp>(f);
        f(group, cmd, time, std::ptr::null_mut())
    }
}
