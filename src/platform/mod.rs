//! What differs between the operating systems, in one place: the rest of the crate calls
//! the functions and types of this module and has no `cfg` of its own for the system it
//! runs on. Each system's side is one file (`platform/unix.rs`, `platform/windows.rs`); both
//! implement every item here, so a missing piece is a compile error on that system.
//!
//! | | Linux (Unix) | Windows (10 or later) |
//! |---|---|---|
//! | [`monotonic_ns`] | `clock_gettime(CLOCK_MONOTONIC)` | `QueryPerformanceCounter` |
//! | [`coarse_monotonic_ns`] | `CLOCK_MONOTONIC_COARSE` | the same as [`monotonic_ns`] |
//! | [`sleep_until_ns`] | `clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME)` | the thread's high-resolution waitable timer, set to the time left |
//! | [`prepare_precise_sleep`] | timer slack 1 ns (`PR_SET_TIMERSLACK`) | creates that timer |
//! | [`raise_priority`] (`MCCL_RT_PRIORITY=N`) | `SCHED_FIFO` at priority N | `THREAD_PRIORITY_TIME_CRITICAL` (every N alike) |
//! | [`pin_to_cpu`] (`MCCL_RT_CPU=N`) | `sched_setaffinity` | `SetThreadAffinityMask` |
//! | [`lock_memory`] (`MCCL_RT_LOCK=1`) | `mlockall` | refused: no equivalent |
//! | [`request_slice`] (`MCCL_RT_SLICE_US`) | `sched_setattr`'s runtime | refused: no per-thread slice |
//! | [`lower_thread_priority`] | nice 10 | `THREAD_PRIORITY_BELOW_NORMAL` |
//!
//! A refusal is an `Err` whose message says what the system lacks; the callers turn it
//! into their own message (the engine's real-time settings print one line and run on).

use std::io;

#[cfg(unix)]
mod unix;
#[cfg(unix)]
use unix as os;

#[cfg(windows)]
mod windows;
#[cfg(windows)]
use windows as os;

/// Now on the monotonic clock, ns since an unspecified start (the clock `Instant` reads).
/// Never goes back; 0 were the system's clock to fail.
#[inline]
pub fn monotonic_ns() -> u64 {
    os::monotonic_ns()
}

/// Now on a monotonic clock that may lag by up to a scheduler tick (1–16 ms), ns, on the
/// same time base as [`monotonic_ns`]: for spacing things tens of ms apart, where it is
/// cheaper to read (on Linux about 6.5 ns against 32 ns).
#[inline]
pub fn coarse_monotonic_ns() -> u64 {
    os::coarse_monotonic_ns()
}

/// Sleeps until `ns` on the [`monotonic_ns`] clock: an absolute deadline, so a late
/// wake-up does not push the next one. May return early (a signal); the caller checks
/// the time again.
#[inline]
pub fn sleep_until_ns(ns: u64) {
    os::sleep_until_ns(ns)
}

/// Makes the calling thread's [`sleep_until_ns`] wake as close to its deadline as the
/// system allows (see the module's table). Call it once on a thread that sleeps to
/// deadlines (the realtime engine thread), before the first sleep.
pub fn prepare_precise_sleep() {
    os::prepare_precise_sleep()
}

/// How many CPUs [`pin_to_cpu`] can name: CPUs `0..CPU_LIMIT`.
pub const CPU_LIMIT: usize = os::CPU_LIMIT;

/// Runs the calling thread on CPU `cpu` only.
pub fn pin_to_cpu(cpu: usize) -> io::Result<()> {
    os::pin_to_cpu(cpu)
}

/// Runs the calling thread above every normally scheduled thread: on Linux `SCHED_FIFO` at
/// `priority` (1..=99), on Windows at `THREAD_PRIORITY_TIME_CRITICAL` whatever `priority`
/// (the top of the process's priority class).
pub fn raise_priority(priority: i32) -> io::Result<()> {
    os::raise_priority(priority)
}

/// Locks the whole process's memory, present and future, so that no page fault waits for
/// the disk.
pub fn lock_memory() -> io::Result<()> {
    os::lock_memory()
}

/// Asks for a time slice of `us` µs for the calling thread under normal scheduling,
/// keeping its policy and nice value. A thread under a real-time policy is left as it
/// is (`Ok`).
pub fn request_slice(us: u64) -> io::Result<()> {
    os::request_slice(us)
}

/// Lowers the calling thread's priority below the program's threads (a best-effort
/// background thread such as the browser panel's).
pub fn lower_thread_priority() -> io::Result<()> {
    os::lower_thread_priority()
}
