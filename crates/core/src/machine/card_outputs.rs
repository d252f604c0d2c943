//! What a card's LED and servo-on outputs show: the program's setting, unless a
//! trigger-out holds the point.

use super::Machine;

impl Machine {
    /// What LED `ch` of card `cd` shows: its trigger-out value while a trigger holds it,
    /// else what `MCC_SetLedLightOn`/`Off` set.
    pub fn led_lit(&self, cd: usize, ch: usize) -> bool {
        let own = self.settings.get(cd).is_some_and(|s| s.leds >> ch & 1 == 1);
        self.triggers
            .get(cd)
            .and_then(|t| t.led_trig_level(ch))
            .unwrap_or(own)
    }

    /// The servo-on output of channel `ch` of card `cd` (`servo_on`: the card's servo-on
    /// bits, bit n channel n): while a trigger-out holds the point, its trigger value
    /// (1 = servo off) overrides it.
    pub fn servo_output(&self, cd: usize, ch: usize, servo_on: u32) -> bool {
        match self.triggers.get(cd).and_then(|t| t.trig_level(ch)) {
            Some(off) => !off,
            None => servo_on >> ch & 1 == 1,
        }
    }
}
