//! How ticks happen. The engine thread asks the clock for permission before every tick;
//! the clock mode decides when it is given:
//!
//! * `realtime` (default): tick n starts at `start + n x period` on the monotonic clock
//!   (absolute deadlines, never a relative sleep). A tick that starts a whole period or
//!   more after its deadline is counted as missed; the engine then catches up back to
//!   back, so virtual time never silently drifts from real time. The engine thread
//!   sleeps straight to the deadline ([`sleep_until_ns`]: `clock_nanosleep(CLOCK_MONOTONIC,
//!   TIMER_ABSTIME)` on Linux, a high-resolution waitable timer on Windows), in slices
//!   of at most [`STOP_SLICE`] so that `stop` is seen promptly, takes no lock and makes
//!   no other system call on the way to a tick, and counts how late each tick started
//!   ([`Clock::lateness`]). Optionally (`MCCL_RT_SPIN_US`, off by default) it wakes a
//!   little early and spins on the clock up to the deadline.
//! * `fast` and `stepped`: virtual time runs only while the program waits, back to back
//!   as fast as the CPU allows, so a program always sees the same sequence of states
//!   whatever the machine's load. `MCC_TimeDelay(ms)` runs exactly the ticks covering
//!   `ms`. A status poll repeated at the same virtual time (a program spinning on
//!   `MCC_GetMotionStatus`) runs one tick under `stepped`, and under `fast` runs ticks
//!   until the polled status changes (at most [`FAST_POLL_MAX`] of virtual time).
//!
//! Virtual time is `ticks x period` in every mode.

pub mod latency;

use once_cell::sync::OnceCell;
use parking_lot::{Condvar, Mutex};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::thread::ThreadId;
use std::time::Duration;

/// The longest single sleep of the realtime engine thread: `stop` waits at most this
/// long for a sleeping engine to notice it.
pub const STOP_SLICE: Duration = Duration::from_millis(5);

/// The largest `MCCL_RT_SPIN_US` accepted, µs.
pub const SPIN_MAX_US: u64 = 1000;

/// Parses a value of `MCCL_RT_SPIN_US`: whole µs, 0..=[`SPIN_MAX_US`].
pub fn parse_spin_us(s: &str) -> Option<u64> {
    s.trim().parse::<u64>().ok().filter(|&v| v <= SPIN_MAX_US)
}

/// The spin `MCCL_RT_SPIN_US` asks for, ns (0 when unset or not valid; the engine
/// thread's set-up reports a bad value, see `engine::thread`).
fn spin_from_env() -> u64 {
    std::env::var("MCCL_RT_SPIN_US")
        .ok()
        .and_then(|v| parse_spin_us(&v))
        .unwrap_or(0)
        * 1000
}

thread_local! {
    /// Set on every engine thread (see [`Clock::set_engine_thread`]).
    static ON_AN_ENGINE_THREAD: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// The most virtual time one status poll runs under the fast clock.
pub const FAST_POLL_MAX: Duration = Duration::from_secs(60);

/// The clock modes selectable with the environment variable `MCCL_CLOCK`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ClockMode {
    /// Ticks on absolute real-time deadlines.
    Realtime,
    /// Back-to-back ticks while the program waits; a spinning status poll runs until the
    /// status changes.
    Fast,
    /// Back-to-back ticks while the program waits; a spinning status poll runs one tick.
    Stepped,
}

impl ClockMode {
    /// Parses a mode name (`realtime`, `fast`, `stepped`; case-insensitive).
    pub fn parse(s: &str) -> Option<ClockMode> {
        match s.trim().to_ascii_lowercase().as_str() {
            "realtime" | "real" | "" => Some(ClockMode::Realtime),
            "fast" => Some(ClockMode::Fast),
            "stepped" | "step" => Some(ClockMode::Stepped),
            _ => None,
        }
    }

    /// The mode named by `MCCL_CLOCK`; unset means realtime. An unknown name is an error
    /// (the caller reports it and refuses to start).
    pub fn from_env() -> Result<ClockMode, String> {
        match std::env::var("MCCL_CLOCK") {
            Err(_) => Ok(ClockMode::Realtime),
            Ok(v) => ClockMode::parse(&v)
                .ok_or_else(|| format!("MCCL_CLOCK={v:?} is not one of realtime, fast, stepped")),
        }
    }

    /// Whether virtual time runs only while the program waits.
    pub fn virtual_time(self) -> bool {
        self != ClockMode::Realtime
    }
}

/// What the engine thread should do next.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Next {
    /// Run one tick.
    Tick,
    /// Stop: the system is closing.
    Stop,
}

/// Where the realtime clock reads the time and how it sleeps: the monotonic clock, or
/// (tests) a scripted time.
#[derive(Debug)]
enum Source {
    Monotonic,
    #[cfg(test)]
    Fake(std::sync::Arc<tests::FakeTime>),
}

/// Now on the monotonic clock, ns ([`crate::platform::monotonic_ns`]).
pub use crate::platform::monotonic_ns;

/// Now on a monotonic clock that may lag by up to a scheduler tick, ns, on the time base
/// of [`monotonic_ns`] ([`crate::platform::coarse_monotonic_ns`]): for spacing things tens
/// of ms apart. Reading it costs a fifth of [`monotonic_ns`] on Linux (about 6.5 ns
/// against 32 ns on the development VM), which matters to a tick of 0.1 µs.
pub(crate) use crate::platform::coarse_monotonic_ns;

/// Sleeps until `ns` on the monotonic clock, an absolute deadline
/// ([`crate::platform::sleep_until_ns`]).
pub use crate::platform::sleep_until_ns;

impl Source {
    fn now_ns(&self) -> u64 {
        match self {
            Source::Monotonic => monotonic_ns(),
            #[cfg(test)]
            Source::Fake(f) => f.now(),
        }
    }

    fn sleep_until(&self, ns: u64) {
        match self {
            Source::Monotonic => sleep_until_ns(ns),
            #[cfg(test)]
            Source::Fake(f) => f.sleep_until(ns),
        }
    }
}

/// The clock shared by the engine thread and the program's threads.
///
/// `run_until`, `stop` and `wake_at` are only written with `inner` locked, so a waiter
/// that checks them under the lock and then waits on `cv` cannot miss a change; the
/// engine thread reads them without the lock on every tick (a tick of a long run then
/// takes no lock here). `tick_done` and a waiter pair up as in Dekker's algorithm: the
/// waiter publishes `wake_at`, then reads `ticks`; the engine bumps `ticks`, then reads
/// `wake_at` (all `SeqCst`), so at least one of them sees the other and the engine
/// locks `inner` to wake the waiter.
#[derive(Debug)]
pub struct Clock {
    mode: ClockMode,
    period: Duration,
    /// When tick 0 was due, ns of the monotonic clock (of `source`): the creation of
    /// the clock, moved to when the engine thread is ready by [`Clock::start_now`].
    start_ns: AtomicU64,
    /// `period` in ns.
    period_ns: u64,
    /// `period` in seconds and exactly in ns, as every tick uses them.
    period_s: f64,
    period_nanos: u128,
    source: Source,
    /// Realtime ticks that started a period or more after their deadline.
    missed: AtomicU64,
    ticks: AtomicU64,
    /// Ticks may run (fast and stepped modes) until the tick count reaches this.
    run_until: AtomicU64,
    stop: AtomicBool,
    /// The earliest tick count a waiter waits for: `tick_done` wakes waiters only then,
    /// so a long `MCC_TimeDelay` costs no context switch per tick.
    wake_at: AtomicU64,
    inner: Mutex<()>,
    cv: Condvar,
    engine_thread: OnceCell<ThreadId>,
    /// Realtime: how late each tick started after its deadline.
    lateness: latency::LatencyHistogram,
    /// Realtime: the engine wakes this long before each deadline and spins on the clock
    /// up to it, ns (`MCCL_RT_SPIN_US`; at most half a period).
    spin_ns: u64,
}

impl Clock {
    /// A clock with the given mode and interpolation period. A realtime clock spins
    /// before each deadline as `MCCL_RT_SPIN_US` asks (read now).
    pub fn new(mode: ClockMode, period: Duration) -> Clock {
        let spin = if mode == ClockMode::Realtime {
            spin_from_env()
        } else {
            0
        };
        Clock::with_source(mode, period, Source::Monotonic, spin)
    }

    fn with_source(mode: ClockMode, period: Duration, source: Source, spin_ns: u64) -> Clock {
        let start_ns = AtomicU64::new(source.now_ns());
        let period_ns = u64::try_from(period.as_nanos()).unwrap_or(u64::MAX).max(1);
        Clock {
            mode,
            period,
            start_ns,
            period_ns,
            period_s: period.as_secs_f64(),
            period_nanos: period.as_nanos(),
            source,
            missed: AtomicU64::new(0),
            ticks: AtomicU64::new(0),
            run_until: AtomicU64::new(0),
            stop: AtomicBool::new(false),
            wake_at: AtomicU64::new(u64::MAX),
            inner: Mutex::new(()),
            cv: Condvar::new(),
            engine_thread: OnceCell::new(),
            lateness: latency::LatencyHistogram::new(),
            spin_ns: spin_ns.min(period_ns / 2),
        }
    }

    /// Realtime: how long before each deadline the engine stops sleeping and spins.
    pub fn spin(&self) -> Duration {
        Duration::from_nanos(self.spin_ns)
    }

    /// The mode.
    pub fn mode(&self) -> ClockMode {
        self.mode
    }

    /// The interpolation period.
    pub fn period(&self) -> Duration {
        self.period
    }

    /// The interpolation period in seconds (`period().as_secs_f64()`, kept).
    pub fn period_s(&self) -> f64 {
        self.period_s
    }

    /// The interpolation period in ns (`period().as_nanos()`, kept).
    pub fn period_nanos(&self) -> u128 {
        self.period_nanos
    }

    /// Ticks completed so far.
    pub fn ticks(&self) -> u64 {
        self.ticks.load(Ordering::Acquire)
    }

    /// Virtual time: completed ticks x period.
    pub fn now(&self) -> Duration {
        self.at_tick(self.ticks())
    }

    /// Virtual time at which tick `n` is due (n x period).
    fn at_tick(&self, n: u64) -> Duration {
        let ns = u128::from(n) * self.period.as_nanos();
        Duration::from_nanos(u64::try_from(ns).unwrap_or(u64::MAX))
    }

    /// When tick `n` is due under the realtime clock: start + n x period, in ns of the
    /// monotonic clock ([`monotonic_ns`]).
    pub fn deadline_ns(&self, n: u64) -> u64 {
        self.start_ns
            .load(Ordering::Relaxed)
            .saturating_add(n.saturating_mul(self.period_ns))
    }

    /// Called by the engine thread once it is ready to tick (its real-time settings
    /// made): the realtime deadlines count from now, so the thread's start-up is not
    /// counted as lateness of the first ticks. No effect once a tick ran.
    pub fn start_now(&self) {
        if self.ticks() == 0 {
            self.start_ns.store(self.source.now_ns(), Ordering::Relaxed);
        }
    }

    /// Virtual time in nanoseconds (exact).
    pub fn now_ns(&self) -> u128 {
        u128::from(self.ticks()) * self.period.as_nanos()
    }

    /// Ticks covering `d` (rounded up).
    pub fn ticks_for(&self, d: Duration) -> u64 {
        let p = self.period.as_nanos().max(1);
        u64::try_from(d.as_nanos().div_ceil(p)).unwrap_or(u64::MAX)
    }

    /// Realtime ticks that started a period or more after their deadline.
    pub fn missed(&self) -> u64 {
        self.missed.load(Ordering::Relaxed)
    }

    /// Realtime: how late each tick started after its deadline.
    pub fn lateness(&self) -> &latency::LatencyHistogram {
        &self.lateness
    }

    /// Whether the next tick is granted already, so that [`Clock::wait_next`] returns it
    /// without waiting (a virtual clock in the middle of a run). Never under the realtime
    /// clock, whose ticks wait for their deadline.
    pub fn granted(&self) -> bool {
        self.mode != ClockMode::Realtime
            && !self.stop.load(Ordering::Acquire)
            && self.ticks() < self.run_until.load(Ordering::Acquire)
    }

    /// Called by the engine thread before each tick; blocks until the tick may run.
    pub fn wait_next(&self) -> Next {
        if self.mode == ClockMode::Realtime {
            return self.wait_realtime();
        }
        // A run in progress: no lock (see the type's documentation).
        if !self.stop.load(Ordering::Acquire)
            && self.ticks() < self.run_until.load(Ordering::Acquire)
        {
            return Next::Tick;
        }
        let mut g = self.inner.lock();
        loop {
            if self.stop.load(Ordering::Acquire) {
                return Next::Stop;
            }
            if self.ticks() < self.run_until.load(Ordering::Acquire) {
                return Next::Tick;
            }
            self.cv.wait(&mut g);
        }
    }

    /// Realtime: sleeps to the absolute deadline of the next tick on the monotonic clock,
    /// then counts how late it woke. No lock and no system call but the sleep; the
    /// sleep is cut into slices of at most [`STOP_SLICE`] so that `stop` is seen. With a
    /// spin (`MCCL_RT_SPIN_US`) the sleep ends that long before the deadline and the
    /// thread reads the clock (vDSO, no system call) until the deadline: a wake-up late
    /// by less than the spin then costs nothing. The lateness is stamped by the read that
    /// saw the deadline pass, before any other work.
    fn wait_realtime(&self) -> Next {
        let deadline = self.deadline_ns(self.ticks());
        let wake = deadline.saturating_sub(self.spin_ns);
        let slice = u64::try_from(STOP_SLICE.as_nanos()).unwrap_or(u64::MAX);
        loop {
            if self.stop.load(Ordering::Acquire) {
                return Next::Stop;
            }
            let now = self.source.now_ns();
            if now >= deadline {
                let late = now - deadline;
                self.lateness.record_ns(late);
                if late >= self.period_ns {
                    self.missed.fetch_add(1, Ordering::Relaxed);
                }
                return Next::Tick;
            }
            if now >= wake {
                std::hint::spin_loop();
                continue;
            }
            self.source.sleep_until(wake.min(now.saturating_add(slice)));
        }
    }

    /// Called by the engine thread after a tick (and its callbacks) completed.
    pub fn tick_done(&self) {
        let now = self.ticks.fetch_add(1, Ordering::SeqCst) + 1;
        if now >= self.wake_at.load(Ordering::SeqCst) {
            let _g = self.inner.lock();
            self.wake_at.store(u64::MAX, Ordering::SeqCst);
            self.cv.notify_all();
        }
    }

    /// Called by the engine thread during a tick: the ticks granted end with this one
    /// (a fast-clock poll saw the status it waited for change).
    pub fn end_run_now(&self) {
        let _g = self.inner.lock();
        let next = self.ticks() + 1;
        if self.run_until.load(Ordering::Acquire) > next {
            self.run_until.store(next, Ordering::Release);
        }
        if self.wake_at.load(Ordering::SeqCst) > next {
            self.wake_at.store(next, Ordering::SeqCst);
        }
    }

    /// Under a virtual clock, during a tick: whether the tick after it is granted already
    /// and is not the last of its run. Never under the realtime clock.
    pub fn next_is_inside_run(&self) -> bool {
        self.mode.virtual_time()
            && !self.stop.load(Ordering::Acquire)
            && self.ticks().saturating_add(2) < self.run_until.load(Ordering::Acquire)
    }

    /// Under a virtual clock: whether the tick now running is the last one granted (the
    /// waiting program resumes after it). Always true in realtime mode.
    pub fn last_of_run(&self) -> bool {
        if !self.mode.virtual_time() {
            return true;
        }
        self.ticks() + 1 >= self.run_until.load(Ordering::Acquire)
    }

    /// Asks the clock to stop; the engine thread and every waiter return.
    pub fn stop(&self) {
        let _g = self.inner.lock();
        self.stop.store(true, Ordering::Release);
        self.cv.notify_all();
    }

    /// Whether `stop` was called.
    pub fn stopped(&self) -> bool {
        self.stop.load(Ordering::Acquire)
    }

    /// Records the engine thread, so that a wait requested from it (a callback that calls
    /// `MCC_TimeDelay`) returns at once instead of waiting for itself.
    pub fn set_engine_thread(&self) {
        let _ = self.engine_thread.set(std::thread::current().id());
        ON_AN_ENGINE_THREAD.with(|e| e.set(true));
    }

    /// Whether a wait asked for on this thread must return at once: on this clock's engine
    /// thread, or on any engine thread — a routine of a system being replaced may reach
    /// the new system's clock, whose ticks may wait for that routine's engine to end.
    fn on_engine_thread(&self) -> bool {
        ON_AN_ENGINE_THREAD.with(std::cell::Cell::get)
            || self.engine_thread.get() == Some(&std::thread::current().id())
    }

    /// Grants `ticks` more ticks (fast and stepped modes) and waits until they ran, or
    /// until the run was ended early ([`Clock::end_run_now`]) or the clock stopped. On
    /// the engine thread it returns at once.
    pub fn wait_ticks(&self, ticks: u64) {
        if self.on_engine_thread() || ticks == 0 {
            return;
        }
        let mut g = self.inner.lock();
        let target = self.ticks().saturating_add(ticks);
        if self.run_until.load(Ordering::Acquire) < target {
            self.run_until.store(target, Ordering::Release);
        }
        self.cv.notify_all();
        loop {
            let now = self.ticks();
            let until = self.run_until.load(Ordering::Acquire);
            if self.stop.load(Ordering::Acquire) || now >= target || now >= until {
                return;
            }
            let w = target.min(until);
            if self.wake_at.load(Ordering::SeqCst) > w {
                self.wake_at.store(w, Ordering::SeqCst);
            }
            // Dekker with `tick_done`: the tick that reaches `w` may have run between
            // the check above and the store; then it did not see `w`, but this sees it.
            let now = self.ticks.load(Ordering::SeqCst);
            if now >= target || now >= until {
                return;
            }
            self.cv.wait(&mut g);
        }
    }

    /// `MCC_TimeDelay` on this clock: a real sleep in realtime mode, otherwise runs the
    /// ticks that cover `ms` of virtual time.
    pub fn delay_ms(&self, ms: u32) {
        let d = Duration::from_millis(u64::from(ms));
        if self.mode.virtual_time() {
            self.wait_ticks(self.ticks_for(d));
        } else if !self.on_engine_thread() {
            std::thread::sleep(d);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;
    use std::time::Instant;

    fn spawn_engine(clock: Arc<Clock>) -> std::thread::JoinHandle<u64> {
        std::thread::spawn(move || {
            let mut n = 0;
            loop {
                match clock.wait_next() {
                    Next::Stop => return n,
                    Next::Tick => {
                        n += 1;
                        clock.tick_done();
                    }
                }
            }
        })
    }

    /// A scripted monotonic clock: time moves only when the test advances it, the
    /// engine sleeps or (`per_read` > 0) reads it; a sleep wakes `overshoot` ns after
    /// the time asked (a kernel's wake-up latency); a read returns the time and then
    /// moves it on by `per_read` ns (what a spin on the clock sees).
    #[derive(Debug)]
    pub(super) struct FakeTime {
        now: AtomicU64,
        overshoot: u64,
        per_read: u64,
        sleeps: AtomicU64,
        reads: AtomicU64,
    }

    impl FakeTime {
        fn new(start: u64, overshoot: u64) -> FakeTime {
            FakeTime::reading(start, overshoot, 0)
        }

        fn reading(start: u64, overshoot: u64, per_read: u64) -> FakeTime {
            FakeTime {
                now: AtomicU64::new(start),
                overshoot,
                per_read,
                sleeps: AtomicU64::new(0),
                reads: AtomicU64::new(0),
            }
        }

        pub(super) fn now(&self) -> u64 {
            self.reads.fetch_add(1, Ordering::SeqCst);
            self.now.fetch_add(self.per_read, Ordering::SeqCst)
        }

        pub(super) fn sleep_until(&self, ns: u64) {
            self.sleeps.fetch_add(1, Ordering::SeqCst);
            self.now.fetch_max(ns + self.overshoot, Ordering::SeqCst);
        }

        fn advance(&self, ns: u64) {
            self.now.fetch_add(ns, Ordering::SeqCst);
        }
    }

    #[test]
    fn realtime_never_drifts_over_ten_minutes_and_catches_up_missed_ticks() {
        // 10 minutes at 1 ms: 600,000 ticks. Every wake-up is 50 us late; a tick's work
        // takes 100 us, except at n % 10,000 == 5,000 (60 times) where it stalls 5.5 ms.
        // After a stall in tick k (deadline D): it ends at D + 50 + 5500 us; ticks k+1..
        // k+4 (deadlines D + 1, 2, 3, 4 ms) start back to back 4550, 3650, 2750, 1850 us
        // late: missed (a period or more); k+5 starts 950 us late, k+6 at D + 6050 us
        // (50 late, no sleep), k+7 sleeps again. So 60 x 4 = 240 missed ticks, 60 x 5 =
        // 300 ticks later than 50 us, the largest 4550 us.
        const START: u64 = 1_000_000_000;
        let fake = Arc::new(FakeTime::new(START, 50_000));
        let clock = Clock::with_source(
            ClockMode::Realtime,
            Duration::from_millis(1),
            Source::Fake(fake.clone()),
            0,
        );
        for n in 0..600_000u64 {
            assert_eq!(clock.wait_next(), Next::Tick);
            assert_eq!(clock.ticks(), n);
            fake.advance(if n % 10_000 == 5_000 {
                5_500_000
            } else {
                100_000
            });
            clock.tick_done();
        }
        // The last tick (599,999, deadline 599.999 s) started 50 us late and took 100 us:
        // real time 599.999150 s, virtual time 600 s; a relative sleep would be
        // 600,000 x 150 us = 90 s behind by now.
        assert_eq!(fake.now() - START, 599_999_150_000);
        assert_eq!(clock.now(), Duration::from_secs(600));
        assert_eq!(clock.missed(), 240);
        let h = clock.lateness();
        assert_eq!(h.count(), 600_000);
        assert_eq!(h.count_between(0, 64), 600_000 - 300);
        assert_eq!(h.quantile_us(0.5), 50.0);
        assert_eq!(h.quantile_us(0.999), 50.0);
        assert_eq!(h.max_us(), 4550.0);
        assert_eq!(h.count_between(4096, 8192), 60, "the 4550 us ticks");
        // One sleep per tick that did not start late: 600,000 - 60 x 6, and tick 0 (due
        // at the start: 0 us late, no sleep).
        assert_eq!(fake.sleeps.load(Ordering::SeqCst), 600_000 - 361);
    }

    #[test]
    fn realtime_deadlines_count_from_when_the_engine_is_ready() {
        // The clock is made at 1 s; the engine thread is ready 30 ms later (a slow thread
        // start on a loaded host). Counted from the clock's creation, tick n would start
        // at 30 ms + n x 100 us (back to back, each taking 100 us), 30 - 0.9 n ms late:
        // ticks 0..=32 missed (33; seen failing so without `start_now`). Counted from
        // `start_now`, every tick starts on time.
        let fake = Arc::new(FakeTime::new(1_000_000_000, 0));
        let clock = Clock::with_source(
            ClockMode::Realtime,
            Duration::from_millis(1),
            Source::Fake(fake.clone()),
            0,
        );
        fake.advance(30_000_000);
        clock.start_now();
        for _ in 0..100 {
            assert_eq!(clock.wait_next(), Next::Tick);
            fake.advance(100_000);
            clock.tick_done();
        }
        assert_eq!(clock.missed(), 0);
        assert_eq!(clock.lateness().max_us(), 0.0);
        // Tick 99 was due at 1.030 s + 99 ms and took 100 us.
        assert_eq!(fake.now(), 1_129_100_000);
        // Once ticks ran, start_now changes nothing.
        fake.advance(5_000_000);
        clock.start_now();
        assert_eq!(clock.deadline_ns(100), 1_130_000_000);
    }

    /// Runs ticks 0..=`n` on a 1 ms realtime clock over `fake` (each tick's work takes
    /// 100 µs) and returns the clock.
    fn run_fake(fake: &Arc<FakeTime>, spin_us: u64, n: u64) -> Clock {
        let clock = Clock::with_source(
            ClockMode::Realtime,
            Duration::from_millis(1),
            Source::Fake(fake.clone()),
            spin_us * 1000,
        );
        for _ in 0..=n {
            assert_eq!(clock.wait_next(), Next::Tick);
            fake.advance(100_000);
            clock.tick_done();
        }
        clock
    }

    #[test]
    fn realtime_spin_absorbs_a_wake_up_late_by_less_than_the_spin() {
        // Every sleep wakes 150 µs after the time asked; a clock read takes 1 µs. The
        // clock's creation reads the time (start S), so tick 0, due at S, starts 1 µs
        // late and ends at S + 102 µs. Without a spin, ticks 1..=1000 each start 150 µs
        // late (the sleep went to the deadline D and woke at D + 150 µs).
        let fake = Arc::new(FakeTime::reading(1_000_000_000, 150_000, 1_000));
        let c = run_fake(&fake, 0, 1000);
        assert_eq!(c.lateness().count(), 1001);
        assert_eq!(c.lateness().count_between(128, 256), 1000);
        assert_eq!(c.lateness().max_us(), 150.0);
        // A 200 µs spin: tick n-1 ended at D - 898 µs (tick 0) or D - 899 µs (its start
        // D - 1000 µs, one read, 100 µs of work); that read is before D - 200, so the
        // engine sleeps once, to D - 200 µs, and wakes at D - 50 µs; the reads then see
        // D - 50, D - 49, ..., D (51 reads): ticks 1..=1000 start on time.
        let fake = Arc::new(FakeTime::reading(1_000_000_000, 150_000, 1_000));
        let c = run_fake(&fake, 200, 1000);
        assert_eq!(c.lateness().count(), 1001);
        assert_eq!(c.lateness().count_between(0, 1), 1000);
        assert_eq!(c.lateness().max_us(), 1.0, "tick 0");
        assert_eq!(c.missed(), 0);
        assert_eq!(fake.sleeps.load(Ordering::SeqCst), 1000);
        // Reads: the creation and tick 0 one each; ticks 1..=1000 one before the sleep
        // and 51 after it.
        assert_eq!(fake.reads.load(Ordering::SeqCst), 2 + 1000 * 52);
        // A wake-up later than the spin: 300 µs late, 200 of them spun away: 100 late.
        let fake = Arc::new(FakeTime::reading(1_000_000_000, 300_000, 1_000));
        let c = run_fake(&fake, 200, 1000);
        assert_eq!(c.lateness().count_between(64, 128), 1000);
        assert_eq!(c.lateness().max_us(), 100.0);
        // The spin is at most half a period: 900 µs asked on a 1 ms clock gives 500.
        let c = Clock::with_source(
            ClockMode::Realtime,
            Duration::from_millis(1),
            Source::Fake(Arc::new(FakeTime::new(0, 0))),
            900_000,
        );
        assert_eq!(c.spin(), Duration::from_micros(500));
    }

    #[test]
    fn spin_values() {
        assert_eq!(parse_spin_us("0"), Some(0));
        assert_eq!(parse_spin_us(" 100 "), Some(100));
        assert_eq!(parse_spin_us("1000"), Some(1000));
        assert_eq!(parse_spin_us("1001"), None);
        assert_eq!(parse_spin_us("-5"), None);
        assert_eq!(parse_spin_us("fast"), None);
    }

    #[test]
    fn realtime_sleeps_in_slices_so_stop_is_seen_promptly() {
        // A 10 s period: after tick 0 (due at the start) the engine sleeps towards 10 s
        // in slices of STOP_SLICE (5 ms), so a stop is seen within one slice, not 10 s.
        let fake = Arc::new(FakeTime::new(0, 0));
        let clock = Clock::with_source(
            ClockMode::Realtime,
            Duration::from_secs(10),
            Source::Fake(fake.clone()),
            0,
        );
        assert_eq!(clock.wait_next(), Next::Tick);
        clock.tick_done();
        // Scripted: 10 s / 5 ms = 2000 slices reach the deadline of tick 1.
        assert_eq!(clock.wait_next(), Next::Tick);
        assert_eq!(fake.sleeps.load(Ordering::SeqCst), 2000);
        assert_eq!(fake.now(), 10_000_000_000);
        clock.tick_done();
        // Real time: the engine thread must return Stop within a few slices.
        let clock = Arc::new(Clock::new(ClockMode::Realtime, Duration::from_secs(10)));
        let h = spawn_engine(clock.clone());
        let t = Instant::now();
        while clock.ticks() < 1 {
            assert!(t.elapsed() < Duration::from_secs(10), "tick 0 never ran");
            std::thread::sleep(Duration::from_millis(1));
        }
        let t = Instant::now();
        clock.stop();
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || tx.send(h.join().unwrap()).unwrap());
        let n = rx
            .recv_timeout(Duration::from_secs(5))
            .expect("the realtime engine did not see stop within 5 s (it sleeps in 5 ms slices)");
        assert_eq!(n, 1);
        // Generous for a loaded 2-core host; without slices it would take ~10 s.
        assert!(t.elapsed() < Duration::from_secs(2), "{:?}", t.elapsed());
    }

    #[test]
    fn parse_modes() {
        assert_eq!(ClockMode::parse("FAST"), Some(ClockMode::Fast));
        assert_eq!(ClockMode::parse("stepped"), Some(ClockMode::Stepped));
        assert_eq!(ClockMode::parse("realtime"), Some(ClockMode::Realtime));
        assert_eq!(ClockMode::parse("warp"), None);
    }

    #[test]
    fn virtual_clocks_run_exactly_the_delay_and_stand_still_otherwise() {
        for mode in [ClockMode::Stepped, ClockMode::Fast] {
            // 2 ms period: a 7 ms delay needs ceil(7/2) = 4 ticks.
            let clock = Arc::new(Clock::new(mode, Duration::from_millis(2)));
            let h = spawn_engine(clock.clone());
            clock.delay_ms(7);
            assert_eq!(clock.ticks(), 4);
            assert_eq!(clock.now(), Duration::from_millis(8));
            std::thread::sleep(Duration::from_millis(20));
            assert_eq!(clock.ticks(), 4, "no waiter, no time");
            clock.wait_ticks(1000);
            assert_eq!(clock.ticks(), 1004);
            clock.stop();
            assert_eq!(h.join().unwrap(), 1004);
        }
    }

    #[test]
    fn a_run_can_end_early() {
        let clock = Arc::new(Clock::new(ClockMode::Fast, Duration::from_millis(1)));
        let c2 = clock.clone();
        // An engine that ends the run during its 10th tick.
        let h = std::thread::spawn(move || loop {
            match c2.wait_next() {
                Next::Stop => return,
                Next::Tick => {
                    if c2.ticks() == 9 {
                        c2.end_run_now();
                    }
                    c2.tick_done();
                }
            }
        });
        clock.wait_ticks(1000);
        assert_eq!(clock.ticks(), 10);
        clock.stop();
        h.join().unwrap();
    }

    #[test]
    fn stop_releases_waiters() {
        let clock = Arc::new(Clock::new(ClockMode::Stepped, Duration::from_millis(1)));
        let c2 = clock.clone();
        let w = std::thread::spawn(move || c2.delay_ms(1000)); // nobody ticks
        std::thread::sleep(Duration::from_millis(10));
        clock.stop();
        w.join().unwrap();
        assert!(clock.stopped());
    }
}
