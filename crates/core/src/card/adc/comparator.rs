//! The A/D converter's comparators, one per channel (user manual §2.12; examples manual
//! §38): each compares a channel's conversions with its compare value on the 12-bit code
//! of the channel's range and reports the crossings its type asks for.
//!
//! `ADC_COMP_RISE` fires when the input goes from below the compare value to at or above
//! it between two conversions, `ADC_COMP_FALL` the other way, `ADC_COMP_LEVEL` both;
//! `MCC_SetADCCompMask(n)` ignores the n lowest bits of both codes. The first conversion
//! after the compare value, type, mask or the channel's range changed only sets the
//! reference (the crossing is between two conversions compared alike).

use super::{range, BITS};
use crate::config::AXES;
use crate::error::{McclError, McclResult};
use crate::vendor::consts as c;

/// The 12-bit code of `v` in the range of conversion type `conv_type` (the ends for a
/// value outside it).
fn code(v: f32, conv_type: u16) -> u32 {
    let (lo, hi) = range(conv_type);
    let max = (1u32 << BITS) - 1;
    let x = ((v.clamp(lo, hi) - lo) / (hi - lo) * max as f32).round();
    (x as u32).min(max)
}

/// The comparators of the eight channels, and where each conversion stood last.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparator {
    /// Compare value per channel, V.
    value: [f32; AXES],
    /// `ADC_COMP_RISE`, `_FALL` or `_LEVEL` per channel.
    kind: [u16; AXES],
    /// Per channel: a crossing raises `COMPn` (`MCC_EnableADCCompTrigger`).
    trigger: [bool; AXES],
    /// Low bits of both codes ignored (`ADC_MASK_NO`..`ADC_MASK_BIT3`), every channel.
    mask: u16,
    /// Whether the last conversion was at or above the compare value (None: no reference).
    above: [Option<bool>; AXES],
}

impl Default for Comparator {
    fn default() -> Comparator {
        Comparator {
            value: [0.0; AXES],
            kind: [c::ADC_COMP_RISE; AXES],
            trigger: [false; AXES],
            mask: c::ADC_MASK_NO,
            above: [None; AXES],
        }
    }
}

impl Comparator {
    /// `MCC_SetADCCompValue` (finite, −10..10 V; else `PARAMETER_ERR` and nothing changes).
    pub fn set_value(&mut self, ch: usize, v: f32) -> McclResult<()> {
        crate::card::dac::check_voltage(v)?;
        self.value[ch] = v;
        self.above[ch] = None;
        Ok(())
    }

    /// `MCC_GetADCCompValue`.
    pub fn value(&self, ch: usize) -> f32 {
        self.value[ch]
    }

    /// `MCC_SetADCCompType`: `ADC_COMP_RISE`, `_FALL` or `_LEVEL`.
    pub fn set_kind(&mut self, ch: usize, t: u16) -> McclResult<()> {
        if t > c::ADC_COMP_LEVEL {
            return Err(McclError::Parameter);
        }
        self.kind[ch] = t;
        self.above[ch] = None;
        Ok(())
    }

    /// `MCC_SetADCCompMask`: `ADC_MASK_NO`..`ADC_MASK_BIT3`.
    pub fn set_mask(&mut self, m: u16) -> McclResult<()> {
        if m > c::ADC_MASK_BIT3 {
            return Err(McclError::Parameter);
        }
        self.mask = m;
        self.above = [None; AXES];
        Ok(())
    }

    /// `MCC_EnableADCCompTrigger` / `MCC_DisableADCCompTrigger`.
    pub fn set_trigger(&mut self, ch: usize, on: bool) {
        self.trigger[ch] = on;
    }

    /// Channel `ch`'s range changed: its next conversion only sets the reference (codes
    /// of two ranges do not compare).
    pub(super) fn forget(&mut self, ch: usize) {
        self.above[ch] = None;
    }

    /// Channel `ch` converted `v` in the range of `conv_type`: records where it stands
    /// and returns whether `COMPn` is raised (a crossing of its type, trigger on).
    pub(super) fn compare(&mut self, ch: usize, v: f32, conv_type: u16) -> bool {
        let m = u32::from(self.mask);
        let above = code(v, conv_type) >> m >= code(self.value[ch], conv_type) >> m;
        let fire = self.above[ch].is_some_and(|was| match self.kind[ch] {
            c::ADC_COMP_RISE => !was && above,
            c::ADC_COMP_FALL => was && !above,
            _ => was != above,
        });
        self.above[ch] = Some(above);
        fire && self.trigger[ch]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_crossing_needs_a_reference_and_the_trigger() {
        let mut k = Comparator::default();
        k.set_value(0, 2.0).unwrap();
        let bip = c::ADC_TYPE_BIP_DIFF;
        // Trigger off: the crossing is recorded, not raised.
        assert!(!k.compare(0, 1.0, bip));
        assert!(!k.compare(0, 3.0, bip));
        k.set_trigger(0, true);
        // Rising (the default): 3 V -> 1 V falls, 1 V -> 3 V rises.
        assert!(!k.compare(0, 1.0, bip));
        assert!(k.compare(0, 3.0, bip));
        // Falling; its first conversion is the reference.
        k.set_kind(0, c::ADC_COMP_FALL).unwrap();
        assert!(!k.compare(0, 3.0, bip));
        assert!(k.compare(0, 1.0, bip));
        assert!(!k.compare(0, 3.0, bip));
        // A new range forgets where the channel stood (3 V, above): 1 V is only the new
        // reference, not a fall; the fall from 3 V is.
        k.forget(0);
        let uni = c::ADC_TYPE_UNI_DIFF;
        assert!(!k.compare(0, 1.0, uni));
        assert!(!k.compare(0, 3.0, uni));
        assert!(k.compare(0, 1.0, uni));
        // Other channels are untouched: channel 1 (compare value 0 V) has no reference.
        assert!(!k.compare(1, 1.0, bip));
        // Refused settings change nothing.
        let before = k.clone();
        assert_eq!(k.set_value(0, f32::NAN), Err(McclError::Parameter));
        assert_eq!(k.set_value(0, 10.5), Err(McclError::Parameter));
        assert_eq!(k.set_kind(0, 3), Err(McclError::Parameter));
        assert_eq!(k.set_mask(4), Err(McclError::Parameter));
        assert_eq!(k, before);
    }
}
