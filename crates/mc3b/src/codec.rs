//! Codec for the MC3B ASCII serial command set (User's Guide §6).
//!
//! Frame syntax (both directions): `<id><code>[p1][,p2]...<CR>`, where `<id>`
//! is the decimal controller ID, `<code>` one ASCII letter and the parameters
//! unsigned decimal integers separated by commas. Line feeds are ignored
//! everywhere in the stream.
//!
//! Decisions where the guide is vague (each applies to both the emulator and
//! the client, which share this module):
//!
//! * Responses are terminated by a CR, like commands (the guide does not say;
//!   a trailing LF would be ignored anyway).
//! * The controller ID is 1 to 3 decimal digits with a value of at most 255.
//! * Parameters are unsigned decimal integers of at most 32 bits; a parameter
//!   that is empty, not numeric (a sign, a space, a letter) or too large is a
//!   *parameter out of range* error (`E3`), since the field count is right.
//! * Check order on the device: unknown command letter (`E0`), then parameter
//!   count (`E2`), then parameter syntax and ranges (`E3`), then motor state
//!   (`E1`).
//! * A line longer than [`MAX_LINE`] bytes is discarded whole and reported as
//!   an error (`E0` on the device side if its ID could be read).
//! * Numbers in responses (limit byte, status flags, product, version) are
//!   decimal, like every number in the guide's examples.

use std::collections::VecDeque;
use std::fmt;

/// Longest frame (without its CR) that either parser accepts.
pub const MAX_LINE: usize = 96;

/// Carriage return, the frame terminator.
pub const CR: u8 = b'\r';
/// Line feed, ignored wherever it appears.
pub const LF: u8 = b'\n';

/// The command letters of §6 (every command of the MC3B).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CommandCode {
    /// `I`: initialize (§6.1).
    Initialize,
    /// `A`: set acceleration (§6.2).
    Acceleration,
    /// `D`: set deceleration (§6.3).
    Deceleration,
    /// `V`: set maximum velocity (§6.4).
    Velocity,
    /// `L`: set limit switch masks (§6.5).
    Limits,
    /// `F`: full/half stepping (§6.6).
    HalfStep,
    /// `R`: run (§6.7).
    Run,
    /// `M`: move (§6.8).
    Move,
    /// `H`: home (§6.9).
    Home,
    /// `G`: rate-based motion (§6.10).
    RateMove,
    /// `S`: stop (§6.11).
    Stop,
    /// `Y`: synchronous move (§6.12).
    SyncMove,
    /// `Q`: query motor status (§6.13).
    QueryStatus,
    /// `B`: query limit inputs (§6.14).
    QueryLimits,
    /// `C`: holding current usage (§6.15).
    HoldingCurrent,
    /// `K`: current limits (§6.16).
    CurrentLimits,
    /// `N`: limit switch debounce count (§6.17).
    Debounce,
    /// `P`: query product ID (§6.18).
    ProductId,
}

impl CommandCode {
    /// All command codes, in the order of §6.
    pub const ALL: [CommandCode; 18] = [
        CommandCode::Initialize,
        CommandCode::Acceleration,
        CommandCode::Deceleration,
        CommandCode::Velocity,
        CommandCode::Limits,
        CommandCode::HalfStep,
        CommandCode::Run,
        CommandCode::Move,
        CommandCode::Home,
        CommandCode::RateMove,
        CommandCode::Stop,
        CommandCode::SyncMove,
        CommandCode::QueryStatus,
        CommandCode::QueryLimits,
        CommandCode::HoldingCurrent,
        CommandCode::CurrentLimits,
        CommandCode::Debounce,
        CommandCode::ProductId,
    ];

    /// The ASCII letter of this command on the wire.
    pub fn letter(self) -> u8 {
        match self {
            CommandCode::Initialize => b'I',
            CommandCode::Acceleration => b'A',
            CommandCode::Deceleration => b'D',
            CommandCode::Velocity => b'V',
            CommandCode::Limits => b'L',
            CommandCode::HalfStep => b'F',
            CommandCode::Run => b'R',
            CommandCode::Move => b'M',
            CommandCode::Home => b'H',
            CommandCode::RateMove => b'G',
            CommandCode::Stop => b'S',
            CommandCode::SyncMove => b'Y',
            CommandCode::QueryStatus => b'Q',
            CommandCode::QueryLimits => b'B',
            CommandCode::HoldingCurrent => b'C',
            CommandCode::CurrentLimits => b'K',
            CommandCode::Debounce => b'N',
            CommandCode::ProductId => b'P',
        }
    }

    /// The command for an ASCII letter (case-sensitive: the guide only uses
    /// capitals), or `None`.
    pub fn from_letter(b: u8) -> Option<CommandCode> {
        CommandCode::ALL.iter().copied().find(|c| c.letter() == b)
    }

    /// Accepted parameter counts `(min, max)` for this command.
    pub fn param_counts(self) -> (usize, usize) {
        match self {
            CommandCode::Initialize | CommandCode::QueryLimits | CommandCode::ProductId => (0, 0),
            CommandCode::Stop | CommandCode::QueryStatus | CommandCode::Debounce => (1, 1),
            CommandCode::Acceleration
            | CommandCode::Deceleration
            | CommandCode::HalfStep
            | CommandCode::Run
            | CommandCode::Home
            | CommandCode::HoldingCurrent => (2, 2),
            CommandCode::Velocity => (2, 3),
            CommandCode::Move | CommandCode::CurrentLimits => (3, 3),
            CommandCode::RateMove => (4, 4),
            CommandCode::Limits => (5, 5),
            CommandCode::SyncMove => (6, 7),
        }
    }

    /// Whether the device answers this command with a bare `<id><letter>`
    /// acknowledgement (all but the three queries).
    pub fn is_acknowledged(self) -> bool {
        !matches!(
            self,
            CommandCode::QueryStatus | CommandCode::QueryLimits | CommandCode::ProductId
        )
    }
}

/// Device error numbers of §6.19 (sent as `<id>E<e>`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ErrorCode {
    /// `E0`: command character not recognized.
    InvalidCommand,
    /// `E1`: the command must be sent while the motor is idle.
    MotorRunning,
    /// `E2`: wrong number of parameters.
    WrongParameterCount,
    /// `E3`: parameter out of range.
    OutOfRange,
}

impl ErrorCode {
    /// Number used on the wire.
    pub fn number(self) -> u32 {
        match self {
            ErrorCode::InvalidCommand => 0,
            ErrorCode::MotorRunning => 1,
            ErrorCode::WrongParameterCount => 2,
            ErrorCode::OutOfRange => 3,
        }
    }

    /// What the error means, in the words of §6.19.
    pub fn meaning(self) -> &'static str {
        match self {
            ErrorCode::InvalidCommand => "invalid command: command character not recognized",
            ErrorCode::MotorRunning => "motor running: command must be sent when motor is idle",
            ErrorCode::WrongParameterCount => {
                "wrong number of parameters: the exact number of expected parameters must be \
                 supplied with a command"
            }
            ErrorCode::OutOfRange => "parameter out of range",
        }
    }

    /// Error code for a wire number, or `None`.
    pub fn from_number(n: u32) -> Option<ErrorCode> {
        match n {
            0 => Some(ErrorCode::InvalidCommand),
            1 => Some(ErrorCode::MotorRunning),
            2 => Some(ErrorCode::WrongParameterCount),
            3 => Some(ErrorCode::OutOfRange),
            _ => None,
        }
    }
}

/// Acceleration/deceleration range of §6.2/§6.3, steps/s².
pub const ACCEL_RANGE: (u32, u32) = (100, 100_000);
/// Maximum velocity range of §6.4, steps/s.
pub const VELOCITY_RANGE: (u32, u32) = (1, 5000);
/// Current limit range of §6.16, mA.
pub const CURRENT_RANGE: (u32, u32) = (0, 2000);
/// Debounce count range of §6.17.
pub const DEBOUNCE_RANGE: (u32, u32) = (1, 100);
/// Smallest rate of §6.10 (in 10 µs units).
pub const MIN_RATE: u32 = 50;
/// Number of motors on one MC3B.
pub const MOTORS: u32 = 3;
/// Largest value of a limit mask: the decision is that a mask is a byte
/// (only bits 0..5 have inputs behind them).
pub const MAX_MASK: u32 = 255;

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

/// One device-to-host response.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Response {
    /// `<id><letter>`: acknowledgement of a non-query command.
    Ack {
        /// Controller ID.
        id: u8,
        /// The acknowledged command.
        code: CommandCode,
    },
    /// `<id>Q<r>,<home0>,<home1>` (§6.13). Any non-zero `r` parses as running.
    Status {
        /// Controller ID.
        id: u8,
        /// Motor in motion.
        running: bool,
        /// At the direction 0 home.
        home0: bool,
        /// At the direction 1 home.
        home1: bool,
    },
    /// `<id>B<h>`: debounced limit input byte (§6.14).
    Limits {
        /// Controller ID.
        id: u8,
        /// Input bits, bit n = input n.
        bits: u8,
    },
    /// `<id>P<product>,<version>` (§6.18).
    ProductId {
        /// Controller ID.
        id: u8,
        /// 1 for the MC3B.
        product: u32,
        /// Firmware version.
        version: u32,
    },
    /// `<id>E<e>` (§6.19).
    Error {
        /// Controller ID.
        id: u8,
        /// Error number.
        code: ErrorCode,
    },
}

impl Response {
    /// Controller ID of the response.
    pub fn id(&self) -> u8 {
        match *self {
            Response::Ack { id, .. }
            | Response::Status { id, .. }
            | Response::Limits { id, .. }
            | Response::ProductId { id, .. }
            | Response::Error { id, .. } => id,
        }
    }
}

/// Why a response frame could not be decoded.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ProtocolError {
    /// The frame does not start with a valid controller ID.
    BadId,
    /// The frame has no letter after the ID, or an unknown one.
    UnknownCode(Option<u8>),
    /// The frame has the wrong number of fields for its letter.
    WrongFieldCount {
        /// The letter.
        code: u8,
        /// Fields present.
        got: usize,
    },
    /// A field is not an unsigned decimal number of the expected size.
    BadField,
    /// An `E` frame carries an error number not listed in §6.19.
    UnknownErrorNumber(u32),
    /// The frame exceeded [`MAX_LINE`] bytes.
    LineTooLong,
}

impl fmt::Display for ProtocolError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ProtocolError::BadId => write!(f, "bad controller id"),
            ProtocolError::UnknownCode(c) => write!(f, "unknown response code {c:?}"),
            ProtocolError::WrongFieldCount { code, got } => {
                write!(f, "wrong field count {got} for '{}'", *code as char)
            }
            ProtocolError::BadField => write!(f, "bad numeric field"),
            ProtocolError::UnknownErrorNumber(n) => write!(f, "unknown error number {n}"),
            ProtocolError::LineTooLong => write!(f, "line too long"),
        }
    }
}

impl std::error::Error for ProtocolError {}

/// Why a command frame was rejected. `id` is `None` when no controller ID
/// could be read: the device then stays silent (it cannot address a reply).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CommandError {
    /// ID the reply goes to, if one was read.
    pub id: Option<u8>,
    /// Error to report.
    pub code: ErrorCode,
}

fn push_num(out: &mut Vec<u8>, n: u32) {
    out.extend_from_slice(n.to_string().as_bytes());
}

fn frame(id: u8, letter: u8, params: &[u32]) -> Vec<u8> {
    let mut out = Vec::with_capacity(8 + params.len() * 6);
    push_num(&mut out, u32::from(id));
    out.push(letter);
    for (i, p) in params.iter().enumerate() {
        if i > 0 {
            out.push(b',');
        }
        push_num(&mut out, *p);
    }
    out.push(CR);
    out
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
    fn from_parts(id: u8, code: CommandCode, p: &[u32]) -> Option<Command> {
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

/// Encode a command as wire bytes, CR included.
pub fn encode(cmd: &Command) -> Vec<u8> {
    frame(cmd.id(), cmd.code().letter(), &cmd.params())
}

/// Encode a response as wire bytes, CR included.
pub fn encode_response(resp: &Response) -> Vec<u8> {
    match *resp {
        Response::Ack { id, code } => frame(id, code.letter(), &[]),
        Response::Status {
            id,
            running,
            home0,
            home1,
        } => frame(
            id,
            b'Q',
            &[u32::from(running), u32::from(home0), u32::from(home1)],
        ),
        Response::Limits { id, bits } => frame(id, b'B', &[u32::from(bits)]),
        Response::ProductId {
            id,
            product,
            version,
        } => frame(id, b'P', &[product, version]),
        Response::Error { id, code } => frame(id, b'E', &[code.number()]),
    }
}

/// A frame split into its parts; fields are still text.
struct RawFrame<'a> {
    id: u8,
    letter: Option<u8>,
    fields: Vec<&'a [u8]>,
}

/// Split `<id><letter>[f1][,f2]...` (no CR, no LF). `None` if no valid ID.
fn split_frame(line: &[u8]) -> Option<RawFrame<'_>> {
    let digits = line.iter().take_while(|b| b.is_ascii_digit()).count();
    if digits == 0 || digits > 3 {
        return None;
    }
    let id = parse_u32(line.get(..digits)?)?;
    let id = u8::try_from(id).ok()?;
    let letter = line.get(digits).copied();
    let rest = line.get(digits + 1..).unwrap_or(&[]);
    let fields = if rest.is_empty() {
        Vec::new()
    } else {
        rest.split(|b| *b == b',').collect()
    };
    Some(RawFrame { id, letter, fields })
}

/// Parse an unsigned decimal of at most 32 bits; `None` for anything else.
fn parse_u32(s: &[u8]) -> Option<u32> {
    if s.is_empty() || s.len() > 10 {
        return None;
    }
    let mut v: u64 = 0;
    for &b in s {
        if !b.is_ascii_digit() {
            return None;
        }
        v = v * 10 + u64::from(b - b'0');
    }
    u32::try_from(v).ok()
}

/// Parse one command frame (without CR; LFs are skipped). Applies the syntax,
/// letter and count checks; not the range checks ([`Command::validate`]).
pub fn parse_command(line: &[u8]) -> Result<Command, CommandError> {
    let clean: Vec<u8> = line.iter().copied().filter(|b| *b != LF).collect();
    let raw = split_frame(&clean).ok_or(CommandError {
        id: None,
        code: ErrorCode::InvalidCommand,
    })?;
    let err = |code| CommandError {
        id: Some(raw.id),
        code,
    };
    let code = raw
        .letter
        .and_then(CommandCode::from_letter)
        .ok_or(err(ErrorCode::InvalidCommand))?;
    let (lo, hi) = code.param_counts();
    if raw.fields.len() < lo || raw.fields.len() > hi {
        return Err(err(ErrorCode::WrongParameterCount));
    }
    let mut params = Vec::with_capacity(raw.fields.len());
    for f in &raw.fields {
        params.push(parse_u32(f).ok_or(err(ErrorCode::OutOfRange))?);
    }
    Command::from_parts(raw.id, code, &params).ok_or(err(ErrorCode::WrongParameterCount))
}

/// Parse one response frame (without CR; LFs are skipped).
pub fn parse_response(line: &[u8]) -> Result<Response, ProtocolError> {
    let clean: Vec<u8> = line.iter().copied().filter(|b| *b != LF).collect();
    let raw = split_frame(&clean).ok_or(ProtocolError::BadId)?;
    let letter = raw.letter.ok_or(ProtocolError::UnknownCode(None))?;
    let id = raw.id;
    let mut nums = Vec::with_capacity(raw.fields.len());
    for f in &raw.fields {
        nums.push(parse_u32(f).ok_or(ProtocolError::BadField)?);
    }
    let wrong = || ProtocolError::WrongFieldCount {
        code: letter,
        got: nums.len(),
    };
    let flag = |v: u32| match v {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(ProtocolError::BadField),
    };
    match (letter, nums.as_slice()) {
        (b'E', &[n]) => {
            let code = ErrorCode::from_number(n).ok_or(ProtocolError::UnknownErrorNumber(n))?;
            Ok(Response::Error { id, code })
        }
        (b'Q', &[r, h0, h1]) => Ok(Response::Status {
            id,
            running: r != 0,
            home0: flag(h0)?,
            home1: flag(h1)?,
        }),
        (b'B', &[b]) => {
            let bits = u8::try_from(b).map_err(|_| ProtocolError::BadField)?;
            Ok(Response::Limits { id, bits })
        }
        (b'P', &[product, version]) => Ok(Response::ProductId {
            id,
            product,
            version,
        }),
        (b'E' | b'Q' | b'B' | b'P', _) => Err(wrong()),
        (other, fields) => {
            let code = CommandCode::from_letter(other)
                .filter(|c| c.is_acknowledged())
                .ok_or(ProtocolError::UnknownCode(Some(other)))?;
            if fields.is_empty() {
                Ok(Response::Ack { id, code })
            } else {
                Err(wrong())
            }
        }
    }
}

/// Splits a byte stream into CR-terminated lines, dropping LFs and capping
/// line length at [`MAX_LINE`].
#[derive(Debug, Default, Clone)]
pub struct LineSplitter {
    buf: Vec<u8>,
    overflow: bool,
}

/// One line out of a [`LineSplitter`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Line {
    /// A complete line (without CR).
    Complete(Vec<u8>),
    /// A line longer than [`MAX_LINE`]; its first bytes are kept so the ID
    /// can still be read.
    TooLong(Vec<u8>),
}

impl LineSplitter {
    /// Empty splitter.
    pub fn new() -> Self {
        Self::default()
    }

    /// Feed one byte; returns a line when `b` is a CR. Empty lines are
    /// skipped.
    pub fn push(&mut self, b: u8) -> Option<Line> {
        match b {
            LF => None,
            CR => {
                let line = std::mem::take(&mut self.buf);
                if std::mem::take(&mut self.overflow) {
                    Some(Line::TooLong(line))
                } else if line.is_empty() {
                    None
                } else {
                    Some(Line::Complete(line))
                }
            }
            _ => {
                if self.buf.len() < MAX_LINE {
                    self.buf.push(b);
                } else {
                    self.overflow = true;
                }
                None
            }
        }
    }

    /// Drop any partial line.
    pub fn clear(&mut self) {
        self.buf.clear();
        self.overflow = false;
    }

    /// Whether the current (unfinished) line has passed [`MAX_LINE`] bytes.
    pub fn overflowing(&self) -> bool {
        self.overflow
    }
}

/// Streaming response parser: feed arbitrary chunks, take parsed frames.
#[derive(Debug, Default, Clone)]
pub struct ResponseParser {
    lines: LineSplitter,
    ready: VecDeque<Result<Response, ProtocolError>>,
}

impl ResponseParser {
    /// Empty parser.
    pub fn new() -> Self {
        Self::default()
    }

    /// Feed a chunk of bytes (any length, any split). A line is reported
    /// [`ProtocolError::LineTooLong`] as soon as it passes [`MAX_LINE`] bytes (no
    /// reply is that long, so a reader need not wait for its CR, which may never
    /// come); the rest of it, up to its CR, is dropped without a second report.
    pub fn feed(&mut self, data: &[u8]) {
        for &b in data {
            let was_over = self.lines.overflowing();
            match self.lines.push(b) {
                Some(Line::Complete(l)) => self.ready.push_back(parse_response(&l)),
                Some(Line::TooLong(_)) => {
                    if !was_over {
                        self.ready.push_back(Err(ProtocolError::LineTooLong));
                    }
                }
                None => {
                    if !was_over && self.lines.overflowing() {
                        self.ready.push_back(Err(ProtocolError::LineTooLong));
                    }
                }
            }
        }
    }

    /// Ends the line being received as if its CR had come: for a reader that knows no
    /// more of it will come (its reply timeout expired), what arrived is a frame of its
    /// own, and the next line is not read glued to it. Nothing when no line is begun.
    pub fn end_line(&mut self) {
        self.feed(&[CR]);
    }

    /// Next complete frame, if any.
    pub fn next_response(&mut self) -> Option<Result<Response, ProtocolError>> {
        self.ready.pop_front()
    }

    /// Drop partial input and unread frames.
    pub fn clear(&mut self) {
        self.lines.clear();
        self.ready.clear();
    }
}

/// Streaming command parser (device side).
#[derive(Debug, Default, Clone)]
pub struct CommandParser {
    lines: LineSplitter,
    ready: VecDeque<Result<Command, CommandError>>,
}

impl CommandParser {
    /// Empty parser.
    pub fn new() -> Self {
        Self::default()
    }

    /// Feed a chunk of bytes.
    pub fn feed(&mut self, data: &[u8]) {
        for &b in data {
            match self.lines.push(b) {
                Some(Line::Complete(l)) => self.ready.push_back(parse_command(&l)),
                Some(Line::TooLong(l)) => {
                    let id = split_frame(&l).map(|r| r.id);
                    self.ready.push_back(Err(CommandError {
                        id,
                        code: ErrorCode::InvalidCommand,
                    }))
                }
                None => {}
            }
        }
    }

    /// Next complete command (or its error), if any.
    pub fn next_command(&mut self) -> Option<Result<Command, CommandError>> {
        self.ready.pop_front()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One example of every command, with optional parameters both ways.
    pub(crate) fn all_commands() -> Vec<Command> {
        vec![
            Command::Initialize { id: 0 },
            Command::SetAcceleration {
                id: 0,
                motor: 1,
                value: 5000,
            },
            Command::SetDeceleration {
                id: 2,
                motor: 2,
                value: 100000,
            },
            Command::SetMaxVelocity {
                id: 0,
                motor: 0,
                value: 1000,
                direction_modifier: None,
            },
            Command::SetMaxVelocity {
                id: 0,
                motor: 0,
                value: 1000,
                direction_modifier: Some(1),
            },
            Command::SetLimits {
                id: 0,
                motor: 2,
                h0_and: 8,
                h0_xor: 0,
                h1_and: 32,
                h1_xor: 32,
            },
            Command::SetHalfStep {
                id: 0,
                motor: 1,
                half: 0,
            },
            Command::Run {
                id: 0,
                motor: 0,
                direction: 1,
            },
            Command::Move {
                id: 0,
                motor: 2,
                steps: u32::MAX,
                direction: 0,
            },
            Command::Home {
                id: 0,
                motor: 1,
                direction: 0,
            },
            Command::RateMove {
                id: 0,
                motor: 1,
                steps: 100,
                direction: 0,
                rate: 75,
            },
            Command::Stop { id: 0, motor: 2 },
            Command::SyncMove {
                id: 0,
                steps: [1000, 1000, 0],
                directions: [0, 1, 0],
                execute: None,
            },
            Command::SyncMove {
                id: 0,
                steps: [1000, 1000, 0],
                directions: [1, 1, 0],
                execute: Some(0),
            },
            Command::QueryStatus { id: 0, motor: 1 },
            Command::QueryLimits { id: 255 },
            Command::SetHoldingCurrent {
                id: 0,
                motor: 0,
                enable: 1,
            },
            Command::SetCurrentLimits {
                id: 0,
                motor: 0,
                holding: 500,
                running: 2000,
            },
            Command::SetDebounce { id: 0, count: 100 },
            Command::QueryProductId { id: 0 },
        ]
    }

    #[test]
    fn every_command_round_trips() {
        let cmds = all_commands();
        let codes: std::collections::HashSet<_> = cmds.iter().map(|c| c.code()).collect();
        assert_eq!(codes.len(), CommandCode::ALL.len(), "every letter covered");
        for c in cmds {
            let bytes = encode(&c);
            assert_eq!(bytes.last(), Some(&CR));
            let parsed = parse_command(&bytes[..bytes.len() - 1]);
            assert_eq!(
                parsed,
                Ok(c.clone()),
                "{:?}",
                String::from_utf8_lossy(&bytes)
            );
            assert_eq!(c.validate(), Ok(()), "{c:?}");
        }
    }

    #[test]
    fn guide_examples_encode_exactly() {
        let ex = Command::SetLimits {
            id: 0,
            motor: 2,
            h0_and: 8,
            h0_xor: 0,
            h1_and: 32,
            h1_xor: 32,
        };
        assert_eq!(encode(&ex), b"0L2,8,0,32,32\r");
        let g = Command::RateMove {
            id: 0,
            motor: 1,
            steps: 100,
            direction: 0,
            rate: 75,
        };
        assert_eq!(encode(&g), b"0G1,100,0,75\r");
        let y = Command::SyncMove {
            id: 0,
            steps: [1000, 1000, 0],
            directions: [1, 0, 0],
            execute: Some(1),
        };
        assert_eq!(encode(&y), b"0Y1000,1,1000,0,0,0,1\r");
        let v = Command::SetMaxVelocity {
            id: 0,
            motor: 0,
            value: 1000,
            direction_modifier: Some(1),
        };
        assert_eq!(encode(&v), b"0V0,1000,1\r");
    }

    #[test]
    fn every_response_round_trips_through_the_stream_parser() {
        let mut resps: Vec<Response> = CommandCode::ALL
            .iter()
            .filter(|c| c.is_acknowledged())
            .map(|&code| Response::Ack { id: 0, code })
            .collect();
        resps.push(Response::Status {
            id: 0,
            running: true,
            home0: false,
            home1: true,
        });
        resps.push(Response::Limits { id: 0, bits: 63 });
        resps.push(Response::ProductId {
            id: 0,
            product: 1,
            version: 100,
        });
        for code in [
            ErrorCode::InvalidCommand,
            ErrorCode::MotorRunning,
            ErrorCode::WrongParameterCount,
            ErrorCode::OutOfRange,
        ] {
            resps.push(Response::Error { id: 7, code });
        }
        // Concatenate with LFs sprinkled in and feed one byte at a time.
        let mut stream = Vec::new();
        for r in &resps {
            let b = encode_response(r);
            stream.push(LF);
            stream.extend_from_slice(&b[..1]);
            stream.push(LF);
            stream.extend_from_slice(&b[1..]);
        }
        let mut p = ResponseParser::new();
        for chunk in stream.chunks(3) {
            p.feed(chunk);
        }
        for r in &resps {
            assert_eq!(p.next_response(), Some(Ok(*r)));
        }
        assert_eq!(p.next_response(), None);
    }

    #[test]
    fn command_errors_follow_the_documented_order() {
        let e = |s: &str| parse_command(s.as_bytes()).err();
        assert_eq!(
            e("0Z1"),
            Some(CommandError {
                id: Some(0),
                code: ErrorCode::InvalidCommand
            })
        );
        assert_eq!(
            e("0A1"),
            Some(CommandError {
                id: Some(0),
                code: ErrorCode::WrongParameterCount
            })
        );
        assert_eq!(
            e("0Y1,0,1,0,1,0,1,1"),
            Some(CommandError {
                id: Some(0),
                code: ErrorCode::WrongParameterCount
            })
        );
        assert_eq!(
            e("0A1,-5"),
            Some(CommandError {
                id: Some(0),
                code: ErrorCode::OutOfRange
            })
        );
        assert_eq!(
            e("0M0,4294967296,0"),
            Some(CommandError {
                id: Some(0),
                code: ErrorCode::OutOfRange
            })
        );
        assert_eq!(e("A1,5").map(|x| x.id), Some(None));
        assert_eq!(parse_command(b"0I\n"), Ok(Command::Initialize { id: 0 }));
        let a = parse_command(b"0A3,5000").map(|c| c.validate());
        assert_eq!(a, Ok(Err(ErrorCode::OutOfRange)));
        let r = parse_command(b"0G1,100,0,49").map(|c| c.validate());
        assert_eq!(r, Ok(Err(ErrorCode::OutOfRange)));
    }

    #[test]
    fn malformed_responses_are_errors() {
        assert_eq!(parse_response(b"E1"), Err(ProtocolError::BadId));
        assert_eq!(
            parse_response(b"0E9"),
            Err(ProtocolError::UnknownErrorNumber(9))
        );
        assert_eq!(
            parse_response(b"0Q1,0"),
            Err(ProtocolError::WrongFieldCount { code: b'Q', got: 2 })
        );
        assert_eq!(parse_response(b"0B256"), Err(ProtocolError::BadField));
        assert_eq!(
            parse_response(b"0Z"),
            Err(ProtocolError::UnknownCode(Some(b'Z')))
        );
        assert_eq!(
            parse_response(b"0A5"),
            Err(ProtocolError::WrongFieldCount { code: b'A', got: 1 })
        );
        let mut p = ResponseParser::new();
        p.feed(&[b'0'; MAX_LINE]);
        assert_eq!(
            p.next_response(),
            None,
            "a line of MAX_LINE bytes may still end"
        );
        p.feed(b"0");
        // Reported at its (MAX_LINE + 1)th byte, before any CR: a reader need not wait.
        assert_eq!(p.next_response(), Some(Err(ProtocolError::LineTooLong)));
        p.feed(&[b'0'; 500]);
        p.feed(b"\r0I\r");
        assert_eq!(
            p.next_response(),
            Some(Ok(Response::Ack {
                id: 0,
                code: CommandCode::Initialize
            }))
        );
    }

    /// xorshift64* PRNG: deterministic, no crates.
    pub(crate) struct XorShift(pub u64);
    impl XorShift {
        pub(crate) fn next(&mut self) -> u64 {
            let mut x = self.0;
            x ^= x >> 12;
            x ^= x << 25;
            x ^= x >> 27;
            self.0 = x;
            x.wrapping_mul(0x2545_F491_4F6C_DD1D)
        }
    }

    #[test]
    fn fuzz_100k_random_byte_strings_never_panic() {
        let mut rng = XorShift(0x9E37_79B9_7F4A_7C15);
        // Bias the alphabet toward the protocol's own bytes so that deep
        // paths are exercised, with raw bytes mixed in.
        const ALPHA: &[u8] = b"0123456789,,,IADVLFRMHGSYQBCKNPEZ\r\r\n- ";
        let mut rp = ResponseParser::new();
        let mut cp = CommandParser::new();
        let (mut ok_r, mut ok_c, mut frames) = (0u32, 0u32, 0u32);
        for _ in 0..100_000 {
            let len = (rng.next() % 40) as usize;
            let bytes: Vec<u8> = (0..len)
                .map(|_| {
                    let r = rng.next();
                    if r % 4 == 0 {
                        (r >> 8) as u8
                    } else {
                        ALPHA[((r >> 8) % ALPHA.len() as u64) as usize]
                    }
                })
                .collect();
            // Whole-line parsers.
            let _ = parse_response(&bytes);
            let _ = parse_command(&bytes).map(|c| c.validate());
            // Streaming parsers.
            rp.feed(&bytes);
            cp.feed(&bytes);
            while let Some(r) = rp.next_response() {
                frames += 1;
                if let Ok(resp) = r {
                    ok_r += 1;
                    // Anything accepted re-encodes to something that parses
                    // back to the same value.
                    let enc = encode_response(&resp);
                    assert_eq!(parse_response(&enc[..enc.len() - 1]), Ok(resp));
                }
            }
            while let Some(c) = cp.next_command() {
                if let Ok(cmd) = c {
                    ok_c += 1;
                    let enc = encode(&cmd);
                    assert_eq!(parse_command(&enc[..enc.len() - 1]), Ok(cmd));
                }
            }
        }
        assert!(frames > 10_000, "frames {frames}");
        assert!(ok_r > 0 && ok_c > 0, "ok_r {ok_r} ok_c {ok_c}");
    }
}
