//! The channels' pulse speed and acceleration limits (user manual §2.7.3).

use super::Machine;
use crate::config::AXES;

/// Default and largest pulse speed and acceleration limits (ZH manual §2.6.4).
pub const MAX_PULSE_LIMIT: i32 = i32::MAX;

/// The pulse limits before `MCC_SetMaxPulseSpeed`/`MCC_SetMaxPulseAcc`: 1,000,000, as the
/// vendor's library reads right after init.
pub const DEFAULT_PULSE_LIMIT: i32 = 1_000_000;

/// Which pulse limit of the channels (user manual §2.7.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PulseLimit {
    /// Most pulses per interpolation period (`MCC_SetMaxPulseSpeed`).
    Speed,
    /// Most change of pulses from one period to the next (`MCC_SetMaxPulseAcc`).
    Acc,
}

impl Machine {
    /// Sets limit `kind` of every channel of card `cd` (each 1..=[`MAX_PULSE_LIMIT`],
    /// checked by the caller) and notes whether any channel's limit is now below the
    /// default, so that the engine checks them.
    pub fn set_pulse_limits(&mut self, cd: usize, kind: PulseLimit, v: [i32; AXES]) {
        for (ch, x) in self.cards[cd].iter_mut().zip(v) {
            ch.set_pulse_limit(kind, x);
        }
        self.pulse_limits_set = self
            .cards
            .iter()
            .flatten()
            .any(|c| c.max_speed() < DEFAULT_PULSE_LIMIT || c.max_acc() < DEFAULT_PULSE_LIMIT);
    }

    /// Limit `kind` of every channel of card `cd`.
    pub fn pulse_limits(&self, cd: usize, kind: PulseLimit) -> [i32; AXES] {
        std::array::from_fn(|ch| match kind {
            PulseLimit::Speed => self.cards[cd][ch].max_speed(),
            PulseLimit::Acc => self.cards[cd][ch].max_acc(),
        })
    }
}
