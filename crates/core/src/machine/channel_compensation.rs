//! Gap compensation on the channels: a channel's tables and the pulses they add to its
//! output, and the machine's note of whether any channel compensates.

use super::{Channel, Machine};
use crate::config::AXES;
use crate::vendor::SYS_COMP_PARAM;

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
        self.compensating = self.cards.iter().flatten().any(Channel::compensates);
    }

    /// Whether a channel compensates (`MCC_UpdateCompParam`).
    pub fn compensating(&self) -> bool {
        self.compensating
    }
}
