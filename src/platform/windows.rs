//! The platform layer on Windows (10 or later), through the `windows-sys` bindings.

use std::cell::Cell;
use std::io;
use std::sync::atomic::{AtomicU64, Ordering};

use windows_sys::Win32::Foundation::{CloseHandle, HANDLE};
use windows_sys::Win32::System::Performance::{QueryPerformanceCounter, QueryPerformanceFrequency};
use windows_sys::Win32::System::Threading::{
    CreateWaitableTimerExW, GetCurrentThread, SetThreadAffinityMask, SetThreadPriority,
    SetWaitableTimer, WaitForSingleObject, CREATE_WAITABLE_TIMER_HIGH_RESOLUTION, INFINITE,
    THREAD_PRIORITY_BELOW_NORMAL, THREAD_PRIORITY_TIME_CRITICAL, TIMER_ALL_ACCESS,
};

/// The performance counter's ticks per second (fixed at boot), read once.
fn counter_frequency() -> u64 {
    static FREQUENCY: AtomicU64 = AtomicU64::new(0);
    let f = FREQUENCY.load(Ordering::Relaxed);
    if f != 0 {
        return f;
    }
    let mut v = 0i64;
    // SAFETY: `v` is a valid, writable i64. The call cannot fail on Windows XP and later.
    unsafe { QueryPerformanceFrequency(&mut v) };
    let f = u64::try_from(v).unwrap_or(0).max(1);
    FREQUENCY.store(f, Ordering::Relaxed);
    f
}

/// `QueryPerformanceCounter` in ns (the counter `Instant` reads too).
#[inline]
pub(super) fn monotonic_ns() -> u64 {
    let mut v = 0i64;
    // SAFETY: `v` is a valid, writable i64. The call cannot fail on Windows XP and later.
    unsafe { QueryPerformanceCounter(&mut v) };
    let ticks = u64::try_from(v).unwrap_or(0);
    let f = counter_frequency();
    // In two parts, so that ticks x 1e9 cannot overflow.
    (ticks / f)
        .saturating_mul(1_000_000_000)
        .saturating_add((ticks % f) * 1_000_000_000 / f)
}

/// Windows has no cheaper reading on the same time base (`GetTickCount64` counts from
/// another start): the precise counter itself.
#[inline]
pub(super) fn coarse_monotonic_ns() -> u64 {
    monotonic_ns()
}

/// The calling thread's waitable timer: high-resolution where the system has them
/// (Windows 10 1803 and later: wakes within about 0.5 ms instead of the 15.6 ms system
/// tick), else a normal one; 0 if none could be made. Closed when the thread ends.
struct ThreadTimer(Cell<HANDLE>);

impl ThreadTimer {
    fn handle(&self) -> HANDLE {
        let h = self.0.get();
        if h != 0 {
            return h;
        }
        let make = |flags| {
            // SAFETY: no attributes and no name (both may be NULL); the flags and access
            // rights are documented values.
            unsafe {
                CreateWaitableTimerExW(std::ptr::null(), std::ptr::null(), flags, TIMER_ALL_ACCESS)
            }
        };
        let mut h = make(CREATE_WAITABLE_TIMER_HIGH_RESOLUTION);
        if h == 0 {
            h = make(0);
        }
        self.0.set(h);
        h
    }
}

impl Drop for ThreadTimer {
    fn drop(&mut self) {
        let h = self.0.get();
        if h != 0 {
            // SAFETY: a handle this thread created and nothing else holds.
            unsafe { CloseHandle(h) };
        }
    }
}

thread_local! {
    static TIMER: ThreadTimer = const { ThreadTimer(Cell::new(0)) };
}

/// The timer's due time is relative (in 100 ns units): an absolute one would be on the
/// wall clock, which may be set. It is the time left to the deadline on the monotonic
/// clock, read just before, so a late wake-up still does not push the next deadline.
pub(super) fn sleep_until_ns(ns: u64) {
    let now = monotonic_ns();
    if ns <= now {
        return;
    }
    let left = ns - now;
    let handle = TIMER.try_with(ThreadTimer::handle).unwrap_or(0);
    if handle == 0 {
        std::thread::sleep(std::time::Duration::from_nanos(left));
        return;
    }
    let due = -i64::try_from(left.div_ceil(100)).unwrap_or(i64::MAX);
    // SAFETY: `handle` is this thread's live timer; `due` is a valid i64; no completion
    // routine.
    let set = unsafe { SetWaitableTimer(handle, &due, 0, None, std::ptr::null(), 0) };
    if set == 0 {
        std::thread::sleep(std::time::Duration::from_nanos(left));
        return;
    }
    // SAFETY: a live handle; the timer fires once, so the wait ends.
    unsafe { WaitForSingleObject(handle, INFINITE) };
}

/// The thread's high-resolution timer is made now, not at the first deadline.
pub(super) fn prepare_precise_sleep() {
    let _ = TIMER.try_with(ThreadTimer::handle);
}

/// A thread's affinity mask has one bit per CPU of its processor group.
pub(super) const CPU_LIMIT: usize = usize::BITS as usize;

pub(super) fn pin_to_cpu(cpu: usize) -> io::Result<()> {
    let mask = 1usize
        .checked_shl(u32::try_from(cpu).unwrap_or(u32::MAX))
        .ok_or_else(|| io::Error::from(io::ErrorKind::InvalidInput))?;
    // SAFETY: the pseudo-handle of the calling thread; any mask is allowed (a CPU the
    // process may not use makes the call fail).
    if unsafe { SetThreadAffinityMask(GetCurrentThread(), mask) } == 0 {
        return Err(io::Error::last_os_error());
    }
    Ok(())
}

fn set_thread_priority(priority: i32) -> io::Result<()> {
    // SAFETY: the pseudo-handle of the calling thread and a documented priority value.
    if unsafe { SetThreadPriority(GetCurrentThread(), priority) } == 0 {
        return Err(io::Error::last_os_error());
    }
    Ok(())
}

/// `THREAD_PRIORITY_TIME_CRITICAL`: 15 in a normal-priority process, above every normal
/// thread, or 31 in a process the program put in `REALTIME_PRIORITY_CLASS`. Windows has
/// no levels between to map the values 1..=99 to.
pub(super) fn raise_priority(_priority: i32) -> io::Result<()> {
    set_thread_priority(THREAD_PRIORITY_TIME_CRITICAL)
}

pub(super) fn lock_memory() -> io::Result<()> {
    Err(io::Error::new(
        io::ErrorKind::Unsupported,
        "Windows cannot lock a whole process's memory (no mlockall)",
    ))
}

pub(super) fn request_slice(_us: u64) -> io::Result<()> {
    Err(io::Error::new(
        io::ErrorKind::Unsupported,
        "Windows has no per-thread time slice to ask for",
    ))
}

pub(super) fn lower_thread_priority() -> io::Result<()> {
    set_thread_priority(THREAD_PRIORITY_BELOW_NORMAL)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_monotonic_clock_moves_and_sleeps_reach_their_deadline() {
        let t0 = monotonic_ns();
        let deadline = t0 + 3_000_000;
        prepare_precise_sleep();
        sleep_until_ns(deadline);
        let t1 = monotonic_ns();
        assert!(t1 >= deadline, "woke {} ns early", deadline - t1);
        assert!(coarse_monotonic_ns() >= t1);
    }

    #[test]
    fn what_windows_lacks_is_refused_with_a_reason() {
        let e = lock_memory().unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::Unsupported);
        assert!(e.to_string().contains("mlockall"), "{e}");
        assert!(request_slice(100).is_err());
    }
}
