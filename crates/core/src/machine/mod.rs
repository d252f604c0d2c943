//! The simulated machine behind the virtual card's channels: what each motor does with
//! the pulses it is sent (an ideal plant, or a first-order lag that makes tracking
//! error), the encoder that follows it, the home sensor and limit switches it passes, the
//! encoder index pulses, gap compensation (user manual §2.7.5) and the emergency-stop
//! input. Positions of sensors are in the axis's user units measured from where the
//! motor was at `MCC_InitSystem` (machine coordinates).

mod card_outputs;
mod card_settings;
pub mod catch_up;
mod channel;
mod channel_compensation;
pub mod compensation;
pub mod deferred;
mod index_pulses;
mod pulse_limits;
mod sensors;
#[cfg(test)]
mod tests;
pub mod triggers;

use crate::config::AXES;
use crate::vendor::SYS_ENCODER_CONFIG;
pub use card_settings::{CardSettings, FilterClock, Gain, Gains};
pub use channel::{Channel, ChannelSpec};
pub use pulse_limits::{PulseLimit, DEFAULT_PULSE_LIMIT, MAX_PULSE_LIMIT};
pub use sensors::{Sensor, SensorLevels};

/// Every card's channels and emergency-stop input.
#[derive(Debug, Clone)]
pub struct Machine {
    /// Channels per card.
    pub(crate) cards: Vec<[Channel; AXES]>,
    /// Emergency-stop input per card (true: pressed).
    pub(crate) emergency: Vec<bool>,
    /// Per-card settings.
    pub(crate) settings: Vec<CardSettings>,
    /// Per-card encoder compare, latch, index, local-input and trigger-out state.
    pub(crate) triggers: Vec<triggers::CardTriggers>,
    /// Some channel's pulse speed or acceleration limit is below the default.
    pub(crate) pulse_limits_set: bool,
    /// Some channel compensates ([`Machine::apply_compensation`]).
    compensating: bool,
    /// The steps channels defer, while some may ([`deferred`]).
    deferred: Option<deferred::DeferredSteps>,
    /// The channels known to record their deferred steps ([`deferred::Recording`]).
    recording: deferred::Recording,
}

impl Machine {
    /// Every card's channels.
    #[inline]
    pub fn cards(&self) -> &[[Channel; AXES]] {
        &self.cards
    }

    /// Every card's channels, to command and step them (each keeps its own state).
    #[inline]
    pub fn cards_mut(&mut self) -> &mut [[Channel; AXES]] {
        &mut self.cards
    }

    /// Each card's channels and triggers, and its settings: what a tick steps and checks.
    #[inline]
    pub fn cards_triggers_settings(
        &mut self,
    ) -> impl Iterator<
        Item = (
            &mut [Channel; AXES],
            &mut triggers::CardTriggers,
            &CardSettings,
        ),
    > {
        self.cards
            .iter_mut()
            .zip(self.triggers.iter_mut())
            .zip(&self.settings)
            .map(|((c, t), s)| (c, t, s))
    }

    /// Each card's triggers and settings.
    pub fn triggers_and_settings(
        &self,
    ) -> impl Iterator<Item = (&triggers::CardTriggers, &CardSettings)> {
        self.triggers.iter().zip(&self.settings)
    }

    /// Card `cd`'s triggers (compares, latches, index, local inputs, trigger-out).
    pub fn triggers(&self, cd: usize) -> &triggers::CardTriggers {
        &self.triggers[cd]
    }

    /// Card `cd`'s triggers, to change.
    pub fn triggers_mut(&mut self, cd: usize) -> &mut triggers::CardTriggers {
        &mut self.triggers[cd]
    }

    /// Card `cd`'s triggers and channels, together.
    pub fn triggers_and_channels_mut(
        &mut self,
        cd: usize,
    ) -> (&mut triggers::CardTriggers, &[Channel; AXES]) {
        (&mut self.triggers[cd], &self.cards[cd])
    }

    /// Card `cd`'s settings (gains, dividers, LEDs, filters, error thresholds).
    pub fn card_settings(&self, cd: usize) -> &CardSettings {
        &self.settings[cd]
    }

    /// Card `cd`'s settings, to change.
    pub fn card_settings_mut(&mut self, cd: usize) -> &mut CardSettings {
        &mut self.settings[cd]
    }

    /// Whether card `cd`'s emergency-stop input is pressed (false for an unknown card).
    pub fn emergency(&self, cd: usize) -> bool {
        self.emergency.get(cd).copied().unwrap_or(false)
    }

    /// Whether any card's emergency-stop input is pressed.
    pub fn any_emergency(&self) -> bool {
        self.emergency.iter().any(|&e| e)
    }

    /// Whether some channel's pulse speed or acceleration limit is below the default.
    pub fn pulse_limits_set(&self) -> bool {
        self.pulse_limits_set
    }

    /// Presses (`on`) or releases the emergency-stop input of card `cd`.
    pub fn set_emergency(&mut self, cd: usize, on: bool) {
        if let Some(e) = self.emergency.get_mut(cd) {
            *e = on;
        }
    }

    /// A machine for `n` cards from the parameters in effect and the specs.
    pub fn new(
        mac: &crate::config::MacTable,
        enc: &[[SYS_ENCODER_CONFIG; AXES]; crate::config::CARDS],
        specs: impl Fn(usize, usize) -> ChannelSpec,
        emergency: impl Fn(usize) -> bool,
        n: usize,
    ) -> Machine {
        Machine {
            cards: (0..n)
                .map(|c| {
                    std::array::from_fn(|ch| Channel::new(specs(c, ch), mac[c][ch], enc[c][ch]))
                })
                .collect(),
            emergency: (0..n).map(emergency).collect(),
            settings: vec![CardSettings::default(); n],
            triggers: vec![triggers::CardTriggers::default(); n],
            pulse_limits_set: false,
            compensating: false,
            deferred: None,
            recording: deferred::Recording::default(),
        }
    }

    /// Channel `ch` of card `card`.
    pub fn channel(&self, card: usize, ch: usize) -> Option<&Channel> {
        self.cards.get(card).and_then(|c| c.get(ch))
    }

    /// Channel `ch` of card `card`.
    pub fn channel_mut(&mut self, card: usize, ch: usize) -> Option<&mut Channel> {
        self.cards.get_mut(card).and_then(|c| c.get_mut(ch))
    }
}
