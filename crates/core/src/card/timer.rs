//! The card's 32-bit timer (user manual §2.13.1; examples manual §31).
//!
//! The period is counted in system clocks of 10 ns (user manual EN and ZH §2.13; the
//! examples manual's "1 µs" disagrees, see docs/compatibility.md "Timer unit"). Virtual
//! time advances by whole ticks: in a tick of `dt` the timer expires as often as its
//! period elapsed since it was enabled, and the TMRINT delivered after that tick has
//! `TIMER` = that count (saturated at 255; 0 expirations: no interrupt).

use crate::error::{McclError, McclResult};

use super::SYSTEM_CLOCK_NS;

/// The timer's period before `MCC_SetTimer`: 100 system clocks = 1 µs, so that the
/// watchdog (which counts timer periods) counts microseconds as the examples manual's
/// §32 says when the program never sets the timer.
pub const DEFAULT_PERIOD: u32 = 100;

/// The timer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Timer {
    period: u32,
    enabled: bool,
    /// `MCC_EnableTimerTrigger`: expirations raise TMRINT.
    trigger: bool,
    /// Time since the last expiration, ns.
    elapsed_ns: u64,
}

impl Default for Timer {
    fn default() -> Timer {
        Timer {
            period: DEFAULT_PERIOD,
            enabled: false,
            trigger: false,
            elapsed_ns: 0,
        }
    }
}

impl Timer {
    /// `MCC_SetTimer`: the period in system clocks (1..=2^32-1); counting restarts.
    pub fn set_period(&mut self, clocks: u32) -> McclResult<()> {
        if clocks == 0 {
            return Err(McclError::Parameter);
        }
        self.period = clocks;
        self.elapsed_ns = 0;
        Ok(())
    }

    /// The period in system clocks.
    pub fn period(&self) -> u32 {
        self.period
    }

    /// The period in ns.
    pub fn period_ns(&self) -> u64 {
        u64::from(self.period) * SYSTEM_CLOCK_NS
    }

    /// `MCC_EnableTimer` (counting starts from 0) / `MCC_DisableTimer`.
    pub fn set_enabled(&mut self, on: bool) {
        if on && !self.enabled {
            self.elapsed_ns = 0;
        }
        self.enabled = on;
    }

    /// Whether the timer counts.
    pub fn enabled(&self) -> bool {
        self.enabled
    }

    /// `MCC_EnableTimerTrigger` / `MCC_DisableTimerTrigger`: whether the expirations raise
    /// TMRINT (the timer counts either way, and the watchdog counts its periods).
    pub fn set_trigger(&mut self, on: bool) {
        self.trigger = on;
    }

    /// Whether the expirations raise TMRINT ([`Timer::set_trigger`]).
    pub fn trigger(&self) -> bool {
        self.trigger
    }

    /// Advances by `dt_ns`; returns how many times the timer expired.
    pub(crate) fn advance(&mut self, dt_ns: u64) -> u64 {
        if !self.enabled {
            return 0;
        }
        let p = self.period_ns();
        self.elapsed_ns += dt_ns;
        let n = self.elapsed_ns / p;
        self.elapsed_ns %= p;
        n
    }
}

/// The watchdog (user manual §2.13.2; examples manual §32). It counts the timer's
/// expirations while both are enabled; when the count reaches the compare value the card
/// is reset and the watchdog disables itself.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Watchdog {
    compare: u32,
    reset_period: u32,
    enabled: bool,
    count: u64,
    /// How many times the watchdog has reset the card since init.
    resets: u32,
}

impl Default for Watchdog {
    fn default() -> Watchdog {
        Watchdog {
            compare: u32::MAX,
            reset_period: 1,
            enabled: false,
            count: 0,
            resets: 0,
        }
    }
}

impl Watchdog {
    /// `MCC_SetWatchDogTimer`: the compare value in timer periods (1..=2^32-1).
    pub fn set_compare(&mut self, v: u32) -> McclResult<()> {
        if v == 0 {
            return Err(McclError::Parameter);
        }
        self.compare = v;
        Ok(())
    }

    /// The compare value.
    pub fn compare(&self) -> u32 {
        self.compare
    }

    /// `MCC_SetWatchDogResetPeriod`: the reset signal's length in system clocks
    /// (1..=2^32-1). Recorded; in virtual time the reset itself is instantaneous.
    pub fn set_reset_period(&mut self, v: u32) -> McclResult<()> {
        if v == 0 {
            return Err(McclError::Parameter);
        }
        self.reset_period = v;
        Ok(())
    }

    /// The reset signal's length in system clocks.
    pub fn reset_period(&self) -> u32 {
        self.reset_period
    }

    /// `MCC_EnableWatchDogTimer` (counting from 0) / `MCC_DisableWatchDogTimer`.
    pub fn set_enabled(&mut self, on: bool) {
        if on && !self.enabled {
            self.count = 0;
        }
        self.enabled = on;
    }

    /// Whether the watchdog counts.
    pub fn enabled(&self) -> bool {
        self.enabled
    }

    /// Timer periods counted since the last refresh.
    pub fn count(&self) -> u64 {
        self.count
    }

    /// How many times the watchdog has reset the card since init (only its expiry counts
    /// them, so that a program or the panel can tell that a reset happened).
    pub fn resets(&self) -> u32 {
        self.resets
    }

    /// `MCC_RefreshWatchDogTimer`.
    pub fn refresh(&mut self) {
        self.count = 0;
    }

    /// Counts `expirations` of the timer; true when the watchdog expired (it then
    /// disables itself).
    pub(crate) fn advance(&mut self, expirations: u64) -> bool {
        if !self.enabled {
            return false;
        }
        self.count += expirations;
        if self.count >= u64::from(self.compare) {
            self.enabled = false;
            self.count = 0;
            self.resets += 1;
            true
        } else {
            false
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn timer_counts_expirations_across_ticks() {
        let mut t = Timer::default();
        assert_eq!(t.advance(2_000_000), 0, "disabled");
        t.set_period(300_000).unwrap(); // 3 ms
        t.set_enabled(true);
        // 2 ms ticks: expirations at 3, 6, 9, 12 ms -> ticks 2, 3, 5, 6
        let n: Vec<u64> = (0..6).map(|_| t.advance(2_000_000)).collect();
        assert_eq!(n, [0, 1, 1, 0, 1, 1]);
        t.set_period(100).unwrap(); // 1 us: 2000 per 2 ms tick
        assert_eq!(t.advance(2_000_000), 2000);
        assert_eq!(t.set_period(0), Err(McclError::Parameter));
        assert_eq!(t.period(), 100);
    }

    #[test]
    fn watchdog_expires_once_and_refresh_restarts() {
        let mut w = Watchdog::default();
        w.set_compare(5).unwrap();
        assert!(!w.advance(10), "disabled");
        w.set_enabled(true);
        assert!(!w.advance(4));
        w.refresh();
        assert!(!w.advance(4));
        assert!(w.advance(1));
        assert!(!w.enabled());
        assert_eq!(w.resets(), 1);
        assert!(!w.advance(100), "disabled after the reset");
        assert_eq!(w.set_compare(0), Err(McclError::Parameter));
        assert_eq!(w.set_reset_period(0), Err(McclError::Parameter));
    }
}
