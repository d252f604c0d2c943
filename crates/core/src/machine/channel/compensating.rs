//! A channel's gap compensation ([`GapCompensation`]): its tables and the pulses they
//! add to its output.

use crate::machine::compensation::{self, Compensation};
use crate::machine::Channel;
use crate::vendor::SYS_COMP_PARAM;

/// A channel's gap compensation: the tables in effect, with the direction and command
/// they last followed, and the tables as last set, from which they start again at every
/// counter restart.
#[derive(Debug, Clone)]
pub(super) struct GapCompensation {
    /// Compensation tables in effect.
    state: Compensation,
    /// The tables last set (boxed: 2 KiB that only a restart reads, kept out of the way
    /// of the fields every step uses).
    tables: Box<SYS_COMP_PARAM>,
}

impl GapCompensation {
    /// No compensation.
    pub(super) fn off() -> GapCompensation {
        GapCompensation {
            state: Compensation::default(),
            tables: Box::new(compensation::off()),
        }
    }

    /// Whether compensation is on.
    #[inline(always)]
    pub(super) fn active(&self) -> bool {
        self.state.active()
    }

    /// The correction (pulses) to add to command `cmd`; the tables follow its direction.
    #[inline]
    pub(super) fn offset(&mut self, cmd: i64) -> i64 {
        self.state.offset(cmd)
    }

    /// The tables start again from their home point.
    pub(super) fn restart(&mut self) {
        self.state = Compensation::new(&self.tables);
    }

    /// New tables, in effect from their home point.
    pub(super) fn set(&mut self, p: &SYS_COMP_PARAM) {
        *self.tables = *p;
        self.state = Compensation::new(p);
    }
}

impl Channel {
    /// The compensation pulses added to the command set this tick (0 without
    /// compensation), as the next step adds them.
    pub fn compensation_now(&mut self) -> i32 {
        if self.comp.active() {
            let c = self.comp.offset(self.step.next());
            c.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
        } else {
            0
        }
    }

    /// Whether the channel compensates.
    pub(in crate::machine) fn compensates(&self) -> bool {
        self.comp.active()
    }

    /// New compensation tables (`MCC_UpdateCompParam`).
    pub fn set_compensation(&mut self, p: &SYS_COMP_PARAM) {
        self.step.wake();
        self.comp.set(p);
        self.refresh_ideal();
    }
}
