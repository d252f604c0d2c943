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

mod command;
mod command_code;
mod error_code;
mod frame;
mod response;
mod stream;

pub use command::Command;
pub use command_code::CommandCode;
pub use error_code::ErrorCode;
pub use frame::{encode, encode_response, parse_command, parse_response, CommandError};
pub use response::{ProtocolError, Response};
pub use stream::{CommandParser, ResponseParser};

/// Longest frame (without its CR) that either parser accepts.
pub const MAX_LINE: usize = 96;

/// Carriage return, the frame terminator.
pub const CR: u8 = b'\r';
/// Line feed, ignored wherever it appears.
pub const LF: u8 = b'\n';

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

#[cfg(test)]
mod tests;
