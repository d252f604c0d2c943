//! Remote I/O (user manual §2.14; examples manual §33–34; INTERFACE.md §2.7).
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
//! Transfer happens once per tick: a transmitting slave takes the master's outputs and
//! the master latches the slave's inputs. A simulated slave's inputs loop back from its
//! outputs unless set otherwise from Rust ([`RioInput`]); a slave or master can be made
//! to fail ([`Master::set_slave_failed`], [`Master::set_master_failed`]): a failed slave
//! stops transferring, and the status functions report it.

use crate::engine::isr::{Interrupt, Pending};
use crate::error::{McclError, McclResult};
use crate::vendor::consts as c;

/// Sets per master.
pub const SETS: usize = 2;
/// RIO ports (= slaves) per set.
pub const RIO_PORTS: usize = 4;
/// ARIO slaves per set.
pub const ARIO_SLAVES: usize = 32;
/// RIO digital inputs with a trigger.
pub const DIS: usize = 8;

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
    /// Set-level control (RIO only; ARIO sets are always on).
    pub control: bool,
    slave_on: u32,
    outputs: [u16; N],
    inputs: [u16; N],
    /// What each slave's inputs read.
    pub source: [RioInput; N],
    slave_fail: u32,
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
            slave_fail: 0,
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

    /// Slave control on or off (`MCC_Enable/Disable(A)RIOSlaveControl`).
    pub fn set_slave_control(&mut self, s: u16, on: bool) -> McclResult<()> {
        let bit = 1u32 << Self::slave(s)?;
        if on {
            self.slave_on |= bit;
        } else {
            self.slave_on &= !bit;
        }
        Ok(())
    }

    /// Outputs of a port/slave (`MCC_Set(A)RIOOutputValue`).
    pub fn set_output(&mut self, s: u16, v: u16) -> McclResult<()> {
        self.outputs[Self::slave(s)?] = v;
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

    /// Failed slaves among the transmitting ones, bit n = slave n.
    pub fn slave_fail(&self) -> u32 {
        self.slave_fail & self.slave_on
    }

    /// 1 when the master works, 0 on a master error.
    pub fn master_status(&self) -> u16 {
        u16::from(!self.master_fail)
    }

    /// 1 when every transmitting slave works, 0 when one failed.
    pub fn slave_status(&self) -> u16 {
        u16::from(self.slave_fail() == 0)
    }

    /// 1 while data moves without error, 0 on a master or slave error.
    pub fn trans_status(&self) -> u16 {
        self.master_status() & self.slave_status()
    }

    /// Simulation: slave `s` fails (or works again).
    pub fn set_slave_failed(&mut self, s: usize, failed: bool) {
        if s < N {
            if failed {
                self.slave_fail |= 1 << s;
            } else {
                self.slave_fail &= !(1 << s);
            }
        }
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

    /// One transfer; raises input edges and transmission failures.
    fn tick(&mut self, p: &mut Pending) {
        if !self.control {
            return;
        }
        let ok = self.trans_status() == 1;
        if self.trans_trigger && self.was_ok && !ok {
            p.raise(Interrupt::RioFail);
        }
        self.was_ok = ok;
        if self.master_fail {
            return;
        }
        for s in 0..N {
            if self.slave_on & !self.slave_fail & (1 << s) != 0 {
                self.inputs[s] = match self.source[s] {
                    RioInput::Loopback => self.outputs[s],
                    RioInput::Constant(v) => v,
                };
            }
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

/// The remote I/O of one card: RIO and ARIO masters, two sets each.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Master {
    /// RIO sets.
    pub rio: [Set<RIO_PORTS>; SETS],
    /// ARIO sets.
    pub ario: [Set<ARIO_SLAVES>; SETS],
}

impl Default for Master {
    fn default() -> Master {
        Master {
            rio: std::array::from_fn(|_| Set::new(false)),
            ario: std::array::from_fn(|_| Set::new(true)),
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

impl Master {
    /// One tick of transfers of every set.
    pub fn tick(&mut self, p: &mut Pending) {
        self.rio.iter_mut().for_each(|s| s.tick(p));
        self.ario.iter_mut().for_each(|s| s.tick(p));
    }

    /// Watchdog reset: every output to 0.
    pub fn reset_outputs(&mut self) {
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

    fn step(m: &mut Master) -> Pending {
        let mut p = Pending::default();
        m.tick(&mut p);
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
        m.rio[1].control = true;
        assert_eq!(m.rio[1].input(2), Ok(0), "not before the tick");
        step(&mut m);
        assert_eq!(m.rio[1].input(2), Ok(0xBEEF));

        let a = &mut m.ario[0];
        a.set_output(31, 0x1234).unwrap();
        a.set_slave_control(31, true).unwrap();
        a.source[31] = RioInput::Constant(0x00F0);
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
        assert_eq!(m.rio[0].slave_fail(), 1);
        assert_eq!((m.rio[0].trans_status(), m.rio[0].slave_status()), (0, 0));
        assert_eq!(step(&mut m).rio[8], 1, "FAIL once");
        assert_eq!(step(&mut m).rio[8], 0);
        m.set_slave_failed(false, 0, 0, false);
        m.set_master_failed(false, 0, true);
        assert_eq!(m.rio[0].master_status(), 0);
        assert_eq!(m.rio[0].slave_status(), 1);
        assert_eq!(step(&mut m).rio[8], 0, "still failing: no new edge");
    }
}
