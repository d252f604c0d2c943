//! The engine thread's CPU time, for the benchmarks that divide it by ticks.
//!
//! Included by `tick_floor.rs` and `engine.rs` (`#[path]`); `benches/support/` holds no
//! benchmark of its own.

use std::time::{Duration, Instant};

/// The thread id of the running engine's thread (named `mccl-engine`).
///
/// The engine of a system closed just before may still be listed: a joined thread leaves
/// `/proc/self/task` a moment after its join returns, and until then two are listed (the
/// old one's CPU clock fails when read). So this waits until there is exactly one, up to
/// 5 s, and panics with what it found after that.
pub fn engine_tid() -> libc::pid_t {
    let deadline = Instant::now() + Duration::from_secs(5);
    loop {
        let engines: Vec<libc::pid_t> = std::fs::read_dir("/proc/self/task")
            .expect("/proc")
            .flatten()
            .filter(|e| {
                std::fs::read_to_string(e.path().join("comm"))
                    .is_ok_and(|c| c.trim() == "mccl-engine")
            })
            .filter_map(|e| e.file_name().to_str()?.parse().ok())
            .collect();
        match engines[..] {
            [tid] => return tid,
            _ if Instant::now() > deadline => panic!("engine threads: {engines:?}"),
            _ => std::thread::sleep(Duration::from_millis(1)),
        }
    }
}

/// The CPU-time clock of the running engine's thread, which the kernel brings up to date
/// when it is read (the clock `pthread_getcpuclockid` gives, made from the thread id as
/// glibc makes it: `(!tid << 3) | CPUCLOCK_PERTHREAD | CPUCLOCK_SCHED`).
/// `/proc/<tid>/schedstat` is not: for a thread running on another CPU it lags until the
/// scheduler's next tick (up to 4 ms here), longer than a short measurement.
pub fn engine_cpu_clock() -> libc::clockid_t {
    (!engine_tid() << 3) | 6
}

/// The time on CPU-time clock `clock`, ns.
pub fn cpu_clock_ns(clock: libc::clockid_t) -> u64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: a valid timespec to write; an invalid clock only makes the call fail.
    let rc = unsafe { libc::clock_gettime(clock, &mut ts) };
    assert_eq!(rc, 0, "clock_gettime of CPU clock {clock}");
    u64::try_from(ts.tv_sec).unwrap_or(0) * 1_000_000_000 + u64::try_from(ts.tv_nsec).unwrap_or(0)
}

/// CPU time the calling thread has used, ns.
#[allow(dead_code)] // used by tick_floor, not by engine
pub fn thread_cpu_ns() -> u64 {
    cpu_clock_ns(libc::CLOCK_THREAD_CPUTIME_ID)
}
