//! How ticks happen. The engine thread asks the clock for permission before every tick;
//! the clock mode decides when it is given:
//!
//! * `realtime` (default): tick n starts at `start + n x period` on the monotonic clock
//!   (absolute deadlines, never a relative sleep). A tick that starts a whole period or
//!   more after its deadline is counted as missed; the engine then catches up back to
//!   back, so virtual time never silently drifts from real time.
//! * `fast`: ticks run back to back on virtual time while the card has work (a group
//!   moving) or a program waits in `MCC_TimeDelay`; when idle, virtual time stands still.
//! * `stepped`: ticks run only while the program waits: `MCC_TimeDelay(ms)` runs exactly
//!   the ticks that cover `ms`, and a status poll that sees the card busy runs one tick.
//!
//! Virtual time is `ticks x period` in every mode.

use once_cell::sync::OnceCell;
use parking_lot::{Condvar, Mutex};
use std::sync::atomic::{AtomicU64, Ordering};
use std::thread::ThreadId;
use std::time::{Duration, Instant};

/// The clock modes selectable with the environment variable `MCCL_CLOCK`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ClockMode {
    /// Ticks on absolute real-time deadlines.
    Realtime,
    /// Back-to-back ticks on virtual time while there is work.
    Fast,
    /// Ticks only while the program waits.
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
    /// Ticks may run (in fast and stepped modes) until the tick count reaches this.
    run_until: u64,
    /// Incremented whenever new work may have arrived (fast mode wake-up).
    kicks: u64,
    stop: bool,
    missed: u64,
    /// The earliest tick count a waiter waits for: `tick_done` wakes waiters only then,
    /// so a long `MCC_TimeDelay` costs no context switch per tick.
    wake_at: u64,
}

/// The clock shared by the engine thread and the program's threads.
#[derive(Debug)]
pub struct Clock {
    mode: ClockMode,
    period: Duration,
    start: Instant,
    ticks: AtomicU64,
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
            inner: Mutex::new(Inner {
                run_until: 0,
                kicks: 0,
                stop: false,
                missed: 0,
                wake_at: u64::MAX,
            }),
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

    /// Virtual time in nanoseconds (exact, u64).
    pub fn now_ns(&self) -> u128 {
        u128::from(self.ticks()) * self.period.as_nanos()
    }

    /// Realtime ticks that started a period or more after their deadline.
    pub fn missed(&self) -> u64 {
        self.inner.lock().missed
    }

    /// Called by the engine thread before each tick; blocks until the tick may run.
    /// `busy` tells whether the card has work (used by the fast mode).
    pub fn wait_next(&self, busy: &dyn Fn() -> bool) -> Next {
        match self.mode {
            ClockMode::Realtime => self.wait_realtime(),
            ClockMode::Fast => loop {
                let kicks = {
                    let g = self.inner.lock();
                    if g.stop {
                        return Next::Stop;
                    }
                    if self.ticks() < g.run_until {
                        return Next::Tick;
                    }
                    g.kicks
                };
                // `busy` may take other locks: call it without holding ours.
                if busy() {
                    return Next::Tick;
                }
                let mut g = self.inner.lock();
                while !g.stop && g.kicks == kicks && self.ticks() >= g.run_until {
                    self.cv.wait(&mut g);
                }
            },
            ClockMode::Stepped => {
                let mut g = self.inner.lock();
                loop {
                    if g.stop {
                        return Next::Stop;
                    }
                    if self.ticks() < g.run_until {
                        return Next::Tick;
                    }
                    self.cv.wait(&mut g);
                }
            }
        }
    }

    fn wait_realtime(&self) -> Next {
        let n = self.ticks();
        let deadline = self.start + self.at_tick(n);
        let mut g = self.inner.lock();
        loop {
            if g.stop {
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
        let mut g = self.inner.lock();
        let now = self.ticks.fetch_add(1, Ordering::AcqRel) + 1;
        if now >= g.wake_at {
            g.wake_at = u64::MAX;
            self.cv.notify_all();
        }
    }

    /// Tells a fast clock that work may have arrived (e.g. a command was queued).
    pub fn kick(&self) {
        let mut g = self.inner.lock();
        g.kicks = g.kicks.wrapping_add(1);
        self.cv.notify_all();
    }

    /// Asks the clock to stop; the engine thread and every waiter return.
    pub fn stop(&self) {
        let mut g = self.inner.lock();
        g.stop = true;
        self.cv.notify_all();
    }

    /// Whether `stop` was called.
    pub fn stopped(&self) -> bool {
        self.inner.lock().stop
    }

    /// Records the engine thread, so that a wait requested from it (a callback that calls
    /// `MCC_TimeDelay`) returns at once instead of waiting for itself.
    pub fn set_engine_thread(&self) {
        let _ = self.engine_thread.set(std::thread::current().id());
    }

    fn on_engine_thread(&self) -> bool {
        self.engine_thread.get() == Some(&std::thread::current().id())
    }

    /// Waits until `ticks` more ticks have completed (fast and stepped modes grant them),
    /// or the clock stops. On the engine thread it returns at once.
    pub fn wait_ticks(&self, ticks: u64) {
        if self.on_engine_thread() {
            return;
        }
        let mut g = self.inner.lock();
        let target = self.ticks().saturating_add(ticks);
        if g.run_until < target {
            g.run_until = target;
        }
        self.cv.notify_all();
        while !g.stop && self.ticks() < target {
            g.wake_at = g.wake_at.min(target);
            self.cv.wait(&mut g);
        }
    }

    /// `MCC_TimeDelay` on this clock: real sleep in realtime mode, otherwise waits until
    /// virtual time has advanced by `ms` (rounded up to whole ticks).
    pub fn delay_ms(&self, ms: u32) {
        match self.mode {
            ClockMode::Realtime => {
                if !self.on_engine_thread() {
                    std::thread::sleep(Duration::from_millis(u64::from(ms)))
                }
            }
            ClockMode::Fast | ClockMode::Stepped => {
                let period_ns = self.period.as_nanos().max(1);
                let want_ns = u128::from(ms) * 1_000_000;
                let ticks = want_ns.div_ceil(period_ns);
                self.wait_ticks(u64::try_from(ticks).unwrap_or(u64::MAX));
            }
        }
    }

    /// A status poll from the program: in stepped mode, when the card is busy, runs one
    /// tick so that `while (MCC_GetMotionStatus(g) != GMS_STOP);` makes progress.
    pub fn poll(&self) {
        if self.mode == ClockMode::Stepped {
            self.wait_ticks(1);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;

    fn spawn_engine(clock: Arc<Clock>, busy_ticks: u64) -> std::thread::JoinHandle<u64> {
        std::thread::spawn(move || {
            let mut n = 0;
            loop {
                let c2 = clock.clone();
                let busy = move || c2.ticks() < busy_ticks;
                match clock.wait_next(&busy) {
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
    fn stepped_runs_exactly_the_delay() {
        // 2 ms period: a 7 ms delay needs ceil(7/2) = 4 ticks, then nothing runs.
        let clock = Arc::new(Clock::new(ClockMode::Stepped, Duration::from_millis(2)));
        let h = spawn_engine(clock.clone(), 0);
        clock.delay_ms(7);
        assert_eq!(clock.ticks(), 4);
        assert_eq!(clock.now(), Duration::from_millis(8));
        clock.poll();
        assert_eq!(clock.ticks(), 5);
        clock.stop();
        assert_eq!(h.join().unwrap(), 5);
    }

    #[test]
    fn fast_runs_while_busy_then_idles() {
        let clock = Arc::new(Clock::new(ClockMode::Fast, Duration::from_millis(1)));
        let h = spawn_engine(clock.clone(), 1000);
        // busy for 1000 ticks; a 1 s delay ends at or after tick 1000
        clock.delay_ms(1000);
        assert!(clock.ticks() >= 1000);
        // idle: virtual time stands still without waiters
        let t = clock.ticks();
        std::thread::sleep(Duration::from_millis(20));
        assert_eq!(clock.ticks(), t);
        clock.delay_ms(5);
        assert_eq!(clock.ticks(), t + 5);
        clock.stop();
        assert_eq!(h.join().unwrap(), t + 5);
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
