//! What the card's inputs trigger (user manual §2.7.4, §2.9.3, §2.10; examples manual
//! §25–30, §39): encoder compare values (a stock per channel, fired one after the other
//! when the count reaches each), 3-D compare, the index trigger and status, the encoder
//! latch, local-input interrupts from the limit and home sensors, local outputs and LEDs
//! pulsed by a compare (trigger-out), and the closed-loop error thresholds.

use super::{Channel, SensorLevels};
use crate::config::AXES;
use crate::error::{McclError, McclResult};
use crate::interrupt::Interrupt;
use crate::vendor::consts as c;
use std::collections::VecDeque;

/// Most compare values a channel's stock holds (the manuals give no number).
pub const MAX_COMPARE_STOCK: usize = 65_536;

/// Per-card trigger settings and state, one part a kind of trigger.
#[derive(Debug, Clone)]
pub struct CardTriggers {
    compares: Compares,
    index: IndexTriggers,
    latches: Latches,
    inputs: LocalInputs,
    outs: TrigOutputs,
}

/// Compare triggers: the stock of compare values per channel, which are on, and how channels compare together.
#[derive(Debug, Clone)]
struct Compares {
    /// Pending compare values per channel; the front one is armed.
    stock: [VecDeque<i64>; AXES],
    /// Compare trigger (and its interrupt) enabled per channel.
    comp_enabled: [bool; AXES],
    /// Channels compared together (`MCC_Enable3DCompareChannel`; 0 or one bit: each
    /// channel on its own).
    compare_mask: u16,
    /// Tolerance (counts) of the 3-D compare.
    compare_tol: u16,
    prev_count: [i64; AXES],
    prev_over: [(bool, bool); AXES],
}

/// Index pulse interrupts and the index status.
#[derive(Debug, Clone)]
struct IndexTriggers {
    /// Index interrupt enabled per channel.
    index_enabled: [bool; AXES],
    /// An index pulse passed since the status was last read.
    index_status: [bool; AXES],
}

/// Count latches per channel.
#[derive(Debug, Clone)]
struct Latches {
    /// `ENC_TRIG_FIRST` / `ENC_TRIG_LAST` per channel.
    latch_type: [u16; AXES],
    /// Latch source bits per channel.
    latch_source: [u32; AXES],
    /// The latched count per channel.
    latch: [Option<i64>; AXES],
}

/// Local-input interrupts per point.
#[derive(Debug, Clone)]
struct LocalInputs {
    /// Local-input interrupt type per point (`LIO_LDI_*`: OTP 0..7, OTN 8..15, HOME 16..23).
    lio_type: [u16; 24],
    /// Local-input interrupt enabled per point.
    lio_enabled: [bool; 24],
}

/// Trigger-out of the local outputs and the LEDs, and how long a trigger holds them.
#[derive(Debug, Clone)]
struct TrigOutputs {
    /// Trigger-out per local output point.
    trig_out: [TrigOut; AXES],
    /// How long a triggered output holds its value, ns.
    trig_period_ns: u64,
    /// Until when each triggered output holds (virtual ns).
    trig_until: [Option<u128>; AXES],
    /// Output levels driven by trigger-out (bit per point), `None` where not driven.
    trig_level: [Option<bool>; AXES],
    /// LED trigger-out per LED point (`MCC_SetLedTrigOut*`; value true: lit). The LEDs
    /// share the trigger period.
    led_trig_out: [TrigOut; AXES],
    /// Until when each triggered LED holds (virtual ns).
    led_trig_until: [Option<u128>; AXES],
    /// Whether any of `trig_until` or `led_trig_until` is set (kept by the tick, which
    /// alone sets and clears them), so that [`CardTriggers::armed`] need not scan them.
    timed_outputs: bool,
    /// LED levels driven by trigger-out, `None` where not driven.
    led_trig_level: [Option<bool>; AXES],
}

/// Trigger-out of one output point (a local output or an LED).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct TrigOut {
    /// Trigger-out on for this point.
    pub enabled: bool,
    /// The level the point takes while a trigger holds it.
    pub value: bool,
    /// The compares (bit n: encoder compare of channel n) that trigger it.
    pub source: u16,
}

/// Which outputs a trigger-out setting is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TrigOutKind {
    /// The local output points (the servo-on outputs).
    Local,
    /// The LEDs.
    Led,
}

/// One setting of a trigger-out point (`MCC_SetLIOTrigOut*`, `MCC_SetLedTrigOut*`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TrigOutSetting {
    /// Trigger-out on or off.
    Enabled(bool),
    /// The value the point takes while triggered.
    Value(bool),
    /// The compares (bit n: channel n) that trigger the point.
    Source(u16),
}

impl CardTriggers {
    /// Changes one setting of trigger-out point `point` (0..7) of `kind`.
    pub fn set_trig_out(&mut self, kind: TrigOutKind, point: usize, s: TrigOutSetting) {
        let o = &mut self.trig_outs(kind)[point];
        match s {
            TrigOutSetting::Enabled(on) => o.enabled = on,
            TrigOutSetting::Value(v) => o.value = v,
            TrigOutSetting::Source(src) => o.source = src,
        }
    }

    /// The trigger-out settings of `kind`'s points.
    pub fn trig_outs(&mut self, kind: TrigOutKind) -> &mut [TrigOut; AXES] {
        match kind {
            TrigOutKind::Local => &mut self.outs.trig_out,
            TrigOutKind::Led => &mut self.outs.led_trig_out,
        }
    }

    /// Sets the trigger value of every local output point whose bit is set in `mask`
    /// to that bit of `values`.
    pub fn set_trig_out_values(&mut self, mask: u32, values: u32) {
        for (p, o) in self.outs.trig_out.iter_mut().enumerate() {
            if mask & (1 << p) != 0 {
                o.value = values & (1 << p) != 0;
            }
        }
    }

    /// The compares that trigger some enabled local output point.
    pub fn lio_sources(&self) -> u16 {
        self.outs
            .trig_out
            .iter()
            .filter(|o| o.enabled)
            .fold(0, |m, o| m | o.source)
    }

    /// Compare values waiting on the channels that trigger local outputs.
    pub fn lio_comp_stock_count(&self) -> usize {
        let src = self.lio_sources();
        (0..AXES)
            .filter(|ch| src & (1 << ch) != 0)
            .map(|ch| self.stock_count(ch))
            .sum()
    }

    /// Removes the compare values of the channels that trigger local outputs.
    pub fn erase_lio_comp_values(&mut self) {
        let src = self.lio_sources();
        for ch in (0..AXES).filter(|ch| src & (1 << ch) != 0) {
            self.compares.stock[ch].clear();
        }
    }
}

/// The compare values start, start + delta, ... up to end (inclusive) of
/// `MCC_SetENCCompValueTab`: a delta of 0, or one pointing away from end, is refused
/// (`PARAMETER_ERR`).
#[derive(Debug, Clone, Copy)]
pub struct CompareTable {
    start: i64,
    delta: i64,
    count: i64,
}

impl CompareTable {
    /// The table from `start` to `end` in steps of `delta` (counts already in range).
    pub fn new(start: i64, end: i64, delta: i64) -> McclResult<CompareTable> {
        if delta == 0 || (end - start).signum() * delta.signum() < 0 {
            return Err(McclError::Parameter);
        }
        Ok(CompareTable {
            start,
            delta,
            count: (end - start) / delta + 1,
        })
    }
}

impl CardTriggers {
    /// `MCC_SetENCLatchType`: sets channel `ch`'s latch type and re-arms its latch.
    pub fn set_latch_type(&mut self, ch: usize, t: u16) {
        self.latches.latch_type[ch] = t;
        self.latches.latch[ch] = None;
    }

    /// `MCC_SetENCLatchSource`: sets channel `ch`'s latch sources and re-arms its latch.
    pub fn set_latch_source(&mut self, ch: usize, src: u32) {
        self.latches.latch_source[ch] = src;
        self.latches.latch[ch] = None;
    }

    /// The latched count of channel `ch` (0 until something was latched).
    pub fn latch_value(&self, ch: usize) -> i64 {
        self.latches.latch[ch].unwrap_or(0)
    }

    /// Whether an index pulse of channel `ch` passed since the last read; the read
    /// clears it.
    pub fn take_index_status(&mut self, ch: usize) -> bool {
        std::mem::take(&mut self.index.index_status[ch])
    }

    /// Adds compare value `v` to channel `ch`'s stock (`BUFFER_FULL_ERR` when full).
    pub fn push_compare(&mut self, ch: usize, v: i64) -> McclResult<()> {
        if self.compares.stock[ch].len() >= MAX_COMPARE_STOCK {
            return Err(McclError::BufferFull);
        }
        self.compares.stock[ch].push_back(v);
        Ok(())
    }

    /// Adds every value of `t` to channel `ch`'s stock, or none (`BUFFER_FULL_ERR`) when
    /// they do not all fit.
    pub fn push_compare_table(&mut self, ch: usize, t: &CompareTable) -> McclResult<()> {
        if self.compares.stock[ch].len() as i64 + t.count > MAX_COMPARE_STOCK as i64 {
            return Err(McclError::BufferFull);
        }
        for k in 0..t.count {
            self.compares.stock[ch].push_back(t.start + k * t.delta);
        }
        Ok(())
    }

    /// The armed compare value of channel `ch` (0 when its stock is empty).
    pub fn armed_compare(&self, ch: usize) -> i64 {
        self.compares.stock[ch].front().copied().unwrap_or(0)
    }

    /// Turns channel `ch`'s compare trigger on or off; turning it on rebases the
    /// reference counts on `chans`, so values already passed do not fire.
    pub fn set_compare_trigger(&mut self, ch: usize, on: bool, chans: &[Channel; AXES]) {
        if on && !self.compares.comp_enabled[ch] {
            self.rebase(chans);
        }
        self.compares.comp_enabled[ch] = on;
    }
}

impl CardTriggers {
    /// Sets the interrupt type (`LIO_INT_*`) of local input point `p` (0..23).
    pub fn set_input_type(&mut self, p: usize, kind: u16) {
        self.inputs.lio_type[p] = kind;
    }

    /// Turns the interrupt of local input point `p` (0..23) on or off.
    pub fn enable_input(&mut self, p: usize, on: bool) {
        self.inputs.lio_enabled[p] = on;
    }

    /// How long a triggered output or LED holds its value, ns.
    pub fn set_trig_period_ns(&mut self, ns: u64) {
        self.outs.trig_period_ns = ns;
    }

    /// The trigger-out settings of the points of `kind`.
    pub fn trig_out_settings(&self, kind: TrigOutKind) -> [TrigOut; AXES] {
        match kind {
            TrigOutKind::Local => self.outs.trig_out,
            TrigOutKind::Led => self.outs.led_trig_out,
        }
    }

    /// The level a trigger-out holds local output `ch` at, if one does.
    pub fn trig_level(&self, ch: usize) -> Option<bool> {
        self.outs.trig_level.get(ch).copied().flatten()
    }

    /// The level a trigger-out holds LED `ch` at, if one does.
    pub fn led_trig_level(&self, ch: usize) -> Option<bool> {
        self.outs.led_trig_level.get(ch).copied().flatten()
    }

    /// Turns the index pulse interrupt of channel `ch` on or off.
    pub fn enable_index(&mut self, ch: usize, on: bool) {
        self.index.index_enabled[ch] = on;
    }

    /// Notes that channel `ch` passed an index pulse (the index status reads it).
    pub fn note_index(&mut self, ch: usize) {
        self.index.index_status[ch] = true;
    }

    /// Removes every compare value of channel `ch`.
    pub fn erase_compares(&mut self, ch: usize) {
        self.compares.stock[ch].clear();
    }

    /// The channels compared together (bit n: channel n).
    pub fn set_compare_mask(&mut self, mask: u16) {
        self.compares.compare_mask = mask;
    }

    /// The tolerance (counts) of the 3-D compare.
    pub fn set_compare_tolerance(&mut self, tol: u16) {
        self.compares.compare_tol = tol;
    }
}

impl Default for CardTriggers {
    fn default() -> Self {
        CardTriggers {
            compares: Compares {
                stock: std::array::from_fn(|_| VecDeque::new()),
                comp_enabled: [false; AXES],
                compare_mask: 0,
                compare_tol: 0,
                prev_count: [0; AXES],
                prev_over: [(false, false); AXES],
            },
            index: IndexTriggers {
                index_enabled: [false; AXES],
                index_status: [false; AXES],
            },
            latches: Latches {
                latch_type: [c::ENC_TRIG_FIRST; AXES],
                latch_source: [0; AXES],
                latch: [None; AXES],
            },
            inputs: LocalInputs {
                lio_type: [c::LIO_INT_RISE; 24],
                lio_enabled: [false; 24],
            },
            outs: TrigOutputs {
                trig_out: [TrigOut::default(); AXES],
                trig_period_ns: 0,
                trig_until: [None; AXES],
                trig_level: [None; AXES],
                led_trig_out: [TrigOut::default(); AXES],
                led_trig_until: [None; AXES],
                timed_outputs: false,
                led_trig_level: [None; AXES],
            },
        }
    }
}

/// Whether the count went from `a` to `b` through (or onto) `v`.
fn reached(a: i64, b: i64, v: i64) -> bool {
    (a < v && v <= b) || (a > v && v >= b) || (a == v && b == v)
}

/// Trigger-out of one kind of output after the compares of a tick: an enabled point whose
/// source includes a compare that fired holds its value until `now_ns + period_ns`
/// (again from now if it was holding); a point whose hold ended returns to its own level.
fn trigger_outputs(
    outs: &[TrigOut; AXES],
    until: &mut [Option<u128>; AXES],
    level: &mut [Option<bool>; AXES],
    compares: &[usize],
    now_ns: u128,
    period_ns: u64,
) {
    for pt in 0..AXES {
        let TrigOut {
            enabled,
            value,
            source,
        } = outs[pt];
        let hit = compares.iter().any(|&c| source & (1 << c) != 0);
        if enabled && hit {
            level[pt] = Some(value);
            until[pt] = Some(now_ns + u128::from(period_ns));
        } else if until[pt].is_some_and(|u| now_ns >= u) {
            until[pt] = None;
            level[pt] = None;
        }
    }
}

fn edge(kind: u16, before: bool, now: bool) -> bool {
    match kind {
        c::LIO_INT_RISE => !before && now,
        c::LIO_INT_FALL => before && !now,
        c::LIO_INT_LEVEL => now,
        _ => false,
    }
}

/// What a tick of the triggers produced.
#[derive(Debug, Default)]
pub struct Fired {
    /// Interrupt causes to raise on the card.
    pub interrupts: Vec<Interrupt>,
    /// Channels whose encoder compare fired (DAC triggers follow them).
    pub compares: Vec<usize>,
}

impl CardTriggers {
    /// The compare values of channel `ch` still waiting (the armed one included).
    pub fn stock_count(&self, ch: usize) -> usize {
        self.compares.stock[ch].len()
    }

    /// Resets the reference counts (after the counts were set or the card reset).
    pub fn rebase(&mut self, chans: &[Channel; AXES]) {
        for (p, ch) in self.compares.prev_count.iter_mut().zip(chans) {
            *p = ch.encoder();
        }
    }

    /// Whether anything on the card is armed: compares, index or local-input interrupts,
    /// latches, closed-loop thresholds or a trigger-out (output or LED) holding. A card
    /// with nothing armed skips its tick (re-arming a compare rebases the counts).
    #[inline]
    pub fn armed(&self, thresholds: &[(u16, u16); AXES]) -> bool {
        // Whole-array comparisons: a few wide compares instead of a loop per array.
        self.compares.comp_enabled != [false; AXES]
            || self.index.index_enabled != [false; AXES]
            || self.inputs.lio_enabled != [false; 24]
            || self.latches.latch_source != [0; AXES]
            || thresholds
                .iter()
                .fold(0, |any, &(plus, minus)| any | plus | minus)
                != 0
            || self.outs.timed_outputs
    }

    /// [`CardTriggers::tick`] for a card with nothing [armed](CardTriggers::armed): only
    /// the index status follows the channels (the tick raises nothing then).
    #[inline]
    pub fn tick_idle(&mut self, chans: &[Channel; AXES]) {
        for (i, ch) in chans.iter().enumerate() {
            if ch.index_events() > 0 {
                self.index.index_status[i] = true;
            }
        }
    }

    /// One tick: `chans` after their step, `thresholds` the closed-loop error bounds,
    /// `now_ns` the virtual time at the end of the tick.
    pub fn tick(
        &mut self,
        chans: &[Channel; AXES],
        prev_levels: &[SensorLevels; AXES],
        thresholds: &[(u16, u16); AXES],
        now_ns: u128,
    ) -> Fired {
        let mut out = Fired::default();
        for (i, ch) in chans.iter().enumerate() {
            if ch.index_events() > 0 {
                self.index.index_status[i] = true;
            }
        }
        if !self.armed(thresholds) {
            return out;
        }
        let counts: [i64; AXES] = std::array::from_fn(|i| chans[i].encoder());
        // Encoder compare: each channel on its own, or the 3-D set together.
        let multi = self.compares.compare_mask.count_ones() > 1;
        if multi {
            let set: Vec<usize> = (0..AXES)
                .filter(|i| self.compares.compare_mask & (1 << i) != 0)
                .collect();
            let tol = i64::from(self.compares.compare_tol);
            let all = set.iter().all(|&i| {
                self.compares.comp_enabled[i]
                    && self.compares.stock[i].front().is_some_and(|&v| {
                        (counts[i] - v).abs() <= tol
                            || reached(self.compares.prev_count[i], counts[i], v)
                    })
            });
            if all && !set.is_empty() {
                for &i in &set {
                    self.compares.stock[i].pop_front();
                    out.compares.push(i);
                }
            }
        }
        for i in 0..AXES {
            if !multi || self.compares.compare_mask & (1 << i) == 0 {
                while self.compares.comp_enabled[i] {
                    match self.compares.stock[i].front() {
                        Some(&v) if reached(self.compares.prev_count[i], counts[i], v) => {
                            self.compares.stock[i].pop_front();
                            out.compares.push(i);
                        }
                        _ => break,
                    }
                }
            }
            let ch = &chans[i];
            if ch.index_events() > 0 && self.index.index_enabled[i] {
                out.interrupts.push(Interrupt::EncIndex(i as u8));
            }
            // Latch: sources are the index pulses, the limit switches and the timer.
            let lv = ch.levels();
            let p = prev_levels[i];
            let src = self.latches.latch_source[i];
            // An index pulse latches the count it happened at (exactly, as the card's
            // hardware latch does); a limit switch the count at the end of the tick.
            let mut latched = None;
            for n in 0..AXES {
                let (now, before) = (chans[n].levels(), prev_levels[n]);
                if src & (1 << n) != 0 && chans[n].index_events() > 0 {
                    latched = match chans[n].last_index_count() {
                        Some(at) if n == i => Some(ch.count_at(at)),
                        _ => Some(counts[i]),
                    };
                }
                if (src & (0x100 << n) != 0 && now.plus && !before.plus)
                    || (src & (0x10000 << n) != 0 && now.minus && !before.minus)
                {
                    latched = Some(counts[i]);
                }
            }
            if let Some(v) = latched {
                if self.latches.latch_type[i] == c::ENC_TRIG_LAST || self.latches.latch[i].is_none()
                {
                    self.latches.latch[i] = Some(v);
                }
            }
            // Local-input interrupts from the sensors.
            let pts = [
                (i, p.plus, lv.plus, Interrupt::LioOtp(i as u8)),
                (8 + i, p.minus, lv.minus, Interrupt::LioOtn(i as u8)),
                (16 + i, p.home, lv.home, Interrupt::LioHome(i as u8)),
            ];
            for (pt, before, now, int) in pts {
                if self.inputs.lio_enabled[pt] && edge(self.inputs.lio_type[pt], before, now) {
                    out.interrupts.push(int);
                }
            }
            // Closed-loop error beyond its thresholds (a threshold of 0 is off).
            let (plus, minus) = thresholds[i];
            let e = ch.error_count();
            let over = (
                plus > 0 && e > i64::from(plus),
                minus > 0 && e < -i64::from(minus),
            );
            if over.0 && !self.compares.prev_over[i].0 {
                out.interrupts.push(Interrupt::PclOvp(i as u8));
            }
            if over.1 && !self.compares.prev_over[i].1 {
                out.interrupts.push(Interrupt::PclOvn(i as u8));
            }
            self.compares.prev_over[i] = over;
        }
        for &i in &out.compares {
            out.interrupts.push(Interrupt::EncComp(i as u8));
        }
        // Trigger-out: local outputs and LEDs whose source includes a compare that fired.
        let period = self.outs.trig_period_ns;
        trigger_outputs(
            &self.outs.trig_out,
            &mut self.outs.trig_until,
            &mut self.outs.trig_level,
            &out.compares,
            now_ns,
            period,
        );
        trigger_outputs(
            &self.outs.led_trig_out,
            &mut self.outs.led_trig_until,
            &mut self.outs.led_trig_level,
            &out.compares,
            now_ns,
            period,
        );
        self.outs.timed_outputs = self
            .outs
            .trig_until
            .iter()
            .chain(&self.outs.led_trig_until)
            .any(Option::is_some);
        self.compares.prev_count = counts;
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::{default_encoder_config, default_mac_param};
    use crate::machine::ChannelSpec;

    fn chans() -> [Channel; AXES] {
        std::array::from_fn(|_| {
            Channel::new(
                ChannelSpec::default(),
                default_mac_param(),
                default_encoder_config(),
            )
        })
    }

    #[test]
    fn compare_table_is_all_or_nothing() {
        // 0, 3, 6, 9: (10 - 0) / 3 + 1 = 4 values; 10 itself is not reached.
        let mut t = CardTriggers::default();
        t.push_compare_table(1, &CompareTable::new(0, 10, 3).unwrap())
            .unwrap();
        assert_eq!(
            t.compares.stock[1].iter().copied().collect::<Vec<_>>(),
            [0, 3, 6, 9]
        );
        assert_eq!(t.armed_compare(1), 0);
        // Downwards with a negative delta: 5, 3, 1.
        t.push_compare_table(2, &CompareTable::new(5, 0, -2).unwrap())
            .unwrap();
        assert_eq!(
            t.compares.stock[2].iter().copied().collect::<Vec<_>>(),
            [5, 3, 1]
        );
        // A zero delta, or one pointing away from the end, is refused.
        assert_eq!(
            CompareTable::new(0, 10, 0).unwrap_err(),
            McclError::Parameter
        );
        assert_eq!(
            CompareTable::new(0, 10, -1).unwrap_err(),
            McclError::Parameter
        );
        // One value over the stock's size: nothing is added. The stock of channel 1
        // holds 4, so MAX - 3 more values (0..=MAX - 4) would make MAX + 1.
        let n = MAX_COMPARE_STOCK as i64 - 3;
        let big = CompareTable::new(0, n - 1, 1).unwrap();
        assert_eq!(t.push_compare_table(1, &big), Err(McclError::BufferFull));
        assert_eq!(t.stock_count(1), 4);
        // MAX - 4 values fill it exactly.
        let fits = CompareTable::new(0, n - 2, 1).unwrap();
        t.push_compare_table(1, &fits).unwrap();
        assert_eq!(t.stock_count(1), MAX_COMPARE_STOCK);
        assert_eq!(t.push_compare(1, 7), Err(McclError::BufferFull));
    }

    #[test]
    fn compare_values_fire_in_turn() {
        let mut ch = chans();
        let mut t = CardTriggers::default();
        t.compares.stock[0].extend([100, 200, 300]);
        t.compares.comp_enabled[0] = true;
        let lv = [SensorLevels::default(); AXES];
        let th = [(0, 0); AXES];
        ch[0].step(150, 0.001);
        let f = t.tick(&ch, &lv, &th, 1);
        assert_eq!(f.compares, vec![0], "150 passed 100");
        ch[0].step(400, 0.001);
        let f = t.tick(&ch, &lv, &th, 2);
        assert_eq!(f.compares, vec![0, 0], "200 and 300 in one tick");
        assert_eq!(t.stock_count(0), 0);
        assert!(f.interrupts.contains(&Interrupt::EncComp(0)));
    }

    #[test]
    fn trigger_out_holds_for_the_period() {
        let mut ch = chans();
        let mut t = CardTriggers::default();
        t.compares.stock[0].push_back(10);
        t.compares.comp_enabled[0] = true;
        t.outs.trig_out[1] = TrigOut {
            enabled: true,
            value: true,
            source: 1,
        };
        t.outs.trig_period_ns = 500_000_000;
        let lv = [SensorLevels::default(); AXES];
        let th = [(0, 0); AXES];
        ch[0].step(20, 0.001);
        t.tick(&ch, &lv, &th, 1_000_000);
        assert_eq!(t.outs.trig_level[1], Some(true));
        t.tick(&ch, &lv, &th, 400_000_000);
        assert_eq!(t.outs.trig_level[1], Some(true));
        t.tick(&ch, &lv, &th, 501_000_000);
        assert_eq!(t.outs.trig_level[1], None, "back after 0.5 s");
    }

    #[test]
    fn led_trigger_out_follows_its_own_source_and_the_shared_period() {
        let mut ch = chans();
        let mut t = CardTriggers::default();
        t.compares.stock[2].extend([10, 20]);
        t.compares.comp_enabled[2] = true;
        t.outs.led_trig_out[5] = TrigOut {
            enabled: true,
            value: true,
            source: 1 << 2,
        }; // LED 5 lights on compare 2
        t.outs.led_trig_out[6] = TrigOut {
            enabled: true,
            value: true,
            source: 1 << 3,
        }; // LED 6 waits for compare 3
        t.outs.trig_out[5] = TrigOut {
            enabled: false,
            value: true,
            source: 1 << 2,
        }; // the local output 5 is not enabled
        t.outs.trig_period_ns = 3_000_000;
        let lv = [SensorLevels::default(); AXES];
        let th = [(0, 0); AXES];
        ch[2].step(15, 0.001);
        t.tick(&ch, &lv, &th, 1_000_000);
        assert_eq!(t.outs.led_trig_level[5], Some(true), "compare 2 passed 10");
        assert_eq!(
            (t.outs.led_trig_level[6], t.outs.trig_level[5]),
            (None, None)
        );
        t.tick(&ch, &lv, &th, 3_000_000);
        assert_eq!(t.outs.led_trig_level[5], Some(true), "held until 4 ms");
        ch[2].step(25, 0.001);
        t.tick(&ch, &lv, &th, 4_000_000);
        assert_eq!(
            t.outs.led_trig_level[5],
            Some(true),
            "retriggered at 4 ms: until 7 ms"
        );
        t.tick(&ch, &lv, &th, 6_000_000);
        assert_eq!(t.outs.led_trig_level[5], Some(true));
        t.tick(&ch, &lv, &th, 7_000_000);
        assert_eq!(t.outs.led_trig_level[5], None, "back after the period");
        t.compares.comp_enabled[2] = false;
        assert!(
            !t.armed(&th),
            "no LED holds any more: the card may skip its ticks"
        );
    }

    #[test]
    fn lio_edges_and_pcl_thresholds() {
        let ch = chans();
        let mut t = CardTriggers::default();
        t.inputs.lio_enabled[0] = true; // OTP0, rising by default
        let th = [(0, 0); AXES];
        let mut prev = [SensorLevels::default(); AXES];
        prev[0].plus = true; // was active, is not: a falling edge
        let f = t.tick(&ch, &prev, &th, 1);
        assert!(f.interrupts.is_empty());
        t.inputs.lio_type[0] = c::LIO_INT_FALL;
        let f = t.tick(&ch, &prev, &th, 2);
        assert_eq!(f.interrupts, vec![Interrupt::LioOtp(0)]);
    }
}
