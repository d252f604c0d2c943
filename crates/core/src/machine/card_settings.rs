//! The card settings the simulation keeps and reports: loop gains, gain clock dividers,
//! LEDs, input filter clocks, error counter thresholds.

use crate::config::AXES;
use crate::error::McclResult;

/// Card settings that the simulation keeps and reports (user manual §2.7.1, §2.9).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct CardSettings {
    /// P, I, D and feed-forward gains per channel (0..255).
    pub gains: [[u16; AXES]; 4],
    /// I and D gain clock dividers.
    pub dividers: [u32; 2],
    /// LED outputs, one bit per channel.
    pub leds: u8,
    /// Limit, home, GPIO and encoder input filter clocks (kept: the simulated inputs
    /// neither bounce nor pick up noise).
    pub filters: [u16; 4],
    /// Closed-loop error counter thresholds (+, −) per channel.
    pub error_threshold: [(u16, u16); AXES],
}

/// A loop gain of a card's channels (index in [`CardSettings::gains`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Gain {
    /// Proportional (`MCC_SetPGain`).
    P = 0,
    /// Integral (`MCC_SetIGain`).
    I = 1,
    /// Derivative (`MCC_SetDGain`).
    D = 2,
    /// Feed-forward (`MCC_SetFGain`).
    FeedForward = 3,
}

/// One gain for each of a card's 8 channels, each 0..255.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Gains([u16; AXES]);

impl Gains {
    /// The gains `v` (`PARAMETER_ERR` when one is above 255).
    pub fn new(v: [u16; AXES]) -> McclResult<Gains> {
        if v.iter().any(|&g| g > 255) {
            return Err(crate::error::McclError::Parameter);
        }
        Ok(Gains(v))
    }
}

/// An input filter clock of a card (index in [`CardSettings::filters`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FilterClock {
    /// The limit switch inputs (`MCC_SetLimitFilterClk`).
    Limit = 0,
    /// The home sensor inputs (`MCC_SetHomeFilterClk`).
    Home = 1,
    /// The general-purpose inputs (`MCC_SetGpioFilterClk`).
    Gpio = 2,
    /// The encoder inputs (`MCC_SetENCFilterClock`).
    Encoder = 3,
}

impl CardSettings {
    /// Keeps gain `k` of every channel (kept and reported: the simulated plant is set by
    /// the configuration).
    pub fn set_gains(&mut self, k: Gain, g: Gains) {
        self.gains[k as usize] = g.0;
    }

    /// Gain `k` of every channel.
    pub fn gains(&self, k: Gain) -> [u16; AXES] {
        self.gains[k as usize]
    }

    /// Keeps filter clock `k` (any value: the manuals give no range).
    pub fn set_filter_clock(&mut self, k: FilterClock, value: u16) {
        self.filters[k as usize] = value;
    }

    /// Sets gain clock divider `k` (0: I, 1: D).
    pub fn set_divider(&mut self, k: usize, v: u32) {
        self.dividers[k] = v;
    }

    /// Sets the error counter thresholds (+, −) of channel `ch`.
    pub fn set_error_threshold(&mut self, ch: usize, plus: u16, minus: u16) {
        self.error_threshold[ch] = (plus, minus);
    }

    /// Sets the LED output of channel `ch` (0..7) on or off.
    pub fn set_led(&mut self, ch: usize, on: bool) {
        let bit = 1u8 << ch;
        if on {
            self.leds |= bit;
        } else {
            self.leds &= !bit;
        }
    }
}
