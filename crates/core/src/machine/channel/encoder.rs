//! A channel's encoder: the count that follows the motor, its input rate, gear rate and
//! direction, and setting the count.

use crate::config::encoder_multiplier;
use crate::machine::Channel;
use crate::vendor::consts as c;

impl Channel {
    fn multiplier(&self) -> f64 {
        if self.enc.wType == c::ENC_TYPE_NO {
            return 0.0;
        }
        let rate = self.input_rate.unwrap_or(self.enc.wInputRate);
        f64::from(encoder_multiplier(rate)) / 4.0
    }

    fn raw_count(&self) -> i64 {
        let dir = if (self.enc.wABSwap == 1) ^ (self.enc.wAInverse == 1) ^ (self.enc.wBInverse == 1)
        {
            -1.0
        } else {
            1.0
        };
        ((self.actual + self.base) * self.multiplier() * self.gear_rate * dir).round() as i64
    }

    /// The encoder count the motor would show at `pulses` (motor pulses since the counter
    /// was last zeroed): what a latch captures at an index pulse.
    pub fn count_at(&self, pulses: i64) -> i64 {
        let dir = if (self.enc.wABSwap == 1) ^ (self.enc.wAInverse == 1) ^ (self.enc.wBInverse == 1)
        {
            -1.0
        } else {
            1.0
        };
        ((pulses as f64) * self.multiplier() * self.gear_rate * dir).round() as i64
            + self.enc_offset
    }

    /// The encoder count (`MCC_GetENCValue`).
    pub fn encoder(&self) -> i64 {
        self.assert_up_to_date();
        self.raw_count() + self.enc_offset
    }

    /// `MCC_SetENCValue`: the count becomes `v` here.
    pub fn set_encoder(&mut self, v: i64) {
        self.enc_offset = v - self.raw_count();
    }

    /// `MCC_SetENCInputRate`: counts per encoder cycle (1, 2 or 4; 3 also means x4);
    /// the count keeps its value at the change.
    pub fn set_input_rate(&mut self, rate: u16) {
        let v = self.encoder();
        self.input_rate = Some(rate);
        self.set_encoder(v);
    }

    /// `MCC_SetENCGearRate`: counts per motor pulse at x4; the count keeps its value at
    /// the change.
    pub fn set_gear_rate(&mut self, r: f64) {
        let v = self.encoder();
        self.gear_rate = r;
        self.set_encoder(v);
    }
}
