//! The timing of the card's serial converters and buses that the vendor's obsolete
//! `MCC_Set{DAC,ADC,RIO}ClockDivider` and `…UpdateRate` set (the manuals describe none
//! of them; docs/undocumented-functions.md). The same reading as the ARIO timing
//! ([`super::rio::ArioTiming`]): a unit of work (one DAC channel's update, one ADC scan,
//! one RIO transfer cycle) moves `bits` serial bits at one bit per `divider` system
//! clocks of 10 ns, so it lasts `bits × divider × 10 ns`; an update rate `r` (Hz) makes
//! it last at least `1 / r`, rounded to whole ns. A rate is finite and > 0 with `1 / r` at
//! most the longest time of [`crate::config::range::time_ms`] (2³² − 1 ms), as every
//! update-rate setter of the card checks it ([`update_period_ns`]).

use super::SYSTEM_CLOCK_NS;
use crate::error::{McclError, McclResult};

/// The least time between cycles for an update rate of `rate` Hz, ns: `1 / rate` rounded
/// to whole ns, at least 1. `PARAMETER_ERR` unless `rate` is finite and > 0 and `1 / rate`
/// at most the longest time (2³² − 1 ms, so `rate` >= 2.33e-7 Hz): a slower rate would
/// hold the converter or bus for longer than any time the library accepts.
pub fn update_period_ns(rate: f64) -> McclResult<u64> {
    if !rate.is_finite() || rate <= 0.0 {
        return Err(McclError::Parameter);
    }
    crate::config::range::time_ms(1000.0 / rate)?;
    // `as` saturates; the period is at most 4.3e15 ns here, far from u64's end.
    Ok(((1e9 / rate).round() as u64).max(1))
}

/// The divider and update rate of one converter or bus, and the time since its last
/// cycle ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Cadence {
    /// System clocks per serial bit (1..65535).
    divider: u16,
    /// Least time between cycles, ns (`None`: as fast as the bits allow).
    update_ns: Option<u64>,
    /// Time since the last cycle ended (or the timing was set), ns.
    elapsed_ns: u64,
}

impl Cadence {
    /// A cadence with divider `divider` and no update rate.
    pub const fn new(divider: u16) -> Cadence {
        Cadence {
            divider,
            update_ns: None,
            elapsed_ns: 0,
        }
    }

    /// The update rate: `rate` cycles per second at most (checked by
    /// [`update_period_ns`]; a refused rate changes nothing). The cycle count restarts.
    pub fn set_update_rate(&mut self, rate: f64) -> McclResult<()> {
        self.update_ns = Some(update_period_ns(rate)?);
        self.elapsed_ns = 0;
        Ok(())
    }

    /// The least time between cycles the update rate set, ns (`None` before any rate:
    /// cycles as fast as the bits allow).
    pub fn update_ns(&self) -> Option<u64> {
        self.update_ns
    }

    /// The clock divider, 1..65535 (0 is `PARAMETER_ERR` and changes nothing). The cycle
    /// count restarts.
    pub fn set_divider(&mut self, divider: u16) -> McclResult<()> {
        if divider == 0 {
            return Err(McclError::Parameter);
        }
        self.divider = divider;
        self.elapsed_ns = 0;
        Ok(())
    }

    /// The clock divider: system clocks per serial bit.
    pub fn divider(&self) -> u16 {
        self.divider
    }

    /// Starts counting a new cycle now.
    pub fn restart(&mut self) {
        self.elapsed_ns = 0;
    }

    /// How long a cycle moving `bits` serial bits lasts, ns (at least 1).
    pub fn cycle_ns(&self, bits: u64) -> u64 {
        let bus = bits
            .saturating_mul(u64::from(self.divider))
            .saturating_mul(SYSTEM_CLOCK_NS);
        bus.max(self.update_ns.unwrap_or(0)).max(1)
    }

    /// Advances by `dt_ns` with cycles of `bits` bits; true when a cycle ended in that
    /// time (at most one is reported: the rest of the time carries over modulo a cycle).
    pub fn advance(&mut self, dt_ns: u64, bits: u64) -> bool {
        let period = self.cycle_ns(bits);
        let e = self.elapsed_ns.saturating_add(dt_ns);
        self.elapsed_ns = e % period;
        e >= period
    }

    /// `n` calls of [`Cadence::advance`] with the same arguments, the cycles that end
    /// ignored: `(e + n × dt) mod period` when nothing saturates, else the calls.
    pub fn advance_n(&mut self, n: u64, dt_ns: u64, bits: u64) {
        let period = self.cycle_ns(bits);
        match n
            .checked_mul(dt_ns)
            .and_then(|d| self.elapsed_ns.checked_add(d))
        {
            Some(e) => self.elapsed_ns = e % period,
            None => {
                for _ in 0..n {
                    self.advance(dt_ns, bits);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cycles_follow_bits_divider_and_rate() {
        let mut c = Cadence::new(10);
        // 16 bits x 10 clocks x 10 ns = 1.6 us: every 1 ms tick ends a cycle.
        assert_eq!(c.cycle_ns(16), 1_600);
        assert!((0..5).all(|_| c.advance(1_000_000, 16)));
        // 400 Hz: 2.5 ms; ticks of 1 ms end cycles in ticks 3, 5, 8, 10.
        c.set_update_rate(400.0).unwrap();
        let ends: Vec<u32> = (1..=10).filter(|_| c.advance(1_000_000, 16)).collect();
        assert_eq!(ends, [3, 5, 8, 10]);
        // Divider 50000, 16 bits: 8 ms, longer than 2.5 ms.
        c.set_divider(50_000).unwrap();
        assert_eq!(c.cycle_ns(16), 8_000_000);
        let before = c;
        // A cycle longer than the longest time (2^32 - 1 ms) is refused: 1 / 2.3e-7 Hz is
        // 4.35e9 s.
        for r in [
            0.0,
            -1.0,
            f64::NAN,
            f64::INFINITY,
            f64::MIN_POSITIVE,
            2.3e-7,
        ] {
            assert_eq!(c.set_update_rate(r), Err(McclError::Parameter));
        }
        assert_eq!(c.set_divider(0), Err(McclError::Parameter));
        assert_eq!(c, before, "refused: unchanged");
        // advance_n is n advances.
        let mut a = c;
        let mut b = c;
        a.advance_n(37, 1_000_000, 16);
        (0..37).for_each(|_| {
            b.advance(1_000_000, 16);
        });
        assert_eq!(a, b);
        // The slowest whole-digit rate accepted: 1 / 2.33e-7 Hz = 4.2918e15 ns.
        c.set_update_rate(2.33e-7).unwrap();
        assert_eq!(c.update_ns(), Some(4_291_845_493_562_232));
        assert_eq!(c.cycle_ns(16), 4_291_845_493_562_232, "rate-bound");
        assert_eq!(c.divider(), 50_000);
        assert_eq!(c.cycle_ns(u64::MAX), u64::MAX, "saturates");
    }
}
