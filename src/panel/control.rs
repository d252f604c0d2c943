//! The panel's controls: what an operator does to the simulated machine, through the core
//! calls the `MCCL_Sim*` functions make (never the C entry points), and optionally the
//! operator panel's feed hold, continue and abort (what `MCC_HoldMotion(g, FALSE)`,
//! `MCC_ContiMotion(g)` and `MCC_AbortMotion(g, FALSE)` do). Every argument is checked
//! first; a refused control changes nothing.

use crate::card::adc::AdcSource;
use crate::card::rio::RioInput;
use crate::config::{CardIx, ChannelIx};
use crate::engine::Shared;
use crate::error::McclError;
use crate::machine::Sensor;
use serde::Deserialize;

/// One control request (the JSON body of `POST /api/control`).
#[derive(Debug, Deserialize, PartialEq)]
#[serde(tag = "action", rename_all = "snake_case")]
pub enum Control {
    /// Press (`level` 1), release (0) or let follow the position (-1) a sensor:
    /// `sensor` is `home`, `limit_plus` or `limit_minus` (as `MCCL_SimSetSensor`).
    Sensor {
        /// Card index.
        card: u16,
        /// Channel 0..7.
        channel: u16,
        /// Which sensor.
        sensor: String,
        /// 1, 0 or -1.
        level: i32,
    },
    /// Press or release the card's emergency stop (as `MCCL_SimSetEmergencyStop`).
    EmergencyStop {
        /// Card index.
        card: u16,
        /// Pressed.
        on: bool,
    },
    /// The voltage at an ADC input (−10..10 V), or `null`: back to reading DAC `channel`.
    Adc {
        /// Card index.
        card: u16,
        /// Channel 0..7.
        channel: u16,
        /// Volts, or none.
        volts: Option<f64>,
    },
    /// The input word of a RIO slave (set 0..1, port 0..3), or `null`: loop back its outputs.
    RioInput {
        /// Card index.
        card: u16,
        /// Set 0..1.
        set: u16,
        /// Port 0..3.
        port: u16,
        /// The word, or none.
        value: Option<u16>,
    },
    /// Feed hold: `MCC_HoldMotion(group, FALSE)`.
    Hold {
        /// Group index.
        group: u16,
    },
    /// `MCC_ContiMotion(group)`.
    Continue {
        /// Group index.
        group: u16,
    },
    /// `MCC_AbortMotion(group, FALSE)`.
    Abort {
        /// Group index.
        group: u16,
    },
}

/// Why a control was refused: the message and whether the request was bad (400) or the
/// machine refused it in its state (409).
#[derive(Debug, PartialEq)]
pub struct Refused {
    /// Said to the client.
    pub message: String,
    /// 400 or 409.
    pub status: u16,
}

fn bad(msg: impl Into<String>) -> Refused {
    Refused {
        message: msg.into(),
        status: 400,
    }
}

fn vendor(e: McclError) -> Refused {
    Refused {
        message: format!("refused: {e:?} (vendor code {})", e.code()),
        status: 409,
    }
}

fn card_of(shared: &Shared, card: u16) -> Result<usize, Refused> {
    let ix = CardIx::new(card).map_err(|_| bad("no such card"))?;
    shared.card(ix).map_err(|_| bad("no such card"))
}

fn channel_of(ch: u16) -> Result<usize, Refused> {
    ChannelIx::new(ch)
        .map(|c| c.0)
        .map_err(|_| bad("channel must be 0..7"))
}

/// Applies a control.
pub fn apply(shared: &Shared, c: &Control) -> Result<(), Refused> {
    match *c {
        Control::Sensor {
            card,
            channel,
            ref sensor,
            level,
        } => {
            let s = match sensor.as_str() {
                "home" => Sensor::Home,
                "limit_plus" => Sensor::LimitPlus,
                "limit_minus" => Sensor::LimitMinus,
                _ => return Err(bad("sensor must be home, limit_plus or limit_minus")),
            };
            let level = match level {
                -1 => None,
                0 => Some(false),
                1 => Some(true),
                _ => return Err(bad("level must be 1, 0 or -1")),
            };
            let (cd, ch) = (card_of(shared, card)?, channel_of(channel)?);
            let mut m = shared.lock_machine();
            let chan = m
                .channel_mut(cd, ch)
                .ok_or_else(|| bad("no such channel"))?;
            chan.force(s, level);
        }
        Control::EmergencyStop { card, on } => {
            let cd = card_of(shared, card)?;
            let mut m = shared.lock_machine();
            if cd >= m.cards().len() {
                return Err(bad("no such card"));
            }
            m.set_emergency(cd, on);
        }
        Control::Adc {
            card,
            channel,
            volts,
        } => {
            let (cd, ch) = (card_of(shared, card)?, channel_of(channel)?);
            let src = match volts {
                None => AdcSource::Dac(ch),
                Some(v) if v.is_finite() && (-10.0..=10.0).contains(&v) => {
                    AdcSource::Constant(v as f32)
                }
                Some(_) => return Err(bad("volts must be -10..10")),
            };
            let p = shared.periph(cd).ok_or_else(|| bad("no such card"))?;
            p.lock().set_adc_source(ch, src);
        }
        Control::RioInput {
            card,
            set,
            port,
            value,
        } => {
            let cd = card_of(shared, card)?;
            let p = shared.periph(cd).ok_or_else(|| bad("no such card"))?;
            let src = value.map_or(RioInput::Loopback, RioInput::Constant);
            p.lock()
                .remote_io_mut()
                .rio_set_mut(usize::from(set))
                .and_then(|s| s.set_input_source(port, src))
                .map_err(|_| bad("set must be 0..1 and port 0..3"))?;
        }
        Control::Hold { group } => {
            let mut g = shared.group(group).map_err(|_| bad("no such group"))?;
            let r = g.hold(false);
            shared.publish(&mut g);
            r.map_err(vendor)?;
        }
        Control::Continue { group } => {
            let mut g = shared.group(group).map_err(|_| bad("no such group"))?;
            let r = g.conti();
            shared.publish(&mut g);
            r.map_err(vendor)?;
        }
        Control::Abort { group } => {
            let mut g = shared.group(group).map_err(|_| bad("no such group"))?;
            g.abort(0.0, false);
            shared.publish(&mut g);
        }
    }
    Ok(())
}

/// Parses a request body.
pub fn parse(body: &[u8]) -> Result<Control, Refused> {
    serde_json::from_slice(body).map_err(|e| bad(format!("bad control: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_each_action() {
        assert_eq!(
            parse(br#"{"action":"emergency_stop","card":0,"on":true}"#),
            Ok(Control::EmergencyStop { card: 0, on: true })
        );
        assert_eq!(
            parse(br#"{"action":"rio_input","card":0,"set":1,"port":3,"value":null}"#),
            Ok(Control::RioInput {
                card: 0,
                set: 1,
                port: 3,
                value: None
            })
        );
        assert_eq!(
            parse(br#"{"action":"hold","group":2}"#),
            Ok(Control::Hold { group: 2 })
        );
        for bad in [
            &b"{"[..],
            b"[]",
            br#"{"action":"explode"}"#,
            br#"{"action":"hold","group":-1}"#,
            br#"{"action":"hold","group":70000}"#,
            br#"{"action":"rio_input","card":0,"set":0,"port":0,"value":65536}"#,
            b"\xff\xfe",
        ] {
            assert_eq!(parse(bad).map_err(|r| r.status), Err(400), "{bad:?}");
        }
    }
}
