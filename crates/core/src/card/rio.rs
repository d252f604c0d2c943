//! Remote I/O (user manual §2.14; examples manual §33–34; docs/vendor-interface.md).
//!
//! Each card has two sets (`RIO_SET0`, `RIO_SET1`) of each master:
//!
//! - RIO: 4 ports (`RIO_PORT0..3`) of 16 outputs and 16 inputs, one simulated slave per
//!   port (slave n = port n). Data moves while the set's control
//!   (`MCC_EnableRIOSetControl`) and the slave's (`MCC_EnableRIOSlaveControl`) are on.
//!   Digital inputs `RIO_DI0..7` are bits 0..7 of port 0's inputs; their edges
//!   (`RIO_INT_RISE`/`FALL`/`LEVEL`) raise `RIOINT.RDIn` (the same field for either set).
//! - ARIO (`MCC_*ARIO*`, the B/C signatures with `wSet`): 32 slaves (`RIO_SLAVE0..31`,
//!   the `wPort` argument) of 16 outputs and 16 inputs; data moves while the slave's
//!   control (`MCC_EnableARIOSlaveControl`) is on.
//!
//! In a transfer a transmitting slave takes the master's outputs and the master latches
//! the slave's inputs. RIO sets transfer once per cycle of their [`Cadence`]: 32 bits per
//! transmitting slave (at least one) at `MCC_SetRIOClockDivider` (default 10) system
//! clocks per bit, or one period of `MCC_SetRIOUpdateRate` if that is longer: 3.2 to
//! 12.8 µs by default, so every tick. ARIO sets transfer once per cycle
//! ([`ArioTiming`]): a cycle lasts `n × (32 × divider + delay) × 10 ns` for `n`
//! transmitting slaves (16 output and 16 input bits each at the system clock of 10 ns
//! divided by `MCC_SetARIOClockDivider`, then the node-to-node delay of
//! `MCC_SetARIONode2NodeDelay` in system clocks), or one period of
//! `MCC_SetARIOUpdateRate` if that is longer; a set transfers in the ticks in which a
//! cycle ends, at most once per tick.
//!
//! A simulated slave's inputs loop back from its outputs unless set otherwise from Rust
//! ([`RioInput`]); a slave or master can be made to fail ([`Master::set_slave_failed`],
//! [`Master::set_master_failed`]). A failing slave does not transfer; each transfer it
//! fails counts, and once it has failed more consecutive transfers than the set tolerates
//! (`MCC_SetRIOTransError`, default 0) the set reports it: `…SlaveFail` has its bit, the
//! slave and transfer statuses read 0, and the transfer trigger fires. Its first good
//! transfer clears the report. A failed master is reported at once.

mod ario_timing;

pub use ario_timing::ArioTiming;

use super::cadence::Cadence;
use crate::error::{McclError, McclResult};
use crate::interrupt::{Interrupt, Pending};
use crate::vendor::consts as c;

/// Sets per master.
pub const SETS: usize = 2;
/// RIO ports (= slaves) per set.
pub const RIO_PORTS: usize = 4;
/// ARIO slaves per set.
pub const ARIO_SLAVES: usize = 32;
/// RIO digital inputs with a trigger.
pub const DIS: usize = 8;
/// Bits one ARIO slave exchanges per cycle: 16 outputs and 16 inputs.
pub const ARIO_BITS_PER_SLAVE: u64 = 32;
/// ARIO clock divider before any `MCC_SetARIOClockDivider`: 10 (a 10 Mbit/s bus).
pub const ARIO_DEFAULT_DIVIDER: u16 = 10;

/// What a simulated slave's inputs read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RioInput {
    /// The slave's own outputs (default).
    Loopback,
    /// A fixed value.
    Constant(u16),
}

/// One set of a master with `N` slaves.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Set<const N: usize> {
    /// Set-level control (RIO only, [`Master::set_rio_control`]; ARIO sets are always on).
    control: bool,
    slave_on: u32,
    outputs: [u16; N],
    inputs: [u16; N],
    /// What each slave's inputs read.
    source: [RioInput; N],
    /// Simulation: slaves whose transfers fail.
    broken: u32,
    /// Slaves reported failed: their consecutive failed transfers exceeded `tolerance`.
    slave_fail: u32,
    /// Consecutive failed transfers per slave.
    fail_run: [u32; N],
    /// Consecutive failed transfers a slave may have before it is reported
    /// (`MCC_SetRIOTransError`).
    tolerance: u16,
    master_fail: bool,
    trig_type: [u16; DIS],
    trig_on: [bool; DIS],
    trans_trigger: bool,
    last_di: Option<u8>,
    was_ok: bool,
}

impl<const N: usize> Set<N> {
    fn new(control: bool) -> Self {
        Set {
            control,
            slave_on: 0,
            outputs: [0; N],
            inputs: [0; N],
            source: [RioInput::Loopback; N],
            broken: 0,
            slave_fail: 0,
            fail_run: [0; N],
            tolerance: 0,
            master_fail: false,
            trig_type: [c::RIO_INT_RISE; DIS],
            trig_on: [false; DIS],
            trans_trigger: false,
            last_di: None,
            was_ok: true,
        }
    }

    fn slave(s: u16) -> McclResult<usize> {
        let s = usize::from(s);
        if s < N {
            Ok(s)
        } else {
            Err(McclError::Parameter)
        }
    }

    /// Slave control on or off (`MCC_Enable/Disable(A)RIOSlaveControl`). Turning it off
    /// forgets the slave's failed transfers.
    pub fn set_slave_control(&mut self, s: u16, on: bool) -> McclResult<()> {
        let i = Self::slave(s)?;
        let bit = 1u32 << i;
        if on {
            self.slave_on |= bit;
        } else {
            self.slave_on &= !bit;
            self.slave_fail &= !bit;
            self.fail_run[i] = 0;
        }
        Ok(())
    }

    /// Whether the set transfers: its set-level control (RIO sets, off until
    /// `MCC_EnableRIOSetControl`; ARIO sets are always on).
    pub fn control(&self) -> bool {
        self.control
    }

    /// Simulation: what slave `s`'s inputs read from now on (its own outputs by default);
    /// the master latches them at the slave's next transfer. A bad slave is
    /// `PARAMETER_ERR`.
    pub fn set_input_source(&mut self, s: u16, src: RioInput) -> McclResult<()> {
        self.source[Self::slave(s)?] = src;
        Ok(())
    }

    /// Slaves whose control is on.
    pub fn transmitting(&self) -> u32 {
        self.slave_on
    }

    /// `MCC_SetRIOTransError`: consecutive failed transfers a slave may have before the
    /// set reports it (0: at its first failed transfer). Takes effect at the next transfer.
    pub fn set_tolerance(&mut self, n: u16) {
        self.tolerance = n;
    }

    /// The tolerance set by [`Set::set_tolerance`].
    pub fn tolerance(&self) -> u16 {
        self.tolerance
    }

    /// Outputs of a port/slave (`MCC_Set(A)RIOOutputValue`).
    pub fn set_output(&mut self, s: u16, v: u16) -> McclResult<()> {
        self.outputs[Self::slave(s)?] = v;
        Ok(())
    }

    /// The bits of `mask` of a port/slave's outputs take those of `value`, the others
    /// stay (`MCC_QueueRIOOutputValue`, `MCC_QueueARIOOutputValue` when the queue reaches
    /// them).
    pub fn set_output_bits(&mut self, s: u16, mask: u16, value: u16) -> McclResult<()> {
        let out = &mut self.outputs[Self::slave(s)?];
        *out = *out & !mask | value & mask;
        Ok(())
    }

    /// The outputs set for a port/slave.
    pub fn output(&self, s: u16) -> McclResult<u16> {
        Ok(self.outputs[Self::slave(s)?])
    }

    /// The inputs latched from a port/slave.
    pub fn input(&self, s: u16) -> McclResult<u16> {
        Ok(self.inputs[Self::slave(s)?])
    }

    /// Slaves reported failed among the transmitting ones, bit n = slave n.
    pub fn slave_fail(&self) -> u32 {
        self.slave_fail & self.slave_on
    }

    /// 1 when the master works, 0 on a master error.
    pub fn master_status(&self) -> u16 {
        u16::from(!self.master_fail)
    }

    /// 1 when no transmitting slave is reported failed, 0 when one is.
    pub fn slave_status(&self) -> u16 {
        u16::from(self.slave_fail() == 0)
    }

    /// 1 while data moves without error, 0 on a master or slave error.
    pub fn trans_status(&self) -> u16 {
        self.master_status() & self.slave_status()
    }

    /// Simulation: slave `s` fails its transfers from now on (or works again); the set
    /// notices at its transfers.
    pub fn set_slave_failed(&mut self, s: usize, failed: bool) {
        if s < N {
            if failed {
                self.broken |= 1 << s;
            } else {
                self.broken &= !(1 << s);
            }
        }
    }

    /// Consecutive failed transfers of slave `s` so far.
    pub fn failed_transfers(&self, s: usize) -> u32 {
        self.fail_run.get(s).copied().unwrap_or(0)
    }

    /// Simulation: the master fails (or works again).
    pub fn set_master_failed(&mut self, failed: bool) {
        self.master_fail = failed;
    }

    /// `MCC_SetRIOTriggerType`: `RIO_INT_NO`, `_RISE`, `_FALL` or `_LEVEL` for DI `di`.
    pub fn set_trigger_type(&mut self, di: u16, t: u16) -> McclResult<()> {
        let di = usize::from(di);
        if di >= DIS || t > c::RIO_INT_LEVEL {
            return Err(McclError::Parameter);
        }
        self.trig_type[di] = t;
        Ok(())
    }

    /// `MCC_Enable/DisableRIOInputTrigger`.
    pub fn set_input_trigger(&mut self, di: u16, on: bool) -> McclResult<()> {
        let di = usize::from(di);
        if di >= DIS {
            return Err(McclError::Parameter);
        }
        self.trig_on[di] = on;
        Ok(())
    }

    /// `MCC_Enable/DisableRIOTransTrigger`.
    pub fn set_trans_trigger(&mut self, on: bool) {
        self.trans_trigger = on;
    }

    /// One transfer; counts failed slave transfers, raises input edges and the
    /// transmission failure (the status going from 1 to 0).
    /// Whether a transfer now would change nothing and raise nothing: the set's control
    /// is off, or nothing transmits and nothing changed since the last transfer (no slave
    /// moves data, the status stays, the digital inputs equal the ones last seen). This
    /// is every idle set on every tick (an ARIO set's control is always on).
    fn transfer_idle(&self) -> bool {
        !self.control
            || (self.slave_on == 0
                && self.was_ok != self.master_fail
                && (self.master_fail || self.last_di == Some((self.inputs[0] & 0xFF) as u8)))
    }

    fn transfer(&mut self, p: &mut Pending) {
        if self.transfer_idle() {
            return;
        }
        if !self.master_fail {
            for s in (0..N).filter(|s| self.slave_on & (1 << s) != 0) {
                let bit = 1u32 << s;
                if self.broken & bit != 0 {
                    self.fail_run[s] = self.fail_run[s].saturating_add(1);
                    if self.fail_run[s] > u32::from(self.tolerance) {
                        self.slave_fail |= bit;
                    }
                    continue;
                }
                self.fail_run[s] = 0;
                self.slave_fail &= !bit;
                self.inputs[s] = match self.source[s] {
                    RioInput::Loopback => self.outputs[s],
                    RioInput::Constant(v) => v,
                };
            }
        }
        let ok = self.trans_status() == 1;
        if self.trans_trigger && self.was_ok && !ok {
            p.raise(Interrupt::RioFail);
        }
        self.was_ok = ok;
        if self.master_fail {
            return;
        }
        let di = (self.inputs[0] & 0xFF) as u8;
        if let Some(last) = self.last_di {
            for n in 0..DIS {
                let (was, is) = (last >> n & 1 == 1, di >> n & 1 == 1);
                let fire = match self.trig_type[n] {
                    c::RIO_INT_RISE => !was && is,
                    c::RIO_INT_FALL => was && !is,
                    c::RIO_INT_LEVEL => was != is,
                    _ => false,
                };
                if fire && self.trig_on[n] {
                    p.raise(Interrupt::RioInput(n as u8));
                }
            }
        }
        self.last_di = Some(di);
    }

    fn reset_outputs(&mut self) {
        self.outputs = [0; N];
    }
}

/// RIO clock divider before any `MCC_SetRIOClockDivider`: 10, as the ARIO's.
pub const RIO_DEFAULT_DIVIDER: u16 = 10;

/// Serial bits of one RIO transfer cycle with the slaves in `transmitting`: 16 output and
/// 16 input bits per transmitting slave, at least one slave's worth.
pub fn rio_cycle_bits(transmitting: u32) -> u64 {
    u64::from(transmitting.count_ones().max(1)) * ARIO_BITS_PER_SLAVE
}

/// The remote I/O of one card: RIO and ARIO masters, two sets each.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Master {
    /// RIO sets.
    rio: [Set<RIO_PORTS>; SETS],
    /// ARIO sets.
    ario: [Set<ARIO_SLAVES>; SETS],
    /// When the ARIO sets transfer.
    ario_timing: ArioTiming,
    /// When each RIO set transfers (`MCC_SetRIOClockDivider`, `MCC_SetRIOUpdateRate`): a
    /// cycle moves 32 bits per transmitting slave (at least one).
    rio_timing: [Cadence; SETS],
}

impl Default for Master {
    fn default() -> Master {
        Master {
            rio: std::array::from_fn(|_| Set::new(false)),
            ario: std::array::from_fn(|_| Set::new(true)),
            ario_timing: ArioTiming::default(),
            rio_timing: [Cadence::new(RIO_DEFAULT_DIVIDER); SETS],
        }
    }
}

/// A set index from C.
pub fn set_ix(w: u16) -> McclResult<usize> {
    let s = usize::from(w);
    if s < SETS {
        Ok(s)
    } else {
        Err(McclError::Parameter)
    }
}

/// Element `set` of a master's per-set array, to change; a bad set is `PARAMETER_ERR`.
fn at_mut<T>(sets: &mut [T; SETS], set: usize) -> McclResult<&mut T> {
    sets.get_mut(set).ok_or(McclError::Parameter)
}

impl Master {
    /// The RIO sets (`RIO_SET0`, `RIO_SET1`), to read.
    pub fn rio_sets(&self) -> &[Set<RIO_PORTS>; SETS] {
        &self.rio
    }

    /// RIO set `set` (`RIO_SET0`, `RIO_SET1`; else `PARAMETER_ERR`), to change through
    /// its methods.
    pub fn rio_set_mut(&mut self, set: usize) -> McclResult<&mut Set<RIO_PORTS>> {
        at_mut(&mut self.rio, set)
    }

    /// The ARIO sets (`RIO_SET0`, `RIO_SET1`), to read.
    pub fn ario_sets(&self) -> &[Set<ARIO_SLAVES>; SETS] {
        &self.ario
    }

    /// ARIO set `set` (`RIO_SET0`, `RIO_SET1`; else `PARAMETER_ERR`), to change through
    /// its methods.
    pub fn ario_set_mut(&mut self, set: usize) -> McclResult<&mut Set<ARIO_SLAVES>> {
        at_mut(&mut self.ario, set)
    }

    /// `MCC_EnableRIOSetControl` / `MCC_DisableRIOSetControl`: RIO set `set` transfers or
    /// not (a bad set is `PARAMETER_ERR`). Only RIO sets have this control: an ARIO set
    /// always transfers, so the ARIO sets offer no way to turn it off.
    pub fn set_rio_control(&mut self, set: usize, on: bool) -> McclResult<()> {
        at_mut(&mut self.rio, set)?.control = on;
        Ok(())
    }

    /// When each RIO set transfers, to read.
    pub fn rio_timing(&self) -> &[Cadence; SETS] {
        &self.rio_timing
    }

    /// `MCC_SetRIOClockDivider`: one bit every `divider` system clocks on RIO set `set`
    /// (1..65535); a bad set or divider is `PARAMETER_ERR` and changes nothing. The cycle
    /// count restarts.
    pub fn set_rio_clock_divider(&mut self, set: usize, divider: u16) -> McclResult<()> {
        at_mut(&mut self.rio_timing, set)?.set_divider(divider)
    }

    /// `MCC_SetRIOUpdateRate`: at most `rate` transfer cycles per second on RIO set `set`
    /// (checked as [`super::cadence::update_period_ns`] says); a bad set or rate is
    /// `PARAMETER_ERR` and changes nothing. The cycle count restarts.
    pub fn set_rio_update_rate(&mut self, set: usize, rate: f64) -> McclResult<()> {
        at_mut(&mut self.rio_timing, set)?.set_update_rate(rate)
    }

    /// When the ARIO sets transfer, to read.
    pub fn ario_timing(&self) -> &ArioTiming {
        &self.ario_timing
    }

    /// `MCC_SetARIOUpdateRate`: see [`ArioTiming::set_update_rate`].
    pub fn set_ario_update_rate(&mut self, set: usize, rate: f64) -> McclResult<()> {
        self.ario_timing.set_update_rate(set, rate)
    }

    /// `MCC_SetARIOClockDivider`: see [`ArioTiming::set_divider`].
    pub fn set_ario_clock_divider(&mut self, set: usize, divider: u16) -> McclResult<()> {
        self.ario_timing.set_divider(set, divider)
    }

    /// `MCC_SetARIONode2NodeDelay`: see [`ArioTiming::set_node_delay`].
    pub fn set_ario_node_delay(&mut self, clocks: u32) {
        self.ario_timing.set_node_delay(clocks);
    }

    /// One tick of `dt_ns`: every RIO set transfers, each ARIO set if one of its cycles
    /// ended in the tick.
    pub(crate) fn tick(&mut self, dt_ns: u64, p: &mut Pending) {
        for (i, s) in self.rio.iter_mut().enumerate() {
            if self.rio_timing[i].advance(dt_ns, rio_cycle_bits(s.transmitting())) {
                s.transfer(p);
            }
        }
        for (i, s) in self.ario.iter_mut().enumerate() {
            if self.ario_timing.advance(i, dt_ns, s.transmitting()) {
                s.transfer(p);
            }
        }
    }

    /// Whether a tick now would only move the ARIO and RIO cycle timing: every set's
    /// transfer would change nothing (`Set::transfer_idle`).
    pub fn idle(&self) -> bool {
        self.rio.iter().all(Set::transfer_idle) && self.ario.iter().all(Set::transfer_idle)
    }

    /// `n` ticks of `dt_ns` of an [idle](Master::idle) master: exactly what `n` calls of
    /// [`Master::tick`] do then (the ARIO and RIO cycle timing moves on; the transfers
    /// would change nothing).
    pub(crate) fn idle_ticks(&mut self, n: u64, dt_ns: u64) {
        for (i, s) in self.rio.iter().enumerate() {
            self.rio_timing[i].advance_n(n, dt_ns, rio_cycle_bits(s.transmitting()));
        }
        for (i, s) in self.ario.iter().enumerate() {
            self.ario_timing.advance_n(i, n, dt_ns, s.transmitting());
        }
    }

    /// Watchdog reset: every output to 0.
    pub(crate) fn reset_outputs(&mut self) {
        self.rio.iter_mut().for_each(Set::reset_outputs);
        self.ario.iter_mut().for_each(Set::reset_outputs);
    }

    /// Simulation: slave `slave` of ARIO (`ario`) or RIO set `set` fails or recovers.
    pub fn set_slave_failed(&mut self, ario: bool, set: usize, slave: usize, failed: bool) {
        if ario {
            if let Some(s) = self.ario.get_mut(set) {
                s.set_slave_failed(slave, failed);
            }
        } else if let Some(s) = self.rio.get_mut(set) {
            s.set_slave_failed(slave, failed);
        }
    }

    /// Simulation: the ARIO (`ario`) or RIO master of set `set` fails or recovers.
    pub fn set_master_failed(&mut self, ario: bool, set: usize, failed: bool) {
        if ario {
            if let Some(s) = self.ario.get_mut(set) {
                s.set_master_failed(failed);
            }
        } else if let Some(s) = self.rio.get_mut(set) {
            s.set_master_failed(failed);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One 1 ms tick.
    fn step(m: &mut Master) -> Pending {
        let mut p = Pending::default();
        m.tick(1_000_000, &mut p);
        p
    }

    #[test]
    fn loopback_needs_control_and_moves_once_per_tick() {
        let mut m = Master::default();
        let s = &mut m.rio[1];
        s.set_output(2, 0xBEEF).unwrap();
        assert_eq!(s.set_output(4, 1), Err(McclError::Parameter));
        s.set_slave_control(2, true).unwrap();
        step(&mut m);
        assert_eq!(m.rio[1].input(2), Ok(0), "set control off");
        m.set_rio_control(1, true).unwrap();
        assert!(m.rio[1].control());
        assert_eq!(m.rio[1].input(2), Ok(0), "not before the tick");
        step(&mut m);
        assert_eq!(m.rio[1].input(2), Ok(0xBEEF));

        let a = &mut m.ario[0];
        a.set_output(31, 0x1004).unwrap();
        a.set_output_bits(31, 0x0FF0, 0xF234).unwrap();
        assert_eq!(a.output(31), Ok(0x1234), "only the masked bits change");
        assert_eq!(a.set_output_bits(32, 1, 1), Err(McclError::Parameter));
        a.set_slave_control(31, true).unwrap();
        a.set_input_source(31, RioInput::Constant(0x00F0)).unwrap();
        assert_eq!(
            a.set_input_source(32, RioInput::Loopback),
            Err(McclError::Parameter)
        );
        assert_eq!(a.set_slave_control(32, true), Err(McclError::Parameter));
        step(&mut m);
        assert_eq!(m.ario[0].input(31), Ok(0x00F0));
        assert_eq!(m.ario[0].output(31), Ok(0x1234));
    }

    #[test]
    fn input_trigger_edges_and_transmission_failure() {
        let mut m = Master::default();
        let s = &mut m.rio[0];
        s.control = true;
        s.set_slave_control(0, true).unwrap();
        s.set_trigger_type(0, c::RIO_INT_RISE).unwrap();
        s.set_trigger_type(1, c::RIO_INT_FALL).unwrap();
        s.set_trigger_type(2, c::RIO_INT_LEVEL).unwrap();
        for di in 0..3 {
            s.set_input_trigger(di, true).unwrap();
        }
        assert_eq!(s.set_trigger_type(8, 1), Err(McclError::Parameter));
        assert_eq!(s.set_trigger_type(0, 4), Err(McclError::Parameter));
        assert!(step(&mut m).is_empty(), "first transfer sets the reference");
        m.rio[0].set_output(0, 0b111).unwrap();
        let p = step(&mut m);
        assert_eq!(&p.rio[..4], &[1, 0, 1, 0], "DI0 rises, DI2 changes");
        m.rio[0].set_output(0, 0).unwrap();
        let p = step(&mut m);
        assert_eq!(&p.rio[..4], &[0, 1, 1, 0], "DI1 falls, DI2 changes");

        m.rio[0].set_trans_trigger(true);
        m.set_slave_failed(false, 0, 0, true);
        assert_eq!(m.rio[0].slave_fail(), 0, "noticed at the next transfer");
        assert_eq!(step(&mut m).rio[8], 1, "FAIL once (tolerance 0)");
        assert_eq!(m.rio[0].slave_fail(), 1);
        assert_eq!((m.rio[0].trans_status(), m.rio[0].slave_status()), (0, 0));
        assert_eq!(step(&mut m).rio[8], 0);
        m.set_slave_failed(false, 0, 0, false);
        step(&mut m);
        assert_eq!(m.rio[0].slave_fail(), 0, "a good transfer clears it");
        m.set_master_failed(false, 0, true);
        assert_eq!(m.rio[0].master_status(), 0);
        assert_eq!(m.rio[0].slave_status(), 1);
        assert_eq!(step(&mut m).rio[8], 1, "the master failure is a new edge");
        assert_eq!(step(&mut m).rio[8], 0, "still failing: no new edge");
    }

    #[test]
    fn trans_error_tolerates_that_many_failed_transfers() {
        let mut m = Master::default();
        let s = &mut m.rio[0];
        s.control = true;
        s.set_slave_control(1, true).unwrap();
        s.set_trans_trigger(true);
        s.set_tolerance(5); // the vendor test's MCC_SetRIOTransError(5, 0, 0)
        m.set_slave_failed(false, 0, 1, true);
        // Transfers 1..5 fail and are tolerated; the 6th is reported.
        for n in 1..=5 {
            assert_eq!(step(&mut m).rio[8], 0, "transfer {n} tolerated");
            assert_eq!(m.rio[0].failed_transfers(1), n);
            assert_eq!((m.rio[0].slave_fail(), m.rio[0].trans_status()), (0, 1));
        }
        assert_eq!(step(&mut m).rio[8], 1, "6th failed transfer");
        assert_eq!((m.rio[0].slave_fail(), m.rio[0].trans_status()), (0b10, 0));
        // Recovery clears the run; a new failure starts counting from 0 again.
        m.set_slave_failed(false, 0, 1, false);
        step(&mut m);
        assert_eq!(
            (m.rio[0].slave_fail(), m.rio[0].failed_transfers(1)),
            (0, 0)
        );
        m.set_slave_failed(false, 0, 1, true);
        (0..5).for_each(|_| assert_eq!(step(&mut m).rio[8], 0));
        assert_eq!(step(&mut m).rio[8], 1);
        // Disabling the slave forgets it; no transfer, no count.
        m.rio[0].set_slave_control(1, false).unwrap();
        assert_eq!(m.rio[0].failed_transfers(1), 0);
        step(&mut m);
        assert_eq!(m.rio[0].failed_transfers(1), 0);
        // A set that does not transfer (set control off) counts nothing.
        m.rio[0].set_slave_control(1, true).unwrap();
        m.rio[0].control = false;
        for _ in 0..10 {
            step(&mut m);
        }
        assert_eq!(m.rio[0].failed_transfers(1), 0);
    }

    /// Ticks (1 ms each) in 1..=n in which ARIO set 0 transferred slave 0's output (a
    /// new value before every tick, never written before).
    fn ario_transfer_ticks(m: &mut Master, n: u16) -> Vec<u16> {
        let mut at = Vec::new();
        for t in 1..=n {
            let v = m.ario[0].output(0).unwrap() + 1;
            m.ario[0].set_output(0, v).unwrap();
            step(m);
            if m.ario[0].input(0) == Ok(v) {
                at.push(t);
            }
        }
        at
    }

    #[test]
    fn rio_cycles_follow_rate_and_divider() {
        let mut m = Master::default();
        m.rio[1].control = true;
        m.rio[1].set_slave_control(2, true).unwrap();
        let transfers = |m: &mut Master, n: u16| -> Vec<u16> {
            let mut at = Vec::new();
            for t in 1..=n {
                let v = m.rio[1].output(2).unwrap().wrapping_add(1);
                m.rio[1].set_output(2, v).unwrap();
                step(m);
                if m.rio[1].input(2) == Ok(v) {
                    at.push(t);
                }
            }
            at
        };
        // Default: 1 slave x 32 bits x 10 clocks x 10 ns = 3.2 us: every tick.
        assert_eq!(transfers(&mut m, 3), [1, 2, 3]);
        // 300 Hz: 3.333333 ms (3333333 ns) from the call: cycles end at 3.33, 6.67,
        // 10.0 ms (3 x 3333333 = 9999999 ns, in tick 10): ticks 4, 7, 10.
        m.rio_timing[1].set_update_rate(300.0).unwrap();
        assert_eq!(transfers(&mut m, 10), [4, 7, 10]);
        // Two slaves at divider 6000: 2 x 32 x 6000 x 10 ns = 3.84 ms, longer than the
        // 300 Hz period: cycles end at 3.84, 7.68, 11.52 ms: ticks 4, 8, 12.
        m.rio[1].set_slave_control(0, true).unwrap();
        m.rio_timing[1].set_divider(6000).unwrap();
        assert_eq!(m.rio_timing[1].cycle_ns(rio_cycle_bits(0b101)), 3_840_000);
        assert_eq!(transfers(&mut m, 12), [4, 8, 12]);
        // Set 0 keeps its own default timing.
        assert_eq!(
            (m.rio_timing[0].divider(), m.rio_timing[0].update_ns()),
            (RIO_DEFAULT_DIVIDER, None)
        );
    }

    #[test]
    fn ario_cycles_follow_rate_divider_and_node_delay() {
        let mut m = Master::default();
        m.ario[0].set_slave_control(0, true).unwrap();
        // Default: 1 slave x 32 bits x 10 clocks x 10 ns = 3.2 us: every tick.
        assert_eq!(m.ario_timing.cycle_ns(0, 1), 3_200);
        assert_eq!(ario_transfer_ticks(&mut m, 3), [1, 2, 3]);
        // 100 Hz: a cycle every 10 ms from the call: ticks 10 and 20.
        m.ario_timing.set_update_rate(0, 100.0).unwrap();
        assert_eq!(ario_transfer_ticks(&mut m, 20), [10, 20]);
        // Divider 5000 and a delay of 90000 clocks: 32 x 50 us + 0.9 ms = 2.5 ms, longer
        // than 1 / 1000 Hz: cycles end at 2.5, 5, 7.5, 10 ms = ticks 3, 5, 8, 10.
        m.ario_timing.set_update_rate(0, 1000.0).unwrap();
        m.ario_timing.set_divider(0, 5000).unwrap();
        m.ario_timing.set_node_delay(90_000);
        assert_eq!(m.ario_timing.cycle_ns(0, 1), 2_500_000);
        assert_eq!(ario_transfer_ticks(&mut m, 10), [3, 5, 8, 10]);
        // Two transmitting slaves double the bus time: 5 ms.
        m.ario[0].set_slave_control(7, true).unwrap();
        m.ario_timing.set_node_delay(90_000);
        assert_eq!(ario_transfer_ticks(&mut m, 10), [5, 10]);
        // Set 1 keeps its own (default) timing.
        assert_eq!(m.ario_timing.cycle_ns(1, 1), 32 * 10 * 10 + 90_000 * 10);
        // Bad values change nothing.
        let before = m.ario_timing.clone();
        for r in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert_eq!(
                m.ario_timing.set_update_rate(0, r),
                Err(McclError::Parameter)
            );
        }
        assert_eq!(
            m.ario_timing.set_update_rate(2, 1.0),
            Err(McclError::Parameter)
        );
        assert_eq!(m.ario_timing.set_divider(0, 0), Err(McclError::Parameter));
        assert_eq!(m.ario_timing, before);
        // A cycle longer than the longest time (2^32 − 1 ms) is refused: 1000 / 2.3e-7 ms
        // = 4.35e9 ms; 2.33e-7 Hz (4.29e9 ms) is the slowest whole-digit rate accepted.
        for r in [f64::MIN_POSITIVE, 2.3e-7] {
            assert_eq!(
                m.ario_timing.set_update_rate(0, r),
                Err(McclError::Parameter)
            );
        }
        assert_eq!(m.ario_timing, before);
        m.ario_timing.set_update_rate(0, 2.33e-7).unwrap();
        // A very fast rate saturates at a period of 1 ns (ario_timing's test).
        m.ario_timing.set_update_rate(0, 1e300).unwrap();
        assert!(ario_transfer_ticks(&mut m, 1).is_empty(), "bus-bound 5 ms");
    }
}
