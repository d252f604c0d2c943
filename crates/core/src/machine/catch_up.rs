//! Bringing deferred channels up to date (`deferred.rs`): one card's channels, and the
//! machine's record of which steps its channels deferred and which record.

use crate::config::AXES;
use crate::machine::deferred::{DeferredSteps, Recording};
use crate::machine::triggers::CardTriggers;
use crate::machine::{Channel, Machine};

/// [`Machine::catch_up`] of one card's channels.
pub fn catch_up_card(
    chans: &mut [Channel; AXES],
    triggers: &mut CardTriggers,
    steps: DeferredSteps,
) {
    for (ch, chan) in chans.iter_mut().enumerate() {
        if chan.catch_up(steps) {
            triggers.note_index(ch);
        }
    }
}

impl Machine {
    /// Notes whether channels of the machine defer `steps` after this tick (`None`:
    /// every channel is up to date), and which of them [record](Recording).
    pub fn set_deferred(&mut self, steps: Option<DeferredSteps>, recording: Recording) {
        // The slots hold the last three outputs only for consecutive steps.
        if let (Some(before), Some(now)) = (self.deferred, steps) {
            debug_assert_eq!(
                before.last.wrapping_add(1),
                now.last,
                "steps not consecutive"
            );
        }
        self.deferred = steps;
        self.recording = if steps.is_some() {
            recording
        } else {
            Recording::default()
        };
    }

    /// Brings every channel with deferred steps up to date; the index status of a channel
    /// whose deferred steps passed an index pulse latches. Nothing to do (one check) when
    /// no channel defers.
    #[inline]
    pub fn catch_up(&mut self) {
        if let Some(steps) = self.deferred.take() {
            self.recording = Recording::default();
            self.catch_up_all(steps);
        }
    }

    #[inline(never)]
    fn catch_up_all(&mut self, steps: DeferredSteps) {
        for (chans, triggers) in self.cards.iter_mut().zip(self.triggers.iter_mut()) {
            catch_up_card(chans, triggers, steps);
        }
    }

    /// The steps deferred, when some channel defers.
    pub fn deferred(&self) -> Option<DeferredSteps> {
        self.deferred
    }

    /// The channels that recorded a deferred step at the last tick ([`Recording`]).
    pub fn recording(&self) -> Recording {
        self.recording
    }
}
