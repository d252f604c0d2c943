//! A channel's encoder ([`Encoder`]): the count that follows the motor, its input rate,
//! gear rate and direction, and setting the count.

use crate::config::encoder_multiplier;
use crate::machine::Channel;
use crate::vendor::consts as c;
use crate::vendor::SYS_ENCODER_CONFIG;

/// A channel's encoder: its configuration, the rates the program set over it, and the
/// offset that makes the count read what the program set it to.
///
/// Positions here are motor positions in pulses; the count follows the motor in the
/// machine frame.
#[derive(Debug, Clone)]
pub(super) struct Encoder {
    /// The encoder configuration (`MCC_SetENCConfig`, `MCC_UpdateParam`).
    config: SYS_ENCODER_CONFIG,
    /// Encoder input rate set by `MCC_SetENCInputRate` (overrides the configuration).
    input_rate: Option<u16>,
    /// `MCC_SetENCGearRate`.
    gear_rate: f64,
    /// Encoder count = raw count + `offset`.
    offset: i64,
}

impl Encoder {
    /// An encoder of `config` that counts 0 at machine pulse 0.
    pub(super) fn new(config: SYS_ENCODER_CONFIG) -> Encoder {
        Encoder {
            config,
            input_rate: None,
            gear_rate: 1.0,
            offset: 0,
        }
    }

    /// Counts per motor pulse, before the gear rate and the direction.
    fn multiplier(&self) -> f64 {
        if self.config.wType == c::ENC_TYPE_NO {
            return 0.0;
        }
        let rate = self.input_rate.unwrap_or(self.config.wInputRate);
        f64::from(encoder_multiplier(rate)) / 4.0
    }

    /// -1 when the wiring (A/B swapped, A or B inverted) reverses the count, else 1.
    fn direction(&self) -> f64 {
        let c = &self.config;
        if (c.wABSwap == 1) ^ (c.wAInverse == 1) ^ (c.wBInverse == 1) {
            -1.0
        } else {
            1.0
        }
    }

    /// The count of a motor at `motor` pulses of the machine frame, without the offset.
    fn raw_count(&self, motor: f64) -> i64 {
        (motor * self.multiplier() * self.gear_rate * self.direction()).round() as i64
    }

    /// The count a motor `pulses` from where the command counter was last zeroed would
    /// show.
    pub(super) fn count_at(&self, pulses: i64) -> i64 {
        ((pulses as f64) * self.multiplier() * self.gear_rate * self.direction()).round() as i64
            + self.offset
    }

    /// The count of a motor at `motor` pulses of the machine frame.
    pub(super) fn count(&self, motor: f64) -> i64 {
        self.raw_count(motor) + self.offset
    }

    /// The count of a motor at `motor` pulses of the machine frame becomes `v`.
    pub(super) fn set(&mut self, v: i64, motor: f64) {
        self.offset = v - self.raw_count(motor);
    }

    /// A new configuration, which drops the input rate the program set; the count of a
    /// motor at `motor` keeps its value.
    pub(super) fn configure(&mut self, config: SYS_ENCODER_CONFIG, motor: f64) {
        let v = self.count(motor);
        self.config = config;
        self.input_rate = None;
        self.set(v, motor);
    }

    /// Counts per encoder cycle; the count of a motor at `motor` keeps its value.
    pub(super) fn set_input_rate(&mut self, rate: u16, motor: f64) {
        let v = self.count(motor);
        self.input_rate = Some(rate);
        self.set(v, motor);
    }

    /// Counts per motor pulse at x4; the count of a motor at `motor` keeps its value.
    pub(super) fn set_gear_rate(&mut self, r: f64, motor: f64) {
        let v = self.count(motor);
        self.gear_rate = r;
        self.set(v, motor);
    }
}

impl Channel {
    /// The encoder count the motor would show at `pulses` (motor pulses since the counter
    /// was last zeroed): what a latch captures at an index pulse.
    pub fn count_at(&self, pulses: i64) -> i64 {
        self.encoder.count_at(pulses)
    }

    /// The encoder count (`MCC_GetENCValue`).
    pub fn encoder(&self) -> i64 {
        self.assert_up_to_date();
        self.encoder.count(self.step.machine_pulses())
    }

    /// `MCC_SetENCValue`: the count becomes `v` here.
    pub fn set_encoder(&mut self, v: i64) {
        self.encoder.set(v, self.step.machine_pulses());
    }

    /// `MCC_SetENCInputRate`: counts per encoder cycle (1, 2 or 4; 3 also means x4);
    /// the count keeps its value at the change.
    pub fn set_input_rate(&mut self, rate: u16) {
        self.assert_up_to_date();
        self.encoder
            .set_input_rate(rate, self.step.machine_pulses());
    }

    /// `MCC_SetENCGearRate`: counts per motor pulse at x4; the count keeps its value at
    /// the change.
    pub fn set_gear_rate(&mut self, r: f64) {
        self.assert_up_to_date();
        self.encoder.set_gear_rate(r, self.step.machine_pulses());
    }
}
