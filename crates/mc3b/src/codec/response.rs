//! The device-to-host responses, and why a response frame could not be decoded.

use std::fmt;

use super::{CommandCode, ErrorCode};

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
    /// The frame exceeded [`MAX_LINE`](super::MAX_LINE) bytes.
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
