//! The card's peripherals that do not depend on the simulated machine: timer and
//! watchdog, D/A and A/D converters, remote I/O; and the interrupt causes raised on the
//! card (the library's engine delivers them to the program's routines). One
//! [`Peripherals`] per card, behind its own mutex ([`PeriphCell`]).
//!
//! Lock order: a group's lock may be held while a card's peripherals are locked (the
//! encoder compare of a group's tick calls [`Peripherals::dac_trigger`]), never the
//! other way round; the system lock is never taken while peripherals are locked.

pub mod adc;
pub mod cadence;
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
use dac::Dac;
use handshake::Handshake;
use parking_lot::{Mutex, MutexGuard};
use rio::Master;
use std::sync::atomic::{AtomicU64, Ordering};
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

/// One card's [`Peripherals`] behind their mutex, and what lets the engine skip the tick
/// of an idle card without taking the lock.
///
/// `state` holds `IDLE` when the peripherals were [idle](Peripherals::idle) as last
/// unlocked, and in its other bits the ticks the engine counted instead of running since
/// (an idle tick only moves the ARIO cycle timing). Whoever locks takes the count and runs
/// those ticks first (`Peripherals::idle_ticks`), so every holder of the lock sees the
/// state an engine ticking every card would have made. Both sides change `state` with one
/// atomic operation: a tick counted before a lock is run by that lock before its holder
/// changes anything; once the lock has taken the count (and cleared `IDLE`) the engine
/// counts no more and ticks the card under the lock.
#[derive(Debug)]
pub struct PeriphCell {
    periph: Mutex<Peripherals>,
    state: AtomicU64,
    /// The tick length the counted ticks have, ns.
    dt_ns: u64,
}

/// [`PeriphCell::state`]: the peripherals are idle.
const IDLE: u64 = 1 << 63;

impl PeriphCell {
    /// Default peripherals, for an engine whose ticks last `dt_ns`.
    pub fn new(dt_ns: u64) -> PeriphCell {
        PeriphCell {
            periph: Mutex::new(Peripherals::default()),
            state: AtomicU64::new(0),
            dt_ns,
        }
    }

    /// Locks the peripherals (after running the ticks counted while they were idle).
    pub fn lock(&self) -> PeriphGuard<'_> {
        let mut periph = self.periph.lock();
        let n = self.state.swap(0, Ordering::AcqRel) & !IDLE;
        if n > 0 {
            periph.idle_ticks(n, self.dt_ns);
        }
        PeriphGuard { cell: self, periph }
    }

    /// The engine's tick of an idle card: counts it instead of running it and returns
    /// true; false (nothing counted) when the card is not idle or is locked.
    pub fn count_idle_tick(&self) -> bool {
        let mut s = self.state.load(Ordering::Acquire);
        loop {
            // Not idle, or (never in practice) the count is full: tick under the lock.
            if s & IDLE == 0 || s & !IDLE == !IDLE {
                return false;
            }
            match self
                .state
                .compare_exchange_weak(s, s + 1, Ordering::AcqRel, Ordering::Acquire)
            {
                Ok(_) => return true,
                Err(now) => s = now,
            }
        }
    }
}

/// The locked peripherals of a [`PeriphCell`]; unlocking records whether they are idle.
#[derive(Debug)]
pub struct PeriphGuard<'a> {
    cell: &'a PeriphCell,
    periph: MutexGuard<'a, Peripherals>,
}

impl std::ops::Deref for PeriphGuard<'_> {
    type Target = Peripherals;
    fn deref(&self) -> &Peripherals {
        &self.periph
    }
}

impl std::ops::DerefMut for PeriphGuard<'_> {
    fn deref_mut(&mut self) -> &mut Peripherals {
        &mut self.periph
    }
}

impl Drop for PeriphGuard<'_> {
    fn drop(&mut self) {
        // Still locked here (the mutex guard drops after this).
        let idle = if self.periph.idle() { IDLE } else { 0 };
        self.cell.state.store(idle, Ordering::Release);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The same change made to both copies.
    fn change(p: &mut Peripherals, k: u64) {
        fn rio(p: &mut Peripherals, set: usize) -> &mut rio::Set<{ rio::RIO_PORTS }> {
            p.rio.rio_set_mut(set).unwrap()
        }
        fn ario(p: &mut Peripherals, set: usize) -> &mut rio::Set<{ rio::ARIO_SLAVES }> {
            p.rio.ario_set_mut(set).unwrap()
        }
        let set = (k / 16 % 2) as usize;
        let slave = (k / 32 % 4) as u16;
        match k % 20 {
            0 => p.rio.set_ario_update_rate(set, 300.0).unwrap(),
            1 => p.rio.set_ario_update_rate(set, 1700.0).unwrap(),
            2 => p.rio.set_ario_clock_divider(set, 2000).unwrap(),
            3 => p.rio.set_ario_node_delay(3000),
            4 | 5 => ario(p, set).set_slave_control(slave, true).unwrap(),
            6..=8 => ario(p, set).set_slave_control(slave, false).unwrap(),
            9 => ario(p, set).set_output(slave, (k >> 8) as u16).unwrap(),
            10 => {
                let on = p.rio.rio_sets()[set].control();
                p.rio.set_rio_control(set, !on).unwrap();
            }
            11 => rio(p, set).set_slave_control(slave, k & 64 != 0).unwrap(),
            12 => rio(p, set).set_output(0, (k >> 8) as u16).unwrap(),
            13 => {
                p.timer.set_period(70_000).unwrap();
                p.timer.set_trigger(true);
                p.timer.set_enabled(k & 128 != 0);
            }
            14 => ario(p, set)
                .set_input_trigger((k % 8) as u16, true)
                .unwrap(),
            16 => p.dac.set_output((k >> 8) as usize % 8, 1.0).unwrap(),
            17 => p.dac.set_update_rate(300.0).unwrap(),
            18 => p.rio.set_rio_update_rate(set, 700.0).unwrap(),
            19 => p.rio.set_rio_clock_divider(set, 3000).unwrap(),
            _ => p
                .rio
                .set_slave_failed(true, set, usize::from(slave), k & 256 != 0),
        }
    }

    #[test]
    fn counted_idle_ticks_give_the_state_of_ticking_every_time() {
        // `plain` ticks every time; `cell` as the engine does: an idle card's tick is
        // counted and run when the card is next locked.
        let dt = 1_000_000;
        let cell = PeriphCell::new(dt);
        let mut plain = Peripherals::default();
        let mut seed: u64 = 99;
        let mut counted = 0;
        for n in 0..50_000 {
            let fired = if cell.count_idle_tick() {
                counted += 1;
                Pending::default()
            } else {
                let mut p = cell.lock();
                assert!(!p.tick(dt));
                std::mem::take(&mut p.pending)
            };
            assert!(!plain.tick(dt));
            assert_eq!(fired, std::mem::take(&mut plain.pending), "tick {n}");
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            // Changes now and then, long idle stretches in between.
            if (seed >> 33) % 40 == 0 {
                let k = seed >> 20;
                change(&mut cell.lock(), k);
                change(&mut plain, k);
            } else if (seed >> 33) % 300 == 1 {
                // Back to idle (the ARIO timing keeps its phase and settings).
                for p in [&mut *cell.lock(), &mut plain] {
                    p.timer.set_enabled(false);
                    for set in 0..2 {
                        p.rio.set_rio_control(set, false).unwrap();
                        for slave in 0..32 {
                            let ario = p.rio.ario_set_mut(set).unwrap();
                            ario.set_slave_control(slave, false).unwrap();
                        }
                    }
                }
            }
            if n % 101 == 0 {
                assert_eq!(*cell.lock(), plain, "tick {n}");
            }
        }
        assert_eq!(*cell.lock(), plain);
        assert!(counted > 10_000, "idle stretches were counted ({counted})");
    }

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
