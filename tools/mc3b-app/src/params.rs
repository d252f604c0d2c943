//! The settings of one motor as the set parameters dialog (§5.3) shows them, and the
//! commands that give them to the board.
//!
//! The MC3B answers no question about its settings (§6 has queries for the motor status,
//! the limit inputs and the product only), so what the dialog "reads back" is the
//! application's record: the §6.1 defaults after its `0I`, then every value the board
//! acknowledged since.

use mc3b::codec::Command;
use serde::{Deserialize, Serialize};

/// Controller ID of the MC3B (no daisy chaining, §4.2).
pub const ID: u8 = 0;

/// One limit switch of a motor direction: an input bit and the level that means "at the
/// limit" (§4.9, §6.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Limit {
    /// Limit input 0..5 (§3.5).
    pub bit: u8,
    /// `true`: the input is pulled to +5 V at the limit; `false`: to 0 V.
    pub high: bool,
}

impl Limit {
    /// `(AND mask, XOR mask)` of §6.5: at the limit when `(inputs & and) ^ xor` is
    /// non-zero, so a 0 V limit has its bit in both masks.
    pub fn masks(self) -> (u32, u32) {
        let m = 1u32 << self.bit;
        (m, if self.high { 0 } else { m })
    }
}

/// The masks of a direction with or without a limit switch (none: both 0, §6.5).
pub fn masks(limit: Option<Limit>) -> (u32, u32) {
    limit.map_or((0, 0), Limit::masks)
}

/// What the set parameters dialog holds for one motor.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct MotorParams {
    /// Maximum velocity, steps/s (1..5000, §6.4).
    pub max_velocity: u32,
    /// Acceleration, steps/s² (100..100000, §6.2).
    pub acceleration: u32,
    /// Deceleration, steps/s² (100..100000, §6.3).
    pub deceleration: u32,
    /// Half steps (`F`, §6.6).
    pub half_steps: bool,
    /// Holding current applied when idle (`C`, §6.15).
    pub holding_on: bool,
    /// Holding current limit, mA (0..2000, §6.16).
    pub holding_current: u32,
    /// Running current limit, mA (0..2000, §6.16).
    pub running_current: u32,
    /// Limit switch of direction 0 (the "home 0"), or none.
    pub limit0: Option<Limit>,
    /// Limit switch of direction 1, or none.
    pub limit1: Option<Limit>,
}

impl MotorParams {
    /// The §6.1 defaults, which `0I` restores.
    pub const DEFAULT: MotorParams = MotorParams {
        max_velocity: 1000,
        acceleration: 5000,
        deceleration: 5000,
        half_steps: true,
        holding_on: false,
        holding_current: 500,
        running_current: 2000,
        limit0: None,
        limit1: None,
    };

    /// The limit of direction `dir` (0 or 1).
    pub fn limit(&self, dir: u32) -> Option<Limit> {
        if dir == 0 {
            self.limit0
        } else {
            self.limit1
        }
    }

    /// The commands that set every value on motor `motor`, each with the name of what it
    /// sets: `V`, `A`, `D`, `F`, `C`, `K`, `L`. All are sent, not only the changed ones:
    /// a board that was reset behind the application's back then holds what the dialog
    /// shows.
    pub fn commands(&self, motor: u32) -> Vec<(&'static str, Command)> {
        let (h0_and, h0_xor) = masks(self.limit0);
        let (h1_and, h1_xor) = masks(self.limit1);
        vec![
            (
                "maximum velocity",
                Command::SetMaxVelocity {
                    id: ID,
                    motor,
                    value: self.max_velocity,
                    direction_modifier: None,
                },
            ),
            (
                "acceleration",
                Command::SetAcceleration {
                    id: ID,
                    motor,
                    value: self.acceleration,
                },
            ),
            (
                "deceleration",
                Command::SetDeceleration {
                    id: ID,
                    motor,
                    value: self.deceleration,
                },
            ),
            (
                "half steps",
                Command::SetHalfStep {
                    id: ID,
                    motor,
                    half: u32::from(self.half_steps),
                },
            ),
            (
                "holding current on/off",
                Command::SetHoldingCurrent {
                    id: ID,
                    motor,
                    enable: u32::from(self.holding_on),
                },
            ),
            (
                "current limits",
                Command::SetCurrentLimits {
                    id: ID,
                    motor,
                    holding: self.holding_current,
                    running: self.running_current,
                },
            ),
            (
                "limit switches",
                Command::SetLimits {
                    id: ID,
                    motor,
                    h0_and,
                    h0_xor,
                    h1_and,
                    h1_xor,
                },
            ),
        ]
    }

    /// The record after `cmd` was acknowledged for this motor.
    pub fn apply(&mut self, cmd: &Command) {
        match *cmd {
            Command::SetMaxVelocity { value, .. } => self.max_velocity = value,
            Command::SetAcceleration { value, .. } => self.acceleration = value,
            Command::SetDeceleration { value, .. } => self.deceleration = value,
            Command::SetHalfStep { half, .. } => self.half_steps = half == 1,
            Command::SetHoldingCurrent { enable, .. } => self.holding_on = enable == 1,
            Command::SetCurrentLimits {
                holding, running, ..
            } => {
                self.holding_current = holding;
                self.running_current = running;
            }
            Command::SetLimits {
                h0_and,
                h0_xor,
                h1_and,
                h1_xor,
                ..
            } => {
                self.limit0 = limit_of(h0_and, h0_xor);
                self.limit1 = limit_of(h1_and, h1_xor);
            }
            _ => {}
        }
    }
}

/// The limit that a pair of masks with at most one bit describes (the inverse of
/// [`Limit::masks`]); `None` for no limit.
fn limit_of(and: u32, xor: u32) -> Option<Limit> {
    if and == 0 || and.count_ones() != 1 {
        return None;
    }
    Some(Limit {
        bit: and.trailing_zeros() as u8,
        high: xor & and == 0,
    })
}

impl Default for MotorParams {
    fn default() -> Self {
        MotorParams::DEFAULT
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use mc3b::codec::encode;

    #[test]
    fn limit_masks_follow_the_guides_example() {
        // §6.5: motor 2, direction 0 on a high level of bit 3, direction 1 on a low level
        // of bit 5: 0L2,8,0,32,32.
        let p = MotorParams {
            limit0: Some(Limit { bit: 3, high: true }),
            limit1: Some(Limit {
                bit: 5,
                high: false,
            }),
            ..MotorParams::DEFAULT
        };
        let cmds = p.commands(2);
        let l = cmds.last().map(|(_, c)| encode(c));
        assert_eq!(l.as_deref(), Some(&b"0L2,8,0,32,32\r"[..]));
        assert_eq!(masks(None), (0, 0));
    }

    #[test]
    fn commands_carry_every_value_and_apply_restores_them() {
        let p = MotorParams {
            max_velocity: 1500,
            acceleration: 8000,
            deceleration: 6000,
            half_steps: false,
            holding_on: true,
            holding_current: 300,
            running_current: 1200,
            limit0: Some(Limit { bit: 2, high: true }),
            limit1: Some(Limit {
                bit: 4,
                high: false,
            }),
        };
        let wire: Vec<String> = p
            .commands(1)
            .iter()
            .map(|(_, c)| String::from_utf8_lossy(&encode(c)).trim_end().to_string())
            .collect();
        assert_eq!(
            wire,
            [
                "0V1,1500",
                "0A1,8000",
                "0D1,6000",
                "0F1,0",
                "0C1,1",
                "0K1,300,1200",
                "0L1,4,0,16,16"
            ]
        );
        let mut r = MotorParams::DEFAULT;
        for (_, c) in p.commands(1) {
            r.apply(&c);
        }
        assert_eq!(r, p);
    }
}
