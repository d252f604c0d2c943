//! Why a command failed.

use std::fmt;
use std::io;

use crate::codec::{ErrorCode, ProtocolError, Response};

/// Why a command failed.
#[derive(Debug)]
pub enum ClientError {
    /// No reply within the timeout.
    Timeout,
    /// The transport failed (including a hang-up).
    Io(io::Error),
    /// The device answered `<id>E<e>`.
    Device(ErrorCode),
    /// A frame that does not fit the command: another command's answer, or another
    /// controller's.
    Unexpected(Response),
    /// A frame that cannot be decoded (garbage, too long).
    Garbled(ProtocolError),
}

impl ClientError {
    /// Whether the device may have acted on the command although no good reply came
    /// (everything but a clean `<id>E<e>`).
    pub fn fate_unknown(&self) -> bool {
        !matches!(self, ClientError::Device(_))
    }
}

impl fmt::Display for ClientError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ClientError::Timeout => write!(f, "timeout waiting for the MC3B"),
            ClientError::Io(e) => write!(f, "serial I/O error: {e}"),
            ClientError::Device(c) => write!(f, "MC3B error {}", c.number()),
            ClientError::Unexpected(r) => write!(f, "unexpected reply {r:?}"),
            ClientError::Garbled(e) => write!(f, "unreadable reply ({e})"),
        }
    }
}

impl std::error::Error for ClientError {}

impl From<io::Error> for ClientError {
    fn from(e: io::Error) -> Self {
        ClientError::Io(e)
    }
}
