//! The A/D converter: 8 input channels (user manual §2.12; examples manual §37–38).
//!
//! - Conversion type per channel: `ADC_TYPE_BIP_DIFF`/`_BIP_SING` read −5..5 V,
//!   `ADC_TYPE_UNI_DIFF`/`_UNI_SING` read 0..10 V (user manual EN/ZH §2.12.1); an input
//!   outside the range reads as the nearest end. The converter is ideal: the value read is
//!   the input voltage itself (as a float).
//! - `ADC_MODE_FREE` (the default): after `MCC_StartADCConv` every enabled channel converts
//!   once per scan, in the ticks in which a scan ends (at most once per tick: the input
//!   only changes at tick boundaries in the virtual card), until `MCC_StopADCConv`. A scan
//!   takes 16 ADC clocks per enabled channel at `MCC_SetADCClockDivider` system clocks
//!   each (default 50: 8 µs per channel), or one period of `MCC_SetADCUpdateRate` if that
//!   is longer ([`Cadence`]); by default every tick. Scans count from `MCC_StartADCConv`
//!   or the last of these setters. `ADC_MODE_SINGLE`: `MCC_StartADCConv` converts the single channel
//!   once, at once (the card needs ~8 µs, less than any tick), and its interrupts are
//!   delivered after the next tick.
//! - Comparator per channel on the 12-bit code of the channel's range ([`Comparator`]):
//!   rising, falling or both crossings of the compare value between two conversions.
//! - Interrupts: `COMPn` (comparator of channel n, if enabled), `CONV` (a conversion
//!   completed, if the conversion trigger is on), `TAG` (the tagged channel converted).

mod comparator;

pub use comparator::Comparator;

use super::cadence::Cadence;
use crate::config::AXES;
use crate::error::{McclError, McclResult};
use crate::interrupt::{Interrupt, Pending};
use crate::vendor::consts as c;

/// Where an ADC channel's input comes from (set from Rust: configuration, tests).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AdcSource {
    /// The output of DAC channel n of the same card (default: ADC n reads DAC n, as the
    /// examples manual wires DAC 0 to ADC 0).
    Dac(usize),
    /// A constant voltage.
    Constant(f32),
}

/// Resolution of the comparator's codes, bits.
pub const BITS: u32 = 12;

/// The voltage range of a conversion type.
pub fn range(conv_type: u16) -> (f32, f32) {
    match conv_type {
        c::ADC_TYPE_UNI_DIFF | c::ADC_TYPE_UNI_SING => (0.0, 10.0),
        _ => (-5.0, 5.0),
    }
}

/// Serial clocks of one channel's conversion.
pub const CONVERSION_BITS: u64 = 16;

/// ADC clock divider before any `MCC_SetADCClockDivider`: 50, so one channel's
/// conversion takes 16 × 50 × 10 ns = 8 µs and a scan of all eight 64 µs.
pub const DEFAULT_DIVIDER: u16 = 50;

/// The A/D converter of one card: what converts when, the values converted, the
/// interrupts of a conversion, and the channels' [`Comparator`]s.
#[derive(Debug, Clone, PartialEq)]
pub struct Adc {
    /// Conversion type per channel (its range).
    conv_type: [u16; AXES],
    /// `ADC_MODE_FREE` or `ADC_MODE_SINGLE`.
    mode: u16,
    /// Channels that convert in free mode.
    channel_on: [bool; AXES],
    /// Free mode started (`MCC_StartADCConv`) and not stopped.
    running: bool,
    /// The channel single mode converts.
    single: usize,
    /// The last converted value per channel, V.
    input: [f32; AXES],
    /// The comparator of each channel.
    comparator: Comparator,
    /// A completed conversion raises `CONV`.
    conv_trigger: bool,
    /// The tagged channel.
    tag: usize,
    /// A conversion of the tagged channel raises `TAG`.
    tag_trigger: bool,
    /// Where each channel's input comes from.
    source: [AdcSource; AXES],
    /// When free-running scans end (`MCC_SetADCClockDivider`, `MCC_SetADCUpdateRate`).
    cadence: Cadence,
}

impl Default for Adc {
    fn default() -> Adc {
        Adc {
            conv_type: [c::ADC_TYPE_BIP_DIFF; AXES],
            mode: c::ADC_MODE_FREE,
            channel_on: [false; AXES],
            running: false,
            single: 0,
            input: [0.0; AXES],
            comparator: Comparator::default(),
            conv_trigger: false,
            tag: 0,
            tag_trigger: false,
            source: std::array::from_fn(AdcSource::Dac),
            cadence: Cadence::new(DEFAULT_DIVIDER),
        }
    }
}

impl Adc {
    /// `MCC_SetADCConvType` (0..=3).
    pub fn set_conv_type(&mut self, ch: usize, t: u16) -> McclResult<()> {
        if t > c::ADC_TYPE_UNI_SING {
            return Err(McclError::Parameter);
        }
        self.conv_type[ch] = t;
        self.comparator.forget(ch);
        Ok(())
    }

    /// `MCC_GetADCConvType`.
    pub fn conv_type(&self, ch: usize) -> u16 {
        self.conv_type[ch]
    }

    /// `MCC_SetADCConvMode`: `ADC_MODE_SINGLE` or `ADC_MODE_FREE`.
    pub fn set_mode(&mut self, m: u16) -> McclResult<()> {
        if m != c::ADC_MODE_SINGLE && m != c::ADC_MODE_FREE {
            return Err(McclError::Parameter);
        }
        self.mode = m;
        if m == c::ADC_MODE_SINGLE {
            self.running = false;
        }
        Ok(())
    }

    /// `MCC_EnableADCConvChannel` / `MCC_DisableADCConvChannel`.
    pub fn set_channel(&mut self, ch: usize, on: bool) {
        self.channel_on[ch] = on;
    }

    /// `MCC_SetADCSingleChannel`.
    pub fn set_single_channel(&mut self, ch: usize) {
        self.single = ch;
    }

    /// `MCC_GetADCWorkStatus`: 1 while converting (free mode started), else 0.
    pub fn work_status(&self) -> u16 {
        u16::from(self.running)
    }

    /// `MCC_StopADCConv`.
    pub fn stop(&mut self) {
        self.running = false;
    }

    /// `MCC_GetADCInput`: the last converted value of a channel (0 before any).
    pub fn input(&self, ch: usize) -> f32 {
        self.input[ch]
    }

    /// `MCC_SetADCCompValue` (finite, −10..10 V): see [`Comparator::set_value`].
    pub fn set_comp_value(&mut self, ch: usize, v: f32) -> McclResult<()> {
        self.comparator.set_value(ch, v)
    }

    /// `MCC_GetADCCompValue`.
    pub fn comp_value(&self, ch: usize) -> f32 {
        self.comparator.value(ch)
    }

    /// `MCC_SetADCCompType`: `ADC_COMP_RISE`, `_FALL` or `_LEVEL`.
    pub fn set_comp_type(&mut self, ch: usize, t: u16) -> McclResult<()> {
        self.comparator.set_kind(ch, t)
    }

    /// `MCC_SetADCCompMask`: `ADC_MASK_NO`..`ADC_MASK_BIT3`.
    pub fn set_comp_mask(&mut self, m: u16) -> McclResult<()> {
        self.comparator.set_mask(m)
    }

    /// `MCC_EnableADCCompTrigger` / `MCC_DisableADCCompTrigger`.
    pub fn set_comp_trigger(&mut self, ch: usize, on: bool) {
        self.comparator.set_trigger(ch, on);
    }

    /// `MCC_EnableADCConvTrigger` / `MCC_DisableADCConvTrigger`.
    pub fn set_conv_trigger(&mut self, on: bool) {
        self.conv_trigger = on;
    }

    /// Where channel `ch`'s input comes from (the simulated wiring; channel checked by
    /// the caller).
    pub fn set_source(&mut self, ch: usize, src: AdcSource) {
        self.source[ch] = src;
    }

    /// Where channel `ch`'s input comes from.
    pub fn source(&self, ch: usize) -> AdcSource {
        self.source[ch]
    }

    /// `MCC_SetADCClockDivider`: one conversion clock every `divider` system clocks
    /// (1..65535; 0 is `PARAMETER_ERR` and changes nothing), so a free-running scan lasts
    /// `16 × enabled channels × divider × 10 ns`. The scan count restarts.
    pub fn set_clock_divider(&mut self, divider: u16) -> McclResult<()> {
        self.cadence.set_divider(divider)
    }

    /// `MCC_SetADCUpdateRate`: at most `rate` free-running scans per second (checked as
    /// [`super::cadence::update_period_ns`] says; a refused rate changes nothing). The
    /// scan count restarts.
    pub fn set_update_rate(&mut self, rate: f64) -> McclResult<()> {
        self.cadence.set_update_rate(rate)
    }

    /// The scan timing as set (divider and update period).
    pub fn cadence(&self) -> &Cadence {
        &self.cadence
    }

    /// `MCC_SetADCTagChannel`.
    pub fn set_tag_channel(&mut self, ch: usize) {
        self.tag = ch;
    }

    /// `MCC_EnableADCTagTrigger` / `MCC_DisableADCTagTrigger`.
    pub fn set_tag_trigger(&mut self, on: bool) {
        self.tag_trigger = on;
    }

    /// Converts channel `ch` with input `v`: stores the value and raises its comparator.
    fn convert(&mut self, ch: usize, v: f32, p: &mut Pending) {
        let t = self.conv_type[ch];
        let (lo, hi) = range(t);
        let v = if v.is_finite() { v.clamp(lo, hi) } else { lo };
        self.input[ch] = v;
        if self.comparator.compare(ch, v, t) {
            p.raise(Interrupt::AdcComp(ch as u8));
        }
        if self.tag_trigger && self.tag == ch {
            p.raise(Interrupt::AdcTag);
        }
    }

    fn done(&self, p: &mut Pending) {
        if self.conv_trigger {
            p.raise(Interrupt::AdcConv);
        }
    }

    /// `MCC_StartADCConv` with the inputs now: free mode starts converting (from the next
    /// tick); single mode converts the single channel now.
    pub(crate) fn start(&mut self, inputs: &[f32; AXES], p: &mut Pending) {
        if self.mode == c::ADC_MODE_FREE {
            self.running = true;
            self.cadence.restart();
        } else {
            let ch = self.single;
            self.convert(ch, inputs[ch], p);
            self.done(p);
        }
    }

    /// Whether a tick converts anything (free mode started with a channel enabled).
    pub fn converting(&self) -> bool {
        self.running && self.channel_on.iter().any(|&x| x)
    }

    /// Serial bits of one scan: [`CONVERSION_BITS`] per enabled channel.
    pub fn scan_bits(&self) -> u64 {
        CONVERSION_BITS * self.channel_on.iter().filter(|&&on| on).count() as u64
    }

    /// One tick of `dt_ns` of free-running conversion with the inputs at its end: every
    /// enabled channel converts if a scan ended in the tick (at most once per tick).
    pub(crate) fn tick(&mut self, dt_ns: u64, inputs: &[f32; AXES], p: &mut Pending) {
        if !self.converting() {
            return;
        }
        let bits = self.scan_bits();
        if !self.cadence.advance(dt_ns, bits) {
            return;
        }
        for (ch, &v) in inputs.iter().enumerate() {
            if self.channel_on[ch] {
                self.convert(ch, v, p);
            }
        }
        self.done(p);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(a: &mut Adc, volts: &[f32]) -> Vec<u8> {
        volts
            .iter()
            .map(|&v| {
                let mut p = Pending::default();
                a.tick(1_000_000, &[v; AXES], &mut p);
                p.adc[0]
            })
            .collect()
    }

    fn comparator(t: u16) -> Adc {
        let mut a = Adc::default();
        a.set_channel(0, true);
        a.set_comp_value(0, 2.0).unwrap();
        a.set_comp_type(0, t).unwrap();
        a.set_comp_trigger(0, true);
        a.start(&[0.0; AXES], &mut Pending::default());
        a
    }

    const WAVE: [f32; 8] = [0.0, 1.0, 2.0, 3.0, 1.9, 1.0, 2.5, 0.0];

    #[test]
    fn rise_fall_level_edges() {
        // crossings: up at 2.0 (tick 2), down at 1.9 (tick 4), up at 2.5, down at 0.0
        assert_eq!(
            run(&mut comparator(c::ADC_COMP_RISE), &WAVE),
            [0, 0, 1, 0, 0, 0, 1, 0]
        );
        assert_eq!(
            run(&mut comparator(c::ADC_COMP_FALL), &WAVE),
            [0, 0, 0, 0, 1, 0, 0, 1]
        );
        assert_eq!(
            run(&mut comparator(c::ADC_COMP_LEVEL), &WAVE),
            [0, 0, 1, 0, 1, 0, 1, 1]
        );
    }

    #[test]
    fn first_conversion_above_is_not_an_edge_and_mask_blunts() {
        let mut a = comparator(c::ADC_COMP_LEVEL);
        assert_eq!(run(&mut a, &[3.0, 3.0]), [0, 0]);
        // One code is 10 V / 4095 = 2.44 mV; 3 masked bits make steps of 8 codes (19.5 mV).
        a.set_comp_mask(c::ADC_MASK_BIT3).unwrap();
        assert_eq!(run(&mut a, &[2.001, 1.999, 2.001]), [0, 0, 0]);
        assert_eq!(run(&mut a, &[1.9, 2.1]), [1, 1]);
        a.set_comp_mask(c::ADC_MASK_NO).unwrap();
        assert_eq!(run(&mut a, &[2.001, 1.99, 2.01]), [0, 1, 1]);
        assert_eq!(a.set_comp_mask(4), Err(McclError::Parameter));
        assert_eq!(a.set_comp_type(0, 3), Err(McclError::Parameter));
    }

    /// Ticks (1 ms) in 1..=n in which a free-running scan converted (CONV raised).
    fn scan_ticks(a: &mut Adc, n: u32) -> Vec<u32> {
        (1..=n)
            .filter(|_| {
                let mut p = Pending::default();
                a.tick(1_000_000, &[1.0; AXES], &mut p);
                p.adc[8] == 1
            })
            .collect()
    }

    #[test]
    fn free_running_scans_follow_divider_rate_and_enabled_channels() {
        let mut a = Adc::default();
        a.set_conv_trigger(true);
        (0..4).for_each(|ch| a.set_channel(ch, true));
        a.start(&[0.0; AXES], &mut Pending::default());
        // Default: 4 channels x 16 bits x 50 clocks x 10 ns = 32 us: every tick.
        assert_eq!(scan_ticks(&mut a, 3), [1, 2, 3]);
        // Divider 12500: 4 x 16 x 12500 x 10 ns = 8 ms: ticks 8 and 16.
        a.set_clock_divider(12_500).unwrap();
        assert_eq!(scan_ticks(&mut a, 16), [8, 16]);
        // Two channels: 4 ms per scan. Counting restarts at MCC_StartADCConv.
        a.set_channel(2, false);
        a.set_channel(3, false);
        scan_ticks(&mut a, 1);
        a.start(&[0.0; AXES], &mut Pending::default());
        assert_eq!(scan_ticks(&mut a, 9), [4, 8]);
        // Back to divider 50 and 250 Hz: 4 ms, rate-bound; the input converted is the
        // one at the scan's tick.
        a.set_clock_divider(50).unwrap();
        a.set_update_rate(250.0).unwrap();
        assert_eq!(scan_ticks(&mut a, 12), [4, 8, 12]);
        let mut p = Pending::default();
        a.tick(1_000_000, &[2.5; AXES], &mut p);
        assert_eq!(a.input(0), 1.0, "no scan ended: the last value stays");
    }

    #[test]
    fn ranges_single_mode_conv_and_tag() {
        let mut a = Adc::default();
        a.set_channel(3, true);
        let mut p = Pending::default();
        a.tick(1_000_000, &[7.0; AXES], &mut p);
        assert_eq!(a.input(3), 0.0, "not started");
        a.set_conv_trigger(true);
        a.set_tag_channel(3);
        a.set_tag_trigger(true);
        a.start(&[0.0; AXES], &mut p);
        assert_eq!(a.work_status(), 1);
        a.tick(1_000_000, &[7.0; AXES], &mut p);
        assert_eq!(a.input(3), 5.0, "bipolar clamps at 5 V");
        assert_eq!((p.adc[8], p.adc[9]), (1, 1));
        a.set_conv_type(3, c::ADC_TYPE_UNI_DIFF).unwrap();
        a.tick(1_000_000, &[-1.0; AXES], &mut p);
        assert_eq!(a.input(3), 0.0, "unipolar clamps at 0 V");
        assert_eq!(a.set_conv_type(3, 4), Err(McclError::Parameter));

        a.set_mode(c::ADC_MODE_SINGLE).unwrap();
        assert_eq!(a.work_status(), 0);
        a.set_single_channel(5);
        let mut p = Pending::default();
        a.start(&[1.25; AXES], &mut p);
        assert_eq!(a.input(5), 1.25);
        assert_eq!(a.input(3), 0.0, "only the single channel");
        assert_eq!((p.adc[8], p.adc[9]), (1, 0));
        let mut q = Pending::default();
        a.tick(1_000_000, &[3.0; AXES], &mut q);
        assert!(q.is_empty(), "single mode: no conversion per tick");
        assert_eq!(a.set_mode(2), Err(McclError::Parameter));
    }
}
