//! The D/A converter: one output per channel, −10..10 V (user manual §2.11; examples
//! manual §35–36).
//!
//! Conversion runs from `MCC_InitSystem` on; `MCC_StopDACConv` holds every output at
//! 0 V (the set values are kept and appear again at `MCC_StartDACConv`). In trigger mode
//! a channel outputs its preset voltage when one of its sources fires
//! ([`Dac::trigger`], called by the encoder compare of the channel in the source mask).

use crate::config::AXES;
use crate::error::{McclError, McclResult};

/// The output range, V.
pub const RANGE: (f32, f32) = (-10.0, 10.0);

/// The trigger-source bits the IMP card has (`DAC_TRIG_ENC0..7`).
pub const TRIG_SOURCES: u32 = 0xFF;

/// The D/A converter of one card.
#[derive(Debug, Clone, PartialEq)]
pub struct Dac {
    running: bool,
    value: [f32; AXES],
    trig_value: [f32; AXES],
    trig_source: [u32; AXES],
    trig_mode: [bool; AXES],
}

impl Default for Dac {
    fn default() -> Dac {
        Dac {
            running: true,
            value: [0.0; AXES],
            trig_value: [0.0; AXES],
            trig_source: [0; AXES],
            trig_mode: [false; AXES],
        }
    }
}

/// A voltage from C: finite and within −10..10 V.
pub fn check_voltage(v: f32) -> McclResult<f32> {
    if v.is_finite() && (RANGE.0..=RANGE.1).contains(&v) {
        Ok(v)
    } else {
        Err(McclError::Parameter)
    }
}

impl Dac {
    /// `MCC_StartDACConv` / `MCC_StopDACConv`.
    pub fn set_running(&mut self, on: bool) {
        self.running = on;
    }

    /// Whether conversion runs.
    pub fn running(&self) -> bool {
        self.running
    }

    /// `MCC_SetDACOutput` (channel checked by the caller).
    pub fn set_output(&mut self, ch: usize, v: f32) -> McclResult<()> {
        self.value[ch] = check_voltage(v)?;
        Ok(())
    }

    /// The voltage on channel `ch`'s output now (0 V while conversion is stopped).
    pub fn output(&self, ch: usize) -> f32 {
        if self.running {
            self.value[ch]
        } else {
            0.0
        }
    }

    /// The value set for channel `ch` (output while conversion runs).
    pub fn value(&self, ch: usize) -> f32 {
        self.value[ch]
    }

    /// `MCC_SetDACTriggerOutput`.
    pub fn set_trigger_output(&mut self, ch: usize, v: f32) -> McclResult<()> {
        self.trig_value[ch] = check_voltage(v)?;
        Ok(())
    }

    /// `MCC_SetDACTriggerSource`: a mask of `DAC_TRIG_ENC0..7` (0 = none).
    pub fn set_trigger_source(&mut self, ch: usize, mask: u32) -> McclResult<()> {
        if mask & !TRIG_SOURCES != 0 {
            return Err(McclError::Parameter);
        }
        self.trig_source[ch] = mask;
        Ok(())
    }

    /// `MCC_EnableDACTriggerMode` / `MCC_DisableDACTriggerMode`.
    pub fn set_trigger_mode(&mut self, ch: usize, on: bool) {
        self.trig_mode[ch] = on;
    }

    /// The encoder compare of channel `enc` fired: every channel in trigger mode with
    /// `DAC_TRIG_ENC<enc>` in its sources takes its preset voltage.
    pub fn trigger(&mut self, enc: usize) {
        let Some(bit) = u32::try_from(enc).ok().and_then(|e| 1u32.checked_shl(e)) else {
            return;
        };
        for ch in 0..AXES {
            if self.trig_mode[ch] && self.trig_source[ch] & bit != 0 {
                self.value[ch] = self.trig_value[ch];
            }
        }
    }

    /// Watchdog reset: every output to 0 V.
    pub fn reset_outputs(&mut self) {
        self.value = [0.0; AXES];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn output_range_stop_and_trigger() {
        let mut d = Dac::default();
        assert!(d.running());
        d.set_output(1, 2.5).unwrap();
        assert_eq!(d.output(1), 2.5);
        for bad in [10.01, -10.5, f32::NAN, f32::INFINITY] {
            assert_eq!(d.set_output(1, bad), Err(McclError::Parameter));
        }
        assert_eq!(d.value(1), 2.5, "unchanged");
        d.set_running(false);
        assert_eq!(d.output(1), 0.0);
        d.set_running(true);
        assert_eq!(d.output(1), 2.5);

        d.set_trigger_output(0, 2.0).unwrap();
        d.set_trigger_source(0, 0x01 | 0x04).unwrap();
        assert_eq!(d.set_trigger_source(0, 0x100), Err(McclError::Parameter));
        d.trigger(0);
        assert_eq!(d.output(0), 0.0, "trigger mode off");
        d.set_trigger_mode(0, true);
        d.trigger(1);
        assert_eq!(d.output(0), 0.0, "not a source");
        d.trigger(2);
        assert_eq!(d.output(0), 2.0);
        d.trigger(99);
        d.reset_outputs();
        assert_eq!((d.output(0), d.output(1)), (0.0, 0.0));
    }
}
