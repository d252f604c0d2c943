//! The simulated machine's configuration: what a software card cannot know about the
//! machine around it — where the home sensor and the limit switches sit, the encoder index
//! pulses, how the plant follows the command, the emergency-stop, ADC and remote I/O
//! inputs, and which channels are an MC3B.
//!
//! The file is TOML. [`SimConfig::from_env`] reads the file named by `MCCL_SIM`
//! ([`ENV_VAR`]) or, when that is unset or empty, the embedded default
//! `src/sim/default.toml` ([`DEFAULT_TOML`]), which documents every key. Unknown keys,
//! wrong types and impossible values are errors whose message names the file, the 1-based
//! line and the key, e.g.
//! `machine.toml:7: card[0].channel[2].limit_minus: must be less than limit_plus (100)`.
//! Nothing is silently defaulted.
//!
//! Positions are in the channel's user units (UU) in machine coordinates: where the axis
//! is right after `MCC_InitSystem` is 0.
//!
//! This module is pure: it parses and validates, and never touches the engine.

use std::ffi::OsStr;
use std::ops::Range;
use std::path::Path;

use serde::Deserialize;
use toml::de::{DeTable, DeValue};
use toml::Spanned;

use crate::config::{AXES, CARDS};

/// The environment variable naming the configuration file.
pub const ENV_VAR: &str = "MCCL_SIM";
/// The embedded default configuration, `src/sim/default.toml`: an ideal machine, with
/// every key documented in comments.
pub const DEFAULT_TOML: &str = include_str!("default.toml");
/// The file name messages give for the embedded default.
pub const DEFAULT_NAME: &str = "src/sim/default.toml (built in)";
/// Remote I/O sets per card (`RIO_SET0`, `RIO_SET1`).
pub const RIO_SETS: usize = 2;
/// Remote I/O slaves per set (`RIO_SLAVE0`..`RIO_SLAVE31`).
pub const RIO_SLAVES: usize = 32;
/// Input ports per remote I/O slave (`RIO_PORT0`..`RIO_PORT3`).
pub const RIO_PORTS: usize = 4;
/// DAC outputs per card an ADC input can be wired to.
pub const DAC_CHANNELS: usize = 8;
/// Largest plant lag time constant accepted, in milliseconds.
pub const MAX_LAG_MS: f64 = 10_000.0;
/// Largest magnitude of a constant ADC input voltage.
pub const MAX_ADC_VOLTS: f64 = 10.0;

/// How the real (feedback) position of a channel follows the commanded one.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Plant {
    /// The position is exactly the command: no tracking error.
    #[default]
    Ideal,
    /// A first-order lag `tau_s × dx/dt = command − x`: at constant speed v the tracking
    /// error settles at `v × tau_s`.
    Lag {
        /// Time constant in seconds, 0 < `tau_s` ≤ 10.
        tau_s: f64,
    },
}

/// Where one ADC input's voltage comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AdcSource {
    /// A constant voltage, −10..10 V (readings saturate at the converter's range).
    Volts(f32),
    /// Wired to this DAC output (0..7) of the same card.
    Dac(u8),
}

/// The machine around one channel (axis) of a card.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ChannelSim {
    /// Home sensor region `(from, to)`, active while `from ≤ position ≤ to`; `from < to`.
    pub home: Option<(f64, f64)>,
    /// The home sensor is a normally-closed contact (`home_contact = "nc"`): its input
    /// is low while hit. Default: normally open, high while hit.
    pub home_nc: bool,
    /// The + limit switch is active while `position ≥ limit_plus`.
    pub limit_plus: Option<f64>,
    /// The − limit switch is active while `position ≤ limit_minus` (< `limit_plus`).
    pub limit_minus: Option<f64>,
    /// Encoder counts between index pulses (> 0); `None`: one per motor turn, see
    /// [`ChannelSim::index_spacing_or`].
    pub index_spacing: Option<u32>,
    /// Encoder count of an index pulse: pulses sit at `index_phase + k × spacing`.
    /// Below `index_spacing` when that is given; see [`ChannelSim::index_phase_in`].
    pub index_phase: u32,
    /// How the real position follows the command.
    pub plant: Plant,
    /// The source of the card's ADC input with this channel's number; `None`: 0 V.
    pub adc: Option<AdcSource>,
    /// On a card that is an MC3B (channels 0..2): the MC3B limit inputs (bits 0..5, -1
    /// none) wired as this motor's + and − limit switches (`mc3b_limit_bits`).
    pub mc3b_limit_bits: Option<[i8; 2]>,
}

/// An ideal channel: no sensors, index pulses once per turn, no lag, ADC at 0 V.
const IDEAL_CHANNEL: ChannelSim = ChannelSim {
    home: None,
    home_nc: false,
    limit_plus: None,
    limit_minus: None,
    index_spacing: None,
    index_phase: 0,
    plant: Plant::Ideal,
    adc: None,
    mc3b_limit_bits: None,
};

impl ChannelSim {
    /// Whether the home sensor is active at `pos` (UU, machine coordinates).
    pub fn home_active(&self, pos: f64) -> bool {
        self.home.is_some_and(|(from, to)| from <= pos && pos <= to)
    }

    /// Whether the + limit switch is active at `pos` (the physical switch, before the
    /// program's normally-open/normally-closed wiring).
    pub fn limit_plus_active(&self, pos: f64) -> bool {
        self.limit_plus.is_some_and(|l| pos >= l)
    }

    /// Whether the − limit switch is active at `pos` (the physical switch, before the
    /// program's normally-open/normally-closed wiring).
    pub fn limit_minus_active(&self, pos: f64) -> bool {
        self.limit_minus.is_some_and(|l| pos <= l)
    }

    /// The index pulse spacing in motor pulses (= encoder counts at x4): the configured
    /// one, else one pulse per motor turn, `ppr` (DECISIONS.md: dwPPR counts per motor
    /// turn at x4; at least 1).
    pub fn index_spacing_or(&self, ppr: u32) -> u32 {
        self.index_spacing.unwrap_or(ppr).max(1)
    }

    /// The index phase reduced below `spacing` (a `spacing` of 0 counts as 1).
    pub fn index_phase_in(&self, spacing: u32) -> u32 {
        self.index_phase % spacing.max(1)
    }
}

/// A simulated remote I/O slave (IMP-ARIO).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RioSlaveSim {
    /// The remote I/O set, 0..1.
    pub set: u8,
    /// The slave, 0..31.
    pub slave: u8,
    /// Input words of ports 0..3 (unused when `loopback`).
    pub inputs: [u16; RIO_PORTS],
    /// The inputs read back what the program last wrote to the slave's outputs.
    pub loopback: bool,
}

/// The machine around one card.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CardSim {
    /// The emergency-stop (EMG) input level at start: `true` = active.
    pub emergency_stop: bool,
    /// Channels 0..2 of this card are an MC3B on this serial port (a device path).
    pub mc3b_port: Option<String>,
    /// Channels 0..7.
    pub channels: [ChannelSim; AXES],
    /// Remote I/O slaves whose inputs are configured, in file order; each (set, slave) at
    /// most once. Slaves not listed read 0.
    pub rio: Vec<RioSlaveSim>,
}

/// An ideal card (what an unconfigured or out-of-range card reads as).
static IDEAL_CARD: CardSim = CardSim {
    emergency_stop: false,
    mc3b_port: None,
    channels: [IDEAL_CHANNEL; AXES],
    rio: Vec::new(),
};

impl CardSim {
    /// Channel `ch` of this card; an ideal channel when `ch` is out of range.
    pub fn channel(&self, ch: usize) -> &ChannelSim {
        self.channels.get(ch).unwrap_or(&IDEAL_CHANNEL)
    }

    /// The configured remote I/O slave `slave` of set `set`, if any.
    pub fn rio_slave(&self, set: usize, slave: usize) -> Option<&RioSlaveSim> {
        self.rio
            .iter()
            .find(|r| usize::from(r.set) == set && usize::from(r.slave) == slave)
    }
}

/// The whole simulated machine: one [`CardSim`] per card index 0..11 (ideal when the file
/// does not mention it).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SimConfig {
    /// Cards 0..11.
    pub cards: [CardSim; CARDS],
}

impl SimConfig {
    /// Card `card`; an ideal card when `card` is out of range.
    pub fn card(&self, card: usize) -> &CardSim {
        self.cards.get(card).unwrap_or(&IDEAL_CARD)
    }

    /// Channel `ch` of card `card`; an ideal channel when either is out of range.
    pub fn channel(&self, card: usize, ch: usize) -> &ChannelSim {
        self.card(card).channel(ch)
    }

    /// Reads the configuration `MCCL_SIM` names, or the embedded default when it is unset
    /// or empty. The error is one message per problem, one per line, each naming the file
    /// and, for the file's contents, the line and the key.
    pub fn from_env() -> Result<SimConfig, String> {
        SimConfig::from_env_value(std::env::var_os(ENV_VAR).as_deref())
    }

    /// [`SimConfig::from_env`] with the variable's value given: `None` or empty uses the
    /// embedded default, anything else is a path.
    pub fn from_env_value(value: Option<&OsStr>) -> Result<SimConfig, String> {
        match value {
            Some(path) if !path.is_empty() => SimConfig::from_file(Path::new(path)),
            _ => SimConfig::parse(DEFAULT_TOML, DEFAULT_NAME),
        }
    }

    /// Reads and parses the file at `path`; an unreadable or non-UTF-8 file is an error
    /// naming the path.
    pub fn from_file(path: &Path) -> Result<SimConfig, String> {
        let name = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| {
            format!("{ENV_VAR}={name}: cannot read the simulation configuration: {e}")
        })?;
        let text = String::from_utf8(bytes)
            .map_err(|e| format!("{ENV_VAR}={name}: the file is not UTF-8 text: {e}"))?;
        SimConfig::parse(&text, &name)
    }

    /// Parses and validates configuration text; `file_name` is what messages call the
    /// file.
    pub fn parse(text: &str, file_name: &str) -> Result<SimConfig, String> {
        let raw: RawFile = match toml::from_str(text) {
            Ok(raw) => raw,
            Err(e) => return Err(toml_error(text, file_name, &e)),
        };
        let mut v = Validator {
            text,
            problems: Vec::new(),
        };
        let cfg = v.file(raw);
        if v.problems.is_empty() {
            return Ok(cfg);
        }
        let root = DeTable::parse(text).ok();
        let mut problems = v.problems;
        problems.sort_by_key(|p| p.0.start);
        let lines: Vec<String> = problems
            .iter()
            .map(|(span, msg)| {
                let path = root
                    .as_ref()
                    .map(|r| locate(r.get_ref(), span.start).join("."))
                    .unwrap_or_default();
                format!("{file_name}:{}: {path}: {msg}", line_of(text, span.start))
            })
            .collect();
        Err(lines.join("\n"))
    }
}

// ---------------------------------------------------------------------------------------
// The file as written: serde checks keys and types, the spans locate later problems.

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    #[serde(default)]
    card: Vec<RawCard>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCard {
    index: Spanned<i64>,
    emergency_stop: Option<bool>,
    mc3b_port: Option<Spanned<String>>,
    #[serde(default)]
    channel: Vec<RawChannel>,
    #[serde(default)]
    rio: Vec<RawRio>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawChannel {
    index: Spanned<i64>,
    home: Option<Spanned<Vec<Spanned<f64>>>>,
    home_contact: Option<Spanned<String>>,
    limit_plus: Option<Spanned<f64>>,
    limit_minus: Option<Spanned<f64>>,
    index_spacing: Option<Spanned<i64>>,
    index_phase: Option<Spanned<i64>>,
    plant: Option<Spanned<toml::Value>>,
    adc: Option<Spanned<toml::Value>>,
    mc3b_limit_bits: Option<Spanned<Vec<Spanned<i64>>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRio {
    set: Spanned<i64>,
    slave: Spanned<i64>,
    inputs: Option<Spanned<Vec<Spanned<i64>>>>,
    loopback: Option<bool>,
}

/// Semantic checks after parsing; every problem keeps the span of the offending value.
struct Validator<'a> {
    text: &'a str,
    problems: Vec<(Range<usize>, String)>,
}

impl Validator<'_> {
    fn fail(&mut self, span: Range<usize>, msg: impl Into<String>) {
        self.problems.push((span, msg.into()));
    }

    /// An index-like integer in `0..n`.
    fn index(&mut self, v: &Spanned<i64>, n: usize) -> Option<usize> {
        match usize::try_from(*v.get_ref()) {
            Ok(i) if i < n => Some(i),
            _ => {
                self.fail(
                    v.span(),
                    format!("must be 0..{}, not {}", n - 1, v.get_ref()),
                );
                None
            }
        }
    }

    /// A finite number (TOML allows `nan` and `inf`).
    fn finite(&mut self, v: &Spanned<f64>) -> Option<f64> {
        let x = *v.get_ref();
        if x.is_finite() {
            Some(x)
        } else {
            self.fail(v.span(), format!("must be a finite number, not {x}"));
            None
        }
    }

    fn file(&mut self, raw: RawFile) -> SimConfig {
        let mut cfg = SimConfig::default();
        let mut first_at: [Option<usize>; CARDS] = [None; CARDS];
        for card in &raw.card {
            let Some(ci) = self.index(&card.index, CARDS) else {
                continue;
            };
            if let Some(first) = first_at[ci] {
                let line = line_of(self.text, first);
                self.fail(
                    card.index.span(),
                    format!("card {ci} is configured twice (first at line {line})"),
                );
                continue;
            }
            first_at[ci] = Some(card.index.span().start);
            cfg.cards[ci] = self.card(card);
        }
        cfg
    }

    fn card(&mut self, raw: &RawCard) -> CardSim {
        let mut card = CardSim {
            emergency_stop: raw.emergency_stop.unwrap_or(false),
            ..CardSim::default()
        };
        if let Some(port) = &raw.mc3b_port {
            if port.get_ref().trim().is_empty() {
                self.fail(port.span(), "must name a serial port, not be empty");
            } else {
                card.mc3b_port = Some(port.get_ref().clone());
            }
        }
        let mut first_at: [Option<usize>; AXES] = [None; AXES];
        for ch in &raw.channel {
            let Some(i) = self.index(&ch.index, AXES) else {
                continue;
            };
            if let Some(first) = first_at[i] {
                let line = line_of(self.text, first);
                self.fail(
                    ch.index.span(),
                    format!("channel {i} is configured twice on this card (first at line {line})"),
                );
                continue;
            }
            first_at[i] = Some(ch.index.span().start);
            card.channels[i] = self.channel(ch);
            if let Some(bits) = &ch.mc3b_limit_bits {
                if card.mc3b_port.is_none() || i >= 3 {
                    self.fail(
                        bits.span(),
                        "only for channels 0..2 of a card with mc3b_port (the MC3B's motors)",
                    );
                }
            }
        }
        let mut rio_first_at: Vec<((u8, u8), usize)> = Vec::new();
        for r in &raw.rio {
            let Some(slave) = self.rio(r) else {
                continue;
            };
            let key = (slave.set, slave.slave);
            if let Some((_, first)) = rio_first_at.iter().find(|(k, _)| *k == key) {
                let line = line_of(self.text, *first);
                self.fail(
                    r.slave.span(),
                    format!(
                        "set {} slave {} is configured twice on this card (first at line {line})",
                        key.0, key.1
                    ),
                );
                continue;
            }
            rio_first_at.push((key, r.slave.span().start));
            card.rio.push(slave);
        }
        card
    }

    fn channel(&mut self, raw: &RawChannel) -> ChannelSim {
        let mut ch = ChannelSim::default();
        if let Some(home) = &raw.home {
            match home.get_ref().as_slice() {
                [from, to] => {
                    if let (Some(a), Some(b)) = (self.finite(from), self.finite(to)) {
                        if a < b {
                            ch.home = Some((a, b));
                        } else {
                            self.fail(
                                home.span(),
                                format!("from must be less than to, not [{a}, {b}]"),
                            );
                        }
                    }
                }
                other => self.fail(
                    home.span(),
                    format!(
                        "must be [from, to], two numbers, not {} value(s)",
                        other.len()
                    ),
                ),
            }
        }
        if let Some(contact) = &raw.home_contact {
            match contact.get_ref().as_str() {
                "no" => ch.home_nc = false,
                "nc" => ch.home_nc = true,
                other => self.fail(
                    contact.span(),
                    format!("must be \"no\" (normally open) or \"nc\" (normally closed), not \"{other}\""),
                ),
            }
        }
        let plus = raw.limit_plus.as_ref().and_then(|v| self.finite(v));
        let minus = raw.limit_minus.as_ref().and_then(|v| self.finite(v));
        if let (Some(p), Some(m), Some(span)) = (plus, minus, raw.limit_minus.as_ref()) {
            if m >= p {
                self.fail(
                    span.span(),
                    format!("must be less than limit_plus ({p}), not {m}"),
                );
            }
        }
        ch.limit_plus = plus;
        ch.limit_minus = minus;
        if let Some(s) = &raw.index_spacing {
            match u32::try_from(*s.get_ref()) {
                Ok(n) if n > 0 => ch.index_spacing = Some(n),
                _ => self.fail(
                    s.span(),
                    format!(
                        "must be 1..{} encoder counts, not {}",
                        u32::MAX,
                        s.get_ref()
                    ),
                ),
            }
        }
        if let Some(p) = &raw.index_phase {
            match (u32::try_from(*p.get_ref()), ch.index_spacing) {
                (Ok(n), Some(spacing)) if n >= spacing => self.fail(
                    p.span(),
                    format!("must be less than index_spacing ({spacing}), not {n}"),
                ),
                (Ok(n), _) => ch.index_phase = n,
                (Err(_), _) => self.fail(
                    p.span(),
                    format!(
                        "must be 0..{} encoder counts, not {}",
                        u32::MAX - 1,
                        p.get_ref()
                    ),
                ),
            }
        }
        if let Some(plant) = &raw.plant {
            if let Some(p) = self.plant(plant) {
                ch.plant = p;
            }
        }
        if let Some(adc) = &raw.adc {
            ch.adc = self.adc(adc);
        }
        if let Some(bits) = &raw.mc3b_limit_bits {
            match bits.get_ref().as_slice() {
                [p, m] if (-1..=5).contains(p.get_ref()) && (-1..=5).contains(m.get_ref()) => {
                    // In range -1..5, so the narrowing keeps the value.
                    ch.mc3b_limit_bits = Some([*p.get_ref() as i8, *m.get_ref() as i8]);
                }
                _ => self.fail(
                    bits.span(),
                    "must be [plus, minus]: two MC3B limit input bits 0..5, or -1 for none",
                ),
            }
        }
        ch
    }

    fn plant(&mut self, raw: &Spanned<toml::Value>) -> Option<Plant> {
        const FORMS: &str = "must be \"ideal\" or { lag_ms = <0 < ms <= 10000> }";
        match raw.get_ref() {
            toml::Value::String(s) if s == "ideal" => Some(Plant::Ideal),
            toml::Value::Table(t) => {
                if let Some(k) = t.keys().find(|k| k.as_str() != "lag_ms") {
                    self.fail(
                        raw.span(),
                        format!("unknown key \"{k}\" in the plant table ({FORMS})"),
                    );
                    return None;
                }
                let lag = match t.get("lag_ms") {
                    Some(toml::Value::Float(f)) => *f,
                    Some(toml::Value::Integer(i)) => *i as f64,
                    Some(other) => {
                        self.fail(
                            raw.span(),
                            format!("lag_ms must be a number, not {}", other.type_str()),
                        );
                        return None;
                    }
                    None => {
                        self.fail(raw.span(), format!("lag_ms is missing ({FORMS})"));
                        return None;
                    }
                };
                if lag.is_finite() && lag > 0.0 && lag <= MAX_LAG_MS {
                    Some(Plant::Lag {
                        tau_s: lag / 1000.0,
                    })
                } else {
                    self.fail(
                        raw.span(),
                        format!("lag_ms must be 0 < lag_ms <= {MAX_LAG_MS}, not {lag}"),
                    );
                    None
                }
            }
            other => {
                self.fail(raw.span(), format!("{FORMS}, not {}", describe(other)));
                None
            }
        }
    }

    fn adc(&mut self, raw: &Spanned<toml::Value>) -> Option<AdcSource> {
        let forms = format!(
            "must be a voltage -{MAX_ADC_VOLTS}..{MAX_ADC_VOLTS} or \"dac0\"..\"dac{}\"",
            DAC_CHANNELS - 1
        );
        let volts = match raw.get_ref() {
            toml::Value::Float(f) => *f,
            toml::Value::Integer(i) => *i as f64,
            toml::Value::String(s) => {
                let dac = s
                    .strip_prefix("dac")
                    .filter(|n| n.len() == 1)
                    .and_then(|n| n.parse::<u8>().ok())
                    .filter(|&n| usize::from(n) < DAC_CHANNELS);
                if dac.is_none() {
                    self.fail(raw.span(), format!("{forms}, not \"{s}\""));
                }
                return dac.map(AdcSource::Dac);
            }
            other => {
                self.fail(raw.span(), format!("{forms}, not {}", describe(other)));
                return None;
            }
        };
        if volts.is_finite() && volts.abs() <= MAX_ADC_VOLTS {
            Some(AdcSource::Volts(volts as f32))
        } else {
            self.fail(raw.span(), format!("{forms}, not {volts}"));
            None
        }
    }

    fn rio(&mut self, raw: &RawRio) -> Option<RioSlaveSim> {
        let set = self.index(&raw.set, RIO_SETS);
        let slave = self.index(&raw.slave, RIO_SLAVES);
        let loopback = raw.loopback.unwrap_or(false);
        let mut inputs = [0u16; RIO_PORTS];
        let mut ok = true;
        if let Some(given) = &raw.inputs {
            if loopback {
                self.fail(
                    given.span(),
                    "a looped-back slave reads its outputs: give no inputs",
                );
                ok = false;
            } else if given.get_ref().len() > RIO_PORTS {
                self.fail(
                    given.span(),
                    format!(
                        "at most {RIO_PORTS} ports (0..{}), not {}",
                        RIO_PORTS - 1,
                        given.get_ref().len()
                    ),
                );
                ok = false;
            } else {
                for (slot, v) in inputs.iter_mut().zip(given.get_ref()) {
                    match u16::try_from(*v.get_ref()) {
                        Ok(w) => *slot = w,
                        Err(_) => {
                            self.fail(
                                v.span(),
                                format!("a port's inputs must be 0..65535, not {}", v.get_ref()),
                            );
                            ok = false;
                        }
                    }
                }
            }
        }
        let (set, slave) = (set?, slave?);
        ok.then_some(RioSlaveSim {
            set: u8::try_from(set).ok()?,
            slave: u8::try_from(slave).ok()?,
            inputs,
            loopback,
        })
    }
}

/// A value's kind for messages.
fn describe(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => format!("\"{s}\""),
        toml::Value::Integer(i) => i.to_string(),
        toml::Value::Float(f) => f.to_string(),
        toml::Value::Boolean(b) => b.to_string(),
        other => other.type_str().to_owned(),
    }
}

// ---------------------------------------------------------------------------------------
// Messages: byte offsets to lines, offsets to key paths, toml/serde errors to our words.

/// The 1-based line holding byte `offset` of `text`.
fn line_of(text: &str, offset: usize) -> usize {
    let end = offset.min(text.len());
    1 + text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
}

/// The key path (`card[0]`, `channel[2]`, `limit_minus`) of the innermost key or value
/// whose span holds `offset`; empty when none does (top level).
fn locate(root: &DeTable<'_>, offset: usize) -> Vec<String> {
    let mut path = Vec::new();
    locate_in(root, offset, &mut path);
    path
}

fn locate_in(table: &DeTable<'_>, offset: usize, path: &mut Vec<String>) -> bool {
    for (key, value) in table.iter() {
        let name: &str = key.get_ref();
        if key.span().contains(&offset) {
            path.push(name.to_owned());
            return true;
        }
        match value.get_ref() {
            DeValue::Table(sub) => {
                path.push(name.to_owned());
                if locate_in(sub, offset, path) || value.span().contains(&offset) {
                    return true;
                }
                path.pop();
            }
            DeValue::Array(items) => {
                for item in items.iter() {
                    if let DeValue::Table(sub) = item.get_ref() {
                        path.push(format!("{name}[{}]", element_label(name, sub)));
                        if locate_in(sub, offset, path) || item.span().contains(&offset) {
                            return true;
                        }
                        path.pop();
                    }
                }
                if value.span().contains(&offset) {
                    path.push(name.to_owned());
                    return true;
                }
            }
            _ => {
                if value.span().contains(&offset) {
                    path.push(name.to_owned());
                    return true;
                }
            }
        }
    }
    false
}

/// How a path names an element of the array of tables `name`: `set,slave` for remote I/O
/// slaves, else its `index` (cards, channels); `?` where those are missing or not integers.
fn element_label(name: &str, table: &DeTable<'_>) -> String {
    let int = |k: &str| -> String {
        table
            .get(k)
            .and_then(|v| v.get_ref().as_integer())
            .and_then(|i| i64::from_str_radix(&i.as_str().replace('_', ""), i.radix()).ok())
            .map_or_else(|| "?".to_owned(), |i| i.to_string())
    };
    if name == "rio" {
        format!("{},{}", int("set"), int("slave"))
    } else {
        int("index")
    }
}

/// A toml/serde error as `file:line: key: what is wrong`.
fn toml_error(text: &str, file: &str, e: &toml::de::Error) -> String {
    let msg = e.message().trim();
    let Some(span) = e.span() else {
        return format!("{file}: {msg}");
    };
    let line = line_of(text, span.start);
    let Ok(root) = DeTable::parse(text) else {
        // A syntax error: no tree to name the key from; quote the text at the error.
        let near = text
            .get(span.clone())
            .map(str::trim)
            .filter(|s| !s.is_empty() && s.len() <= 60 && !s.contains('\n'))
            .map(|s| format!(" (at `{s}`)"))
            .unwrap_or_default();
        return format!("{file}:{line}: TOML syntax error: {msg}{near}");
    };
    let mut path = locate(root.get_ref(), span.start);
    if let Some(rest) = msg.strip_prefix("unknown field `") {
        let (key, tail) = rest.split_once('`').unwrap_or((rest, ""));
        if path.last().map(String::as_str) == Some(key) {
            path.pop();
        }
        let place = if path.is_empty() {
            "at the top level".to_owned()
        } else {
            format!("in {}", path.join("."))
        };
        let known = tail
            .trim_start_matches(", ")
            .trim_start_matches("expected ")
            .trim_start_matches("one of ")
            .replace('`', "");
        let known = if known.is_empty() || known == "there are no fields" {
            String::new()
        } else {
            format!(" (known keys: {known})")
        };
        return format!("{file}:{line}: unknown key \"{key}\" {place}{known}");
    }
    let what = if let Some(rest) = msg.strip_prefix("missing field `") {
        format!("missing required key \"{}\"", rest.trim_end_matches('`'))
    } else if let Some(rest) = msg.strip_prefix("invalid type: ") {
        format!("wrong type: {}", plain_words(rest))
    } else if let Some(rest) = msg.strip_prefix("invalid value: ") {
        format!("invalid value: {}", plain_words(rest))
    } else {
        plain_words(msg)
    };
    let hint = if !path.is_empty() && what.ends_with("found a table, expected an array") {
        // The header of an array of tables names the keys without element labels.
        let keys: Vec<&str> = path.iter().filter_map(|p| p.split('[').next()).collect();
        format!(" (write [[{}]] for each element)", keys.join("."))
    } else {
        String::new()
    };
    let path = if path.is_empty() {
        "(top level)".to_owned()
    } else {
        path.join(".")
    };
    format!("{file}:{line}: {path}: {what}{hint}")
}

/// serde's type words ("map, expected f64") as a TOML user reads them.
fn plain_words(s: &str) -> String {
    let (found, expected) = s.split_once(", expected ").unwrap_or((s, ""));
    let found = match found {
        "map" => "a table".to_owned(),
        "sequence" => "an array".to_owned(),
        f => f.replace('`', ""),
    };
    let expected = match expected {
        "" => return format!("found {found}"),
        "f64" => "a number",
        "i64" => "an integer",
        "a sequence" => "an array",
        "a boolean" => "true or false",
        e if e.starts_with("struct ") => "a table",
        e => e,
    };
    format!("found {found}, expected {expected}")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Parses `text` as `m.toml`, expecting an error; returns the message.
    fn err(text: &str) -> String {
        match SimConfig::parse(text, "m.toml") {
            Ok(cfg) => panic!("expected an error, parsed {cfg:?}"),
            Err(e) => e,
        }
    }

    /// Asserts that `msg` starts with `m.toml:<line>: ` and contains every one of `parts`.
    fn assert_msg(msg: &str, line: usize, parts: &[&str]) {
        let prefix = format!("m.toml:{line}: ");
        assert!(
            msg.starts_with(&prefix),
            "{msg:?} should start with {prefix:?}"
        );
        for p in parts {
            assert!(msg.contains(p), "{msg:?} should contain {p:?}");
        }
    }

    /// The lines of `text` that are a single-`#` commented example, uncommented.
    fn uncomment(text: &str) -> String {
        text.lines()
            .filter_map(|l| {
                if l == "#" {
                    Some("")
                } else {
                    l.strip_prefix("# ")
                }
            })
            .map(|l| format!("{l}\n"))
            .collect()
    }

    #[test]
    fn embedded_default_is_the_ideal_machine() {
        let cfg = SimConfig::parse(DEFAULT_TOML, DEFAULT_NAME).expect("default parses");
        assert_eq!(cfg, SimConfig::default());
        assert_eq!(SimConfig::from_env_value(None), Ok(SimConfig::default()));
        assert_eq!(
            SimConfig::from_env_value(Some(OsStr::new(""))),
            Ok(SimConfig::default())
        );
        let ch = cfg.channel(0, 0);
        assert!(!ch.home_active(0.0) && !ch.limit_plus_active(1e9) && !ch.limit_minus_active(-1e9));
        assert_eq!(ch.plant, Plant::Ideal);
        assert_eq!(ch.adc, None);
        assert!(!cfg.card(0).emergency_stop);
        assert_eq!(cfg.card(0).rio_slave(0, 0), None);
    }

    /// The example commented into the default (every key) parses to exactly this.
    #[test]
    fn default_example_parses_to_expected_structs() {
        let text = uncomment(DEFAULT_TOML);
        let cfg = SimConfig::parse(&text, "example.toml").expect("example parses");
        let mut want = SimConfig::default();
        want.cards[0].mc3b_port = Some("/dev/pts/5".to_owned());
        want.cards[0].channels[0] = ChannelSim {
            home: Some((-1.0, 1.0)),
            home_nc: false,
            limit_plus: Some(100.0),
            limit_minus: Some(-100.0),
            index_spacing: Some(2000),
            index_phase: 0,
            plant: Plant::Lag { tau_s: 0.02 },
            adc: Some(AdcSource::Dac(0)),
            mc3b_limit_bits: Some([0, 1]),
        };
        want.cards[0].channels[1].adc = Some(AdcSource::Volts(2.5));
        want.cards[0].rio = vec![
            RioSlaveSim {
                set: 0,
                slave: 3,
                inputs: [1, 0, 0, 0xFFFF],
                loopback: false,
            },
            RioSlaveSim {
                set: 1,
                slave: 0,
                inputs: [0; 4],
                loopback: true,
            },
        ];
        assert_eq!(cfg, want);
        assert_eq!(cfg.card(0).rio_slave(1, 0).map(|r| r.loopback), Some(true));
    }

    /// The README's example is valid.
    #[test]
    fn readme_example_parses() {
        let readme = include_str!("../../README.md");
        let section = readme
            .split("## The simulated machine: `MCCL_SIM`")
            .nth(1)
            .expect("README has the MCCL_SIM section");
        let block = section
            .split("```toml\n")
            .nth(1)
            .and_then(|b| b.split("```").next())
            .expect("the section has a toml block");
        let cfg = SimConfig::parse(block, "machine.toml").expect("README example parses");
        assert_eq!(cfg.channel(0, 0).index_phase, 500);
        assert_eq!(cfg.channel(0, 0).plant, Plant::Lag { tau_s: 0.02 });
        assert_eq!(
            cfg.card(0).rio_slave(0, 3).map(|r| r.inputs),
            Some([1, 0, 0, 0])
        );
        // The two messages the README shows are the ones the library gives.
        let shown: Vec<&str> = section
            .lines()
            .map(str::trim)
            .filter(|l| l.starts_with("machine.toml:"))
            .collect();
        assert_eq!(shown.len(), 2);
        let bad_limit = block.replace("limit_minus = -100.0", "limit_minus = 100.0");
        let e = SimConfig::parse(&bad_limit, "machine.toml").expect_err("bad limit");
        assert_eq!(e, shown[0]);
        let typo = block.replace("limit_plus = 100.0", "lmit_plus = 100.0");
        let e = SimConfig::parse(&typo, "machine.toml").expect_err("typo");
        let cut = shown[1].trim_end_matches("...)");
        assert!(e.starts_with(cut), "{e:?} should start with {cut:?}");
    }

    #[test]
    fn full_example_with_every_form() {
        let text = r#"
[[card]]
index = 2
emergency_stop = true

[[card.channel]]
index = 7
home = [5, 6.5]          # integers are numbers too
limit_minus = -0.5
index_phase = 123        # no spacing: reduced modulo the default later
plant = { lag_ms = 1e4 }
adc = -10

[[card.rio]]
set = 1
slave = 31
inputs = [0b1010]

[[card]]
index = 11
"#;
        let cfg = SimConfig::parse(text, "m.toml").expect("parses");
        let card = cfg.card(2);
        assert!(card.emergency_stop);
        assert_eq!(card.mc3b_port, None);
        let ch = cfg.channel(2, 7);
        assert_eq!(ch.home, Some((5.0, 6.5)));
        assert_eq!((ch.limit_plus, ch.limit_minus), (None, Some(-0.5)));
        assert_eq!((ch.index_spacing, ch.index_phase), (None, 123));
        assert_eq!(ch.plant, Plant::Lag { tau_s: 10.0 });
        assert_eq!(ch.adc, Some(AdcSource::Volts(-10.0)));
        assert_eq!(
            card.rio,
            vec![RioSlaveSim {
                set: 1,
                slave: 31,
                inputs: [10, 0, 0, 0],
                loopback: false
            }]
        );
        assert_eq!(cfg.card(11), &CardSim::default());
        assert_eq!(cfg.channel(2, 0), &ChannelSim::default());
        // Out of range reads as ideal rather than panicking.
        assert_eq!(cfg.card(12), &CardSim::default());
        assert_eq!(cfg.channel(2, 8), &ChannelSim::default());
    }

    #[test]
    fn inline_tables_are_accepted_and_located() {
        let ok = "card = [{ index = 1, channel = [{ index = 3, limit_plus = 9 }] }]\n";
        let cfg = SimConfig::parse(ok, "m.toml").expect("parses");
        assert_eq!(cfg.channel(1, 3).limit_plus, Some(9.0));
        let bad =
            "card = [\n  { index = 1, channel = [\n    { index = 3, limit_plus = nan } ] } ]\n";
        assert_msg(&err(bad), 3, &["card[1].channel[3].limit_plus", "finite"]);
        let unknown = "card = [{ index = 1, channel = [{ index = 3, lmit = 1 }] }]\n";
        assert_msg(
            &err(unknown),
            1,
            &["unknown key \"lmit\" in card[1].channel[3]"],
        );
    }

    #[test]
    fn sensor_helpers() {
        let ch = ChannelSim {
            home: Some((-1.0, 1.0)),
            limit_plus: Some(100.0),
            limit_minus: Some(-100.0),
            index_phase: 2500,
            ..ChannelSim::default()
        };
        assert!(ch.home_active(-1.0) && ch.home_active(1.0) && !ch.home_active(1.001));
        assert!(ch.limit_plus_active(100.0) && !ch.limit_plus_active(99.9));
        assert!(ch.limit_minus_active(-100.0) && !ch.limit_minus_active(-99.9));
        assert_eq!(
            ch.index_spacing_or(500),
            500,
            "one index per motor turn: dwPPR pulses"
        );
        assert_eq!(ch.index_phase_in(2000), 500);
        assert_eq!(ch.index_spacing_or(0), 1);
        assert_eq!(ch.index_phase_in(0), 0);
        let set = ChannelSim {
            index_spacing: Some(7),
            ..ChannelSim::default()
        };
        assert_eq!(set.index_spacing_or(500), 7);
        assert_eq!(ChannelSim::default().index_spacing_or(u32::MAX), u32::MAX);
    }

    // ---- one test per error kind: the line and the key are in the message ----

    #[test]
    fn unknown_key() {
        let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nlmit_plus = 100.0\n";
        assert_msg(
            &err(text),
            5,
            &[
                "unknown key \"lmit_plus\" in card[0].channel[0]",
                "limit_plus",
            ],
        );
        assert_msg(
            &err("\n\ncards = 1\n"),
            3,
            &["unknown key \"cards\" at the top level"],
        );
        assert_msg(
            &err("[[card]]\nindex = 4\nemergncy_stop = true\n"),
            3,
            &["unknown key \"emergncy_stop\" in card[4]"],
        );
        assert_msg(
            &err("[[card]]\nindex = 0\n[[card.rio]]\nset = 0\nslave = 2\nloopbak = true\n"),
            6,
            &["unknown key \"loopbak\" in card[0].rio[0,2]"],
        );
        assert_msg(
            &err("[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nplant = { lag = 3 }\n"),
            5,
            &["card[0].channel[0].plant", "unknown key \"lag\""],
        );
    }

    #[test]
    fn wrong_type() {
        let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 1\nlimit_plus = \"far\"\n";
        assert_msg(
            &err(text),
            5,
            &[
                "card[0].channel[1].limit_plus",
                "wrong type",
                "\"far\"",
                "a number",
            ],
        );
        assert_msg(
            &err("[[card]]\nindex = 0\nemergency_stop = 1\n"),
            3,
            &["card[0].emergency_stop", "wrong type", "true or false"],
        );
        assert_msg(
            &err("[[card]]\nindex = 1.5\n"),
            2,
            &["card[?].index", "wrong type", "an integer"],
        );
        assert_msg(
            &err("[card]\nindex = 0\n"),
            1,
            &[
                "card",
                "wrong type: found a table, expected an array",
                "[[card]]",
            ],
        );
        assert_msg(
            &err("[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nhome = 1.0\n"),
            5,
            &["card[0].channel[0].home", "wrong type", "an array"],
        );
        assert_msg(
            &err("[[card]]\nindex = 0\n[card.channel]\nindex = 0\n"),
            3,
            &["card[0].channel", "[[card.channel]]"],
        );
    }

    #[test]
    fn missing_index() {
        assert_msg(
            &err("[[card]]\nemergency_stop = true\n"),
            1,
            &["card[?]", "missing required key \"index\""],
        );
        assert_msg(
            &err("[[card]]\nindex = 0\n\n[[card.rio]]\nslave = 1\n"),
            4,
            &["card[0].rio[?,1]", "missing required key \"set\""],
        );
    }

    #[test]
    fn toml_syntax_errors_name_the_line() {
        let text =
            "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nlimit_plus = 1\nlimit_plus = 2\n";
        assert_msg(&err(text), 6, &["duplicate key", "limit_plus"]);
        assert_msg(&err("[[card]]\nindex = = 0\n"), 2, &["TOML syntax error"]);
    }

    #[test]
    fn duplicate_card_index() {
        let text = "[[card]]\nindex = 3\n\n[[card]]\nindex = 3\n";
        assert_msg(
            &err(text),
            5,
            &[
                "card[3].index",
                "card 3 is configured twice (first at line 2)",
            ],
        );
    }

    #[test]
    fn duplicate_channel_index() {
        let text =
            "[[card]]\nindex = 0\n[[card.channel]]\nindex = 2\n[[card.channel]]\nindex = 2\n";
        assert_msg(
            &err(text),
            6,
            &[
                "card[0].channel[2].index",
                "channel 2 is configured twice",
                "line 4",
            ],
        );
        // The same channel index on two cards is fine.
        let ok = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 2\n\
                  [[card]]\nindex = 1\n[[card.channel]]\nindex = 2\n";
        assert!(SimConfig::parse(ok, "m.toml").is_ok());
    }

    #[test]
    fn index_out_of_range() {
        assert_msg(
            &err("[[card]]\nindex = 12\n"),
            2,
            &["card[12].index", "must be 0..11, not 12"],
        );
        assert_msg(
            &err("[[card]]\nindex = -1\n"),
            2,
            &["card[-1].index", "must be 0..11"],
        );
        assert_msg(
            &err("[[card]]\nindex = 0\n[[card.channel]]\nindex = 8\n"),
            4,
            &["card[0].channel[8].index", "must be 0..7, not 8"],
        );
    }

    #[test]
    fn home_from_not_below_to() {
        let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nhome = [1.0, 1.0]\n";
        assert_msg(
            &err(text),
            5,
            &["card[0].channel[0].home", "from must be less than to"],
        );
        let three = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nhome = [1, 2, 3]\n";
        assert_msg(&err(three), 5, &["card[0].channel[0].home", "two numbers"]);
    }

    #[test]
    fn limit_minus_not_below_limit_plus() {
        let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 2\n\
                    limit_plus = 100.0\n\nlimit_minus = 100\n";
        assert_msg(
            &err(text),
            7,
            &["card[0].channel[2].limit_minus: must be less than limit_plus (100)"],
        );
    }

    #[test]
    fn index_spacing_zero() {
        let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nindex_spacing = 0\n";
        assert_msg(
            &err(text),
            5,
            &["card[0].channel[0].index_spacing", "must be 1.."],
        );
        let big =
            "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nindex_spacing = 0x1_0000_0000\n";
        assert_msg(
            &err(big),
            5,
            &["card[0].channel[0].index_spacing", "4294967296"],
        );
    }

    #[test]
    fn index_phase_not_below_spacing() {
        let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\n\
                    index_spacing = 2000\nindex_phase = 2000\n";
        assert_msg(
            &err(text),
            6,
            &[
                "card[0].channel[0].index_phase",
                "less than index_spacing (2000)",
            ],
        );
        let neg = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nindex_phase = -1\n";
        assert_msg(&err(neg), 5, &["card[0].channel[0].index_phase", "not -1"]);
    }

    #[test]
    fn lag_out_of_range() {
        for (lag, shown) in [("0", "not 0"), ("-5", "not -5"), ("10000.5", "not 10000.5")] {
            let text = format!(
                "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nplant = {{ lag_ms = {lag} }}\n"
            );
            assert_msg(
                &err(&text),
                5,
                &[
                    "card[0].channel[0].plant",
                    "lag_ms must be 0 < lag_ms <= 10000",
                    shown,
                ],
            );
        }
        let name = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nplant = \"lag\"\n";
        assert_msg(
            &err(name),
            5,
            &["card[0].channel[0].plant", "\"ideal\"", "not \"lag\""],
        );
        let missing = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nplant = {}\n";
        assert_msg(&err(missing), 5, &["plant", "lag_ms is missing"]);
    }

    #[test]
    fn nan_and_inf() {
        let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 1\nlimit_plus = nan\n";
        assert_msg(
            &err(text),
            5,
            &["card[0].channel[1].limit_plus", "finite", "NaN"],
        );
        let inf = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 1\nhome = [-inf, 0]\n";
        assert_msg(&err(inf), 5, &["card[0].channel[1].home", "finite", "-inf"]);
        let lag = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 1\nplant = { lag_ms = inf }\n";
        assert_msg(&err(lag), 5, &["plant", "not inf"]);
        let adc = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 1\nadc = nan\n";
        assert_msg(&err(adc), 5, &["card[0].channel[1].adc", "not NaN"]);
    }

    #[test]
    fn bad_adc_source() {
        for (v, shown) in [
            ("\"dac8\"", "not \"dac8\""),
            ("\"DAC0\"", "not \"DAC0\""),
            ("\"dac\"", "not \"dac\""),
            ("\"dac01\"", "not \"dac01\""),
            ("10.5", "not 10.5"),
            ("true", "not true"),
            ("[1]", "not array"),
        ] {
            let text = format!("[[card]]\nindex = 5\n[[card.channel]]\nindex = 6\nadc = {v}\n");
            assert_msg(
                &err(&text),
                5,
                &["card[5].channel[6].adc", "\"dac0\"..\"dac7\"", shown],
            );
        }
        let ok = "[[card]]\nindex = 5\n[[card.channel]]\nindex = 6\nadc = \"dac7\"\n";
        let cfg = SimConfig::parse(ok, "m.toml").expect("dac7 is fine");
        assert_eq!(cfg.channel(5, 6).adc, Some(AdcSource::Dac(7)));
    }

    #[test]
    fn bad_rio() {
        let set = "[[card]]\nindex = 0\n[[card.rio]]\nset = 2\nslave = 0\n";
        assert_msg(
            &err(set),
            4,
            &["card[0].rio[2,0].set", "must be 0..1, not 2"],
        );
        let slave = "[[card]]\nindex = 0\n[[card.rio]]\nset = 0\nslave = 32\n";
        assert_msg(
            &err(slave),
            5,
            &["card[0].rio[0,32].slave", "must be 0..31, not 32"],
        );
        let ports =
            "[[card]]\nindex = 0\n[[card.rio]]\nset = 0\nslave = 0\ninputs = [1, 2, 3, 4, 5]\n";
        assert_msg(
            &err(ports),
            6,
            &["card[0].rio[0,0].inputs", "at most 4 ports", "not 5"],
        );
        let word = "[[card]]\nindex = 0\n[[card.rio]]\nset = 0\nslave = 0\ninputs = [0x10000]\n";
        assert_msg(
            &err(word),
            6,
            &["card[0].rio[0,0].inputs", "0..65535, not 65536"],
        );
        let both = "[[card]]\nindex = 0\n[[card.rio]]\nset = 0\nslave = 0\n\
                    inputs = [1]\nloopback = true\n";
        assert_msg(&err(both), 6, &["card[0].rio[0,0].inputs", "looped-back"]);
        let twice = "[[card]]\nindex = 0\n[[card.rio]]\nset = 1\nslave = 4\n\
                     [[card.rio]]\nset = 1\nslave = 4\n";
        assert_msg(
            &err(twice),
            8,
            &[
                "card[0].rio[1,4].slave",
                "set 1 slave 4 is configured twice",
                "line 5",
            ],
        );
    }

    #[test]
    fn home_contact() {
        let ok = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 1\nhome_contact = \"nc\"\n";
        let cfg = SimConfig::parse(ok, "t.toml").expect("nc parses");
        assert!(cfg.channel(0, 1).home_nc && !cfg.channel(0, 0).home_nc);
        let text = ok.replace("\"nc\"", "\"closed\"");
        assert_msg(
            &err(&text),
            5,
            &["card[0].channel[1].home_contact", "\"no\"", "\"closed\""],
        );
    }

    #[test]
    fn mc3b_limit_bits() {
        let ok = "[[card]]\nindex = 0\nmc3b_port = \"/dev/x\"\n[[card.channel]]\nindex = 2\nmc3b_limit_bits = [5, -1]\n";
        let cfg = SimConfig::parse(ok, "t.toml").expect("parses");
        assert_eq!(cfg.channel(0, 2).mc3b_limit_bits, Some([5, -1]));
        let e = err(&ok.replace("[5, -1]", "[6, 0]"));
        assert_msg(&e, 6, &["card[0].channel[2].mc3b_limit_bits", "0..5"]);
        let e = err(&ok.replace("index = 2", "index = 3"));
        assert_msg(&e, 6, &["mc3b_limit_bits", "channels 0..2"]);
        let e = err(&ok.replace("mc3b_port = \"/dev/x\"\n", ""));
        assert_msg(&e, 5, &["mc3b_limit_bits", "mc3b_port"]);
    }

    #[test]
    fn empty_mc3b_port() {
        let text = "[[card]]\nindex = 0\nmc3b_port = \"\"\n";
        assert_msg(&err(text), 3, &["card[0].mc3b_port", "serial port"]);
    }

    #[test]
    fn every_problem_is_reported_in_file_order() {
        let text = "[[card]]\nindex = 0\n[[card.channel]]\nindex = 9\n\
                    [[card.channel]]\nindex = 1\nindex_spacing = 0\n";
        let msg = err(text);
        let lines: Vec<&str> = msg.lines().collect();
        assert_eq!(lines.len(), 2, "{msg}");
        assert_msg(lines[0], 4, &["card[0].channel[9].index"]);
        assert_msg(lines[1], 7, &["card[0].channel[1].index_spacing"]);
    }

    #[test]
    fn unreadable_path_is_named() {
        let path =
            std::env::temp_dir().join(format!("mccl-sim-missing-{}.toml", std::process::id()));
        let e = SimConfig::from_env_value(Some(path.as_os_str())).expect_err("missing file");
        assert!(e.contains("MCCL_SIM="), "{e}");
        assert!(e.contains(&path.display().to_string()), "{e}");
        assert!(e.contains("cannot read"), "{e}");
        // A directory is not readable as a file either.
        let dir = std::env::temp_dir();
        let e = SimConfig::from_env_value(Some(dir.as_os_str())).expect_err("a directory");
        assert!(e.contains(&dir.display().to_string()), "{e}");
    }

    #[test]
    fn file_errors_name_the_path_and_line() {
        let dir = std::env::temp_dir();
        let path = dir.join(format!("mccl-sim-test-{}.toml", std::process::id()));
        std::fs::write(
            &path,
            "[[card]]\nindex = 0\n[[card.channel]]\nindex = 0\nlimit_plus = -1\nlimit_minus = 1\n",
        )
        .expect("write temp file");
        let e = SimConfig::from_file(&path).expect_err("bad limits");
        let name = path.display().to_string();
        assert!(
            e.starts_with(&format!("{name}:6: card[0].channel[0].limit_minus")),
            "{e}"
        );
        std::fs::write(&path, b"\xff\xfe").expect("write temp file");
        let e = SimConfig::from_file(&path).expect_err("not UTF-8");
        assert!(e.contains(&name) && e.contains("UTF-8"), "{e}");
        std::fs::write(&path, "[[card]]\nindex = 1\nemergency_stop = true\n").expect("write");
        let cfg = SimConfig::from_env_value(Some(path.as_os_str())).expect("good file");
        assert!(cfg.card(1).emergency_stop);
        let _ = std::fs::remove_file(&path);
    }
}
