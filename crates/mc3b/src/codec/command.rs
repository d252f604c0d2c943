//! The host-to-device commands of §6 as typed values: their letter, parameters and
//! range checks.

use super::{
    CommandCode, ErrorCode, ACCEL_RANGE, CURRENT_RANGE, DEBOUNCE_RANGE, MAX_MASK, MIN_RATE, MOTORS,
    VELOCITY_RANGE,
};

/// One host-to-device command of §6. Every numeric field holds the raw wire
/// value (`u32`), so out-of-range commands can be represented, encoded and
/// parsed; [`Command::validate`] applies the device's range checks.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Command {
    /// `<id>I`: initialize and set the controller ID to `id` (§6.1).
    Initialize {
        /// Controller ID.
        id: u8,
    },
    /// `<id>A<m>,<a>` (§6.2).
    SetAcceleration {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
        /// Steps/s², 100..100000.
        value: u32,
    },
    /// `<id>D<m>,<d>` (§6.3).
    SetDeceleration {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
        /// Steps/s², 100..100000.
        value: u32,
    },
    /// `<id>V<m>,<v>[,<direction modifier>]` (§6.4).
    SetMaxVelocity {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
        /// Steps/s, 1..5000.
        value: u32,
        /// Direction modifier 0/1; `None` when omitted (means 0).
        direction_modifier: Option<u32>,
    },
    /// `<id>L<m>,<h0a>,<h0x>,<h1a>,<h1x>` (§6.5).
    SetLimits {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
        /// Home AND mask, direction 0.
        h0_and: u32,
        /// Home XOR mask, direction 0.
        h0_xor: u32,
        /// Home AND mask, direction 1.
        h1_and: u32,
        /// Home XOR mask, direction 1.
        h1_xor: u32,
    },
    /// `<id>F<m>,<f>`: 0 full steps, 1 half steps (§6.6).
    SetHalfStep {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
        /// 0 full, 1 half.
        half: u32,
    },
    /// `<id>R<m>,<d>` (§6.7).
    Run {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
        /// Direction 0/1.
        direction: u32,
    },
    /// `<id>M<m>,<s>,<d>` (§6.8).
    Move {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
        /// Steps (32-bit unsigned).
        steps: u32,
        /// Direction 0/1.
        direction: u32,
    },
    /// `<id>H<m>,<d>` (§6.9).
    Home {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
        /// Direction 0/1.
        direction: u32,
    },
    /// `<id>G<m>,<s>,<d>,<rate>` (§6.10).
    RateMove {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
        /// Steps.
        steps: u32,
        /// Direction 0/1.
        direction: u32,
        /// 10 µs intervals between steps, >= 50.
        rate: u32,
    },
    /// `<id>S<m>` (§6.11).
    Stop {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
    },
    /// `<id>Y<s0>,<d0>,<s1>,<d1>,<s2>,<d2>[,<execute>]` (§6.12).
    SyncMove {
        /// Controller ID.
        id: u8,
        /// Steps of motors 0, 1, 2.
        steps: [u32; 3],
        /// Directions of motors 0, 1, 2.
        directions: [u32; 3],
        /// `None`: execute now, discarding the buffer; `Some(0)`: store;
        /// `Some(1)`: store and run the whole buffer.
        execute: Option<u32>,
    },
    /// `<id>Q<m>` (§6.13).
    QueryStatus {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
    },
    /// `<id>B` (§6.14).
    QueryLimits {
        /// Controller ID.
        id: u8,
    },
    /// `<id>C<m>,<c>` (§6.15).
    SetHoldingCurrent {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
        /// 0 off, 1 on.
        enable: u32,
    },
    /// `<id>K<m>,<h>,<r>` (§6.16).
    SetCurrentLimits {
        /// Controller ID.
        id: u8,
        /// Motor 0..2.
        motor: u32,
        /// Holding current, mA 0..2000.
        holding: u32,
        /// Running current, mA 0..2000.
        running: u32,
    },
    /// `<id>N<count>` (§6.17).
    SetDebounce {
        /// Controller ID.
        id: u8,
        /// 1..100.
        count: u32,
    },
    /// `<id>P` (§6.18).
    QueryProductId {
        /// Controller ID.
        id: u8,
    },
}

impl Command {
    /// Controller ID the command is addressed to.
    pub fn id(&self) -> u8 {
        match *self {
            Command::Initialize { id }
            | Command::SetAcceleration { id, .. }
            | Command::SetDeceleration { id, .. }
            | Command::SetMaxVelocity { id, .. }
            | Command::SetLimits { id, .. }
            | Command::SetHalfStep { id, .. }
            | Command::Run { id, .. }
            | Command::Move { id, .. }
            | Command::Home { id, .. }
            | Command::RateMove { id, .. }
            | Command::Stop { id, .. }
            | Command::SyncMove { id, .. }
            | Command::QueryStatus { id, .. }
            | Command::QueryLimits { id }
            | Command::SetHoldingCurrent { id, .. }
            | Command::SetCurrentLimits { id, .. }
            | Command::SetDebounce { id, .. }
            | Command::QueryProductId { id } => id,
        }
    }

    /// The command letter.
    pub fn code(&self) -> CommandCode {
        match self {
            Command::Initialize { .. } => CommandCode::Initialize,
            Command::SetAcceleration { .. } => CommandCode::Acceleration,
            Command::SetDeceleration { .. } => CommandCode::Deceleration,
            Command::SetMaxVelocity { .. } => CommandCode::Velocity,
            Command::SetLimits { .. } => CommandCode::Limits,
            Command::SetHalfStep { .. } => CommandCode::HalfStep,
            Command::Run { .. } => CommandCode::Run,
            Command::Move { .. } => CommandCode::Move,
            Command::Home { .. } => CommandCode::Home,
            Command::RateMove { .. } => CommandCode::RateMove,
            Command::Stop { .. } => CommandCode::Stop,
            Command::SyncMove { .. } => CommandCode::SyncMove,
            Command::QueryStatus { .. } => CommandCode::QueryStatus,
            Command::QueryLimits { .. } => CommandCode::QueryLimits,
            Command::SetHoldingCurrent { .. } => CommandCode::HoldingCurrent,
            Command::SetCurrentLimits { .. } => CommandCode::CurrentLimits,
            Command::SetDebounce { .. } => CommandCode::Debounce,
            Command::QueryProductId { .. } => CommandCode::ProductId,
        }
    }

    /// The parameters in wire order.
    pub fn params(&self) -> Vec<u32> {
        match *self {
            Command::Initialize { .. }
            | Command::QueryLimits { .. }
            | Command::QueryProductId { .. } => vec![],
            Command::SetAcceleration { motor, value, .. }
            | Command::SetDeceleration { motor, value, .. } => vec![motor, value],
            Command::SetMaxVelocity {
                motor,
                value,
                direction_modifier,
                ..
            } => {
                let mut v = vec![motor, value];
                v.extend(direction_modifier);
                v
            }
            Command::SetLimits {
                motor,
                h0_and,
                h0_xor,
                h1_and,
                h1_xor,
                ..
            } => vec![motor, h0_and, h0_xor, h1_and, h1_xor],
            Command::SetHalfStep { motor, half, .. } => vec![motor, half],
            Command::Run {
                motor, direction, ..
            }
            | Command::Home {
                motor, direction, ..
            } => vec![motor, direction],
            Command::Move {
                motor,
                steps,
                direction,
                ..
            } => vec![motor, steps, direction],
            Command::RateMove {
                motor,
                steps,
                direction,
                rate,
                ..
            } => vec![motor, steps, direction, rate],
            Command::Stop { motor, .. } | Command::QueryStatus { motor, .. } => vec![motor],
            Command::SyncMove {
                steps,
                directions,
                execute,
                ..
            } => {
                let mut v = vec![
                    steps[0],
                    directions[0],
                    steps[1],
                    directions[1],
                    steps[2],
                    directions[2],
                ];
                v.extend(execute);
                v
            }
            Command::SetHoldingCurrent { motor, enable, .. } => vec![motor, enable],
            Command::SetCurrentLimits {
                motor,
                holding,
                running,
                ..
            } => vec![motor, holding, running],
            Command::SetDebounce { count, .. } => vec![count],
        }
    }

    /// Range checks of §6 (and §4 for the same quantities). Returns
    /// [`ErrorCode::OutOfRange`] on the first violation.
    pub fn validate(&self) -> Result<(), ErrorCode> {
        fn within(v: u32, (lo, hi): (u32, u32)) -> Result<(), ErrorCode> {
            if (lo..=hi).contains(&v) {
                Ok(())
            } else {
                Err(ErrorCode::OutOfRange)
            }
        }
        let motor = |m: u32| within(m, (0, MOTORS - 1));
        let flag = |f: u32| within(f, (0, 1));
        match *self {
            Command::Initialize { .. }
            | Command::QueryLimits { .. }
            | Command::QueryProductId { .. } => Ok(()),
            Command::SetAcceleration {
                motor: m, value, ..
            }
            | Command::SetDeceleration {
                motor: m, value, ..
            } => {
                motor(m)?;
                within(value, ACCEL_RANGE)
            }
            Command::SetMaxVelocity {
                motor: m,
                value,
                direction_modifier,
                ..
            } => {
                motor(m)?;
                within(value, VELOCITY_RANGE)?;
                flag(direction_modifier.unwrap_or(0))
            }
            Command::SetLimits {
                motor: m,
                h0_and,
                h0_xor,
                h1_and,
                h1_xor,
                ..
            } => {
                motor(m)?;
                for mask in [h0_and, h0_xor, h1_and, h1_xor] {
                    within(mask, (0, MAX_MASK))?;
                }
                Ok(())
            }
            Command::SetHalfStep {
                motor: m, half: f, ..
            }
            | Command::SetHoldingCurrent {
                motor: m,
                enable: f,
                ..
            }
            | Command::Run {
                motor: m,
                direction: f,
                ..
            }
            | Command::Home {
                motor: m,
                direction: f,
                ..
            }
            | Command::Move {
                motor: m,
                direction: f,
                ..
            } => {
                motor(m)?;
                flag(f)
            }
            Command::RateMove {
                motor: m,
                direction,
                rate,
                ..
            } => {
                motor(m)?;
                flag(direction)?;
                within(rate, (MIN_RATE, u32::MAX))
            }
            Command::Stop { motor: m, .. } | Command::QueryStatus { motor: m, .. } => motor(m),
            Command::SyncMove {
                directions,
                execute,
                ..
            } => {
                for d in directions {
                    flag(d)?;
                }
                flag(execute.unwrap_or(0))
            }
            Command::SetCurrentLimits {
                motor: m,
                holding,
                running,
                ..
            } => {
                motor(m)?;
                within(holding, CURRENT_RANGE)?;
                within(running, CURRENT_RANGE)
            }
            Command::SetDebounce { count, .. } => within(count, DEBOUNCE_RANGE),
        }
    }

    /// Build a command from its letter and raw parameters. The parameter
    /// count must be within [`CommandCode::param_counts`].
    pub(super) fn from_parts(id: u8, code: CommandCode, p: &[u32]) -> Option<Command> {
        let (lo, hi) = code.param_counts();
        if p.len() < lo || p.len() > hi {
            return None;
        }
        let g = |i: usize| p.get(i).copied();
        Some(match code {
            CommandCode::Initialize => Command::Initialize { id },
            CommandCode::Acceleration => Command::SetAcceleration {
                id,
                motor: g(0)?,
                value: g(1)?,
            },
            CommandCode::Deceleration => Command::SetDeceleration {
                id,
                motor: g(0)?,
                value: g(1)?,
            },
            CommandCode::Velocity => Command::SetMaxVelocity {
                id,
                motor: g(0)?,
                value: g(1)?,
                direction_modifier: g(2),
            },
            CommandCode::Limits => Command::SetLimits {
                id,
                motor: g(0)?,
                h0_and: g(1)?,
                h0_xor: g(2)?,
                h1_and: g(3)?,
                h1_xor: g(4)?,
            },
            CommandCode::HalfStep => Command::SetHalfStep {
                id,
                motor: g(0)?,
                half: g(1)?,
            },
            CommandCode::Run => Command::Run {
                id,
                motor: g(0)?,
                direction: g(1)?,
            },
            CommandCode::Move => Command::Move {
                id,
                motor: g(0)?,
                steps: g(1)?,
                direction: g(2)?,
            },
            CommandCode::Home => Command::Home {
                id,
                motor: g(0)?,
                direction: g(1)?,
            },
            CommandCode::RateMove => Command::RateMove {
                id,
                motor: g(0)?,
                steps: g(1)?,
                direction: g(2)?,
                rate: g(3)?,
            },
            CommandCode::Stop => Command::Stop { id, motor: g(0)? },
            CommandCode::SyncMove => Command::SyncMove {
                id,
                steps: [g(0)?, g(2)?, g(4)?],
                directions: [g(1)?, g(3)?, g(5)?],
                execute: g(6),
            },
            CommandCode::QueryStatus => Command::QueryStatus { id, motor: g(0)? },
            CommandCode::QueryLimits => Command::QueryLimits { id },
            CommandCode::HoldingCurrent => Command::SetHoldingCurrent {
                id,
                motor: g(0)?,
                enable: g(1)?,
            },
            CommandCode::CurrentLimits => Command::SetCurrentLimits {
                id,
                motor: g(0)?,
                holding: g(1)?,
                running: g(2)?,
            },
            CommandCode::Debounce => Command::SetDebounce { id, count: g(0)? },
            CommandCode::ProductId => Command::QueryProductId { id },
        })
    }
}
