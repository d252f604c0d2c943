//! When a card's ARIO sets transfer: their serial clock, update rate and node-to-node
//! delay (see [`ArioTiming`]).

use super::{ARIO_BITS_PER_SLAVE, ARIO_DEFAULT_DIVIDER, SETS};
use crate::card::cadence::update_period_ns;
use crate::card::SYSTEM_CLOCK_NS;
use crate::error::{McclError, McclResult};

/// When the ARIO sets of a card transfer (the vendor headers: `MCC_SetARIOUpdateRate`,
/// `MCC_SetARIOClockDivider` per set, `MCC_SetARIONode2NodeDelay` per card; the manuals
/// say nothing more). A cycle with `n` transmitting slaves (at least 1) takes
/// `n × (32 × divider + delay) × 10 ns`; a set with an update rate waits at least
/// `1 / rate` between cycles. The cycle count restarts when any of the three is set.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ArioTiming {
    /// Least time between cycles per set, ns (`MCC_SetARIOUpdateRate`); `None`: as fast
    /// as the bus allows.
    update_ns: [Option<u64>; SETS],
    /// Serial clock divider per set: one bit takes `divider` system clocks (1..65535).
    divider: [u16; SETS],
    /// Gap after each slave's frame, system clocks (`MCC_SetARIONode2NodeDelay`).
    node_delay: u32,
    /// Time since the set's last cycle ended (or its timing was set), ns.
    elapsed_ns: [u64; SETS],
}

impl Default for ArioTiming {
    fn default() -> Self {
        ArioTiming {
            update_ns: [None; SETS],
            divider: [ARIO_DEFAULT_DIVIDER; SETS],
            node_delay: 0,
            elapsed_ns: [0; SETS],
        }
    }
}

impl ArioTiming {
    /// `MCC_SetARIOUpdateRate`: `rate` updates per second at most on set `set` (checked
    /// as [`update_period_ns`] says: finite, > 0, its cycle `1 / rate` at most the longest
    /// time, so `rate` >= 2.33e-7 Hz); the period is rounded to whole ns (at least 1). A
    /// bad set or rate is `PARAMETER_ERR` and changes nothing.
    pub fn set_update_rate(&mut self, set: usize, rate: f64) -> McclResult<()> {
        if set >= SETS {
            return Err(McclError::Parameter);
        }
        self.update_ns[set] = Some(update_period_ns(rate)?);
        self.elapsed_ns[set] = 0;
        Ok(())
    }

    /// `MCC_SetARIOClockDivider`: 1..65535 system clocks per bit (0 is `PARAMETER_ERR`).
    pub fn set_divider(&mut self, set: usize, divider: u16) -> McclResult<()> {
        if divider == 0 || set >= SETS {
            return Err(McclError::Parameter);
        }
        self.divider[set] = divider;
        self.elapsed_ns[set] = 0;
        Ok(())
    }

    /// `MCC_SetARIONode2NodeDelay`: system clocks after each slave's frame, both sets.
    pub fn set_node_delay(&mut self, clocks: u32) {
        self.node_delay = clocks;
        self.elapsed_ns = [0; SETS];
    }

    /// How long a cycle of set `set` takes with the slaves in `transmitting`, ns: the
    /// bus time, or the update period if that is longer.
    pub fn cycle_ns(&self, set: usize, transmitting: u32) -> u64 {
        let n = u64::from(transmitting.count_ones().max(1));
        let per_slave =
            ARIO_BITS_PER_SLAVE * u64::from(self.divider[set]) + u64::from(self.node_delay);
        let bus = n.saturating_mul(per_slave).saturating_mul(SYSTEM_CLOCK_NS);
        bus.max(self.update_ns[set].unwrap_or(0))
    }

    /// Advances set `set` by `dt_ns`; true when a cycle ended in that time.
    pub(super) fn advance(&mut self, set: usize, dt_ns: u64, transmitting: u32) -> bool {
        let period = self.cycle_ns(set, transmitting).max(1);
        let e = self.elapsed_ns[set].saturating_add(dt_ns);
        self.elapsed_ns[set] = e % period;
        e >= period
    }

    /// `n` calls of [`ArioTiming::advance`] with the same arguments, the cycles that end
    /// ignored: `(e + n x dt) mod period`, which is what the calls compute when nothing
    /// saturates (each call's sum is at most this one); otherwise the calls themselves.
    pub(super) fn advance_n(&mut self, set: usize, n: u64, dt_ns: u64, transmitting: u32) {
        let period = self.cycle_ns(set, transmitting).max(1);
        match n
            .checked_mul(dt_ns)
            .and_then(|d| self.elapsed_ns[set].checked_add(d))
        {
            Some(e) => self.elapsed_ns[set] = e % period,
            None => {
                for _ in 0..n {
                    self.advance(set, dt_ns, transmitting);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_very_fast_rate_is_a_period_of_one_ns() {
        let mut t = ArioTiming::default();
        t.set_update_rate(0, 1e300).unwrap();
        assert_eq!(t.update_ns, [Some(1), None]);
        // 1 slave x 32 bits x 10 clocks x 10 ns = 3.2 us: the bus bounds the cycle.
        assert_eq!(t.cycle_ns(0, 1), 3_200);
    }
}
