//! The simulated machine's configuration: what a software card cannot know about the
//! machine around it — where the home sensor and the limit switches sit, the encoder index
//! pulses, how the plant follows the command, the emergency-stop, ADC and remote I/O
//! inputs, and which channels are an MC3B.
//!
//! The file is TOML. [`SimConfig::from_env_value`] reads the file named by `MCCL_SIM`
//! ([`ENV_VAR`]; the library reads the variable) or, when that is unset or empty, the
//! embedded default `crates/core/src/sim/default.toml` ([`DEFAULT_TOML`]), which
//! documents every key. Unknown keys,
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
    /// one, else one pulse per motor turn, `ppr` (docs/decisions.md: dwPPR counts per motor
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

    /// The configuration the value of `MCCL_SIM` ([`ENV_VAR`]) names: `None` or empty uses
    /// the embedded default, anything else is a path. The error is one message per
    /// problem, one per line, each naming the file and, for the file's contents, the line
    /// and the key. (The caller reads the environment; this crate reads none.)
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

mod messages;
mod raw;
#[cfg(test)]
mod tests;

use messages::*;
use raw::*;
