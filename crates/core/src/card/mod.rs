//! The card's peripherals that do not depend on the simulated machine: timer and
//! watchdog, D/A and A/D converters, remote I/O; and the interrupt causes raised on the
//! card (the library's engine delivers them to the program's routines). One
//! [`Peripherals`] per card, behind its own mutex ([`PeriphCell`]); every card's together
//! with the word that counts the engine's ticks of the idle ones ([`PeriphCells`]).
//!
//! Lock order: a group's lock may be held while a card's peripherals are locked (the
//! encoder compare of a group's tick calls [`Peripherals::dac_trigger`]), never the
//! other way round; the system lock is never taken while peripherals are locked.

pub mod adc;
pub mod cadence;
mod cell;
pub mod dac;
pub mod handshake;
pub mod rio;
pub mod timer;

/// One system clock of the card, ns (user manual §2.13: the timer counts it; the serial
/// converters and buses move one bit per divider's worth of them).
pub const SYSTEM_CLOCK_NS: u64 = 10;

use crate::config::AXES;
use crate::interrupt::{Interrupt, Pending};
use adc::{Adc, AdcSource};
pub use cell::{PeriphCell, PeriphCells, PeriphGuard};
use dac::Dac;
use handshake::Handshake;
use rio::Master;
use timer::{Timer, Watchdog};

/// The peripherals of one card.
///
/// Each part keeps its own rules through its methods; the accessors below lend a part
/// to read or to change through those methods. What involves two parts (the ADC reading
/// the DAC, an interrupt cause raised) is a method here.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Peripherals {
    /// The 32-bit timer.
    timer: Timer,
    /// The watchdog.
    watchdog: Watchdog,
    /// The D/A converter.
    dac: Dac,
    /// The A/D converter.
    adc: Adc,
    /// The remote I/O masters.
    rio: Master,
    /// The handshake with the host (`MCC_HostInterrupt`, `MCC_SlaveInterrupt`).
    handshake: Handshake,
    /// Interrupt causes raised since the last delivery.
    pending: Pending,
}

impl Peripherals {
    /// The timer, to read.
    pub fn timer(&self) -> &Timer {
        &self.timer
    }

    /// The timer, to set (`MCC_SetTimer`, `MCC_EnableTimer`, …).
    pub fn timer_mut(&mut self) -> &mut Timer {
        &mut self.timer
    }

    /// The watchdog, to read.
    pub fn watchdog(&self) -> &Watchdog {
        &self.watchdog
    }

    /// The watchdog, to set (`MCC_SetWatchDogTimer`, `MCC_RefreshWatchDogTimer`, …).
    pub fn watchdog_mut(&mut self) -> &mut Watchdog {
        &mut self.watchdog
    }

    /// The D/A converter, to read.
    pub fn dac(&self) -> &Dac {
        &self.dac
    }

    /// The D/A converter, to set (`MCC_SetDACOutput`, `MCC_StartDACConv`, …).
    pub fn dac_mut(&mut self) -> &mut Dac {
        &mut self.dac
    }

    /// The A/D converter, to read.
    pub fn adc(&self) -> &Adc {
        &self.adc
    }

    /// The A/D converter, to set (`MCC_SetADCConvType`, `MCC_StopADCConv`, …; starting a
    /// conversion reads the inputs: [`Peripherals::start_adc`]).
    pub fn adc_mut(&mut self) -> &mut Adc {
        &mut self.adc
    }

    /// The remote I/O (RIO and ARIO masters), to read.
    pub fn remote_io(&self) -> &Master {
        &self.rio
    }

    /// The remote I/O, to set (`MCC_Set(A)RIOOutputValue`, the set and slave controls, …).
    pub fn remote_io_mut(&mut self) -> &mut Master {
        &mut self.rio
    }

    /// The handshake with the host, to read (the requests received).
    pub fn handshake(&self) -> &Handshake {
        &self.handshake
    }

    /// `MCC_HostInterrupt`: the card receives the host's request; it acknowledges it in
    /// its next tick with a `HANDSHAKE` cause.
    pub fn host_interrupt(&mut self) {
        self.handshake.host_interrupt();
    }

    /// `MCC_SlaveInterrupt`: the card interrupts the host now (one `HANDSHAKE` cause,
    /// delivered after the next tick).
    pub fn slave_interrupt(&mut self) {
        self.handshake.slave_interrupt(&mut self.pending);
    }

    /// Raises an interrupt cause on the card (an encoder compare, a trigger of the
    /// simulated machine); it is delivered with the causes of the card's next tick.
    pub fn raise(&mut self, i: Interrupt) {
        self.pending.raise(i);
    }

    /// The causes raised since the last delivery, taken for delivery (`None` when there
    /// are none: nothing to deliver, nothing changed).
    pub fn take_pending(&mut self) -> Option<Pending> {
        (!self.pending.is_empty()).then(|| std::mem::take(&mut self.pending))
    }

    /// One tick of `dt_ns`: timer, watchdog, D/A updates, A/D conversion, remote I/O
    /// transfer, handshake acknowledgements. Returns
    /// true when the watchdog expired; the card's outputs here are then reset already
    /// (DAC at 0 V, remote outputs at 0); the caller resets the rest of the card.
    pub fn tick(&mut self, dt_ns: u64) -> bool {
        let n = self.timer.advance(dt_ns);
        if n > 0 && self.timer.trigger() {
            self.pending.raise(Interrupt::Timer(n));
        }
        let reset = self.watchdog.advance(n);
        if reset {
            self.dac.reset_outputs();
            self.rio.reset_outputs();
        }
        self.dac.tick(dt_ns);
        if self.adc.converting() {
            let inputs = self.adc_inputs();
            self.adc.tick(dt_ns, &inputs, &mut self.pending);
        }
        self.rio.tick(dt_ns, &mut self.pending);
        self.handshake.tick(&mut self.pending);
        reset
    }

    /// Whether a tick now would only move time (the ARIO and RIO cycle timing, the DAC's
    /// clock): timer, watchdog and ADC stopped, no handshake request and no DAC value
    /// waiting, no cause pending, the remote I/O [idle](Master::idle).
    pub fn idle(&self) -> bool {
        !self.timer.enabled()
            && !self.watchdog.enabled()
            && !self.adc.converting()
            && !self.handshake.waiting()
            && !self.dac.holding()
            && self.pending.is_empty()
            && self.rio.idle()
    }

    /// `n` ticks of `dt_ns` of [idle](Peripherals::idle) peripherals: exactly what `n`
    /// calls of [`Peripherals::tick`] do then (they return false and raise nothing).
    pub(crate) fn idle_ticks(&mut self, n: u64, dt_ns: u64) {
        self.rio.idle_ticks(n, dt_ns);
        self.dac.idle_ticks(n, dt_ns);
    }

    /// The voltage at each ADC input now.
    pub fn adc_inputs(&self) -> [f32; AXES] {
        std::array::from_fn(|ch| match self.adc.source(ch) {
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
            self.adc.set_source(ch, src);
        }
    }

    /// The encoder compare of channel `enc_channel` fired: DAC channels in trigger mode
    /// with that source take their preset voltage (user manual §2.11.2).
    pub fn dac_trigger(&mut self, enc_channel: usize) {
        self.dac.trigger(enc_channel);
    }
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
        p.rio
            .ario_set_mut(0)
            .unwrap()
            .set_output(5, 0xFFFF)
            .unwrap();
        p.watchdog.set_enabled(true);
        assert!(!(0..20).any(|_| p.tick(2_000_000)), "timer off: no count");
        p.timer.set_enabled(true);
        p.timer.set_trigger(true);
        let fired: Vec<bool> = (0..5).map(|_| p.tick(2_000_000)).collect();
        assert_eq!(fired, [false, false, false, false, true]);
        assert_eq!(p.pending.tmr[0], 10, "2 expirations per tick");
        assert_eq!(p.dac.output(3), 0.0);
        assert_eq!(p.rio.ario_sets()[0].output(5), Ok(0));
        assert_eq!(p.watchdog.resets(), 1);
    }
}
