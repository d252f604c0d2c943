//! A channel's gap compensation: its tables and the pulses they add to its output.

use crate::machine::compensation::Compensation;
use crate::machine::Channel;
use crate::vendor::SYS_COMP_PARAM;

impl Channel {
    /// The compensation pulses added to the command set this tick (0 without
    /// compensation), as the next step adds them.
    pub fn compensation_now(&mut self) -> i32 {
        if self.comp.active() {
            let c = self.comp.offset(self.next);
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
        self.resting = false;
        *self.comp_param = *p;
        self.comp = Compensation::new(p);
        self.refresh_ideal();
    }
}
