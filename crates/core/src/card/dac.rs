//! The D/A converter: one output per channel, −10..10 V (user manual §2.11; examples
//! manual §35–36).
//!
//! Conversion runs from `MCC_InitSystem` on; `MCC_StopDACConv` holds every output at
//! 0 V (the set values are kept and appear again at `MCC_StartDACConv`). In trigger mode
//! a channel outputs its preset voltage when one of its sources fires
//! ([`super::Peripherals::dac_trigger`], called by the encoder compare of the channel in
//! the source mask).
//!
//! Update timing ([`Cadence`], `MCC_SetDACClockDivider`, `MCC_SetDACUpdateRate`): a
//! channel's output changes at most once per cycle (16 bits at the divider's system
//! clocks, default 1.6 µs, or the update period if longer). A value written a cycle or
//! more after the channel last changed appears at once; one written sooner waits for the
//! cycle to end and appears at the end of the tick in which it ends (the latest value
//! written meanwhile).

use super::cadence::Cadence;
use crate::config::AXES;
use crate::error::{McclError, McclResult};

/// The output range, V.
pub const RANGE: (f32, f32) = (-10.0, 10.0);

/// The trigger-source bits the IMP card has (`DAC_TRIG_ENC0..7`).
pub const TRIG_SOURCES: u32 = 0xFF;

/// The D/A converter of one card.
#[derive(Debug, Clone, PartialEq)]
pub struct Dac {
    running: bool,
    value: [f32; AXES],
    trig_value: [f32; AXES],
    trig_source: [u32; AXES],
    trig_mode: [bool; AXES],
    /// How long one channel's update takes (`MCC_SetDACClockDivider`,
    /// `MCC_SetDACUpdateRate`); only its cycle length is used.
    cadence: Cadence,
    /// The DAC's time since init, ns (advanced by [`Dac::tick`]).
    now_ns: u64,
    /// When each channel's output last changed.
    last_update: [Option<u64>; AXES],
    /// A value written less than a cycle after the channel's last update: it waits for
    /// that cycle to end.
    held: [Option<f32>; AXES],
}

/// Serial clocks of one channel's update.
pub const UPDATE_BITS: u64 = 16;

/// DAC clock divider before any `MCC_SetDACClockDivider`: 10, so a channel updates in
/// 16 × 10 × 10 ns = 1.6 µs.
pub const DEFAULT_DIVIDER: u16 = 10;

impl Default for Dac {
    fn default() -> Dac {
        Dac {
            running: true,
            value: [0.0; AXES],
            trig_value: [0.0; AXES],
            trig_source: [0; AXES],
            trig_mode: [false; AXES],
            cadence: Cadence::new(DEFAULT_DIVIDER),
            now_ns: 0,
            last_update: [None; AXES],
            held: [None; AXES],
        }
    }
}

/// A voltage from C: finite and within −10..10 V.
pub fn check_voltage(v: f32) -> McclResult<f32> {
    if v.is_finite() && (RANGE.0..=RANGE.1).contains(&v) {
        Ok(v)
    } else {
        Err(McclError::Parameter)
    }
}

impl Dac {
    /// `MCC_StartDACConv` / `MCC_StopDACConv`.
    pub fn set_running(&mut self, on: bool) {
        self.running = on;
    }

    /// Whether conversion runs.
    pub fn running(&self) -> bool {
        self.running
    }

    /// `MCC_SetDACOutput` (channel checked by the caller): see `Dac::write`.
    pub fn set_output(&mut self, ch: usize, v: f32) -> McclResult<()> {
        let v = check_voltage(v)?;
        self.write(ch, v);
        Ok(())
    }

    /// `MCC_SetDACClockDivider`: one serial bit every `divider` system clocks (1..65535;
    /// 0 is `PARAMETER_ERR` and changes nothing), so a channel's update lasts
    /// `16 × divider × 10 ns` and its output changes at most once per update.
    pub fn set_clock_divider(&mut self, divider: u16) -> McclResult<()> {
        self.cadence.set_divider(divider)
    }

    /// `MCC_SetDACUpdateRate`: at most `rate` updates per second on each channel (checked
    /// as [`super::cadence::update_period_ns`] says; a refused rate changes nothing): a
    /// value written sooner than `1 / rate` after the channel's last change waits for it.
    pub fn set_update_rate(&mut self, rate: f64) -> McclResult<()> {
        self.cadence.set_update_rate(rate)
    }

    /// The update timing as set (divider and update period).
    pub fn cadence(&self) -> &Cadence {
        &self.cadence
    }

    /// How long one channel's update lasts, ns: 16 bits at the divider, or the update
    /// period if that is longer.
    pub fn cycle_ns(&self) -> u64 {
        self.cadence.cycle_ns(UPDATE_BITS)
    }

    /// A new value for channel `ch`: it reaches the output at once when the channel's
    /// last update is a cycle or more ago (or there was none), else when that cycle
    /// ends — in the tick in which it ends, the latest value written meanwhile.
    fn write(&mut self, ch: usize, v: f32) {
        match self.last_update[ch] {
            Some(t) if self.now_ns.saturating_sub(t) < self.cycle_ns() => {
                self.held[ch] = Some(v);
            }
            _ => {
                self.value[ch] = v;
                self.last_update[ch] = Some(self.now_ns);
                self.held[ch] = None;
            }
        }
    }

    /// Whether a written value waits for its channel's cycle to end.
    pub fn holding(&self) -> bool {
        self.held.iter().any(Option::is_some)
    }

    /// One tick of `dt_ns`: held values whose cycle ended by the tick's end reach the
    /// output; the next cycle of that channel starts where the last one ended.
    pub(crate) fn tick(&mut self, dt_ns: u64) {
        self.now_ns = self.now_ns.saturating_add(dt_ns);
        let period = self.cycle_ns();
        for ch in 0..AXES {
            if let (Some(v), Some(t)) = (self.held[ch], self.last_update[ch]) {
                let due = t.saturating_add(period);
                if due <= self.now_ns {
                    self.value[ch] = v;
                    self.last_update[ch] = Some(due);
                    self.held[ch] = None;
                }
            }
        }
    }

    /// `n` ticks of `dt_ns` with nothing held: only time moves.
    pub(crate) fn idle_ticks(&mut self, n: u64, dt_ns: u64) {
        self.now_ns = self.now_ns.saturating_add(n.saturating_mul(dt_ns));
    }

    /// The voltage on channel `ch`'s output now (0 V while conversion is stopped).
    pub fn output(&self, ch: usize) -> f32 {
        if self.running {
            self.value[ch]
        } else {
            0.0
        }
    }

    /// The value set for channel `ch` (output while conversion runs).
    pub fn value(&self, ch: usize) -> f32 {
        self.value[ch]
    }

    /// `MCC_SetDACTriggerOutput`.
    pub fn set_trigger_output(&mut self, ch: usize, v: f32) -> McclResult<()> {
        self.trig_value[ch] = check_voltage(v)?;
        Ok(())
    }

    /// `MCC_SetDACTriggerSource`: a mask of `DAC_TRIG_ENC0..7` (0 = none).
    pub fn set_trigger_source(&mut self, ch: usize, mask: u32) -> McclResult<()> {
        if mask & !TRIG_SOURCES != 0 {
            return Err(McclError::Parameter);
        }
        self.trig_source[ch] = mask;
        Ok(())
    }

    /// `MCC_EnableDACTriggerMode` / `MCC_DisableDACTriggerMode`.
    pub fn set_trigger_mode(&mut self, ch: usize, on: bool) {
        self.trig_mode[ch] = on;
    }

    /// The encoder compare of channel `enc` fired: every channel in trigger mode with
    /// `DAC_TRIG_ENC<enc>` in its sources takes its preset voltage.
    pub(crate) fn trigger(&mut self, enc: usize) {
        let Some(bit) = u32::try_from(enc).ok().and_then(|e| 1u32.checked_shl(e)) else {
            return;
        };
        for ch in 0..AXES {
            if self.trig_mode[ch] && self.trig_source[ch] & bit != 0 {
                self.write(ch, self.trig_value[ch]);
            }
        }
    }

    /// Watchdog reset: every output to 0 V.
    pub(crate) fn reset_outputs(&mut self) {
        self.value = [0.0; AXES];
        self.held = [None; AXES];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outputs_change_at_most_once_per_cycle() {
        let mut d = Dac::default();
        // Default: a cycle of 16 x 10 x 10 ns = 1.6 us. The first write shows at once; a
        // second one at the same instant waits 1.6 us, i.e. the end of the next tick.
        d.set_output(0, 1.0).unwrap();
        assert_eq!(d.output(0), 1.0);
        d.set_output(0, 2.0).unwrap();
        assert_eq!(d.output(0), 1.0, "held");
        d.set_output(1, 3.0).unwrap();
        assert_eq!(d.output(1), 3.0, "channels are independent");
        d.tick(1_000_000);
        assert_eq!(d.output(0), 2.0);
        // 100 Hz (a 10 ms cycle) on a fresh DAC, 1 ms ticks, value k / 4 written at k ms
        // (k = 0..29), then a tick. k = 0: no update yet, at once (last update 0 ms).
        // k = 1..9 wait; the tick ending at 10 ms (k = 9) applies the latest, 9 / 4, and
        // the next cycle runs from 10 ms: the tick ending at 20 ms (k = 19) applies
        // 19 / 4, the one ending at 30 ms (k = 29) 29 / 4.
        let mut d = Dac::default();
        d.set_update_rate(100.0).unwrap();
        assert_eq!(d.cycle_ns(), 10_000_000);
        let mut seen = Vec::new();
        for k in 0..30 {
            d.set_output(0, k as f32 / 4.0).unwrap();
            d.tick(1_000_000);
            seen.push(d.output(0));
        }
        let mut want = vec![0.0; 9];
        want.extend([2.25; 10]);
        want.extend([4.75; 10]);
        want.push(7.25);
        assert_eq!(seen, want);
        // Divider 65535: 16 x 65535 x 10 ns = 10.4856 ms, longer than 10 ms.
        d.set_clock_divider(65535).unwrap();
        assert_eq!(d.cycle_ns(), 10_485_600);
        // The watchdog's reset drops what waits.
        d.set_output(0, 5.0).unwrap();
        d.reset_outputs();
        assert!(!d.holding());
        (0..20).for_each(|_| d.tick(1_000_000));
        assert_eq!(d.output(0), 0.0);
    }

    #[test]
    fn output_range_stop_and_trigger() {
        let mut d = Dac::default();
        assert!(d.running());
        d.set_output(1, 2.5).unwrap();
        assert_eq!(d.output(1), 2.5);
        for bad in [10.01, -10.5, f32::NAN, f32::INFINITY] {
            assert_eq!(d.set_output(1, bad), Err(McclError::Parameter));
        }
        assert_eq!(d.value(1), 2.5, "unchanged");
        d.set_running(false);
        assert_eq!(d.output(1), 0.0);
        d.set_running(true);
        assert_eq!(d.output(1), 2.5);

        d.set_trigger_output(0, 2.0).unwrap();
        d.set_trigger_source(0, 0x01 | 0x04).unwrap();
        assert_eq!(d.set_trigger_source(0, 0x100), Err(McclError::Parameter));
        d.trigger(0);
        assert_eq!(d.output(0), 0.0, "trigger mode off");
        d.set_trigger_mode(0, true);
        d.trigger(1);
        assert_eq!(d.output(0), 0.0, "not a source");
        d.trigger(2);
        assert_eq!(d.output(0), 2.0);
        d.trigger(99);
        d.reset_outputs();
        assert_eq!((d.output(0), d.output(1)), (0.0, 0.0));
    }
}
