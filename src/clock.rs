//! How ticks happen. The engine thread asks the clock for permission before every tick;
//! the clock mode decides when it is given:
//!
//! * `realtime` (default): tick n starts at `start + n x period` on the monotonic clock
//!   (absolute deadlines, never a relative sleep). A tick that starts a whole period or
//!   more after its deadline is counted as missed; the engine then catches up back to
//!   back, so virtual time never silently drifts from real time.
//! * `fast` and `stepped`: virtual time runs only while the program waits, back to back
//!   as fast as the CPU allows, so a program always sees the same sequence of states
//!   whatever the machine's load. `MCC_TimeDelay(ms)` runs exactly the ticks covering
//!   `ms`. A status poll repeated at the same virtual time (a program spinning on
//!   `MCC_GetMotionStatus`) runs one tick under `stepped`, and under `fast` runs ticks
//!   until the polled status changes (at most [`FAST_POLL_MAX`] of virtual time).
//!
//! Virtual time is `ticks x period` in every mode.

use once_cell::sync::OnceCell;
use parking_lot::{Condvar, Mutex};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::thread::ThreadId;
use std::time::{Duration, Instant};

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

#[derive(Debug)]
struct Inner {
    missed: u64,
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
    start: Instant,
    ticks: AtomicU64,
    /// Ticks may run (fast and stepped modes) until the tick count reaches this.
    run_until: AtomicU64,
    stop: AtomicBool,
    /// The earliest tick count a waiter waits for: `tick_done` wakes waiters only then,
    /// so a long `MCC_TimeDelay` costs no context switch per tick.
    wake_at: AtomicU64,
    inner: Mutex<Inner>,
    cv: Condvar,
    engine_thread: OnceCell<ThreadId>,
}

impl Clock {
    /// A clock with the given mode and interpolation period.
    pub fn new(mode: ClockMode, period: Duration) -> Clock {
        Clock {
            mode,
            period,
            start: Instant::now(),
            ticks: AtomicU64::new(0),
            run_until: AtomicU64::new(0),
            stop: AtomicBool::new(false),
            wake_at: AtomicU64::new(u64::MAX),
            inner: Mutex::new(Inner { missed: 0 }),
            cv: Condvar::new(),
            engine_thread: OnceCell::new(),
        }
    }

    /// The mode.
    pub fn mode(&self) -> ClockMode {
        self.mode
    }

    /// The interpolation period.
    pub fn period(&self) -> Duration {
        self.period
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
        self.inner.lock().missed
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

    fn wait_realtime(&self) -> Next {
        let deadline = self.start + self.at_tick(self.ticks());
        let mut g = self.inner.lock();
        loop {
            if self.stop.load(Ordering::Acquire) {
                return Next::Stop;
            }
            let now = Instant::now();
            if now >= deadline {
                if now >= deadline + self.period {
                    g.missed += 1;
                }
                return Next::Tick;
            }
            let _ = self.cv.wait_until(&mut g, deadline);
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
