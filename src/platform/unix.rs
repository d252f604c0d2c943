//! The platform layer on Linux (and, where the calls exist, other Unix systems).

use std::io;

/// Now on clock `id`, ns (`None` if the call fails). The monotonic clocks are answered by
/// the vDSO, without a system call.
#[inline]
fn clock_ns(id: libc::clockid_t) -> Option<u64> {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid, writable timespec; an unknown clock only makes the call
    // fail.
    if unsafe { libc::clock_gettime(id, &mut ts) } != 0 {
        return None;
    }
    let s = u64::try_from(ts.tv_sec).unwrap_or(0);
    let ns = u64::try_from(ts.tv_nsec).unwrap_or(0);
    Some(s.saturating_mul(1_000_000_000).saturating_add(ns))
}

/// CLOCK_MONOTONIC always exists; were the call to fail, this reads 0.
#[inline]
pub(super) fn monotonic_ns() -> u64 {
    clock_ns(libc::CLOCK_MONOTONIC).unwrap_or(0)
}

/// CLOCK_MONOTONIC_COARSE exists on every Linux since 2.6.32; elsewhere (or should it
/// fail) the monotonic clock.
#[inline]
pub(super) fn coarse_monotonic_ns() -> u64 {
    #[cfg(any(target_os = "linux", target_os = "android"))]
    if let Some(ns) = clock_ns(libc::CLOCK_MONOTONIC_COARSE) {
        return ns;
    }
    monotonic_ns()
}

pub(super) fn sleep_until_ns(ns: u64) {
    #[cfg(any(target_os = "linux", target_os = "android", target_os = "freebsd"))]
    {
        let ts = libc::timespec {
            tv_sec: libc::time_t::try_from(ns / 1_000_000_000).unwrap_or(libc::time_t::MAX),
            tv_nsec: libc::c_long::try_from(ns % 1_000_000_000).unwrap_or(0),
        };
        // SAFETY: `ts` is a valid timespec; with TIMER_ABSTIME the remainder pointer is
        // not used, so NULL is allowed. An interrupted sleep (EINTR) just returns.
        unsafe {
            libc::clock_nanosleep(
                libc::CLOCK_MONOTONIC,
                libc::TIMER_ABSTIME,
                &ts,
                std::ptr::null_mut(),
            )
        };
    }
    #[cfg(not(any(target_os = "linux", target_os = "android", target_os = "freebsd")))]
    {
        let now = monotonic_ns();
        if ns > now {
            std::thread::sleep(std::time::Duration::from_nanos(ns - now));
        }
    }
}

/// The thread's timer slack is set to 1 ns (`PR_SET_TIMERSLACK`), so the kernel does not
/// defer its wake-up by the default 50 µs a normal thread may be kept waiting.
pub(super) fn prepare_precise_sleep() {
    #[cfg(any(target_os = "linux", target_os = "android"))]
    // SAFETY: PR_SET_TIMERSLACK takes an unsigned long and changes only this thread.
    unsafe {
        libc::prctl(libc::PR_SET_TIMERSLACK, 1 as libc::c_ulong, 0, 0, 0);
    }
}

#[cfg(any(target_os = "linux", target_os = "android"))]
pub(super) const CPU_LIMIT: usize = libc::CPU_SETSIZE as usize;
#[cfg(not(any(target_os = "linux", target_os = "android")))]
pub(super) const CPU_LIMIT: usize = 0;

#[cfg(not(any(target_os = "linux", target_os = "android")))]
fn unsupported(what: &str) -> io::Error {
    io::Error::new(io::ErrorKind::Unsupported, what.to_string())
}

pub(super) fn pin_to_cpu(cpu: usize) -> io::Result<()> {
    #[cfg(any(target_os = "linux", target_os = "android"))]
    {
        if cpu >= CPU_LIMIT {
            return Err(io::Error::from(io::ErrorKind::InvalidInput));
        }
        // SAFETY: a zeroed cpu_set_t is a valid empty set; `cpu` < CPU_SETSIZE (checked
        // above); pid 0 is the calling thread.
        let r = unsafe {
            let mut set: libc::cpu_set_t = std::mem::zeroed();
            libc::CPU_SET(cpu, &mut set);
            libc::sched_setaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &set)
        };
        if r != 0 {
            return Err(io::Error::last_os_error());
        }
        Ok(())
    }
    #[cfg(not(any(target_os = "linux", target_os = "android")))]
    {
        let _ = cpu;
        Err(unsupported("no sched_setaffinity on this system"))
    }
}

pub(super) fn raise_priority(priority: i32) -> io::Result<()> {
    let p = libc::sched_param {
        sched_priority: priority,
    };
    // SAFETY: the calling thread's handle and a valid sched_param.
    let r = unsafe { libc::pthread_setschedparam(libc::pthread_self(), libc::SCHED_FIFO, &p) };
    if r != 0 {
        return Err(io::Error::from_raw_os_error(r));
    }
    Ok(())
}

pub(super) fn lock_memory() -> io::Result<()> {
    // SAFETY: mlockall has no memory-safety preconditions.
    if unsafe { libc::mlockall(libc::MCL_CURRENT | libc::MCL_FUTURE) } != 0 {
        return Err(io::Error::last_os_error());
    }
    Ok(())
}

/// `struct sched_attr` of `sched_setattr(2)` (the first version, 48 bytes), which the
/// `libc` crate does not declare.
#[cfg(any(target_os = "linux", target_os = "android"))]
#[repr(C)]
#[derive(Debug, Default)]
struct SchedAttr {
    size: u32,
    sched_policy: u32,
    sched_flags: u64,
    sched_nice: i32,
    sched_priority: u32,
    sched_runtime: u64,
    sched_deadline: u64,
    sched_period: u64,
}

/// The calling thread's scheduling attributes (`sched_getattr(2)`).
#[cfg(any(target_os = "linux", target_os = "android"))]
fn own_sched_attr() -> io::Result<SchedAttr> {
    let mut a = SchedAttr::default();
    let size = std::mem::size_of::<SchedAttr>() as u32;
    // SAFETY: `a` is a writable sched_attr of `size` bytes; pid 0 is this thread.
    let r = unsafe {
        libc::syscall(
            libc::SYS_sched_getattr,
            0,
            &mut a as *mut SchedAttr,
            size,
            0,
        )
    };
    if r != 0 {
        return Err(io::Error::last_os_error());
    }
    a.size = size;
    Ok(a)
}

/// Linux 6.12 and later (EEVDF) let a thread with a shorter slice preempt the running one
/// when it wakes; older kernels accept the request and ignore it. The nice value is read
/// first and written back unchanged (which needs no privilege).
pub(super) fn request_slice(us: u64) -> io::Result<()> {
    #[cfg(any(target_os = "linux", target_os = "android"))]
    {
        let mut a = own_sched_attr()?;
        let normal = [libc::SCHED_OTHER, libc::SCHED_BATCH];
        if !normal.iter().any(|&p| p as u32 == a.sched_policy) {
            return Ok(());
        }
        a.sched_flags = 0;
        a.sched_runtime = us.saturating_mul(1000);
        // SAFETY: `a` is a valid sched_attr of `a.size` bytes; pid 0 is this thread.
        let r = unsafe { libc::syscall(libc::SYS_sched_setattr, 0, &a as *const SchedAttr, 0) };
        if r != 0 {
            return Err(io::Error::last_os_error());
        }
        Ok(())
    }
    #[cfg(not(any(target_os = "linux", target_os = "android")))]
    {
        let _ = us;
        Err(unsupported("no sched_setattr on this system"))
    }
}

/// Nice 10: lowering one's own priority is always permitted.
pub(super) fn lower_thread_priority() -> io::Result<()> {
    #[cfg(any(target_os = "linux", target_os = "android"))]
    {
        // SAFETY: gettid has no preconditions and returns the calling thread's id.
        let tid = unsafe { libc::syscall(libc::SYS_gettid) };
        let tid = libc::id_t::try_from(tid).map_err(|_| io::Error::last_os_error())?;
        // SAFETY: setpriority on this thread's own id changes only its nice value.
        if unsafe { libc::setpriority(libc::PRIO_PROCESS, tid, 10) } != 0 {
            return Err(io::Error::last_os_error());
        }
        Ok(())
    }
    #[cfg(not(any(target_os = "linux", target_os = "android")))]
    {
        Err(unsupported("no per-thread nice value on this system"))
    }
}

#[cfg(all(test, any(target_os = "linux", target_os = "android")))]
mod tests {
    use super::*;

    /// Whether the running kernel grants custom time slices to normal threads (Linux
    /// 6.12 and later).
    fn kernel_has_custom_slices() -> bool {
        let release = std::fs::read_to_string("/proc/sys/kernel/osrelease").unwrap_or_default();
        let mut v = release
            .split(|c: char| !c.is_ascii_digit())
            .filter_map(|n| n.parse::<u32>().ok());
        let (major, minor) = (v.next().unwrap_or(0), v.next().unwrap_or(0));
        (major, minor) >= (6, 12)
    }

    #[test]
    fn a_slice_request_keeps_the_nice_value() {
        // On a thread niced to 5 or more (raising the nice value needs no privilege), a
        // request for a 100 µs slice succeeds: the kernel reports 100,000 ns where it
        // grants custom slices, and the nice value is still the one set (written back as
        // read: asking for 0 would need privilege and fail).
        let (r, slice, nice) = std::thread::spawn(|| {
            // SAFETY: setpriority/getpriority on the calling thread (tid) only.
            unsafe {
                let tid = libc::gettid() as libc::id_t;
                // 5, or more if the tests already run niced (lowering it would need
                // privilege).
                let nice = (libc::getpriority(libc::PRIO_PROCESS, tid) + 1).clamp(5, 19);
                assert_eq!(libc::setpriority(libc::PRIO_PROCESS, tid, nice), 0);
                prepare_precise_sleep();
                let r = request_slice(100);
                let now = libc::getpriority(libc::PRIO_PROCESS, tid);
                let slice = own_sched_attr().ok().map(|a| a.sched_runtime);
                (r, slice, (nice, now))
            }
        })
        .join()
        .unwrap();
        assert!(r.is_ok(), "{r:?}");
        assert_eq!(nice.1, nice.0, "the nice value set before");
        if let (Some(slice), true) = (slice, kernel_has_custom_slices()) {
            assert_eq!(slice, 100_000);
        }
    }
}
