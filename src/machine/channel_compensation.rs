//! Gap compensation on the channels: a channel's tables and the pulses they add to its
//! output, and the machine's note of whether any channel compensates.

use super::compensation::Compensation;
use super::{Channel, Machine};
use crate::config::AXES;
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

    /// New compensation tables (`MCC_UpdateCompParam`).
    pub fn set_compensation(&mut self, p: &SYS_COMP_PARAM) {
        self.resting = false;
        *self.comp_param = *p;
        self.comp = Compensation::new(p);
        self.refresh_ideal();
    }
}

impl Machine {
    /// `MCC_UpdateCompParam`: every channel with a compensation table set in `comp`
    /// (per card, per channel) takes it; the others keep theirs.
    pub fn apply_compensation(&mut self, comp: &[[Option<SYS_COMP_PARAM>; AXES]]) {
        for (chans, tables) in self.cards.iter_mut().zip(comp) {
            for (chan, p) in chans.iter_mut().zip(tables) {
                if let Some(p) = p {
                    chan.set_compensation(p);
                }
            }
        }
        self.compensating = self.cards.iter().flatten().any(|c| c.comp.active());
    }

    /// Whether a channel compensates (`MCC_UpdateCompParam`).
    pub fn compensating(&self) -> bool {
        self.compensating
    }
}
