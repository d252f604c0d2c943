//! The card's peripherals that do not depend on the simulated machine: timer and
//! watchdog, D/A and A/D converters, remote I/O; and the interrupt causes raised on the
//! card ([`crate::engine::isr`]). One [`Peripherals`] per card, behind its own mutex in
//! [`crate::engine::Shared::periph`].
//!
//! Lock order: a group's lock may be held while a card's peripherals are locked (the
//! encoder compare of a group's tick calls [`Peripherals::dac_trigger`]), never the
//! other way round; the system lock is never taken while peripherals are locked.

pub mod adc;
pub mod dac;
pub mod rio;
pub mod timer;

use crate::config::AXES;
use crate::engine::isr::{Interrupt, Pending};
use adc::{Adc, AdcSource};
use dac::Dac;
use rio::Master;
use timer::{Timer, Watchdog};

/// The peripherals of one card.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Peripherals {
    /// The 32-bit timer.
    pub timer: Timer,
    /// The watchdog.
    pub watchdog: Watchdog,
    /// The D/A converter.
    pub dac: Dac,
    /// The A/D converter.
    pub adc: Adc,
    /// The remote I/O masters.
    pub rio: Master,
    /// Interrupt causes raised since the last delivery.
    pub pending: Pending,
}

impl Peripherals {
    /// One tick of `dt_ns`: timer, watchdog, A/D conversion, remote I/O transfer. Returns
    /// true when the watchdog expired; the card's outputs here are then reset already
    /// (DAC at 0 V, remote outputs at 0); the caller resets the rest of the card.
    pub fn tick(&mut self, dt_ns: u64) -> bool {
        let n = self.timer.advance(dt_ns);
        if n > 0 && self.timer.trigger {
            self.pending.raise(Interrupt::Timer(n));
        }
        let reset = self.watchdog.advance(n);
        if reset {
            self.dac.reset_outputs();
            self.rio.reset_outputs();
        }
        if self.adc.converting() {
            let inputs = self.adc_inputs();
            self.adc.tick(&inputs, &mut self.pending);
        }
        self.rio.tick(dt_ns, &mut self.pending);
        reset
    }

    /// The voltage at each ADC input now.
    pub fn adc_inputs(&self) -> [f32; AXES] {
        std::array::from_fn(|ch| match self.adc.source[ch] {
            AdcSource::Dac(d) if d < AXES => self.dac.output(d),
            AdcSource::Dac(_) => 0.0,
            AdcSource::Constant(v) => v,
        })
    }

    /// `MCC_StartADCConv`.
    pub fn start_adc(&mut self) {
        let inputs = self.adc_inputs();
        self.adc.start(&inputs, &mut self.pending);
    }

    /// Where ADC channel `ch` reads its input (default: DAC channel `ch` of this card).
    pub fn set_adc_source(&mut self, ch: usize, src: AdcSource) {
        if ch < AXES {
            self.adc.source[ch] = src;
        }
    }

    /// The encoder compare of channel `enc_channel` fired: DAC channels in trigger mode
    /// with that source take their preset voltage (user manual §2.11.2).
    pub fn dac_trigger(&mut self, enc_channel: usize) {
        self.dac.trigger(enc_channel);
    }
}

/// Runs `f` on the peripherals of card `wCardIndex` of the running system:
/// `INITIAL_MOTION_ERR` before init, `PARAMETER_ERR` for a card not passed to
/// `MCC_InitSystem`. Takes no other lock.
pub fn with_card<R>(
    wCardIndex: u16,
    f: impl FnOnce(&mut Peripherals) -> crate::error::McclResult<R>,
) -> crate::error::McclResult<R> {
    let shared = crate::system::active()?;
    let cd = shared.card(crate::config::CardIx::new(wCardIndex)?)?;
    let mut p = shared.periph[cd].lock();
    f(&mut p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn adc_reads_the_dac_by_default_and_a_set_source() {
        let mut p = Peripherals::default();
        p.dac.set_output(0, 2.0).unwrap();
        p.adc.set_channel(0, true);
        p.adc.set_channel(1, true);
        p.set_adc_source(1, AdcSource::Constant(-1.5));
        p.start_adc();
        p.tick(1_000_000);
        assert_eq!((p.adc.input(0), p.adc.input(1)), (2.0, -1.5));
        p.dac.set_running(false);
        p.tick(1_000_000);
        assert_eq!(p.adc.input(0), 0.0, "stopped DAC outputs 0 V");
    }

    #[test]
    fn watchdog_counts_timer_periods_and_resets_outputs() {
        let mut p = Peripherals::default();
        p.timer.set_period(100_000).unwrap(); // 1 ms
        p.watchdog.set_compare(10).unwrap(); // 10 ms
        p.dac.set_output(3, 4.0).unwrap();
        p.rio.ario[0].set_output(5, 0xFFFF).unwrap();
        p.watchdog.set_enabled(true);
        assert!(!(0..20).any(|_| p.tick(2_000_000)), "timer off: no count");
        p.timer.set_enabled(true);
        p.timer.trigger = true;
        let fired: Vec<bool> = (0..5).map(|_| p.tick(2_000_000)).collect();
        assert_eq!(fired, [false, false, false, false, true]);
        assert_eq!(p.pending.tmr[0], 10, "2 expirations per tick");
        assert_eq!(p.dac.output(3), 0.0);
        assert_eq!(p.rio.ario[0].output(5), Ok(0));
        assert_eq!(p.watchdog.resets, 1);
    }
}
