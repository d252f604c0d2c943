//! The state the panel shows, as JSON, read from what the engine publishes: the groups'
//! snapshots (sequence-locked, never waiting for the engine), the clock's counters and
//! the engine's view copy ([`crate::engine::view`]). Nothing here locks a group or the
//! machine.

use crate::clock::ClockMode;
use crate::config::{GroupDef, AXES};
use crate::engine::Shared;
use crate::vendor::consts as c;
use serde_json::{json, Value};
use std::sync::Arc;

/// Where the state comes from.
#[derive(Debug)]
pub struct Source {
    /// The running engine's shared state.
    pub shared: Arc<Shared>,
    /// The groups that run, `(index, definition)`.
    pub groups: Vec<(usize, GroupDef)>,
}

/// The name of a motion status.
fn status_name(s: i32) -> &'static str {
    match s {
        c::GMS_RUNNING => "RUNNING",
        c::GMS_STOP => "STOP",
        c::GMS_HOLD => "HOLD",
        c::GMS_DELAYING => "DELAYING",
        c::GMS_BLOCKHOLD => "BLOCKHOLD",
        c::GMS_MPGING => "MPGING",
        _ => "?",
    }
}

/// What an error record means (README, "The checks that stop a group").
pub fn error_meaning(code: i32) -> String {
    const AXIS: [&str; AXES] = ["X", "Y", "Z", "U", "V", "W", "A", "B"];
    let axis = |base: i32| AXIS.get((code - base) as usize).copied().unwrap_or("?");
    match code {
        0 => "none".into(),
        0xF102 => "emergency stop input".into(),
        0xF103 => "watchdog reset the card".into(),
        0xF104 => "bad arc or circle".into(),
        0xF1FF => "internal error (the library stopped the group)".into(),
        0xF203 => "pulse speed over its limit".into(),
        0xF204 => "pulse acceleration over its limit".into(),
        0xF301..=0xF308 => format!("software over-travel, axis {}", axis(0xF301)),
        0xF501 => "in-position check failed".into(),
        0xF701..=0xF708 => format!("limit switch, axis {}", axis(0xF701)),
        0xF801..=0xF808 => format!("tracking error over its limit, axis {}", axis(0xF801)),
        0xF901 => "MC3B did not answer".into(),
        0xF902 => "MC3B refused a command".into(),
        _ => "unknown".into(),
    }
}

fn clock_name(m: ClockMode) -> &'static str {
    match m {
        ClockMode::Realtime => "realtime",
        ClockMode::Fast => "fast",
        ClockMode::Stepped => "stepped",
    }
}

/// Rounds for display and keeps the JSON small (1e-6 UU is below any pulse here).
fn r6(x: f64) -> f64 {
    if x.is_finite() {
        (x * 1e6).round() / 1e6
    } else {
        0.0
    }
}

impl Source {
    /// A source for the panel of a running engine.
    pub fn new(shared: Arc<Shared>, groups: &[(usize, GroupDef)]) -> Source {
        Source {
            shared,
            groups: groups.to_vec(),
        }
    }

    /// Asks the engine to keep (or stop) copying its view.
    pub fn want(&self, on: bool) {
        self.shared.view().want(on);
    }

    /// The whole state.
    pub fn json(&self) -> Value {
        let s = &self.shared;
        let clock = s.clock();
        let view = s.view().get();
        let groups: Vec<Value> = self
            .groups
            .iter()
            .filter_map(|(g, def)| {
                let snap = s.snapshot(u16::try_from(*g).ok()?).ok()?;
                let gv = view.groups.get(*g).copied().flatten();
                Some(json!({
                    "index": g,
                    "card": def.card.0,
                    "channels": def.channels.iter().map(|c| c.map(|c| c.0)).collect::<Vec<_>>(),
                    "status": snap.status,
                    "status_name": status_name(snap.status),
                    "error": snap.error,
                    "error_hex": format!("0x{:04X}", snap.error),
                    "error_meaning": error_meaning(snap.error),
                    "queued": snap.queued,
                    "command_index": snap.cmd.nCommandIndex,
                    "command_type": snap.cmd.nType,
                    "pos": snap.pos.map(r6),
                    "path_speed": r6(snap.path_speed),
                    "override": gv.map(|v| v.override_pct),
                    "inpos": gv.map(|v| v.inpos),
                }))
            })
            .collect();
        let cards: Vec<Value> = (0..s.cards())
            .map(|cd| {
                let cv = view.cards.get(cd).copied().unwrap_or_default();
                let servo = s.servo_on(cd);
                let channels: Vec<Value> = cv
                    .channels
                    .iter()
                    .enumerate()
                    .map(|(ch, v)| {
                        json!({
                            "home": v.inputs[0], "limit_plus": v.inputs[1], "limit_minus": v.inputs[2],
                            "home_hit": v.raw[0], "limit_plus_hit": v.raw[1], "limit_minus_hit": v.raw[2],
                            "servo_on": servo >> ch & 1 == 1,
                            "encoder": v.encoder,
                            "motor": r6(v.motor),
                            "pulses": v.pulses,
                            "dac": v.dac,
                            "adc_input": v.adc[0],
                            "adc": v.adc[1],
                            "led": v.led,
                        })
                    })
                    .collect();
                json!({
                    "index": cd,
                    "emergency_stop": cv.emergency,
                    "servo_on": servo,
                    "pos_ready": s.pos_ready(cd),
                    "channels": channels,
                    "timer": { "enabled": cv.timer.0, "period_clocks": cv.timer.1 },
                    "watchdog": { "enabled": cv.watchdog.0, "compare": cv.watchdog.1,
                                  "count": cv.watchdog.2, "resets": cv.watchdog.3 },
                    "adc_running": cv.adc_running,
                    "rio_in": cv.rio_in,
                    "rio_out": cv.rio_out,
                })
            })
            .collect();
        let period_ms = clock.period().as_secs_f64() * 1e3;
        json!({
            "clock": clock_name(clock.mode()),
            "virtual_time": clock.mode().virtual_time(),
            "period_ms": period_ms,
            "ticks": clock.ticks(),
            "time_ms": clock.now_ns() as f64 / 1e6,
            "missed_ticks": clock.missed(),
            "io_time_ms": if view.made { Some(view.ticks as f64 * period_ms) } else { None },
            "home_status": if view.made { Some(view.home_status) } else { None },
            "groups": groups,
            "cards": cards,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn meanings_name_the_axis() {
        assert_eq!(error_meaning(0xF701), "limit switch, axis X");
        assert_eq!(error_meaning(0xF703), "limit switch, axis Z");
        assert_eq!(error_meaning(0xF308), "software over-travel, axis B");
        assert_eq!(error_meaning(0xF102), "emergency stop input");
        assert_eq!(error_meaning(0x1234), "unknown");
    }
}
